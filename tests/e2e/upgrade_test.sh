#!/usr/bin/env bash
# A newer plugin package installed over the one in use, as a user upgrades: Install from ZIP in
# the real QGIS desktop under Xvfb, into a fresh profile. QGIS's installer first unpacks the new
# package over the files in use, which rewrote the loaded library under the running code: QGIS
# crashed as it unloaded the plugin, and the old library stayed in use until a restart. Now QGIS
# lives on, the layers drawn before are drawn as before, and the new library runs.
# Usage: upgrade_test.sh PLUGIN_ZIP NEWER_LIBRARY DEM OUTPUT_DIR
# NEWER_LIBRARY: the plugin's library built again with upgrade_marker.cpp; the newer package is
# PLUGIN_ZIP with it in the old library's place.
set -euo pipefail
zip=$1 newer_library=$2 dem=$3 out=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out"
newer_zip="$out/$(basename "$zip" .zip)-newer.zip"
/usr/bin/python3 - "$zip" "$newer_library" "$newer_zip" <<'PY'
import sys, zipfile
source, library, target = sys.argv[1:]
with zipfile.ZipFile(source) as old, zipfile.ZipFile(target, "w", zipfile.ZIP_DEFLATED) as new:
    for entry in old.infolist():
        if entry.filename.endswith("/libterrain_sketch_provider.so"):
            new.write(library, entry.filename)
        else:
            new.writestr(entry, old.read(entry))
PY
source "$here/desktop_profile.sh"
fresh_profiles "$out"
status=0
TSK_E2E_OUT="$out" TSK_E2E_DEM="$dem" TSK_E2E_ZIP="$zip" TSK_E2E_NEWER_ZIP="$newer_zip" \
  TSK_E2E_SCRIPTS="$here" timeout 240 xvfb-run -a -s "-screen 0 1600x1000x24" /usr/bin/qgis.bin \
  --profiles-path "$out/profiles" --nologo --noversioncheck --code "$here/upgrade_run.py" \
  > "$out/qgis.log" 2>&1 || status=$?
[ -f "$out/report.json" ] || { echo "no report (QGIS exit $status); QGIS log:"; tail -40 "$out/qgis.log"; exit 1; }
/usr/bin/python3 - "$out/report.json" "$status" <<'PY'
import json, sys
r, status = json.load(open(sys.argv[1])), int(sys.argv[2])
errors = []
def check(cond, what):
    if not cond: errors.append(what)
check(r.get("ok"), "the runs finished: %s" % r.get("error"))
check(status == 0, "QGIS exited normally (exit status %d)" % status)
check(r.get("first_marker") is False, "the first package's library is in use at first")
check(r.get("first_layers") == 2, "the first run loaded two layers: %s" % r.get("first_layers"))
check("TerrainSketchTaperedLine" in r.get("first_symbol_layers", []),
      "the first layers are drawn by the tapered line: %s" % r.get("first_symbol_layers"))
check(r.get("inked_before", 0) > 1000, "the first layers draw strokes: %s" % r.get("inked_before"))
check(r.get("provider_after"), "the provider is registered after the upgrade")
check(r.get("newer_marker") is True, "the newer package's library is in use after the upgrade")
check(r.get("same_drawing"), "the first layers draw as before after the upgrade (%s, %s inked)"
      % (r.get("inked_before"), r.get("inked_after")))
check(r.get("newer_layers") == 2 and r.get("newer_features", 0) > 100,
      "the newer library's run loaded its strokes: %s layers, %s features"
      % (r.get("newer_layers"), r.get("newer_features")))
check("TerrainSketchTaperedLine" in r.get("newer_symbol_layers", []),
      "the newer layers are styled from the plugin folder: %s" % r.get("newer_symbol_layers"))
if errors:
    print("FAILED:\n  " + "\n  ".join(errors))
    sys.exit(1)
print("plugin upgrade in the desktop: 11 passed, 0 failed")
PY
