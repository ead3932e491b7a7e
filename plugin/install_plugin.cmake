# Copies the built plugin folder into a QGIS profile and enables it (desktop and qgis_process).
# cmake -DPLUGIN_DIR=... -DPROFILE_DIR=... -DPLUGIN_NAME=terrain_sketch_plugin \
#   -P install_plugin.cmake
set(target "${PROFILE_DIR}/python/plugins/${PLUGIN_NAME}")
file(REMOVE_RECURSE "${target}")
# An earlier install under the folder's old name would load a second copy, and a folder named
# terrain_sketch hid the Python package of that name from QGIS's Python: it goes.
set(old_target "${PROFILE_DIR}/python/plugins/terrain_sketch")
if(EXISTS "${old_target}/libterrain_sketch_provider.so" AND NOT old_target STREQUAL target)
  file(REMOVE_RECURSE "${old_target}")
endif()
file(MAKE_DIRECTORY "${PROFILE_DIR}/python/plugins" "${PROFILE_DIR}/QGIS")
file(COPY "${PLUGIN_DIR}" DESTINATION "${PROFILE_DIR}/python/plugins")

set(ini "${PROFILE_DIR}/QGIS/QGIS3.ini")
set(content "")
if(EXISTS "${ini}")
  file(READ "${ini}" content)
endif()
if(NOT content MATCHES "${PLUGIN_NAME}=true")
  if(content MATCHES "\\[PythonPlugins\\]")
    string(REPLACE "[PythonPlugins]" "[PythonPlugins]\n${PLUGIN_NAME}=true" content "${content}")
  else()
    string(APPEND content "\n[PythonPlugins]\n${PLUGIN_NAME}=true\n")
  endif()
  file(WRITE "${ini}" "${content}")
endif()
message(STATUS "Terrain Sketch installed in ${target} and enabled in ${ini}")
