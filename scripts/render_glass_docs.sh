#!/usr/bin/env bash
# Renders every picture of docs/glass.md into docs/images/glass/ with the `snell` CLI, or checks
# docs/glass.md's parameter tables (glass and ice) against `snell list`.
#
# Usage:
#   bash scripts/render_glass_docs.sh                 render the pictures (about 25 s on lavapipe)
#   bash scripts/render_glass_docs.sh --check-table   check the parameter tables; exit 1 on mismatch
#
# The CLI is build/default/samples/cli/snell (build it with
# `cmake --preset default && cmake --build --preset default --target snell`); SNELL=/path/to/snell
# overrides it. The device is the CLI's choice (lavapipe unless a GPU is present; SNELL_DEVICE
# chooses). The pictures in the repository were rendered on lavapipe.
set -euo pipefail

# shellcheck source=scripts/docs_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/docs_lib.sh" "$@"
doc="$repo_root/docs/glass.md"
out_dir="$repo_root/docs/images/glass"

# ==== --check-table ==============================================================================
# Every glass (ice) parameter printed by `snell list` must have a row in the table between
# <!-- glass-params:begin --> and <!-- glass-params:end --> (<!-- ice-params:... -->) of
# docs/glass.md with the same name, type, default, range and unit, and each table must have no
# other rows (scripts/check_params_table.py). Both tables are checked even when the first fails.
if [[ $mode == check ]]; then
  status=0
  for effect in glass ice; do
    python3 "$repo_root/scripts/check_params_table.py" --snell "$snell" --effect "$effect" \
      --doc "$doc" || status=1
  done
  exit "$status"
fi

# ==== render =====================================================================================
mkdir -p "$out_dir"

grid=samples/assets/glass_grid.gltf
# Cameras. The window scene: a 2.8 x 2 m window (the "window" anchor) at z = 1.5, centre
# (0, 1.5, 1.5), in a wooden frame; the crate on its pedestal at (0, 1.5, -1.2) and the blue ball
# at (1.8, 0.4, -2.4) behind it, the brick backdrop at z = -5. The grid: spheres at z = 1.2, slabs
# turned 30 degrees about Y at z = -1.6 (x = -1.95, -0.65, 0.65, 1.95), striped backdrop at
# z = -2.9. They are passed to render() by name (a nameref); the commas are the CLI's vector syntax.
# shellcheck disable=SC2034,SC2054
{
  cam_default=()                                           # the scene's camera
  cam_side=(--eye 4.5,1.8,3.5 --target 0,1.5,1)            # window from the right: grazing angles
  cam_zoom=(--eye 0,2.1,6 --target 0.3,1.3,-1.2 --fov 18)  # window camera zoomed on the crate
  cam_row=(--eye 3.8,0.75,-1.1 --target 0.5,0.4,-1.7)      # grid: along the slabs' row from +x
  # The pane turned 36.9 degrees about Y (normal 0.6, 0, 0.8): the scene camera sees it at about
  # that incidence, so a thick pane's lateral shift shows (facing the camera it is almost zero).
  turned=(--set glass.normal=0.6,0,0.8)
  # A 5.6 x 1.1 m pane, tinted light blue, standing in front of the grid's slabs (the grid has no
  # "window" anchor, so the pane is off until `pane=true`).
  pane_in_grid=(--set glass.pane=true --set glass.center=0,0.55,-0.9 --set glass.size=5.6,1.1
    --set glass.tint=0.8,0.9,1)
}

count=0
# render NAME SCENE CAMERA_ARRAY_NAME [extra CLI arguments: --effect, --set, ...]
render() {
  local name="$1" scene="$2" cam_name="$3"
  shift 3
  local -n cam="$cam_name"
  local log
  if ! log="$("$snell" render --scene "$scene" --size 640x360 \
    --out "$out_dir/$name.png" "${cam[@]}" "$@" 2>&1)"; then
    echo "$log" >&2
    echo "render_glass_docs.sh: rendering $name.png failed" >&2
    exit 1
  fi
  count=$((count + 1))
  echo "  snell render --scene $scene --size 640x360 --out ${out_dir#"$repo_root"/}/$name.png" \
    "${cam[@]}" "$@"
}

