set -u
for f in .gl/*.deb; do dpkg -x $f / >/dev/null; done; ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json SNELL_DEVICE=gpu
mkdir -p /work/main/build/default/plugins/mirror/output /work/main/build/default/plugins/dynamic_cubemap/output
build/gpu/snell_mirror_tests 2>&1 | tail -3
build/gpu/snell_dynamic_cubemap_tests 2>&1 | tail -2
for size in 1280x720 3840x2160; do for sc in 0.5 1.0; do echo "== mirror $size scale $sc"; build/gpu/snell bench --scene mirror --effect mirror --set mirror.resolution_scale=$sc --size $size --frames 300 | grep -E "^plain|^effect|ratio|pass"; done; done
echo "== mirror rough 0.5 1280x720"; build/gpu/snell bench --scene mirror --effect mirror --set mirror.roughness=0.5 --size 1280x720 --frames 300 | grep -E "ratio|pass mirror|surfaces"
