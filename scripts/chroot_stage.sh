#!/usr/bin/env bash
# Builds and tests Terrain Sketch against the QGIS of another Debian suite, in a chroot made from
# Debian's packages: trixie (Debian 13, QGIS 3.40 LTR, GDAL 3.10) or sid (QGIS 3.44).
#   scripts/chroot_stage.sh SUITE [OTHER_RELEASE_ZIP]
# The chroot is cached outside the repository, in $TSK_CHROOT_CACHE (default
# /var/cache/terrain-sketch/chroots), and made again when it is missing or its package list
# changed. The repository is mounted read-only; the build folder is made anew in the chroot.
# OTHER_RELEASE_ZIP: a plugin package built for another QGIS; installing it here must give
# QGIS's user a clear message, not a crash.
set -euo pipefail
suite=$1 other_zip=${2:-}
repo=$(cd "$(dirname "$0")/.." && pwd)
cache=${TSK_CHROOT_CACHE:-/var/cache/terrain-sketch/chroots}
root=$cache/$suite
packages="qgis libqgis-dev qttools5-dev qttools5-dev-tools libsqlite3-dev cmake g++ make catch2
  libgdal-dev gdal-bin python3-gdal xvfb xauth poppler-utils pybind11-dev python3-dev
  python3-pytest python3-distributed"
packages=$(echo $packages)

source "$repo/scripts/debian_root.sh"

# Every mount in the chroot, deepest first: at the end of a run, and before the next one for those
# a killed run left (its EXIT trap never ran), as a bind over a folder deleted since fails the next
# mount there, and rm -rf of the chroot would reach /dev.
unmount_in_chroot() {
  local target
  awk -v r="$root/" 'index($2, r) == 1 {print $2}' /proc/mounts | sort -r |
    while read -r target; do umount -l "$target" 2>/dev/null || true; done
}
unmount_in_chroot
make_chroot() {
  rm -rf "$root" "$root.new"
  mkdir -p "$cache"
  make_debian_root "$suite" "$root.new" --include="${packages// /,}"
  echo "$packages" > "$root.new/.terrain-sketch-packages"
  mv "$root.new" "$root"
}

if [ "$(cat "$root/.terrain-sketch-packages" 2>/dev/null)" != "$packages" ]; then
  echo "-- making the $suite chroot in $root"
  start=$(date +%s)
  make_chroot
  echo "-- $suite chroot made in $(( $(date +%s) - start )) s"
fi

trap unmount_in_chroot EXIT
bind() {  # SOURCE TARGET [ro]
  mkdir -p "$2"
  mount --bind "$1" "$2"
  if [ "${3:-}" = ro ]; then mount -o remount,bind,ro "$2"; fi
}
bind /dev "$root/dev"
bind /dev/pts "$root/dev/pts"
mount -t proc proc "$root/proc"
bind "$repo" "$root/src" ro
if [ -n "$other_zip" ]; then cp "$other_zip" "$root/tmp/other-release.zip"; fi

jobs=$(nproc)
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
  JOBS="$jobs" OTHER_ZIP="${other_zip:+/tmp/other-release.zip}" bash -euo pipefail -c '
  rm -rf /build
  cmake -S /src -B /build -DCMAKE_BUILD_TYPE=Release -DTSK_BUILD_CLI=ON -DTSK_BUILD_PLUGIN=ON \
    -DTSK_BUILD_TESTS=ON -DTSK_BUILD_BENCH=ON -DTSK_SANITIZE=OFF -DTSK_FUZZ=OFF > /dev/null
  cmake --build /build -j "$JOBS"
  ctest --test-dir /build --output-on-failure --no-tests=error -j "$JOBS"
  if [ -n "$OTHER_ZIP" ]; then bash /src/tests/e2e/other_release_test.sh "$OTHER_ZIP" /tmp/other; fi
'
