# The house style: every C++ file of the repository is formatted as the repository's .clang-format
# says (clang-format 14, Debian 12's). Skipped (exit code 77) when clang-format 14 is not installed:
# other versions format some constructs differently.
#   cmake -DROOT=<repo> -DCLANG_FORMAT=<clang-format> -P format.cmake
cmake_minimum_required(VERSION 3.21)
if(NOT CLANG_FORMAT)
  message("clang-format 14 not found: skipped (apt-get install clang-format-14)")
  cmake_language(EXIT 77)
endif()
execute_process(COMMAND ${CLANG_FORMAT} --version OUTPUT_VARIABLE _version)
if(NOT _version MATCHES "version 14\\.")
  message("${CLANG_FORMAT} is not clang-format 14 (${_version}): skipped")
  cmake_language(EXIT 77)
endif()
file(GLOB_RECURSE _files ${ROOT}/include/*.hpp ${ROOT}/examples/*.cpp ${ROOT}/examples/*.hpp ${ROOT}/tests/*.cpp
     ${ROOT}/tests/*.hpp ${ROOT}/benchmarks/*.cpp ${ROOT}/benchmarks/*.hpp ${ROOT}/src/*.cpp)
list(FILTER _files EXCLUDE REGEX "/tests/structural/compile_fail/")
execute_process(COMMAND ${CLANG_FORMAT} --dry-run -Werror --style=file ${_files} RESULT_VARIABLE _rc
                ERROR_VARIABLE _err WORKING_DIRECTORY ${ROOT})
if(NOT _rc EQUAL 0)
  string(REGEX MATCHALL "[^\n]*error: code should be clang-formatted[^\n]*" _where "${_err}")
  list(REMOVE_DUPLICATES _where)
  list(JOIN _where "\n  " _where)
  message(FATAL_ERROR "not formatted as .clang-format says (run clang-format-14 -i on them):\n  ${_where}")
endif()
list(LENGTH _files _n)
message("${_n} files formatted as .clang-format says")
