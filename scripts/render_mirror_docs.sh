#!/usr/bin/env bash
# Renders every picture of docs/mirror.md into docs/images/mirror/ with the `snell` CLI, or
# checks docs/mirror.md's parameter table (mirror) against `snell list`.
#
# Usage:
#   bash scripts/render_mirror_docs.sh                 render the pictures (~15 s on lavapipe)
#   bash scripts/render_mirror_docs.sh --check-table   check the parameter table (exit 1: mismatch)
#
# The CLI is build/default/samples/cli/snell (build it with
# `cmake --preset default && cmake --build --preset default --target snell`); SNELL=/path/to/snell
# overrides it. The device is the CLI's choice (lavapipe unless a GPU is present; SNELL_DEVICE
# chooses). The pictures in the repository were rendered on lavapipe.
set -euo pipefail

# shellcheck source=scripts/docs_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/docs_lib.sh" "$@"
doc="$repo_root/docs/mirror.md"
out_dir="$repo_root/docs/images/mirror"

# ==== --check-table ==============================================================================
# Every mirror parameter printed by `snell list` must have a row in the table between
# <!-- mirror-params:begin --> and <!-- mirror-params:end --> of docs/mirror.md with the same
# name, type, default, range and unit, and the table must have no other rows
# (scripts/check_params_table.py, shared with the other effects' pages).
if [[ $mode == check ]]; then
  exec python3 "$repo_root/scripts/check_params_table.py" --snell "$snell" \
    --effect mirror --doc "$doc"
fi

# ==== render =====================================================================================
mkdir -p "$out_dir"

# The normal map of the distortion pictures: a tileable ripple map generated deterministically
# (rewritten only when its bytes would change).
normal_map=samples/assets/ripple_normal.png
python3 "$repo_root/scripts/make_ripple_normal_map.py" "$repo_root/$normal_map" >/dev/null

# Cameras. The mirror scene: a 6 x 6 m floor mirror (the node mirror_floor, y = 0.01) with a
# pedestal and a tumbling torus at its centre, a red box standing on it at (1.8, 0, 1), an orange
# ball floating 1 m above it at (-1.8, 1.36, 1), a green ball resting on it at (-1.8, 0.36, -1.2),
# a brick wall behind; camera 0 at (0, 2.6, 7). The window scene: a spinning crate on a pedestal
# behind a wooden window frame at z = 1.5, a blue ball, a brick backdrop; camera 0 at (0, 2.1, 6).
# They are passed to render() by name (a nameref); the commas are the CLI's vector syntax.
# shellcheck disable=SC2034,SC2054
{
  cam_default=()                                                 # the scene's camera
  cam_high=(--eye 0,4.5,6.5 --target 0,0.2,0 --fov 45)           # mirror: higher, the ball's image in view
  cam_close=(--eye 1.2,1.6,4.2 --target 0.6,0,0.5 --fov 35)      # mirror: close to the pedestal's foot
  cam_above=(--eye 0,4.2,4.5 --target 0,1.2,-1.2 --fov 40)       # window: above the crate
  cam_behind=(--eye -5.5,2.2,-3.5 --target -1,1.3,0 --fov 50)    # window: behind the wall mirror
  cam_sky=(--eye 0,6,5 --target 0,2.2,3 --fov 45)                # mirror: down onto a small mirror
}

# A wall mirror of the effect's own (node "") in the window scene: 2 x 2.4 m, left of the window,
# turned toward the crate and the camera.
# shellcheck disable=SC2054  # the commas are the CLI's vector syntax
wall=(--set mirror.node= --set mirror.center=-2.3,1.4,-0.6 --set mirror.normal=1,0,0.5
  --set mirror.size=2,2.4)

count=0 # pictures rendered (docs_render in scripts/docs_lib.sh counts them)

echo "rendering into ${out_dir#"$repo_root"/} with $snell"
# The page's first picture: the mirror scene with the default mirror (the floor node).
docs_render mirror_default mirror 640x360 cam_default --effect mirror
# Roughness 0, 0.2, 0.5, 0.8 from higher up: the box stands on the mirror, the ball floats.
for r in 0 0.2 0.5 0.8; do
  docs_render "roughness_$r" mirror 480x270 cam_high --effect mirror --set "mirror.roughness=$r"
done
# A gold metal (tint), and a dielectric (exact Fresnel, IOR 1.5) over a dark blue-grey base.
docs_render tint_gold mirror 480x270 cam_default --effect mirror --set mirror.tint=1,0.78,0.34
docs_render dielectric mirror 480x270 cam_default --effect mirror --set mirror.fresnel=dielectric \
  --set mirror.ior=1.5 --set mirror.base_color=0.05,0.05,0.08
