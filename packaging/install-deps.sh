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
  # Qt's own dialogs in German and Polish; the locales the locale test matrix runs under
  qt6-translations-l10n locales
  # 3D (VTK 9 without its Qt 5 module)
  libvtk9-dev
  # maths, data, exact solver
  libeigen3-dev libboost-dev nlohmann-json3-dev libglpk-dev glpk-utils libcli11-dev
  # k-d tree (point-to-surface search), XML (QIF, MTConnect)
  libnanoflann-dev libpugixml-dev
  # tests and benchmark peers
  googletest libgtest-dev libgmock-dev libpagmo-dev libboost-serialization-dev libtbb-dev libceres-dev
  # headless GUI tests and PDF checks
  xvfb xauth libgl1-mesa-dri poppler-utils
  # packaging checks
  dpkg-dev file appstream desktop-file-utils man-db
  # the project file type (update-mime-database) and XML checks of the packaging files
  shared-mime-info libxml2-utils
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# The locale test matrix (C.UTF-8, de_DE.UTF-8, pl_PL.UTF-8): generate the two that are missing.
ensure_locales() {
  local need=()
  for l in de_DE pl_PL; do
    if ! locale -a 2>/dev/null | grep -qi "^${l}\.utf-\?8$"; then need+=("$l"); fi
  done
  [ ${#need[@]} -eq 0 ] && return 0
  for l in "${need[@]}"; do
    echo "install-deps: generating locale ${l}.UTF-8"
    $SUDO localedef -i "$l" -f UTF-8 "${l}.UTF-8" || echo "install-deps: could not generate ${l}.UTF-8 (tests under it are skipped)"
  done
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  ensure_locales
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
ensure_locales
echo "install-deps: done"
