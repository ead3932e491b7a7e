# Sourced by the desktop tests: a fresh QGIS profile folder that starts without prompts or tips.
# fresh_profiles OUTPUT_DIR makes OUTPUT_DIR/profiles, for qgis.bin --profiles-path.
fresh_profiles() {
  local profile="$1/profiles/profiles/default"
  mkdir -p "$profile/QGIS"
  cat >> "$profile/QGIS/QGIS3.ini" <<'INI'
[app]
askToSaveMemoryLayers=false
[qgis]
checkVersion=false
showTips=false
INI
}
