# Fails unless FILE exists and its text matches REGEX:
#   cmake -DFILE=<path> -DREGEX=<regex> -P check_file_matches.cmake
cmake_minimum_required(VERSION 3.21)
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "${FILE} does not exist")
endif()
file(READ "${FILE}" _text)
if(NOT _text MATCHES "${REGEX}")
  message(FATAL_ERROR "${FILE} does not match ${REGEX}:\n${_text}")
endif()
