# The Debian package (CPack): the command-line tool, its man page and, when built, the Python
# package in Debian's Python path and the QGIS plugin in QGIS's system plugin folder, for the
# Debian and QGIS it is built on.
#   cmake --build build --target package    ->  build/terrain-sketch_VERSION-qgisX.Y-PLATFORM.deb
# Its dependencies come from the libraries the binaries link (dpkg-shlibdeps).
find_program(TSK_GZIP gzip REQUIRED)
# The page's commands and options come from the command line's own tables (cli/man_page.h).
set(TSK_MAN_TEMPLATE ${PROJECT_SOURCE_DIR}/docs/man/terrain-sketch.1.in)
set(TSK_MAN_SOURCE ${CMAKE_BINARY_DIR}/terrain-sketch.1)
set(TSK_MAN_PAGE ${CMAKE_BINARY_DIR}/terrain-sketch.1.gz)
add_custom_command(OUTPUT ${TSK_MAN_SOURCE}
  COMMAND tsk-man-page ${TSK_MAN_TEMPLATE} ${TSK_MAN_SOURCE}
  DEPENDS tsk-man-page ${TSK_MAN_TEMPLATE}
  VERBATIM)
add_custom_command(OUTPUT ${TSK_MAN_PAGE}
  COMMAND ${TSK_GZIP} -9nc ${TSK_MAN_SOURCE} > ${TSK_MAN_PAGE}
  DEPENDS ${TSK_MAN_SOURCE}
  VERBATIM)
add_custom_target(tsk_man_page ALL DEPENDS ${TSK_MAN_PAGE})
install(FILES ${TSK_MAN_PAGE} DESTINATION share/man/man1)

set(TSK_DEB_FLAVOUR "")
if(TSK_BUILD_PLUGIN)
  install(DIRECTORY ${TSK_PLUGIN_DIR} DESTINATION share/qgis/python/plugins
          USE_SOURCE_PERMISSIONS)
  set(TSK_DEB_FLAVOUR "-qgis${TSK_QGIS_RELEASE}")
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME terrain-sketch)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "Terrain Sketch developers <dev@terrain-sketch.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "silhouettes of a DEM seen obliquely from above, as vector strokes")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qgis, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_VERSION "${PROJECT_VERSION}${TSK_DEB_FLAVOUR}")
set(CPACK_DEBIAN_FILE_NAME "terrain-sketch_${PROJECT_VERSION}${TSK_DEB_FLAVOUR}-${TSK_DEBIAN_RELEASE}_amd64.deb")
if(NOT CMAKE_SYSTEM_PROCESSOR STREQUAL x86_64)
  string(REPLACE "_amd64" "_${CMAKE_SYSTEM_PROCESSOR}" CPACK_DEBIAN_FILE_NAME
         "${CPACK_DEBIAN_FILE_NAME}")
endif()
set(CPACK_OUTPUT_FILE_PREFIX ${CMAKE_BINARY_DIR})
include(CPack)
