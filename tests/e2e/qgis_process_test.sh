#!/usr/bin/env bash
# qgis_process end to end: the plugin package (ZIP) unpacked into a fresh profile, as QGIS's
# installer unpacks it, is listed, runs on the sample DEM, refuses a geographic DEM with a
# message, and a Model Builder model chaining GDAL warp, native hillshade and our algorithm runs.
# Usage: qgis_process_test.sh PLUGIN_ZIP REPO_DIR OUTPUT_DIR
set -uo pipefail
zip=$1 repo=$2 out=$3
rm -rf "$out" && mkdir -p "$out/home"
export HOME="$out/home" QT_QPA_PLATFORM=offscreen
profile="$HOME/.local/share/QGIS/QGIS3/profiles/default"
source "$(dirname "$0")/install_zip.sh"
install_zip "$zip" "$profile"
qp() { timeout 300 /usr/bin/qgis_process.bin "$@" 2>&1; }
passed=0 failed=0
check() {  # check NAME CONDITION-EXIT-CODE
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $1"; fi
}
features() { ogrinfo -so -al "$1" 2>/dev/null | sed -n 's/^Feature Count: //p'; }

qp list > "$out/list.txt"
grep -q "terrainsketch:silhouettes" "$out/list.txt"; check "provider listed" $?

qp run terrainsketch:silhouettes --INPUT="$repo/resources/sample/jacksboro_utm16n.tif" --BAND=1 \
  --FACTUAL="$out/f.gpkg" --FORMULATED="$out/o.gpkg" > "$out/run.txt"
check "sample run exit code" $?
[ "$(features "$out/f.gpkg")" -gt 100 ] 2>/dev/null; check "factual features" $?
[ "$(features "$out/o.gpkg")" -gt 100 ] 2>/dev/null; check "formulated features" $?

qp run terrainsketch:silhouettes --INPUT="$repo/tests/data/jacksboro_geo.tif" --BAND=1 \
  --FACTUAL="$out/g.gpkg" --FORMULATED="$out/h.gpkg" > "$out/geo.txt"
[ $? -ne 0 ]; check "geographic DEM fails" $?
# The message names the CRS in any language (under LANG=de it is our German translation).
grep -q "(EPSG:4326)" "$out/geo.txt"; check "geographic DEM message" $?
[ ! -e "$out/g.gpkg" ]; check "no output for the refused DEM" $?

qp run "$repo/resources/models/silhouettes_over_hillshade.model3" \
  --dem="$repo/tests/data/jacksboro_geo.tif" --crs=EPSG:32616 --hillshade:Hillshade="$out/hs.tif" \
  "--silhouettes:Factual silhouettes=$out/mf.gpkg" \
  "--silhouettes:Formulated silhouettes=$out/mo.gpkg" > "$out/model.txt"
check "model exit code" $?
gdalinfo "$out/hs.tif" > /dev/null 2>&1; check "model hillshade raster" $?
[ "$(features "$out/mf.gpkg")" -gt 100 ] 2>/dev/null; check "model factual features" $?

# The panorama from the sample's summit, the observer given as a point with its CRS.
qp run terrainsketch:panorama --INPUT="$repo/resources/sample/jacksboro_utm16n.tif" \
  --OBSERVER='749008.1394,4009477.9308 [EPSG:32616]' --OBSERVER_HEIGHT=2 \
  --MAP_OUTPUT="$out/pm.gpkg" --PANORAMA_OUTPUT="$out/pp.gpkg" --VISIBILITY="$out/seen.tif" \
  > "$out/panorama.txt"
