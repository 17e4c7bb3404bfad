#!/usr/bin/env bash
# Installs the Debian package that `cpack -G DEB` builds on a fresh Debian 12 (bookworm) system and
# runs it there: a minimal debootstrap chroot, `apt-get install ./metrofit_*.deb` (apt resolves the
# runtime libraries from the package's Depends line alone), then the command line, the demo with
# its PDF report, the GUI's --version/--help, a screenshot run under Xvfb, and the manual pages.
#
#   packaging/test-deb-in-chroot.sh [--no-build] [BUILD_DIR] [CHROOT_DIR]
#
#   BUILD_DIR   CMake build folder (default: build). Unless --no-build, the script builds the two
#               executables and the packaging files there and runs `cpack -G DEB`.
#   CHROOT_DIR  work folder, outside the source tree (default: /var/tmp/metrofit-deb-chroot).
#               CHROOT_DIR/pristine is the debootstrapped system (made once, never changed);
#               every run copies it to CHROOT_DIR/run, so each install starts from a fresh system.
#   MIRROR      environment: Debian mirror (default: http://deb.debian.org/debian).
#
# Needs root (debootstrap, chroot, mounts), network access to a Debian mirror and ~1.5 GB of disk.
# Idempotent: run it again after a rebuild. Not run by CI. Prints every command and its output and
# ends with "test-deb-in-chroot: PASS" (exit 0) or stops at the first failing step (exit 1).
set -euo pipefail

BUILD=1
if [ "${1:-}" = "--no-build" ]; then
  BUILD=0
  shift
fi
SOURCE_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="$(realpath -m "${1:-$SOURCE_DIR/build}")"
CHROOT_DIR="$(realpath -m "${2:-/var/tmp/metrofit-deb-chroot}")"
MIRROR="${MIRROR:-http://deb.debian.org/debian}"
PRISTINE="$CHROOT_DIR/pristine"
ROOT="$CHROOT_DIR/run"

say() { printf '\n== %s\n' "$*"; }
fail() {
  printf 'test-deb-in-chroot: FAIL: %s\n' "$*" >&2
  exit 1
}

