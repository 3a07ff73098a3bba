# Compiles one file that must NOT compile and checks that the compiler's message contains the regex
# given on the file's "// expect: REGEX" line (so explain_*() and deleted overloads say what they
# promise). -DCXX=<compiler> -DFILE=<source> -DFLAGS=<|-separated flags> -P compile_fail.cmake
cmake_minimum_required(VERSION 3.21)
string(REPLACE "|" ";" FLAGS "${FLAGS}")
file(STRINGS "${FILE}" _expect REGEX "^// expect: " LIMIT_COUNT 1)
string(REGEX REPLACE "^// expect: " "" _expect "${_expect}")
if(_expect STREQUAL "")
  message(FATAL_ERROR "${FILE}: no '// expect: REGEX' line")
endif()
execute_process(COMMAND ${CXX} ${FLAGS} -fsyntax-only "${FILE}" RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
                ERROR_VARIABLE _out)
if(_rc EQUAL 0)
  message(FATAL_ERROR "${FILE} compiled, but it must fail with: ${_expect}")
endif()
if(NOT _out MATCHES "${_expect}")
  message(FATAL_ERROR "${FILE} failed to compile as expected, but without '${_expect}':\n${_out}")
endif()
message(STATUS "${FILE}: fails to compile with '${_expect}' as expected")
