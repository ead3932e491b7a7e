#!/usr/bin/env bash
# Builds Terrain Sketch and draws the silhouettes of the bundled sample DEM (Jacksboro fault,
# Tennessee): out/jacksboro_silhouettes.gpkg, out/jacksboro_stats.json, out/jacksboro_sketch.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh core
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTSK_BUILD_TESTS=OFF > /dev/null
cmake --build build -j "$(nproc)" --target terrain-sketch
mkdir -p out
build/cli/terrain-sketch silhouettes resources/sample/jacksboro_utm16n.tif \
  out/jacksboro_silhouettes.gpkg --geometry oblique \
  --stats-json out/jacksboro_stats.json --preview out/jacksboro_sketch.png
echo "wrote out/jacksboro_silhouettes.gpkg, out/jacksboro_stats.json and out/jacksboro_sketch.png"
