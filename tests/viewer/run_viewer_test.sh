#!/usr/bin/env bash
# Drives `snell view` in a real window (tests/viewer/CMakeLists.txt registers the modes):
#   args    bad arguments and scripts exit 2 before any window opens; no display: exit 1
#   golden  a scripted session sets a parameter through the panel's code path (and has a value
#           refused), screenshots the scene at t = 0.5 s, which must match `snell render` of the
#           same state within the golden tolerance; the window screenshot shows the UI on top
#   stress  300 frames with two resizes and a minimise (and mailbox presentation, thumbnails,
#           an effect added and removed) with synchronization validation: no validation message
# The window needs an X server: the test starts its own Xvfb on a free display (-displayfd), or
# uses $DISPLAY when Xvfb is not installed, and is skipped (exit 77) with the reason otherwise.
#
# usage: run_viewer_test.sh MODE SNELL IMAGE_COMPARE WORK_DIR
set -euo pipefail
mode="$1" snell="$2" compare="$3" work="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$work"
mkdir -p "$work"
cd "$work"

skip() {
  echo "SKIP: $*"
  exit 77
}
fail() {
  echo "FAILED: $*" >&2
  exit 1
}

# Runs "$@" expecting exit code $expect; its output goes to out.txt (and is shown).
run_expect() {
  local expect="$1"
  shift
  local rc=0
  "$@" >out.txt 2>&1 || rc=$?
  cat out.txt
  [[ $rc -eq $expect ]] || fail "exit $rc, expected $expect: $*"
}
expect_output() {
  grep -qF -- "$1" out.txt || fail "the output lacks '$1'"
}

start_x() {
  if command -v Xvfb >/dev/null 2>&1; then
    # -displayfd: Xvfb takes a free display number and writes it once it accepts clients, so
    # parallel tests (and other X servers on this machine) never clash.
    Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>display 2>xvfb.log &
    xvfb_pid=$!
    trap 'kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true' EXIT
    for _ in $(seq 1 100); do
      [[ -s display ]] && break
      kill -0 "$xvfb_pid" 2>/dev/null || break
      sleep 0.1
    done
    [[ -s display ]] || skip "Xvfb did not start: $(tail -n 3 xvfb.log 2>/dev/null)"
    export DISPLAY=":$(head -n 1 display)"
    echo "Xvfb on $DISPLAY"
  elif [[ -n "${DISPLAY:-}" ]]; then
    echo "Xvfb is not installed: using DISPLAY=$DISPLAY"
  else
    skip "no X server: Xvfb is not installed (Debian: xvfb) and DISPLAY is not set"
  fi
}

# The PNG's width x height (IHDR).
png_size() {
  python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print("%dx%d" % struct.unpack(">II", d[16:24]))' "$1"
}

case "$mode" in
args)
  # Checked before any window opens: no X server needed (DISPLAY unset to prove it).
  printf '0 set water.wave_hieght=1\n' >bad_key.txt
  printf '0 set water.wave_height=0.5\n1 jump\n' >bad_line.txt
  printf '0 set lava.heat=1\n' >bad_effect.txt
  run_expect 2 env -u DISPLAY "$snell" view --script missing.txt
  expect_output "missing.txt"
  run_expect 2 env -u DISPLAY "$snell" view --effect water --script bad_key.txt
  expect_output "bad_key.txt:1:"
  expect_output "wave_height"
  run_expect 2 env -u DISPLAY "$snell" view --script bad_line.txt
  expect_output "bad_line.txt:2: unknown action 'jump'"
  run_expect 2 env -u DISPLAY "$snell" view --script bad_effect.txt
  expect_output "unknown effect 'lava'"
  run_expect 2 env -u DISPLAY "$snell" view --present vsync
  expect_output "fifo or mailbox"
  run_expect 2 env -u DISPLAY "$snell" view --out x.png
  expect_output "view: unknown option '--out'"
  run_expect 2 env -u DISPLAY "$snell" view --effect lava
  expect_output "registered effects"
  # Good arguments but no display: one clear line, exit 1.
  run_expect 1 env -u DISPLAY -u WAYLAND_DISPLAY "$snell" view --scene pool
  expect_output "cannot open a window"
  ;;
golden)
  start_x
  run_expect 0 "$snell" view --scene pool --effect water --size 640x360 --validation \
    --script "$here/golden.txt"
  expect_output "set water.wave_height=0.8: ok"
  expect_output "set water.ior=9: water.ior = 9 is outside [1, 3]" # refused, shown, not applied
  run_expect 0 "$snell" render --scene pool --effect water --set water.wave_height=0.8 \
    --time 0.5 --size 640x360 --out render.png --validation
  run_expect 0 "$compare" view_scene.png render.png diff_scene.png
  # The presented image (blit to the sRGB swapchain, copied back) with the panel hidden.
  run_expect 0 "$compare" view_window.png render.png diff_window.png
  # With the panel: the scene under the UI, so not the scene alone.
  [[ "$(png_size view_window_ui.png)" == "640x360" ]] || fail "window screenshot is $(png_size view_window_ui.png)"
  run_expect 1 "$compare" view_window_ui.png render.png
  ;;
stress)
  start_x
  start=$SECONDS
  run_expect 0 "$snell" view --scene pool --effect water --size 320x240 --validation \
    --present mailbox --frames 300 --script "$here/stress.txt"
  expect_output "snell view: 300 frames, "
  grep -qE "300 frames, ([2-9]|[1-9][0-9]+) swapchain recreation" out.txt ||
    fail "two resizes did not recreate the swapchain twice"
  grep -qE "\), [1-9][0-9]* tick\(s\) minimised" out.txt ||
    fail "the minimise left no frame out"
  [[ "$(png_size after_restore.png)" == "240x180" ]] || fail "after the resizes: $(png_size after_restore.png)"
  echo "stress: $((SECONDS - start)) s"
  ;;
*)
  fail "unknown mode '$mode'"
  ;;
esac
echo "viewer.$mode: passed"
