# Debian's YADE 2023.02a (double precision): where it is, and the compile definitions that its
# build used where they change what the plugin sees (layouts, Eigen alignment).
# Facts measured on the binary: ../shared/docs/yade-2023.02a-binary.md (steering repo).

set(YADE_LIB_DIR "/usr/lib/x86_64-linux-gnu/yade-double" CACHE PATH "Debian's YADE plugin directory")
if(NOT EXISTS "${YADE_LIB_DIR}/libyade.so")
  message(FATAL_ERROR "Debian's yade is not installed (no ${YADE_LIB_DIR}/libyade.so): run 'sudo apt-get install yade' or scripts/setup.sh")
endif()

# Python 3.11 of Debian, which YADE's Python package imports from.
set(Python3_EXECUTABLE /usr/bin/python3)
find_package(Python3 3.11 EXACT REQUIRED COMPONENTS Interpreter Development)
find_package(Boost 1.74 REQUIRED COMPONENTS python311 serialization)
find_package(OpenMP REQUIRED)

add_library(yade_debian INTERFACE)
target_include_directories(yade_debian INTERFACE ${PROJECT_SOURCE_DIR}/yade-interface)
target_compile_definitions(yade_debian INTERFACE
  # layouts: every class declared in yade-interface/ assumes these (OpenMP ForceContainer,
  # MPI members of Scene/Body, FEM member of Shape, OpenGL renderer in Scene)
  YADE_OPENMP YADE_MPI YADE_FEM YADE_OPENGL
  YADE_REAL_BIT=64 YADE_REAL_DEC=15)
target_link_libraries(yade_debian INTERFACE
  "${YADE_LIB_DIR}/libyade.so"
  Boost::python311 Boost::serialization Python3::Python OpenMP::OpenMP_CXX)
