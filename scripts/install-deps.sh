#!/usr/bin/env bash
# Installs what Terrain Sketch needs on Debian 12, from Debian's packages only.
# Usage: scripts/install-deps.sh [core|qgis]   (core: library, CLI and tests; qgis: plus the plugin)
set -euo pipefail
what=${1:-core}
# poppler-utils and librsvg2-bin: the vector previews' tests render the PDF and SVG they write.
# pybind11-dev, python3-dev: the Python package; python3-distributed: its runs on a Dask cluster;
# python3-pytest, python3-gdal (with numpy) and python3-geopandas: its tests (python3-gdal: the
# front-end parity test's rasters too).
# libjemalloc-dev: the command line's allocator (cli/CMakeLists.txt).
packages=(build-essential cmake catch2 libgdal-dev libsqlite3-dev libjemalloc-dev gdal-bin clang libclang-rt-dev
  clang-format git poppler-utils librsvg2-bin pybind11-dev python3-dev python3-pytest python3-gdal
  python3-geopandas python3-distributed)
if [ "$what" = qgis ]; then
  # mount: the chroots' /proc and /dev (a minimal Debian root has no mount command);
  # mmdebstrap: the chroots of the newer QGIS releases; qt6-*: the Qt6 readiness build;
  # dpkg-dev and file: the Debian package (CPack).
  packages+=(mount libqgis-dev qgis qgis-providers qttools5-dev-tools qttools5-dev xvfb xauth mmdebstrap
    qt6-base-dev qt6-tools-dev qt6-l10n-tools dpkg-dev file)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