echo "rendering into ${out_dir#"$repo_root"/} with $snell"
# The window without glass, with the default glass, the seed preset and ice.
render window_plain window cam_default
render window_glass window cam_default --effect glass
render window_seed window cam_default --effect glass --set glass.preset=seed
render window_ice window cam_default --effect ice
# The default pane from the side, and its Fresnel term.
render side_glass window cam_side --effect glass
render debug_fresnel window cam_side --effect glass --set glass.debug_view=fresnel
# thickness 0, 0.3, 0.6 of the turned pane: the lateral shift.
for t in 0 0.3 0.6; do
  render "thickness_$t" window cam_default --effect glass "${turned[@]}" --set "glass.thickness=$t"
done
# ior 1.1, 1.5, 2.0 of a 0.4 m turned pane.
for i in 1.1 1.5 2.0; do
  render "ior_$i" window cam_default --effect glass "${turned[@]}" --set glass.thickness=0.4 \
    --set "glass.ior=$i"
done
# roughness 0.2, 0.5 (0 is window_glass).
for r in 0.2 0.5; do
  render "roughness_$r" window cam_default --effect glass --set "glass.roughness=$r"
done
# dispersion 0 and 5 of a 0.5 m turned pane, zoomed in (the fringes are about a pixel wide at the
# scene camera's field of view).
for d in 0 5; do
  render "dispersion_$d" window cam_zoom --effect glass "${turned[@]}" \
    --set glass.thickness=0.5 --set "glass.dispersion=$d"
done
# tint; Beer-Lambert attenuation of a 0.3 m pane.
render tint window cam_default --effect glass --set glass.tint=1,0.8,0.5
render attenuation window cam_default --effect glass --set glass.thickness=0.3 \
  --set glass.attenuation_color=0.6,0.8,0.6 --set glass.attenuation_distance=0.2
# The seed's normal-map offset: refraction_scale 0.02 and 0.1, without and with color_blend 0.3.
for s in 0.02 0.1; do
  render "refraction_scale_$s" window cam_default --effect glass --set "glass.refraction_scale=$s"
  render "refraction_scale_${s}_blend" window cam_default --effect glass \
    --set "glass.refraction_scale=$s" --set glass.color_blend=0.3
done
# The lookup offset of the turned 0.6 m pane: the lateral shift alone, then with the normal map.
render debug_offset window cam_default --effect glass "${turned[@]}" --set glass.thickness=0.6 \
  --set glass.debug_view=offset
render debug_offset_normal_map window cam_default --effect glass "${turned[@]}" \
  --set glass.thickness=0.6 --set glass.refraction_scale=0.05 --set glass.debug_view=offset
# The glTF grid, opaque (no effect) and with glass: spheres (curved solids) and slabs, each from
# its material's KHR_materials_* fields.
render grid_plain "$grid" cam_default
render grid_glass "$grid" cam_default --effect glass
# Stacked panes: a pane in front of the grid's slabs, then the slabs seen through one another
# along their row; each with max_layers=1 too (what is behind the nearer surface is lost).
render stacked_pane "$grid" cam_default --effect glass "${pane_in_grid[@]}"
render stacked_pane_1 "$grid" cam_default --effect glass "${pane_in_grid[@]}" \
  --set glass.max_layers=1
render stacked_slabs "$grid" cam_row --effect glass
render stacked_slabs_1 "$grid" cam_row --effect glass --set glass.max_layers=1

total=$(du -cb "$out_dir"/*.png | tail -n 1 | cut -f 1)
pngs=("$out_dir"/*.png)
echo "rendered $count pictures; docs/images/glass/ holds ${#pngs[@]} PNGs, $((total / 1024)) KiB in all"
if ((total > 6 * 1024 * 1024)); then
  echo "render_glass_docs.sh: warning: the pictures exceed 6 MiB" >&2
fi
