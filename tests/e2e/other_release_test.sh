#!/usr/bin/env bash
# A plugin package built for another QGIS release, installed into this one: its loader must say
# which release it was built for and load nothing, and QGIS must go on (no crash, no silent
# failure). Usage: other_release_test.sh ZIP WORK_DIR
set -euo pipefail
zip=$1 work=$2
rm -rf "$work"
profile="$work/.local/share/QGIS/QGIS3/profiles/default"
source "$(dirname "$0")/install_zip.sh"
install_zip "$zip" "$profile"
status=0
out=$(HOME="$work" QT_QPA_PLATFORM=offscreen qgis_process.bin list 2>&1) || status=$?
fail() { echo "FAILED: $1"; echo "$out" | tail -20; exit 1; }
[ "$status" -eq 0 ] || fail "qgis_process list exited with $status"
echo "$out" | grep -q "Terrain Sketch was not loaded: this package" || fail "no message"
echo "$out" | grep -q "works only in the QGIS release it was built for" || fail "no reason given"
echo "$out" | grep -q "native:buffer" || fail "QGIS's own algorithms are not listed"
if echo "$out" | grep -q "terrainsketch:"; then fail "the provider was loaded"; fi
echo "$out" | grep "Terrain Sketch was not loaded" | head -1
echo "other QGIS release: 1 passed, 0 failed"