# Fade over 1 m and 3 m of height above the mirror.
for f in 1 3; do
  docs_render "fade_$f" mirror 480x270 cam_default --effect mirror --set "mirror.fade_distance=$f"
done
# The reflection target at a quarter and at the full output resolution, close up.
for s in 0.25 1; do
  docs_render "resolution_$s" mirror 480x270 cam_close --effect mirror \
    --set "mirror.resolution_scale=$s"
done
# The ripple normal map, a tile every 4 m of the floor's uv (1 per metre): distortion 0.02 and
# 0.05.
for d in 0.02 0.05; do
  docs_render "normal_map_$d" mirror 480x270 cam_default --effect mirror \
    --set "mirror.normal_map=$normal_map" --set mirror.normal_tiles=0.25 \
    --set "mirror.distortion=$d"
done
# Oblique near plane and clip distance: a horizontal mirror of its own cutting the crate at
# y = 1.2; only the crate's top is reflected, the same way by both.
for c in oblique clip_distance; do
  docs_render "clip_$c" window 480x270 cam_above --effect mirror --set mirror.node= \
    --set mirror.center=0,1.2,-1.2 --set mirror.normal=0,1,0 --set mirror.size=3.2,3.2 \
    --set "mirror.clip=$c"
done
# A wall mirror of the effect's own in the window scene, and its debug targets.
docs_render wall_mirror window 640x360 cam_default --effect mirror "${wall[@]}"
docs_render debug_targets window 640x360 cam_default --effect mirror "${wall[@]}" --debug-targets
# Two mirrors in one frame: the floor (the scene's node) and a wall mirror of its own.
docs_render two_mirrors mirror 640x360 cam_default --effect mirror --effect mirror \
  --set mirror@2.node= --set mirror@2.center=-3.5,1.45,-1.6 --set mirror@2.normal=1,0,0.5 \
  --set mirror@2.size=2.4,2.8
# The camera behind the wall mirror: no pass, the surface shows back_color.
docs_render back window 480x270 cam_behind --effect mirror "${wall[@]}" \
  --set mirror.back_color=0.3,0.18,0.1

# Known problems (docs/mirror.md). A 1 m mirror of its own, 2.2 m up, reflecting only the sky:
# roughness 0, 0.3 and 0.8 (the sky is the same colour at every blur level).
for r in 0 0.3 0.8; do
  docs_render "problem_sky_roughness_$r" mirror 320x180 cam_sky --effect mirror --set mirror.node= \
    --set mirror.center=0,2.2,3 --set mirror.normal=0,1,0 --set mirror.size=1,1 \
    --set "mirror.roughness=$r"
done
# Two mirrors of their own, flat colours (fade_distance 1 mm: base_color everywhere): a green
# one 2.5 m from the camera and a red one behind it, the green drawn first, then the red first.
# shellcheck disable=SC2054  # the commas are the CLI's vector syntax
near=(center=0,1.5,3.5 size=1.2,1.2 base_color=0,1,0)
# shellcheck disable=SC2054
far=(center=0,1.5,-3 size=4,2.5 base_color=1,0,0)
for order in near_first far_first; do
  args=()
  if [[ $order == near_first ]]; then first=("${near[@]}") second=("${far[@]}"); else
    first=("${far[@]}") second=("${near[@]}"); fi
  for kv in "${first[@]}"; do args+=(--set "mirror@1.$kv"); done
  for kv in "${second[@]}"; do args+=(--set "mirror@2.$kv"); done
  docs_render "problem_overlap_$order" window 320x180 cam_default --effect mirror --effect mirror \
    --set mirror.node= --set mirror.fade_distance=0.001 "${args[@]}"
done

# Lossless recompression (RGB, per-row filters, zlib 9): about a third smaller than the CLI's.
python3 "$repo_root/scripts/shrink_png.py" "$out_dir"/*.png

total=$(du -cb "$out_dir"/*.png | tail -n 1 | cut -f 1)
pngs=("$out_dir"/*.png)
echo "rendered $count pictures; docs/images/mirror/ holds ${#pngs[@]} PNGs," \
  "$((total / 1024)) KiB in all"
if ((total > 2560 * 1024)); then
  echo "render_mirror_docs.sh: warning: the pictures exceed 2.5 MiB" >&2
fi
