#!/usr/bin/env bash
# Installs the Debian package into a clean chroot of the Debian it was built on, with apt-get
# (which brings its dependencies from Debian's packages), and runs the sample DEM through the
# installed command-line tool; checks the man page and the plugin's files are in place.
#   scripts/deb_install_test.sh PACKAGE.deb
# The clean chroot is kept as a tarball in $TSK_CHROOT_CACHE (default
# /var/cache/terrain-sketch/chroots) and unpacked afresh for each run.
set -euo pipefail
deb=$(realpath "$1")
repo=$(cd "$(dirname "$0")/.." && pwd)
cache=${TSK_CHROOT_CACHE:-/var/cache/terrain-sketch/chroots}
suite=$(. /etc/os-release && echo "$VERSION_CODENAME")
base=$cache/$suite-clean.tar
source "$repo/scripts/debian_root.sh"
if [ ! -f "$base" ]; then
  mkdir -p "$cache"
  make_debian_root "$suite" "$base.new" --format=tar
  mv "$base.new" "$base"
fi
root=$(mktemp -d "$cache/deb-test.XXXXXX")
cleanup() {
  umount -l "$root/proc" "$root/dev" 2>/dev/null || true
  rm -rf "$root"
}
trap cleanup EXIT
tar -xf "$base" -C "$root"
mount --bind /dev "$root/dev"
mount -t proc proc "$root/proc"
cp "$deb" "$root/tmp/"
cp "$repo/resources/sample/jacksboro_utm16n.tif" "$root/tmp/sample.tif"
chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  DEBIAN_FRONTEND=noninteractive PACKAGE="/tmp/$(basename "$deb")" bash -euo pipefail -c '
  apt-get update -q -o Acquire::Check-Valid-Until=false > /dev/null
  apt-get install -y -q --no-install-recommends "$PACKAGE" > /tmp/apt.log || {
    tail -20 /tmp/apt.log; exit 1; }
  terrain-sketch silhouettes /tmp/sample.tif /tmp/out.gpkg --stats-json /tmp/stats.json
  grep -q "\"formulated_strokes\": [1-9]" /tmp/stats.json
  test -s /usr/share/man/man1/terrain-sketch.1.gz
  test -s /usr/share/qgis/python/plugins/terrain_sketch_plugin/libterrain_sketch_provider.so
  test -s /usr/share/qgis/python/plugins/terrain_sketch_plugin/metadata.txt
  # The Python package, in Debian'"'"'s Python path: the same run from Python.
  apt-get install -y -q --no-install-recommends python3 > /tmp/apt.log
  python3 -c "import terrain_sketch as t; s = t.silhouettes(\"/tmp/sample.tif\", \"/tmp/py.gpkg\"); assert s[\"formulated_strokes\"] > 0, s"
  # QGIS puts its plugin folders first on Python'"'"'s path: the package is still the one found.
  python3 -c "import sys; sys.path.insert(0, \"/usr/share/qgis/python/plugins\"); import terrain_sketch as t; assert hasattr(t, \"sketch\"), t.__file__"
  dpkg -s terrain-sketch | grep "^Version"
'
echo "Debian package installed and ran: 1 passed, 0 failed"
