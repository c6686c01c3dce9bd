#!/usr/bin/env bash
# Renders every picture of docs/water.md into docs/images/water/ with the `snell` CLI, or checks
# docs/water.md's parameter table against `snell list`.
#
# Usage:
#   bash scripts/render_water_docs.sh                 render the pictures (about 10 s on lavapipe)
#   bash scripts/render_water_docs.sh --check-table   check the parameter table; exit 1 on mismatch
#
# The CLI is build/default/samples/cli/snell (build it with
# `cmake --preset default && cmake --build --preset default --target snell`); SNELL=/path/to/snell
# overrides it. The device is the CLI's choice (lavapipe unless a GPU is present; SNELL_DEVICE
# chooses). The pictures in the repository were rendered on lavapipe.
set -euo pipefail

# shellcheck source=scripts/docs_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/docs_lib.sh" "$@"
doc="$repo_root/docs/water.md"
out_dir="$repo_root/docs/images/water"

# ==== --check-table ==============================================================================
# Every water parameter printed by `snell list` must have a row in the table between
# <!-- water-params:begin --> and <!-- water-params:end --> of docs/water.md with the same name,
# type, default, range and unit, and the table must have no other rows
# (scripts/check_params_table.py, shared with the other effects' pages).
if [[ $mode == check ]]; then
  exec python3 "$repo_root/scripts/check_params_table.py" --snell "$snell" --effect water \
    --doc "$doc"
fi

# ==== render =====================================================================================
mkdir -p "$out_dir"

# Cameras (the pool: water at y = 2.75 over x, z in [-4, 4], rim at y = 3, brick wall at z = 8).
# They are passed to render() by name (a nameref), and the commas are the CLI's vector syntax.
# shellcheck disable=SC2034,SC2054
{
  cam_default=()                                                 # the scene's camera, high
  cam_low=(--eye 0,3.8,-5.5 --target 0,2.6,4)                    # low, across the whole pool
  cam_grazing=(--eye -3,3.5,-4.2 --target 0,2.6,4)               # 0.75 m above the water: Fresnel
  cam_ball=(--eye -0.3,3.1,-1 --target -1,2.5,2)                 # the orange ball at the water line
  cam_under=(--eye 0,1.6,-2 --target 0,3.6,0.4)                  # under the water, looking up
}

count=0
# render NAME WxH CAMERA_ARRAY_NAME [extra CLI arguments...]
render() {
  local name="$1" size="$2" cam_name="$3"
  shift 3
  local -n cam="$cam_name"
  local log
  if ! log="$("$snell" render --scene pool --effect water --size "$size" \
    --out "$out_dir/$name.png" "${cam[@]}" "$@" 2>&1)"; then
    echo "$log" >&2
    echo "render_water_docs.sh: rendering $name.png failed" >&2
    exit 1
  fi
  count=$((count + 1))
  echo "  snell render --scene pool --effect water --size $size --out ${out_dir#"$repo_root"/}/$name.png" \
    "${cam[@]}" "$@"
}

echo "rendering into ${out_dir#"$repo_root"/} with $snell"
render pool_water 640x360 cam_default
render low_default 480x270 cam_low
# wave_height: 0, 0.3 (default: low_default), 1
render wave_height_0 480x270 cam_low --set water.wave_height=0
render wave_height_1 480x270 cam_low --set water.wave_height=1.0
# Fresnel modes, final image and the Fresnel term (debug_view=fresnel)
for f in exact schlick seed; do
  render "fresnel_$f" 480x270 cam_grazing --set "water.fresnel=$f"
  render "fresnel_term_$f" 480x270 cam_grazing --set "water.fresnel=$f" --set water.debug_view=fresnel
done
# debug views (fresnel: see fresnel_term_exact)
for v in reflection refraction normals; do
  render "debug_$v" 480x270 cam_low --set "water.debug_view=$v"
done
# absorption: 0, default (low_default), strong
render absorption_0 480x270 cam_low --set water.absorption=0,0,0
render absorption_strong 480x270 cam_low --set water.absorption=1.5,0.3,0.2
# shore_softness: 0 and 0.5 at the orange ball's water line
render shore_0 480x270 cam_ball --set water.shore_softness=0
render shore_0.5 480x270 cam_ball --set water.shore_softness=0.5
# refraction_source: pass (snapshot is low_default)
render refraction_pass 480x270 cam_low --set water.refraction_source=pass
# clip_mode: clip_distance (oblique is low_default)
render clip_distance 480x270 cam_low --set water.clip_mode=clip_distance
# the seed preset (default: low_default and pool_water)
render seed_preset 480x270 cam_low --set water.preset=seed
render seed_preset_pool 640x360 cam_default --set water.preset=seed
# resolution_scale: 0.25 and 1 (0.5 is low_default)
render resolution_0.25 480x270 cam_low --set water.resolution_scale=0.25
render resolution_1 480x270 cam_low --set water.resolution_scale=1.0
# from under the water: total internal reflection and Snell's window
render underwater 480x270 cam_under
render underwater_fresnel 480x270 cam_under --set water.debug_view=fresnel --set water.wave_height=0
# --debug-targets thumbnails
render debug_targets 640x360 cam_low --debug-targets

total=$(du -cb "$out_dir"/*.png | tail -n 1 | cut -f 1)
pngs=("$out_dir"/*.png)
echo "rendered $count pictures; docs/images/water/ holds ${#pngs[@]} PNGs, $((total / 1024)) KiB in all"
if ((total > 6 * 1024 * 1024)); then
  echo "render_water_docs.sh: warning: the pictures exceed 6 MiB" >&2
fi
