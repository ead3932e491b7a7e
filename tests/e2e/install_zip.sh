# Sourced by the end-to-end tests: install_zip ZIP PROFILE unpacks the plugin package into a
# QGIS profile, as QGIS's installer unpacks it, and enables the plugin there.
install_zip() {
  mkdir -p "$2/python/plugins" "$2/QGIS"
  python3 -m zipfile -e "$1" "$2/python/plugins"
  printf '[PythonPlugins]\nterrain_sketch_plugin=true\n' > "$2/QGIS/QGIS3.ini"
}
