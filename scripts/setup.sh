#!/usr/bin/env bash
# Installs the Debian packages this project builds, runs and tests with.
# Idempotent: installs only what is missing; uses sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools libglm-dev libglfw3-dev
  libtinygltf-dev nlohmann-json3-dev libstb-dev
  libmeshoptimizer-dev libimgui-dev libgtest-dev libsqlite3-dev
)
# Extra packages only the test suite needs (virtual X server for the viewer test and xdotool to resize
# its window, broken glTF corpus, plotting for benchmark figures).
if [[ "${1:-}" == "--tests" ]]; then
  packages+=(xvfb xauth xdotool assimp-testmodels python3-matplotlib clang libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if (( ${#missing[@]} == 0 )); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
echo "setup: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
