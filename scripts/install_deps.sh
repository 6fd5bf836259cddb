#!/usr/bin/env bash
# Installs the Debian 12 packages Weft builds and tests with. Idempotent: when everything is
# present it returns in well under a second without touching apt.
set -euo pipefail

PACKAGES=(
  cmake ninja-build g++ pkg-config git
  libeigen3-dev libsuitesparse-dev nlohmann-json3-dev libcli11-dev libtinyobjloader-dev libgmp-dev
  libgtest-dev libbenchmark-dev
  libimgui-dev libglfw3-dev libegl-dev libgl-dev libgl1-mesa-dev libegl-mesa0 libgl1-mesa-dri
  libstb-dev libpng-dev libboost-dev xvfb xauth xdotool x11-apps
  ffmpeg
  clang
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "weft: installing Debian packages: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -o DPkg::Lock::Timeout=600 -qq
$SUDO apt-get install -y -q -o DPkg::Lock::Timeout=600 --no-install-recommends "${missing[@]}"
