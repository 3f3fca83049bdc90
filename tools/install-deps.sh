#!/usr/bin/env bash
# Installs the Debian 12 packages Candela needs to build and test, when any is missing.
# Uses sudo when not root. Safe to run repeatedly (does nothing when all are present).
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config python3
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libspirv-cross-c-shared-dev spirv-tools
  libglm-dev libstb-dev libopenexr-dev libtinygltf-dev nlohmann-json3-dev zlib1g-dev
  libgtest-dev
  libglfw3-dev libimgui-dev glslang-dev xvfb xauth
  clang libclang-rt-14-dev
  libdraco-dev libmeshoptimizer-dev gltfpack
  libwebp-dev libzstd-dev
  chromium chromium-driver  # the HTML page in a browser (tests/html, label browser)
  zsh fish groff-base       # the completions parsed and the manual page formatted (tests/install)
  dpkg-dev file             # cpack -G DEB: dpkg-shlibdeps derives Depends (packaging/)
  python3-dev pybind11-dev python3-numpy python3-pytest python3-distributed   # the Python module (python/)
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
# The glTF-Validator oracle (validator.oracle) runs the npm validator under Node.js: Debian's, when
# the machine has no node and npm of its own (a minimal Debian root has neither).
command -v node >/dev/null && command -v npm >/dev/null || missing+=(nodejs npm)
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
