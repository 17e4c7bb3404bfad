#!/usr/bin/env bash
# Installs every Debian 12 package Metrofit needs to build, test, benchmark and run its demo.
# Idempotent and non-interactive; run as root (or with sudo available). Installs only what is missing.
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build ccache pkg-config git clang-format clang-tidy clang libclang-rt-14-dev
  # GUI: Qt 6 widgets, charts, OpenGL widgets, tools (linguist), svg; fonts for headless rendering
  qt6-base-dev qt6-base-dev-tools qt6-charts-dev libqt6opengl6-dev qt6-svg-dev
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-qpa-plugins libgl1-mesa-dev fonts-dejavu-core
  # 3D (VTK 9 without its Qt 5 module)
  libvtk9-dev
  # maths, data, exact solver
  libeigen3-dev libboost-dev nlohmann-json3-dev libglpk-dev glpk-utils libcli11-dev
  # tests and benchmark peers
  googletest libgtest-dev libgmock-dev libpagmo-dev libboost-serialization-dev libtbb-dev
  # headless GUI tests and PDF checks
  xvfb xauth libgl1-mesa-dri poppler-utils
  # packaging checks
  dpkg-dev file appstream desktop-file-utils man-db
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "install-deps: done"
