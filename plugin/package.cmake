# The plugin package for the QGIS it is built against: metadata.txt with that QGIS as its
# minimum and maximum version, build_info.py for the loader's version check, and the zip that
# QGIS's Plugin Manager installs ("Install from ZIP"). Included from plugin/CMakeLists.txt.

# This QGIS's version from its qgsconfig.h (already read into TSK_QGSCONFIG).
string(REGEX MATCH "#define _QGIS_VERSION_INT ([0-9]+)" _ "${TSK_QGSCONFIG}")
set(TSK_QGIS_VERSION_INT ${CMAKE_MATCH_1})
math(EXPR TSK_QGIS_MAJOR "${TSK_QGIS_VERSION_INT} / 10000")
math(EXPR TSK_QGIS_MINOR "(${TSK_QGIS_VERSION_INT} / 100) % 100")
set(TSK_QGIS_RELEASE "${TSK_QGIS_MAJOR}.${TSK_QGIS_MINOR}" CACHE INTERNAL "")

# The platform: Debian's release (cmake/debian_release.cmake) and the processor.
set(TSK_PLATFORM "${TSK_DEBIAN_RELEASE}-${CMAKE_SYSTEM_PROCESSOR}")
set(TSK_PACKAGE_NAME
    "${PROJECT_NAME}-${PROJECT_VERSION}-qgis${TSK_QGIS_RELEASE}-${TSK_PLATFORM}"
    CACHE INTERNAL "")

# metadata.txt for this QGIS release: QGIS's Plugin Manager marks the package incompatible with
# any other.
file(READ ${PROJECT_SOURCE_DIR}/metadata.txt TSK_METADATA)
string(REGEX REPLACE "qgisMinimumVersion=[^\n]*"
       "qgisMinimumVersion=${TSK_QGIS_RELEASE}\nqgisMaximumVersion=${TSK_QGIS_RELEASE}.99"
       TSK_METADATA "${TSK_METADATA}")
file(GENERATE OUTPUT ${TSK_PLUGIN_DIR}/metadata.txt CONTENT "${TSK_METADATA}")
file(GENERATE OUTPUT ${TSK_PLUGIN_DIR}/build_info.py CONTENT
"\"\"\"The QGIS this plugin's compiled provider was built against (written by CMake).\"\"\"
BUILT_FOR_QGIS_VERSION_INT = ${TSK_QGIS_VERSION_INT}
BUILT_FOR_QGIS = \"${TSK_QGIS_RELEASE}\"
PACKAGE = \"${TSK_PACKAGE_NAME}\"
")

# cmake --build build --target plugin-zip: build/<package>.zip, with the plugin's folder
# (terrain_sketch_plugin/) at its top as QGIS's installer expects.
set(TSK_PLUGIN_ZIP ${CMAKE_BINARY_DIR}/${TSK_PACKAGE_NAME}.zip CACHE INTERNAL "")
add_custom_command(OUTPUT ${TSK_PLUGIN_ZIP}
  COMMAND ${CMAKE_COMMAND} -E rm -f ${TSK_PLUGIN_ZIP}
  COMMAND ${CMAKE_COMMAND} -E tar cf ${TSK_PLUGIN_ZIP} --format=zip ${TSK_PLUGIN_NAME}
  WORKING_DIRECTORY ${CMAKE_BINARY_DIR}/qgis-plugin
  DEPENDS terrain_sketch_provider tsk_plugin_files tsk_translations
          ${TSK_PLUGIN_DIR}/metadata.txt ${TSK_PLUGIN_DIR}/build_info.py
          $<TARGET_FILE:terrain_sketch_provider>
          # the sources the targets copy: a changed style or shim repacks the zip too
          ${TSK_STYLE_FILES} ${TSK_LAYOUT_FILES} ${CMAKE_CURRENT_SOURCE_DIR}/python/__init__.py
          ${TSK_QM_FILES}
  COMMENT "Packing ${TSK_PACKAGE_NAME}.zip"
  VERBATIM)
add_custom_target(plugin-zip ALL DEPENDS ${TSK_PLUGIN_ZIP})
