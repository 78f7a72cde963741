# rbsm_add_pytest(<name> <test file> [ENVIRONMENT VAR=value ...] [LABELS ...] [TIMEOUT s] [RUN_SERIAL])
# Registers a pytest file as one ctest test, run by Debian's /usr/bin/python3 (the interpreter
# YADE's Python package and pytest are installed for). ctest stays the single entry point.
set(RBSM_PYTHON /usr/bin/python3 CACHE FILEPATH "Debian's python3 (runs the pytest suites)")

function(rbsm_add_pytest name file)
  cmake_parse_arguments(ARG "RUN_SERIAL" "TIMEOUT" "ENVIRONMENT;LABELS" ${ARGN})
  get_filename_component(abs "${file}" ABSOLUTE)
  get_filename_component(dir "${abs}" DIRECTORY)
  add_test(NAME ${name}
    COMMAND ${RBSM_PYTHON} -m pytest -q -rfEs -p no:cacheprovider "${abs}"
    WORKING_DIRECTORY "${dir}")
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  set_tests_properties(${name} PROPERTIES
    TIMEOUT ${ARG_TIMEOUT}
    LABELS "${ARG_LABELS}"
    ENVIRONMENT "PYTHONDONTWRITEBYTECODE=1;RBSM_SOURCE_DIR=${PROJECT_SOURCE_DIR};RBSM_BUILD_DIR=${PROJECT_BINARY_DIR};${ARG_ENVIRONMENT}")
  if(ARG_RUN_SERIAL)
    set_tests_properties(${name} PROPERTIES RUN_SERIAL TRUE)
  endif()
endfunction()

# rbsm_add_pytest_dir(<prefix> [LABELS ...] [TIMEOUT s] [NEEDS_YADE] [RUN_SERIAL])
# Registers every test_*.py of the calling directory as the ctest test <prefix>.<name>
# (test_<name>.py); with NEEDS_YADE the tests get RBSM_LAUNCHER (the build's yade-rbsm); with
# RUN_SERIAL ctest runs none of them next to another test (tests that start several processes).
function(rbsm_add_pytest_dir prefix)
  cmake_parse_arguments(ARG "NEEDS_YADE;RUN_SERIAL" "TIMEOUT" "LABELS" ${ARGN})
  if(NOT ARG_LABELS)
    set(ARG_LABELS ${prefix})
  endif()
  set(env "")
  if(ARG_NEEDS_YADE)
    set(env ENVIRONMENT "RBSM_LAUNCHER=${RBSM_LAUNCHER}")
  endif()
  set(timeout "")
  if(ARG_TIMEOUT)
    set(timeout TIMEOUT ${ARG_TIMEOUT})
  endif()
  set(serial "")
  if(ARG_RUN_SERIAL)
    set(serial RUN_SERIAL)
  endif()
  file(GLOB files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/test_*.py)
  foreach(f ${files})
    get_filename_component(n ${f} NAME_WE)
    string(REGEX REPLACE "^test_" "" n ${n})
    rbsm_add_pytest(${prefix}.${n} ${f} LABELS "${ARG_LABELS}" ${timeout} ${env} ${serial})
  endforeach()
endfunction()
