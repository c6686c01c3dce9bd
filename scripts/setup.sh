#!/usr/bin/env bash
# Installs the Debian 12 packages Snell needs to build, test and run its demos.
# Idempotent: does nothing when every package is already installed.
# Usage: bash scripts/setup.sh
set -euo pipefail

# The one list of system packages. Add new build/test/run-time dependencies here.
PACKAGES=(
  build-essential
  cmake
  ninja-build
  pkg-config
  git
  libglm-dev
  doctest-dev
  libvulkan-dev
  mesa-vulkan-drivers
  vulkan-validationlayers
  vulkan-tools
  glslang-tools
  spirv-tools
  libstb-dev
  libtinygltf-dev
  nlohmann-json3-dev
  clang
  clang-format
  libclang-rt-14-dev
  python3
  # `snell view` (SNELL_BUILD_VIEWER, ON when both are found): the window and the panel.
  libglfw3-dev
  libimgui-dev
  # The viewer's tests open a real window on a virtual X server (tests/viewer).
  xvfb
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$pkg")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "setup: all ${#PACKAGES[@]} packages already installed; nothing to do."
  exit 0
fi

if [[ ${EUID:-$(id -u)} -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "setup: error: missing packages (${missing[*]}) and not root, and sudo is not available." >&2
  echo "setup: run this script as root, or install the packages yourself." >&2
  exit 1
fi

echo "setup: installing ${#missing[@]} missing package(s): ${missing[*]}"
"${as_root[@]}" apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
echo "setup: done."