[ "$(id -u)" -eq 0 ] || fail "needs root (debootstrap, chroot and mounts)"
case "$CHROOT_DIR/" in
  "$SOURCE_DIR"/*) fail "CHROOT_DIR must be outside the source tree ($SOURCE_DIR)" ;;
esac
[ "$CHROOT_DIR" != "/" ] || fail "CHROOT_DIR must not be /"
export DEBIAN_FRONTEND=noninteractive LC_ALL=C.UTF-8

# ---- 1. the package --------------------------------------------------------------------------
if [ "$BUILD" -eq 1 ]; then
  say "build the package in $BUILD_DIR"
  [ -f "$BUILD_DIR/CMakeCache.txt" ] || cmake --preset default -B "$BUILD_DIR" -S "$SOURCE_DIR"
  cmake --build "$BUILD_DIR" --target metrofit metrofit-cli metrofit_packaging_files
  (cd "$BUILD_DIR" && rm -f metrofit_*.deb && cpack -G DEB)
fi
shopt -s nullglob
debs=("$BUILD_DIR"/metrofit_*.deb)
shopt -u nullglob
[ ${#debs[@]} -eq 1 ] || fail "expected one metrofit_*.deb in $BUILD_DIR, found ${#debs[@]}"
DEB="${debs[0]}"
say "package $(basename "$DEB"): $(stat -c %s "$DEB") bytes"
dpkg-deb -f "$DEB" Package Version Architecture Installed-Size Depends
dpkg-deb -c "$DEB" | grep -q '/usr/share/doc/metrofit/file-formats.md$' || fail "the package lacks file-formats.md"

# ---- 2. a fresh Debian 12 --------------------------------------------------------------------
umount_all() {
  for m in dev/pts dev sys proc; do
    if mountpoint -q "$ROOT/$m"; then umount -l "$ROOT/$m" || true; fi
  done
}
trap umount_all EXIT

if [ ! -f "$PRISTINE/etc/debian_version" ]; then
  if ! command -v debootstrap >/dev/null; then
    say "apt-get install debootstrap"
    apt-get update -q
    apt-get install -y -q debootstrap
  fi
  say "debootstrap --variant=minbase bookworm $PRISTINE $MIRROR"
  rm -rf "$PRISTINE"
  mkdir -p "$CHROOT_DIR"
  debootstrap --variant=minbase bookworm "$PRISTINE.tmp" "$MIRROR"
  mv "$PRISTINE.tmp" "$PRISTINE"
fi
say "fresh copy of the pristine system: $ROOT"
umount_all
rm -rf "$ROOT"
cp -a "$PRISTINE" "$ROOT"
echo "deb $MIRROR bookworm main" >"$ROOT/etc/apt/sources.list"
cp /etc/resolv.conf "$ROOT/etc/resolv.conf"
mount -t proc proc "$ROOT/proc"
mount -t sysfs sys "$ROOT/sys"
mount --bind /dev "$ROOT/dev"
mount --bind /dev/pts "$ROOT/dev/pts"

in_root() {
  printf '$ %s\n' "$*"
  chroot "$ROOT" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LC_ALL=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive TERM=dumb bash -c "$*"
}

# ---- 3. install ------------------------------------------------------------------------------
say "install the package with apt (dependencies from its Depends line only)"
cp "$DEB" "$ROOT/tmp/"
in_root "cat /etc/debian_version"
in_root "apt-get update -q"
in_root "apt-get install -y -q --no-install-recommends /tmp/$(basename "$DEB") 2>&1 | tail -n 3"
in_root "dpkg -s metrofit | grep -E '^(Status|Version|Installed-Size):'"
in_root "dpkg -L metrofit | grep -v '/\$' | sort"

# ---- 4. run it -------------------------------------------------------------------------------
say "command line"
[ "$(in_root 'metrofit-cli --version' | tail -n 1)" = "metrofit $(dpkg-deb -f "$DEB" Version)" ] ||
  fail "metrofit-cli --version does not print 'metrofit <version>'"
in_root "metrofit-cli --version"
in_root "metrofit-cli --help | head -n 5"
in_root "cd /tmp && metrofit-cli demo --out-dir /tmp/d"
in_root "head -c 5 /tmp/d/metrofit-demo-report.pdf | grep -q '%PDF-' && ls -l /tmp/d/metrofit-demo-report.pdf" ||
  fail "metrofit-cli demo wrote no PDF report"
in_root "metrofit-cli kinematic identify --data /tmp/d/data/circular_demo.csv --out /tmp/errors.json && head -c 200 /tmp/errors.json; echo"
set +e
in_root "metrofit-cli match --data /tmp/no-such-file.csv"
code=$?
set -e
[ "$code" -eq 2 ] || fail "bad input must exit 2, got $code"
echo "(exit $code)"

say "GUI without a display"
in_root "QT_QPA_PLATFORM=offscreen metrofit --version"
in_root "QT_QPA_PLATFORM=offscreen metrofit --help"

say "GUI screenshots under Xvfb"
in_root "apt-get install -y -q --no-install-recommends xvfb xauth 2>&1 | tail -n 1"
in_root "xvfb-run -a -s '-screen 0 1600x1000x24' metrofit --screenshots /tmp/shots 2>&1 | tail -n 3; ls /tmp/shots"
shots=$(find "$ROOT/tmp/shots" -name '*.png' -size +10k | wc -l)
[ "$shots" -ge 8 ] || fail "expected at least 8 screenshots larger than 10 kB, found $shots"
echo "$shots screenshots"

say "manual pages"
in_root "apt-get install -y -q --no-install-recommends man-db 2>&1 | tail -n 1"
in_root "MANWIDTH=80 man metrofit-cli 2>&1 | head -n 12"
in_root "MANWIDTH=80 man metrofit 2>&1 | head -n 6"
in_root "man -w metrofit metrofit-cli"

say "user documentation (named by metrofit-cli --help and the manual page)"
in_root "ls /usr/share/doc/metrofit; test -s /usr/share/doc/metrofit/file-formats.md"
in_root "metrofit-cli --help | grep -F /usr/share/doc/metrofit/file-formats.md"

say "desktop integration files"
in_root "ls /usr/share/applications /usr/share/metainfo /usr/share/icons/hicolor/*/apps"

umount_all
echo
echo "test-deb-in-chroot: PASS ($(basename "$DEB"), $(stat -c %s "$DEB") bytes, fresh bookworm in $ROOT)"
