#!/usr/bin/env bash
# Builds Snell (default preset) and runs the demo "main job"; results go to out/.
# Usage: bash scripts/demo.sh
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
repo_root="$(pwd)"
build_dir="$repo_root/build/default"
out_dir="$repo_root/out"

bash scripts/setup.sh

cmake --preset default
cmake --build --preset default -j"$(nproc 2>/dev/null || echo 2)"

mkdir -p "$out_dir"

# ==== Main job: math sample ======================================================================
echo "=== math sample -> out/math-sample.txt ==="
"$build_dir/samples/math-only/snell-math-sample" | tee "$out_dir/math-sample.txt"
# ==== End: math sample ===========================================================================

# ==== Main job: demo scenes ======================================================================
# Renders the built-in demo scenes headlessly (lavapipe unless a GPU is present; SNELL_DEVICE
# chooses) to out/*.png with the `snell` CLI.
for scene in pool window spheres room mirror; do
  echo "=== render $scene -> out/$scene.png ==="
  "$build_dir/samples/cli/snell" render --scene "$scene" --size 1280x720 --out "$out_dir/$scene.png"
done
echo "=== render pool with water -> out/pool_water.png ==="
"$build_dir/samples/cli/snell" render --scene pool --effect water --size 1280x720 \
  --out "$out_dir/pool_water.png"
for effect in glass ice; do
  echo "=== render window with $effect -> out/window_$effect.png ==="
  "$build_dir/samples/cli/snell" render --scene window --effect "$effect" --size 1280x720 \
    --out "$out_dir/window_$effect.png"
done
echo "=== render samples/assets/glass_grid.gltf with glass -> out/glass_grid.png ==="
"$build_dir/samples/cli/snell" render --scene samples/assets/glass_grid.gltf --effect glass \
  --size 1280x720 --out "$out_dir/glass_grid.png"
echo "=== render spheres with a mirror and a glass probe -> out/spheres_cubemap.png ==="
"$build_dir/samples/cli/snell" render --scene spheres --effect dynamic_cubemap \
  --effect dynamic_cubemap --set dynamic_cubemap@2.node= --set dynamic_cubemap@2.center=2.6,0.8,1.2 \
  --set dynamic_cubemap@2.radius=0.8 --set dynamic_cubemap@2.surface=glass --size 1280x720 \
  --out "$out_dir/spheres_cubemap.png"
echo "=== render room with a box-projected probe -> out/room_cubemap.png ==="
"$build_dir/samples/cli/snell" render --scene room --effect dynamic_cubemap \
  --set dynamic_cubemap.box_projection=true --size 1280x720 --out "$out_dir/room_cubemap.png"
echo "=== render mirror with the mirror effect -> out/mirror.png ==="
"$build_dir/samples/cli/snell" render --scene mirror --effect mirror --size 1280x720 \
  --out "$out_dir/mirror.png"
echo "=== render samples/assets/mirror_hall.gltf with its Mirror node -> out/mirror_hall.png ==="
"$build_dir/samples/cli/snell" render --scene samples/assets/mirror_hall.gltf --effect mirror \
  --set mirror.node=Mirror --size 1280x720 --out "$out_dir/mirror_hall.png"
echo "=== render samples/assets/courtyard.gltf -> out/courtyard.png ==="
"$build_dir/samples/cli/snell" render --scene samples/assets/courtyard.gltf --size 1280x720 \
  --out "$out_dir/courtyard.png"
# ==== End: demo scenes ===========================================================================

echo "=== demo done; outputs in out/ ==="
ls -l "$out_dir"
