#!/usr/bin/env bash
# End-to-end test in the real QGIS desktop under Xvfb: the plugin package is installed into a
# fresh profile through QGIS's own installer (Install from ZIP), the algorithm runs from
# Processing, both styled layers are on the canvas, a screenshot is saved.
# Usage: desktop_test.sh PLUGIN_ZIP DEM OUTPUT_DIR
set -euo pipefail
zip=$1 dem=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out"
profiles="$out/profiles"
source "$here/desktop_profile.sh"
fresh_profiles "$out"
export TSK_E2E_OUT="$out" TSK_E2E_DEM="$dem" TSK_E2E_ZIP="$zip" TSK_E2E_SCRIPTS="$here"

run_qgis() {
  rm -f "$out/report.json"
  timeout 180 xvfb-run -a -s "-screen 0 1600x1000x24" /usr/bin/qgis.bin --profiles-path "$profiles" \
    --nologo --noversioncheck --code "$here/desktop_run.py" > "$out/qgis.log" 2>&1 || true
  [ -f "$out/report.json" ] || { echo "no report; QGIS log:"; tail -40 "$out/qgis.log"; return 1; }
  /usr/bin/python3 - "$out/report.json" <<'PY'
import json, os, sys
r = json.load(open(sys.argv[1]))
errors = []
def check(cond, what):
    if not cond: errors.append(what)
check(r.get("ok"), "run finished: %s" % r.get("error"))
check(r.get("installed_from_zip"), "installed from the ZIP by QGIS's installer")
check(os.path.exists(os.path.join(os.environ["TSK_E2E_OUT"], "profiles/profiles/default/python/plugins/terrain_sketch_plugin/libterrain_sketch_provider.so")), "unpacked into the profile")
check(r.get("provider"), "provider registered")
# The Python package, imported by its name inside QGIS (where plugin folders come first on
# Python's path), is the package and runs.
if os.environ.get("TSK_E2E_PYTHON_PACKAGE"):
    package = r.get("python_package", {})
    check("/plugins/" not in package.get("file", "/plugins/"),
          "import terrain_sketch in QGIS gives the Python package: %s" % package)
    check((package.get("formulated_strokes") or 0) > 0,
          "the Python package runs in QGIS: %s" % package)
# Every algorithm's dialog builds its widgets, and the Silhouettes dialog's scale widget gives
# back the scale it was given.
dialogs = r.get("dialogs", {})
check(len(dialogs) == 8, "eight dialogs built: %s" % list(dialogs))
check(dialogs.get("terrainsketch:silhouettes", {}).get("DRAWN_FOR") == 250000,
      "the dialog's Drawn for scale: %s" % dialogs.get("terrainsketch:silhouettes"))
check(r.get("plugin_active"), "plugin active in the plugin manager")
check(not r.get("not_loaded"), "outputs not loaded: %s" % r.get("not_loaded"))
layers = {l["file"]: l for l in r.get("layers", [])}
check(len(layers) == 10, "ten layers loaded, got %s" % list(layers))
# The default strokes are drawn ones: LineString M, styled by the plugin's tapered line, which
# draws each point's weight (the M values), over four stepped stand-ins for QGIS without the
# plugin whose widths follow each stroke's largest weight.
for path, colour in (("factual.gpkg", "#111111"), ("formulated.gpkg", "#6e3e1c")):
    l = layers.get(path, {})
    check(l.get("features", 0) > 100, path + " has features")
    check(l.get("crs") == "EPSG:32616", path + " CRS")
    check(l.get("geometry_type") == "LineStringM", path + " LineString M, got %s" % l.get("geometry_type"))
    check(l.get("renderer") == "singleSymbol", path + " styled")
    check(l.get("colour") == colour, path + " colour %s" % l.get("colour"))
    kinds = l.get("symbol_layers") or []
    check(kinds[:1] == ["TerrainSketchTaperedLine"], path + " drawn by the tapered line: %s" % kinds)
    check(kinds[1:] == ["SimpleLine"] * 4, path + " with four stepped stand-ins: %s" % kinds)
check(layers.get("profiles.gpkg", {}).get("features", 0) > 20, "profile plot lines")
check(layers.get("classes.tif", {}).get("renderer") == "paletted", "classes paletted")
check(layers.get("rowslope.tif", {}).get("renderer") == "singlebandgray", "row slope grey")
# The ramp meets the raster's own values (it was fixed at 0-60 %: low relief showed blank).
ramp = layers.get("rowslope.tif", {}).get("ramp_max", 60)
check(0 < ramp != 60, "row slope ramp from the data, up to %s" % ramp)
check(layers.get("pstrokes.gpkg", {}).get("features", 0) > 100, "P-strokes drawn")
check("draped.tif" in layers, "draped raster loaded")
# The panorama: its strokes on the map in the DEM's CRS, the same strokes in the panorama, both
# styled, and the visibility raster with its colour table.
pmap, pano = layers.get("panorama_map.gpkg", {}), layers.get("panorama.gpkg", {})
check(pmap.get("features", 0) > 100, "panorama strokes on the map")
check(pmap.get("crs") == "EPSG:32616", "panorama map CRS")
check(pano.get("features") == pmap.get("features"), "panorama strokes in the panorama")
for l in (pmap, pano):
    check(l.get("renderer") == "singleSymbol" and l.get("colour") == "#111111", "panorama styled")
check(layers.get("seen.tif", {}).get("renderer") == "paletted", "visibility paletted")
shots = r.get("screenshots", [])
check(len(shots) == 6, "six screenshots")
for shot in shots:
    check(os.path.exists(shot) and os.path.getsize(shot) > 10000, "screenshot " + shot)
if errors:
    print("FAILED:\n  " + "\n  ".join(errors))
    print("layers: %s" % [(l["name"], l["file"]) for l in r.get("layers", [])])
    print("QGIS message log (last 30):\n  " + "\n  ".join(r.get("log", [])[-30:]))
    sys.exit(1)
print("desktop end-to-end: 1 passed, 0 failed")
PY
}

# One session, no second try: a failure prints the report's findings and the end of QGIS's log.
run_qgis
