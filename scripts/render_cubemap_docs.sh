#!/usr/bin/env bash
# Renders every picture of docs/cubemap.md into docs/images/cubemap/ with the `snell` CLI, or
# checks docs/cubemap.md's parameter table (dynamic_cubemap) against `snell list`.
#
# Usage:
#   bash scripts/render_cubemap_docs.sh                 render the pictures (~15 s on lavapipe)
#   bash scripts/render_cubemap_docs.sh --check-table   check the parameter table (exit 1: mismatch)
#
# The CLI is build/default/samples/cli/snell (build it with
# `cmake --preset default && cmake --build --preset default --target snell`); SNELL=/path/to/snell
# overrides it. The device is the CLI's choice (lavapipe unless a GPU is present; SNELL_DEVICE
# chooses). The pictures in the repository were rendered on lavapipe.
set -euo pipefail

# shellcheck source=scripts/docs_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/docs_lib.sh" "$@"
doc="$repo_root/docs/cubemap.md"
out_dir="$repo_root/docs/images/cubemap"

# ==== --check-table ==============================================================================
# Every dynamic_cubemap parameter printed by `snell list` must have a row in the table between
# <!-- dynamic_cubemap-params:begin --> and <!-- dynamic_cubemap-params:end --> of
# docs/cubemap.md with the same name, type, default, range and unit, and the table must have no
# other rows (scripts/check_params_table.py, shared with the other effects' pages).
if [[ $mode == check ]]; then
  exec python3 "$repo_root/scripts/check_params_table.py" --snell "$snell" \
    --effect dynamic_cubemap --doc "$doc"
fi

# ==== render =====================================================================================
mkdir -p "$out_dir"

# Cameras. The spheres scene: the probe ball (radius 1) at (0, 1.5, 0) on a pedestal, coloured
# objects around it at 3.5..4.5 m, camera 0 at (5, 3.4, 7.5). The room: a closed 10 x 5 x 10 m
# room, inside exactly the default box (-5, 0, -5)..(5, 5, 5), its mirror ball (radius 0.7) at
# (2.8, 1.1, -0.4), 2.2 m from the blue right wall with two paintings; camera 0 at (4.7, 1.6, 0.9)
# with its back to that wall. The window scene: the "window" anchor at (0, 1.5, 1.5), camera 0
# at (0, 2.1, 6). They are passed to render() by name (a nameref); the commas are the CLI's
# vector syntax.
# shellcheck disable=SC2034,SC2054
{
  cam_default=()                                             # the scene's camera
  cam_ball=(--eye 5,3.4,7.5 --target 0,1.5,0 --fov 22)       # spheres: camera 0 zoomed on the ball
  cam_lens=(--eye 5,3.4,7.5 --target -0.25,1.3,0 --fov 8)    # spheres: closer still (dispersion)
  cam_room=(--eye 4.7,1.6,0.9 --target 2.8,1.1,-0.4 --fov 38) # room: camera 0 on the ball
  cam_ring=(--eye 4,4.5,6 --target 0,0.9,0 --fov 40)         # spheres: above the ring of probes
}

# A probe of its own (node "": the effect's sphere) 1 m in front of the window, 1 cm in radius
# (a dot at the window's centre): the glass reflects its capture.
# shellcheck disable=SC2054  # the commas are the CLI's vector syntax
window_probe=(--effect dynamic_cubemap --set dynamic_cubemap.center=0,1.5,2.5
  --set dynamic_cubemap.radius=0.01)

