# Debian package of the plugin: `cpack --config build/CPackConfig.cmake` (or `cmake --build build
# --target package`) writes yade-rbsm_<version>-1_amd64.deb holding exactly what `cmake --install`
# installs (the plugin in YADE's plugin directory, the Python package and the tessellation module
# where Debian's python3 finds them). Install it with `apt-get install ./yade-rbsm_*.deb`.
set(RBSM_VERSION 0.1.0 CACHE STRING "Version of the yade-rbsm Debian package")

# Debian wants a copyright file with every package; cmake --install puts it there too.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION /usr/share/doc/yade-rbsm RENAME copyright)

# What a collaborator starts from: the README, the examples the manual teaches, and the manual itself (HTML,
# built by scripts/build_docs.sh; refused with that advice when it is not built, never left out silently).
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION /usr/share/doc/yade-rbsm)
install(FILES ${PROJECT_SOURCE_DIR}/scripts/first_scene.py ${PROJECT_SOURCE_DIR}/scripts/tutorial_jointed_slope.py
              ${PROJECT_SOURCE_DIR}/scripts/tutorial_soil_slope.py ${PROJECT_SOURCE_DIR}/scripts/tutorial_water_earthquake.py
              ${PROJECT_SOURCE_DIR}/scripts/landslide_slope.py ${PROJECT_SOURCE_DIR}/scripts/mixed_scene_demo.py
              ${PROJECT_SOURCE_DIR}/scripts/distributed_bricks.py
        DESTINATION /usr/share/doc/yade-rbsm/examples)
install(CODE "if(NOT EXISTS \"${PROJECT_BINARY_DIR}/docs/html/index.html\")
  message(FATAL_ERROR \"yade-rbsm: the manual is not built (${PROJECT_BINARY_DIR}/docs/html): run scripts/build_docs.sh first\")
endif()")
install(DIRECTORY ${PROJECT_BINARY_DIR}/docs/html DESTINATION /usr/share/doc/yade-rbsm PATTERN .buildinfo EXCLUDE)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME yade-rbsm)
set(CPACK_PACKAGE_VERSION ${RBSM_VERSION})
set(CPACK_PACKAGE_VENDOR "yade-rbsm developers")
set(CPACK_PACKAGE_CONTACT "yade-rbsm developers <yade-rbsm@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "2D Rigid-Bodies-Spring Model (RBSM) plugin for YADE")
set(CPACK_PACKAGE_DESCRIPTION "Rigid convex polygon blocks (Polygon2D) joined by normal and shear
springs with a Mohr-Coulomb joint law, for slope stability and landslide runs in Debian's YADE
2023.02a (double precision). The classes appear in every yade script; the Python package
yade_rbsm adds block builders, engines, factor of safety, VTK and CSV/DXF input and output.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The plugin is built against the layout of Debian's YADE 2023.02a binary (yade-interface/): any
# other upstream version of yade may differ, so the dependency is pinned to that version.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "yade (>= 2023.02a), yade (<< 2023.02b), libyade (>= 2023.02a), libyade (<< 2023.02b), python3 (>= 3.11), python3 (<< 3.12), python3-scipy")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-ezdxf, python3-vtk9, python3-mpi4py, openmpi-bin") # DXF, VTK, yade.mpy
# The runtime libraries (boost, python, gmp ...) from dpkg-shlibdeps; libyade.so lives in YADE's
# private directory and has no shlibs entry (dpkg-shlibdeps warns), hence the explicit pin above.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${YADE_LIB_DIR}")
set(CPACK_STRIP_FILES ON)
# Byte-compile on install and clean on removal (what dh_python3 adds), so that removal leaves no
# __pycache__ behind in dist-packages.
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
  "${PROJECT_SOURCE_DIR}/cmake/deb/postinst;${PROJECT_SOURCE_DIR}/cmake/deb/prerm")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_PACKAGE_CHECKSUM SHA256)
include(CPack)
