set -u
for f in .gl/*.deb; do dpkg -x $f / >/dev/null; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json SNELL_DEVICE=gpu
mkdir -p /work/main/build/default/plugins/dynamic_cubemap/output /work/main/build/default/plugins/glass/output /work/main/build/default/tests/gpu/output
build/gpu/snell info 2>&1 | head -5
for t in snell_dynamic_cubemap_tests; do build/gpu/$t 2>&1 | tail -4; done
build/gpu/snell_glass_tests -tc="*probe*" 2>&1 | tail -3
build/gpu/snell_gpu_tests -tc="*prefilter*,*cube capture*" 2>&1 | tail -3
SNELL=build/gpu/snell bash scripts/bench_cubemap.sh --frames 200 --size 1280x720 2>&1
SNELL=build/gpu/snell bash scripts/bench_cubemap.sh --frames 200 --size 3840x2160 2>&1
for pf in mips ggx; do build/gpu/snell bench --scene spheres --effect dynamic_cubemap --set dynamic_cubemap.prefilter=$pf --set dynamic_cubemap.roughness=0.5 --frames 200 --size 1280x720 | grep -E "ratio|pass"; done
