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
# The log's messages (stderr) and the list of algorithms (stdout) apart: merged, the list's
# buffered output could land inside the message's line (seen once under QGIS 3.44).
log=$(HOME="$work" QT_QPA_PLATFORM=offscreen qgis_process.bin list 2>&1 >"$work/list.txt") ||
  status=$?
listed=$(cat "$work/list.txt")
fail() { echo "FAILED: $1"; echo "$log" | tail -10; echo "$listed" | tail -10; exit 1; }
[ "$status" -eq 0 ] || fail "qgis_process list exited with $status"
echo "$log" | grep -q "Terrain Sketch was not loaded: this package" || fail "no message"
echo "$log" | grep -q "works only in the QGIS release it was built for" || fail "no reason given"
echo "$listed" | grep -q "native:buffer" || fail "QGIS's own algorithms are not listed"
if echo "$listed" | grep -q "terrainsketch:"; then fail "the provider was loaded"; fi
echo "$log" | grep "Terrain Sketch was not loaded" | head -1
echo "other QGIS release: 1 passed, 0 failed"