check "panorama exit code" $?
[ "$(features "$out/pm.gpkg")" -gt 100 ] 2>/dev/null; check "panorama map features" $?
[ "$(features "$out/pp.gpkg")" = "$(features "$out/pm.gpkg")" ]; check "panorama features" $?
gdalinfo "$out/seen.tif" > /dev/null 2>&1; check "panorama visibility raster" $?
qp run terrainsketch:panorama --INPUT="$repo/resources/sample/jacksboro_utm16n.tif" \
  --OBSERVER='0,0 [EPSG:32616]' --MAP_OUTPUT="$out/px.gpkg" --PANORAMA_OUTPUT="$out/py.gpkg" \
  > "$out/panorama_off.txt"
[ $? -ne 0 ] && [ ! -e "$out/px.gpkg" ]; check "panorama observer off the DEM refused" $?

# Two runs writing the same outputs at once, one on a larger DEM: each waits for the other's
# outputs to be complete (a lock per output file), both succeed, and the outputs are whole (one
# run's failure used to delete the other's files).
gdal_translate -q -outsize 5000 5000 -r bilinear "$repo/resources/sample/jacksboro_utm16n.tif" \
  "$out/large.tif"
for round in 1 2; do
  rm -f "$out"/cc_*.gpkg
  # Without --BAND: the band is optional, the first by default.
  qp run terrainsketch:silhouettes --INPUT="$out/large.tif" \
    --FACTUAL="$out/cc_f.gpkg" --FORMULATED="$out/cc_m.gpkg" > "$out/cc_large$round.txt" &
  large=$!
  qp run terrainsketch:silhouettes --INPUT="$repo/resources/sample/jacksboro_utm16n.tif" \
    --FACTUAL="$out/cc_f.gpkg" --FORMULATED="$out/cc_m.gpkg" > "$out/cc_sample$round.txt"
  sample_rc=$?
  wait $large; large_rc=$?
  [ $sample_rc -eq 0 ] && [ $large_rc -eq 0 ]; check "concurrent runs $round both succeed" $?
  [ "$(features "$out/cc_f.gpkg")" -gt 100 ] 2>/dev/null && \
    [ "$(features "$out/cc_m.gpkg")" -gt 100 ] 2>/dev/null; check "concurrent runs $round outputs" $?
done

# A run killed outright (kill -9) once it has begun writing keeps the earlier outputs whole (QGIS
# had written over them when the run started, leaving them empty with a lock and a -journal);
# it leaves a hidden staging folder, which the next run into the folder removes.
staging() { ls -A "$out" | grep -c '^\.f\.gpkg\.partial-'; }
before=$(features "$out/f.gpkg")
/usr/bin/qgis_process.bin run terrainsketch:silhouettes --INPUT="$out/large.tif" \
  --FACTUAL="$out/f.gpkg" --FORMULATED="$out/o.gpkg" > /dev/null 2>&1 &
killed=$!
# Staged as the run begins, seconds before its 25 million cells are sketched.
for _ in $(seq 2400); do [ "$(staging)" -gt 0 ] && break; sleep 0.05; done
kill -9 $killed; wait $killed 2> /dev/null
[ "$(staging)" -eq 1 ] && [ "$(features "$out/f.gpkg")" = "$before" ] && \
  [ ! -e "$out/f.gpkg-journal" ]; check "killed run keeps the earlier outputs" $?
qp run terrainsketch:silhouettes --INPUT="$repo/resources/sample/jacksboro_utm16n.tif" \
  --FACTUAL="$out/f2.gpkg" --FORMULATED="$out/o2.gpkg" > /dev/null
[ "$(staging)" -eq 0 ]; check "the next run removes the killed run's staging" $?

# The German translation loads when the profile's locale is German.
printf '\n[locale]\noverrideFlag=true\nuserLocale=de\n' \
  >> "$HOME/.local/share/QGIS/QGIS3/profiles/default/QGIS/QGIS3.ini"
qp help terrainsketch:silhouettes > "$out/help_de.txt"
grep -q "Silhouetten (faktisch und formuliert)" "$out/help_de.txt"; check "German help title" $?
grep -q "Überhöhung" "$out/help_de.txt"; check "German parameter names" $?

echo "qgis_process end-to-end: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
