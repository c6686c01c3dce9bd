#!/usr/bin/env bash
# The dynamic cube map's benchmark set (docs/cubemap.md, "Performance"): `snell bench` on the
# spheres scene for multiview vs six passes, time slicing, and 1 / 4 / 16 probes sharing a
# capture budget of 6 faces a frame (and 16 without one), printed as a Markdown table.
#
#   bash scripts/bench_cubemap.sh [--size WxH] [--frames N] [--device NAME]
#
# SNELL=path/to/snell picks the binary (default build/default/samples/cli/snell). Every figure is
# a median over N interleaved plain / effect frames of GPU timestamps; ratios come from one run.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
size=1280x720
frames=30
device=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --size) size="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --device) device=(--device "$2"); shift 2 ;;
    *) echo "bench_cubemap.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
snell="${SNELL:-build/default/samples/cli/snell}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# Extra probes: balls of their own (node "", radius 0.25 m) on a ring of 2.2 m around the
# scene's probe ball.
probes() {
  local n="$1" args=() k
  for ((k = 1; k <= n; k++)); do
    args+=(--effect dynamic_cubemap)
    if ((k > 1)); then
      local a x z
      a=$(awk -v k="$k" -v n="$n" 'BEGIN { printf "%.4f", 6.2831853 * (k - 2) / (n - 1) }')
      x=$(awk -v a="$a" 'BEGIN { printf "%.3f", 2.2 * sin(a) }')
      z=$(awk -v a="$a" 'BEGIN { printf "%.3f", 2.2 * cos(a) }')
      args+=(--set "dynamic_cubemap@$k.node=" --set "dynamic_cubemap@$k.center=$x,0.6,$z"
        --set "dynamic_cubemap@$k.radius=0.25")
    fi
  done
  printf '%s\n' "${args[@]}"
}

row() {
  local label="$1"; shift
  "$snell" bench --scene spheres --size "$size" --frames "$frames" "${device[@]}" \
    --json "$out/b.json" "$@" >/dev/null
  python3 - "$label" "$out/b.json" <<'PY'
import json, sys
label, path = sys.argv[1], sys.argv[2]
b = json.load(open(path))
p = b["passes"]
print(f"| {label} | {b['plain_ms']:.2f} | {b['effect_ms']:.2f} | **{b['ratio']:.2f}** | "
      f"{p.get('dynamic_cubemap.capture', 0.0):.2f} | {p.get('surfaces', 0.0):.2f} |")
PY
}

mapfile -t four < <(probes 4)
mapfile -t sixteen < <(probes 16)
"$snell" info "${device[@]}" 2>/dev/null | grep -i "chosen\|using" | head -1 || true
echo "spheres scene, $size, $frames frames, 256² faces"
echo
echo "| configuration | plain ms | with probes ms | ratio | captures ms | surfaces ms |"
echo "|---|---|---|---|---|---|"
row "1 probe, every frame, multiview" --effect dynamic_cubemap
row "1 probe, every frame, six_pass" --effect dynamic_cubemap --set dynamic_cubemap.capture=six_pass
row "1 probe, faces_per_frame 1" --effect dynamic_cubemap --set dynamic_cubemap.refresh=faces_per_frame
row "4 probes, budget 6 faces" "${four[@]}" --capture-budget 6
row "16 probes, budget 6 faces" "${sixteen[@]}" --capture-budget 6
row "16 probes, no budget" "${sixteen[@]}"
