#!/usr/bin/env bash
# Builds Terrain Sketch (library, command-line tool, QGIS plugin), installs the plugin into your
# default QGIS profile, and draws the silhouettes of the bundled sample DEM (Jacksboro fault,
# Tennessee) twice:
#   through qgis_process:  out/jacksboro_factual.gpkg, out/jacksboro_formulated.gpkg
#   with the CLI:          out/jacksboro_silhouettes.gpkg, out/jacksboro_stats.json,
#                          out/jacksboro_sketch.png (a picture of the oblique sketch)
#                          out/jacksboro_sketch.pdf (the sketch as vector art on an A3 page)
#                          out/jacksboro_panorama.gpkg, out/jacksboro_panorama.svg (the panorama
#                          from the sample's summit, looking north)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh qgis
# Every option is set, so that a build folder configured otherwise before gives this build.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTSK_BUILD_CLI=ON -DTSK_BUILD_PLUGIN=ON \
  -DTSK_BUILD_TESTS=OFF -DTSK_BUILD_BENCH=OFF -DTSK_SANITIZE=OFF -DTSK_FUZZ=OFF > /dev/null
cmake --build build -j "$(nproc)"
cmake --build build --target install-plugin
mkdir -p out
dem=resources/sample/jacksboro_utm16n.tif

QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen} /usr/bin/qgis_process.bin run \
  terrainsketch:silhouettes --INPUT="$dem" --BAND=1 --GEOMETRY=1 \
  --FACTUAL=out/jacksboro_factual.gpkg --FORMULATED=out/jacksboro_formulated.gpkg

build/cli/terrain-sketch silhouettes "$dem" out/jacksboro_silhouettes.gpkg --geometry oblique \
  --stats-json out/jacksboro_stats.json --preview out/jacksboro_sketch.png
build/cli/terrain-sketch silhouettes "$dem" out/jacksboro_page.gpkg --preview out/jacksboro_sketch.pdf \
  --page A3
build/cli/terrain-sketch panorama "$dem" out/jacksboro_panorama.gpkg \
  --observer 749008.1394,4009477.9308 --observer-height 2 --azimuth-from 300 --azimuth-to 30 \
  --visibility out/jacksboro_seen.tif --preview out/jacksboro_panorama.svg
echo "wrote out/jacksboro_factual.gpkg, out/jacksboro_formulated.gpkg (qgis_process),"
echo "      out/jacksboro_silhouettes.gpkg, out/jacksboro_stats.json, out/jacksboro_sketch.png,"
echo "      out/jacksboro_sketch.pdf (an A3 page of vector art),"
echo "      out/jacksboro_panorama.gpkg, out/jacksboro_seen.tif, out/jacksboro_panorama.svg (CLI)"