# N probes, as scripts/bench_cubemap.sh builds them: the scene's probe ball, then balls of their
# own (node "", radius 0.25 m) on a ring of 2.2 m around it, each set by its instance number.
probes() {
  local n="$1" k a x z
  for ((k = 1; k <= n; k++)); do
    echo --effect
    echo dynamic_cubemap
    if ((k > 1)); then
      a=$(awk -v k="$k" -v n="$n" 'BEGIN { printf "%.4f", 6.2831853 * (k - 2) / (n - 1) }')
      x=$(awk -v a="$a" 'BEGIN { printf "%.3f", 2.2 * sin(a) }')
      z=$(awk -v a="$a" 'BEGIN { printf "%.3f", 2.2 * cos(a) }')
      printf '%s\n' --set "dynamic_cubemap@$k.node=" --set "dynamic_cubemap@$k.center=$x,0.6,$z" \
        --set "dynamic_cubemap@$k.radius=0.25"
    fi
  done
}

count=0 # pictures rendered (docs_render in scripts/docs_lib.sh counts them)

echo "rendering into ${out_dir#"$repo_root"/} with $snell"
# The page's first row: the default mirror, glass, roughness 0.4, scene camera.
docs_render spheres_reflect spheres 640x360 cam_default --effect dynamic_cubemap
docs_render spheres_glass spheres 640x360 cam_default --effect dynamic_cubemap \
  --set dynamic_cubemap.surface=glass
docs_render spheres_rough spheres 640x360 cam_default --effect dynamic_cubemap \
  --set dynamic_cubemap.roughness=0.4
# The three surfaces, zoomed on the ball.
for s in reflect refract glass; do
  docs_render "surface_$s" spheres 480x270 cam_ball --effect dynamic_cubemap \
    --set "dynamic_cubemap.surface=$s"
done
# Dispersion 0 and 1 of the glass ball, closer (the fringes are a pixel wide at cam_ball).
for d in 0 1; do
  docs_render "dispersion_$d" spheres 480x270 cam_lens --effect dynamic_cubemap \
    --set dynamic_cubemap.surface=glass --set "dynamic_cubemap.dispersion=$d"
done
# Roughness 0.3 and 0.6 with box mips and with the GGX prefilter (roughness 0 is surface_reflect
# for both: GGX level 0 is a copy of the capture's level 0, the same picture to the byte).
for p in mips ggx; do
  for r in 0.3 0.6; do
    docs_render "roughness_${p}_$r" spheres 480x270 cam_ball --effect dynamic_cubemap \
      --set "dynamic_cubemap.prefilter=$p" --set "dynamic_cubemap.roughness=$r"
  done
done
# Box projection off and on in the room (its inside is the default box).
for b in false true; do
  docs_render "room_box_$b" room 640x360 cam_room --effect dynamic_cubemap \
    --set "dynamic_cubemap.box_projection=$b"
done
# The six faces of the capture: --debug-targets composites the effect's debug targets
# (dynamic_cubemap.face+x ... face-z) and the main view's depth into a 3 x 3 grid; a square
# picture keeps the faces square.
docs_render faces spheres 480x480 cam_default --effect dynamic_cubemap --debug-targets
# node=sphere_green: the probe attached to another object of the scene.
docs_render spheres_node_green spheres 640x360 cam_default --effect dynamic_cubemap \
  --set dynamic_cubemap.node=sphere_green
# Glass reflecting a probe: the window's reflection alone (debug_view=reflection), the sky
# without a probe, the probe's capture with one.
docs_render glass_reflection_sky window 640x360 cam_default --effect glass \
  --set glass.debug_view=reflection
docs_render glass_reflection_probe window 640x360 cam_default --effect glass \
  --set glass.debug_view=reflection "${window_probe[@]}"
# 16 probes: the scene's ball and 15 small balls, each capturing its own cube.
mapfile -t sixteen < <(probes 16)
docs_render probes_16 spheres 640x360 cam_ring "${sixteen[@]}"

total=$(du -cb "$out_dir"/*.png | tail -n 1 | cut -f 1)
pngs=("$out_dir"/*.png)
echo "rendered $count pictures; docs/images/cubemap/ holds ${#pngs[@]} PNGs," \
  "$((total / 1024)) KiB in all"
if ((total > 4 * 1024 * 1024)); then
  echo "render_cubemap_docs.sh: warning: the pictures exceed 4 MiB" >&2
fi
