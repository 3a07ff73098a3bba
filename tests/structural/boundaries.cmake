# The boundary rules of docs/architecture.md that a text scan can check:
#   1. nothing outside a family includes that family's detail/ headers: only include/tessera/<family>/
#      and the family's own tests (tests/<family>/) may (examples, the CLI, benchmarks, other
#      families and other test folders use public headers only);
#   2. a detail/ header defines nothing public: every type, alias and function it declares sits in
#      `namespace detail` (a public result or option type lives in a public header);
#   3. public headers keep the compile-time `Deferred` device off their API: it appears only inside
#      `namespace detail`;
#   4. no public declaration names a detail type: a declaration starting at column 0 outside
#      `namespace detail` (a signature, an alias, a variable) does not mention `detail::` (the
#      adapters' constraints use the public concepts EigenDense and OpenMeshMesh);
#   5. the tessera command (examples/cli/) calls no `tessera::detail::`.
#   cmake -DROOT=<repo> -P boundaries.cmake
cmake_minimum_required(VERSION 3.21)  # policies: keep empty list elements (lines), IN_LIST
set(_inc ${ROOT}/include/tessera)
set(_bad "")

# --- 1. detail/ includes ------------------------------------------------------------------------------
file(GLOB_RECURSE _files ${ROOT}/include/*.hpp ${ROOT}/examples/*.cpp ${ROOT}/examples/*.hpp
     ${ROOT}/tests/*.cpp ${ROOT}/tests/*.hpp ${ROOT}/benchmarks/*.cpp ${ROOT}/benchmarks/*.hpp)
foreach(_f IN LISTS _files)
  file(STRINGS ${_f} _includes REGEX "^#include [<\"].*detail/")
  if(NOT _includes)
    continue()
  endif()
  file(RELATIVE_PATH _rel ${ROOT} ${_f})
  get_filename_component(_dir ${_f} DIRECTORY)
  foreach(_line IN LISTS _includes)
    if(_line MATCHES "^#include <tessera/(.*)>")
      set(_target ${CMAKE_MATCH_1})
    elseif(_line MATCHES "^#include \"(.*)\"")
      get_filename_component(_abs "${CMAKE_MATCH_1}" ABSOLUTE BASE_DIR ${_dir})
      string(FIND "${_abs}" "${_inc}/" _at)
      if(NOT _at EQUAL 0)
        continue()  # a test's own helper header
      endif()
      file(RELATIVE_PATH _target ${_inc} ${_abs})
    else()
      continue()
    endif()
    if(NOT _target MATCHES "^([a-z_]+)/detail/")
      if(_target MATCHES "^detail/")
        list(APPEND _bad "${_rel}: includes ${_target}: the top-level detail/ is gone; a helper lives in its family's detail/")
      endif()
      continue()
    endif()
    set(_family ${CMAKE_MATCH_1})
    if(NOT _rel MATCHES "^include/tessera/${_family}/" AND NOT _rel MATCHES "^tests/${_family}/")
      list(APPEND _bad "${_rel}: includes ${_target}, internal to ${_family}/ (use its public headers)")
    endif()
  endforeach()
endforeach()

# --- 2 to 4: what headers declare outside namespace detail ---------------------------------------------
file(GLOB_RECURSE _headers ${_inc}/*.hpp)
foreach(_h IN LISTS _headers)
  file(RELATIVE_PATH _rel ${ROOT} ${_h})
  set(_is_detail OFF)
  if(_rel MATCHES "/detail/")
    set(_is_detail ON)
  endif()
  # one list element per line: protect the semicolons first
  file(READ ${_h} _text)
  string(REPLACE ";" "<semicolon>" _text "${_text}")
  string(REPLACE "[" "<lbracket>" _text "${_text}")  # a bracket would stop the list from splitting
  string(REPLACE "]" "<rbracket>" _text "${_text}")
  string(REPLACE "\n" ";" _lines "${_text}")
  set(_depth 0)  # inside namespace detail (blocks may nest: namespace detail::raster)
  set(_n 0)
  foreach(_l IN LISTS _lines)
    math(EXPR _n "${_n} + 1")
    if(_l MATCHES "^namespace detail(::[a-z_]+)? {")
      math(EXPR _depth "${_depth} + 1")
      continue()
    elseif(_l MATCHES "^}  // namespace detail")
      math(EXPR _depth "${_depth} - 1")
      continue()
    endif()
    if(_depth GREATER 0 OR _l MATCHES "^ *//" OR _l MATCHES "^#")
      continue()
    endif()
    if(_is_detail AND _l MATCHES "^(struct|class|enum|union|using|inline|template|constexpr|concept)[ <]")
      list(APPEND _bad "${_rel}:${_n}: declared outside namespace detail in a detail/ header: ${_l}")
    endif()
    if(NOT _is_detail AND _l MATCHES "template <class Deferred")
      list(APPEND _bad "${_rel}:${_n}: the Deferred device on a public signature (keep it in namespace detail)")
    endif()
    if(NOT _is_detail AND _l MATCHES "^[A-Za-z].*detail::" AND NOT _l MATCHES "^using tessera::")
      list(APPEND _bad "${_rel}:${_n}: a public declaration names a detail type: ${_l}")
    endif()
  endforeach()
endforeach()

# --- 5. the CLI calls no detail:: ---------------------------------------------------------------------
file(GLOB _cli ${ROOT}/examples/cli/*.cpp ${ROOT}/examples/cli/*.hpp)
foreach(_f IN LISTS _cli)
  file(RELATIVE_PATH _rel ${ROOT} ${_f})
  file(STRINGS ${_f} _uses REGEX "^[^/]*detail::")
  foreach(_u IN LISTS _uses)
    if(NOT _u MATCHES "detail::")
      continue()  # the rest of a line cut at a semicolon
    endif()
    list(APPEND _bad "${_rel}: the tessera command uses tessera::detail: ${_u}")
  endforeach()
endforeach()

if(_bad)
  list(JOIN _bad "\n  " _shown)
  string(REPLACE "<semicolon>" ";" _shown "${_shown}")
  string(REPLACE "<lbracket>" "[" _shown "${_shown}")
  string(REPLACE "<rbracket>" "]" _shown "${_shown}")
  message(FATAL_ERROR "boundary rules broken (docs/architecture.md, \"What may include what\"):\n  ${_shown}")
endif()
message("boundary rules hold: detail/ includes, detail/ declarations, the Deferred device, public signatures, the CLI")
