#!/usr/bin/env bash
# Takes docs/viewer.md's screenshot with the viewer itself: `snell view` on the pool with the
# water, its panel, the GPU pass plot and the debug-target thumbnails, captured by the viewer's
# own screenshot action (the presented swapchain image, UI included).
#
# Usage:
#   bash scripts/render_viewer_docs.sh      writes docs/images/viewer.png (about 10 s on lavapipe)
#
# The CLI is build/default/samples/cli/snell built with the viewer (SNELL_BUILD_VIEWER=ON);
# SNELL=/path/to/snell overrides it. The window needs an X server: $DISPLAY when set, else a
# virtual one (Xvfb, Debian xvfb) that this script starts and stops. The picture in the
# repository was taken on lavapipe under Xvfb.
set -euo pipefail

# shellcheck source=scripts/docs_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/docs_lib.sh" "$@"
out="$repo_root/docs/images/viewer.png"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

if [[ -z "${DISPLAY:-}" ]]; then
  command -v Xvfb >/dev/null 2>&1 || { echo "$script: no DISPLAY and no Xvfb (Debian: xvfb)" >&2; exit 1; }
  Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp 3>"$work/display" 2>"$work/xvfb.log" &
  xvfb_pid=$!
  trap 'kill "$xvfb_pid" 2>/dev/null || true; rm -rf "$work"' EXIT
  for _ in $(seq 1 100); do
    [[ -s "$work/display" ]] && break
    sleep 0.1
  done
  [[ -s "$work/display" ]] || { echo "$script: Xvfb did not start" >&2; exit 1; }
  export DISPLAY=":$(head -n 1 "$work/display")"
fi

# A little tuning through the panel's code path, a turn of the camera, the thumbnails, then the
# whole window at t = 1 s.
cat >"$work/docs.txt" <<'SCRIPT'
0.0 set water.wave_height=0.6
0.0 set water.water_color=0.02,0.2,0.22
0.0 set water.color_blend=0.15
0.0 orbit -20 -8
0.0 zoom 1.5
0.0 debug-targets on
1.0 screenshot viewer.png window
1.0 quit
SCRIPT
(cd "$work" && "$snell" view --scene pool --effect water --size 1280x720 --script docs.txt)
mkdir -p "$(dirname "$out")"
cp "$work/viewer.png" "$out"
echo "wrote $out"
