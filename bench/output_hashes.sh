#!/usr/bin/env bash
# Hashes of what the tool outputs, to show that a change of structure changed no output:
# the CLI's strokes on a DEM in four configurations and the QGIS algorithm's strokes on the sample.
# Usage: output_hashes.sh BUILD_DIR DEM.tif SAMPLE.tif WORK_DIR
# FILTER=adaptive hashes the default filter's outputs; by default the thesis's (fixed), whose
# outputs never change. The stats hash covers the stage figures, not the filter's report.
set -euo pipefail
filter=${FILTER:-fixed}
# STROKES=drawn hashes the drawn strokes; by default SPEC's exact ones, which never change.
strokes=${STROKES:-exact}
mkdir -p "$4"
build=$(realpath "$1") dem=$(realpath "$2") sample=$(realpath "$3") work=$(realpath "$4")
repo=$(cd "$(dirname "$0")/.." && pwd)
dump() {  # the rows of every layer of a vector file, geometry as WKT, in file order
  ogr2ogr -f CSV /vsistdout/ "$1" -lco GEOMETRY=AS_WKT 2>/dev/null | sha256sum | cut -c1-16
}
run_cli() {  # NAME ARGS...
  local name=$1; shift
  "$build/cli/terrain-sketch" silhouettes "$dem" "$work/$name.gpkg" --stats-json "$work/$name.json" \
    --filter "$filter" --strokes "$strokes" "$@" > /dev/null 2>&1
  local stats
  stats=$(sed '/"filter"/,$d' "$work/$name.json" | tr -d ',' | sha256sum | cut -c1-16)
  echo "cli $name: strokes $(dump "$work/$name.gpkg") stats $stats"
}
run_cli west_map
run_cli west_oblique --geometry oblique
run_cli az45_map --azimuth 45
run_cli az200_oblique_subcell --azimuth 200 --geometry oblique --subcell --no-diagonals
if [ -x /usr/bin/qgis_process.bin ] && [ -d "$build/qgis-plugin/terrain_sketch_plugin" ]; then
  export HOME="$work/home" QT_QPA_PLATFORM=offscreen
  rm -rf "$HOME"
  cmake -DPLUGIN_DIR="$build/qgis-plugin/terrain_sketch_plugin" \
    -DPROFILE_DIR="$HOME/.local/share/QGIS/QGIS3/profiles/default" -DPLUGIN_NAME=terrain_sketch_plugin \
    -P "$repo/plugin/install_plugin.cmake" > /dev/null
  for az in 90 45; do
    /usr/bin/qgis_process.bin run terrainsketch:silhouettes --INPUT="$sample" --BAND=1 --AZIMUTH=$az \
      --FILTER=$([ "$filter" = fixed ] && echo 1 || echo 0) \
      --STROKES=$([ "$strokes" = exact ] && echo 1 || echo 0) --GEOMETRY=1 --FACTUAL="$work/q$az-f.gpkg" --FORMULATED="$work/q$az-o.gpkg" > "$work/q$az.log" 2>&1
    echo "qgis azimuth $az oblique: factual $(dump "$work/q$az-f.gpkg") formulated $(dump "$work/q$az-o.gpkg")"
  done
fi
