# Checks that tessera/tessera.hpp includes every public header except the optional file and adapter
# parts (io/, adapters/) and the internal detail/ folders.
#   cmake -DINCLUDE_DIR=<repo>/include -P umbrella.cmake
file(READ ${INCLUDE_DIR}/tessera/tessera.hpp _umbrella)
file(GLOB_RECURSE _headers RELATIVE ${INCLUDE_DIR}/tessera ${INCLUDE_DIR}/tessera/*.hpp)
set(_missing "")
foreach(_h IN LISTS _headers)
  if(_h MATCHES "^(io|adapters)/|/detail/|^detail/|^tessera.hpp$")
    continue()
  endif()
  string(FIND "${_umbrella}" "#include \"${_h}\"" _at)
  if(_at EQUAL -1)
    list(APPEND _missing ${_h})
  endif()
endforeach()
if(_missing)
  message(FATAL_ERROR "tessera/tessera.hpp does not include: ${_missing}")
endif()
message("tessera/tessera.hpp includes every public header")
