# Checks that no Catch2 test name contains a semicolon: catch_discover_tests splits such a name in
# two, ctest then runs a filter that matches nothing and reports a pass, so the test never runs.
#   cmake -DTESTS_DIR=<repo>/tests -P test_names.cmake
file(GLOB_RECURSE _sources ${TESTS_DIR}/*.cpp)
set(_bad "")
foreach(_f IN LISTS _sources)
  file(STRINGS ${_f} _lines REGEX "TEST_CASE\\(\"[^\"]*;")
  if(_lines)
    list(APPEND _bad "${_f}")
  endif()
endforeach()
if(_bad)
  message(FATAL_ERROR "test names with a semicolon (never run by ctest): ${_bad}")
endif()
message("no test name contains a semicolon")
