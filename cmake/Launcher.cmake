# build/yade-rbsm: Debian's yade with this build's plugin loaded, through an overlay prefix in the
# build directory (see cmake/yade-rbsm.in). No root needed. The overlay is refreshed after every
# link of the plugin (target rbsm_overlay, part of ALL) and again by every run of the launcher.
find_program(YADE_EXECUTABLE NAMES yade PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT YADE_EXECUTABLE)
  set(YADE_EXECUTABLE /usr/bin/yade)
endif()

set(RBSM_PLUGIN_FILE "${PROJECT_BINARY_DIR}/pkg/rbsm/libpkg_rbsm.so")
set(RBSM_OVERLAY_PREFIX "${PROJECT_BINARY_DIR}/yade-prefix")
set(RBSM_LAUNCHER "${PROJECT_BINARY_DIR}/yade-rbsm")

configure_file(${PROJECT_SOURCE_DIR}/cmake/yade-rbsm.in ${RBSM_LAUNCHER} @ONLY
  FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

add_custom_target(rbsm_overlay ALL
  COMMAND ${CMAKE_COMMAND} -E env YADE_RBSM_REFRESH_ONLY=1 ${RBSM_LAUNCHER}
  COMMENT "Refreshing the YADE overlay prefix ${RBSM_OVERLAY_PREFIX}"
  VERBATIM)
add_dependencies(rbsm_overlay pkg_rbsm)

# cmake --install: the plugin into YADE's plugin directory, the Python package where Debian's
# python3 finds it, so a plain `yade script.py` sees the classes and can `import yade_rbsm`.
set(RBSM_PYTHON_INSTALL_DIR "/usr/lib/python3/dist-packages" CACHE PATH
  "Where `cmake --install` puts the Python package yade_rbsm (a directory on Debian python3's sys.path)")
install(TARGETS pkg_rbsm LIBRARY DESTINATION "${YADE_LIB_DIR}")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/py/yade_rbsm DESTINATION "${RBSM_PYTHON_INSTALL_DIR}"
  PATTERN "__pycache__" EXCLUDE PATTERN "*.pyc" EXCLUDE)
