# Builds and runs a consumer project (tests/consumer/<MODE>) against this tessera build.
#   cmake -DMODE=find_package|build_tree|add_subdirectory -DSOURCE_DIR=<tessera> -DBINARY_DIR=<tessera build>
#         -DWORK_DIR=<scratch> -DGENERATOR=<gen> -DCXX=<compiler> [-DLAUNCHER=<ccache>] -P run_consumer.cmake
# find_package: installs the tessera build tree into WORK_DIR/prefix and points CMAKE_PREFIX_PATH
# there. build_tree: the find_package project against the build tree's export (tessera_DIR =
# BINARY_DIR), nothing installed. compiled: installs, builds tests/consumer/compiled (COMPONENTS compiled,
# tessera::compiled) and checks its digests equal those of the same program built header-only. add_subdirectory: the consumer adds SOURCE_DIR itself.
cmake_minimum_required(VERSION 3.21)
foreach(var MODE SOURCE_DIR BINARY_DIR WORK_DIR GENERATOR CXX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/out")

function(run)
  string(REPLACE ";" " " _shown "${ARGN}")
  message(STATUS "consumer: ${_shown}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "consumer (${MODE}): command failed (${_rc}): ${_shown}")
  endif()
endfunction()

set(_args -G "${GENERATOR}" -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release -Wno-dev)
if(LAUNCHER)
  list(APPEND _args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
if(MODE STREQUAL "find_package" OR MODE STREQUAL "compiled")
  run(${CMAKE_COMMAND} --install "${BINARY_DIR}" --prefix "${WORK_DIR}/prefix")
  list(APPEND _args -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
  if(MODE STREQUAL "compiled")
    # -O1: the header-only build of the engine TU is the expensive part (~0.6x the CPU of -O3); the
    # digests do not depend on it, and tessera::compiled itself is built at -O2
    list(APPEND _args "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG")
  endif()
elseif(MODE STREQUAL "build_tree")
  list(APPEND _args -Dtessera_DIR=${BINARY_DIR} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
elseif(MODE STREQUAL "add_subdirectory")
  list(APPEND _args -DTESSERA_SOURCE_DIR=${SOURCE_DIR})
else()
  message(FATAL_ERROR "run_consumer.cmake: unknown MODE '${MODE}'")
endif()

set(_project ${MODE})
if(MODE STREQUAL "build_tree")
  set(_project find_package)
endif()
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/consumer/${_project}" -B "${WORK_DIR}/build" ${_args})
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
if(MODE STREQUAL "compiled")
  foreach(_exe consumer consumer_header_only)
    execute_process(COMMAND "${WORK_DIR}/build/${_exe}" RESULT_VARIABLE _rc OUTPUT_VARIABLE _out_${_exe})
    if(NOT _rc EQUAL 0)
      message(FATAL_ERROR "consumer (compiled): ${_exe} failed (${_rc}): ${_out_${_exe}}")
    endif()
  endforeach()
  message(STATUS "consumer (compiled):\n${_out_consumer}")
  if(NOT _out_consumer STREQUAL _out_consumer_header_only OR _out_consumer STREQUAL "")
    message(FATAL_ERROR "consumer (compiled): digests differ from the header-only build:\n${_out_consumer}\n"
                        "header-only:\n${_out_consumer_header_only}")
  endif()
  return()
endif()
run("${WORK_DIR}/build/consumer" "${WORK_DIR}/out")
if(EXISTS "${WORK_DIR}/build/consumer_openmesh")
  run("${WORK_DIR}/build/consumer_openmesh")
endif()
