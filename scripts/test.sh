#!/usr/bin/env bash
# Set up, configure, build and test Snell for one or more CMake presets.
# Usage: bash scripts/test.sh [--preset NAME]...     (default: --preset default)
# Exits non-zero if any preset fails (all requested presets are still attempted).
set -euo pipefail

usage() {
  echo "usage: bash scripts/test.sh [--preset NAME]...   (presets: see 'cmake --list-presets')"
}

presets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --preset)
      [[ $# -ge 2 ]] || { usage >&2; exit 2; }
      presets+=("$2"); shift 2 ;;
    --preset=*)
      presets+=("${1#--preset=}"); shift ;;
    -h|--help)
      usage; exit 0 ;;
    *)
      echo "test.sh: unknown argument: $1" >&2; usage >&2; exit 2 ;;
  esac
done
[[ ${#presets[@]} -gt 0 ]] || presets=(default)

cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh

jobs="$(nproc 2>/dev/null || echo 2)"

run_preset() {
  local p="$1"
  cmake --preset "$p" &&
    cmake --build --preset "$p" -j"$jobs" &&
    ctest --preset "$p"
}

failed=()
summary=()
for p in "${presets[@]}"; do
  echo "=== preset '$p' ==="
  start=$SECONDS
  if run_preset "$p"; then
    result=passed
  else
    result=FAILED
    failed+=("$p")
  fi
  elapsed=$((SECONDS - start))
  line="preset '$p': $result in ${elapsed}s"
  echo "=== $line ==="
  summary+=("$line")
done

echo
echo "=== summary ==="
printf '  %s\n' "${summary[@]}"
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "test.sh: failed presets: ${failed[*]}" >&2
  exit 1
fi
