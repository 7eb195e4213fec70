#!/usr/bin/env bash
# Installs the Debian packages the project needs. Safe to run repeatedly:
# does nothing when they are all present.
#   setup.sh        everything: build, run, tests, benchmarks (scripts/test.sh)
#   setup.sh run    only what building and running the sample needs (scripts/run.sh)
set -euo pipefail

# Building and running the sample.
RUN_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libvulkan-dev mesa-vulkan-drivers
  glslang-tools glslang-dev spirv-tools
  libglfw3-dev libglm-dev libassimp-dev
  libopenimageio-dev libimgui-dev nlohmann-json3-dev
  # Debian's OpenImageIO CMake package names its command-line tools'
  # files, and find_package fails without them.
  openimageio-tools
)
# The tests and benchmarks, and the sample's --validation.
TEST_PACKAGES=(
  vulkan-validationlayers vulkan-tools assimp-testmodels
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool openbox matchbox-window-manager
)

case "${1:-all}" in
  run) wanted=("${RUN_PACKAGES[@]}") ;;
  all) wanted=("${RUN_PACKAGES[@]}" "${TEST_PACKAGES[@]}") ;;
  *) echo "usage: setup.sh [run|all]" >&2; exit 2 ;;
esac

missing=()
for p in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
