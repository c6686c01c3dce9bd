# shellcheck shell=bash
# shellcheck disable=SC2034  # the variables set here are read by the script that sources this
# Shared by the scripts that render a docs page's pictures (scripts/render_*_docs.sh); sourced
# with the caller's arguments:
#     source "$(dirname "${BASH_SOURCE[0]}")/docs_lib.sh" "$@"
# It changes to the repository root and sets
#     repo_root  the repository root
#     snell      the CLI: $SNELL, else build/default/samples/cli/snell
#     mode       render (no argument) or check (--check-table)
#     script     the caller's file name, for messages
# --help prints the caller's header comment (its lines 2-12) and exits 0; any other argument
# exits 2; a missing or non-executable CLI exits 1 with how to build it.
script="$(basename "${BASH_SOURCE[1]}")"
caller="$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)/$script"
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
repo_root="$(pwd)"
snell="${SNELL:-$repo_root/build/default/samples/cli/snell}"

mode=render
case "${1:-}" in
  "") ;;
  --check-table) mode=check ;;
  -h | --help)
    sed -n '2,12p' "$caller" | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  *)
    echo "$script: unknown argument '$1' (use --check-table or nothing)" >&2
    exit 2
    ;;
esac

if [[ ! -x "$snell" ]]; then
  echo "$script: the snell CLI is missing or not executable: $snell" >&2
  echo "  build it: cmake --preset default && cmake --build --preset default --target snell" >&2
  echo "  (or point SNELL at a built snell binary)" >&2
  exit 1
fi

# docs_render NAME SCENE WxH CAMERA_ARRAY_NAME [extra CLI arguments: --effect, --set, ...]
# Renders $out_dir/NAME.png with the CLI and the camera arguments held in the array named
# CAMERA_ARRAY_NAME, prints the command line (the pages quote it), counts it in `count`, and
# stops the calling script on failure with the CLI's output.
docs_render() {
  local name="$1" scene="$2" size="$3" cam_name="$4"
  shift 4
  local -n cam="$cam_name"
  local log
  if ! log="$("$snell" render --scene "$scene" --size "$size" \
    --out "$out_dir/$name.png" "${cam[@]}" "$@" 2>&1)"; then
    echo "$log" >&2
    echo "$(basename "$0"): rendering $name.png failed" >&2
    exit 1
  fi
  count=$((count + 1))
  echo "  snell render --scene $scene --size $size --out ${out_dir#"$repo_root"/}/$name.png" \
    "${cam[@]}" "$@"
}
