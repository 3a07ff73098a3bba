# Keeps the code in README.md and docs/*.md identical to compiled example code, so it cannot rot:
# every ```cpp block there must be marked (the check fails on an unmarked one).
#
# In an example (examples/*.cpp) or a docs test (tests/<family>/test_docs_*.cpp), mark a region:
#     // [snippet:NAME]
#     ...code...
#     // [/snippet]
# In a markdown file, put the marker line right before a ```cpp block:
#     <!-- snippet:NAME -->
#     ```cpp
#     ...the same code...
#     ```
# cmake -DROOT=<repo> -P snippets.cmake            checks (fails naming the first difference)
# cmake -DROOT=<repo> -DUPDATE=ON -P snippets.cmake  rewrites the markdown blocks from the examples
cmake_minimum_required(VERSION 3.21)
if(NOT ROOT)
  message(FATAL_ERROR "snippets.cmake: -DROOT=<repository> is required")
endif()

# --- collect snippets from the examples -----------------------------------------------------------
set(_names "")
# ... or in a docs test (tests/<family>/test_docs_*.cpp), compiled with that family's tests.
file(GLOB _sources ${ROOT}/examples/*.cpp ${ROOT}/examples/*/*.cpp ${ROOT}/tests/*/test_docs_*.cpp)
foreach(_src IN LISTS _sources)
  file(READ "${_src}" _rest)
  while(TRUE)
    string(FIND "${_rest}" "// [snippet:" _at)
    if(_at EQUAL -1)
      break()
    endif()
    string(SUBSTRING "${_rest}" ${_at} -1 _rest)
    string(FIND "${_rest}" "]" _close)
    math(EXPR _name_len "${_close} - 12")
    string(SUBSTRING "${_rest}" 12 ${_name_len} _name)
    string(FIND "${_rest}" "\n" _eol)
    math(EXPR _eol "${_eol} + 1")
    string(SUBSTRING "${_rest}" ${_eol} -1 _rest)
    string(FIND "${_rest}" "// [/snippet]" _end)
    if(_end EQUAL -1)
      message(FATAL_ERROR "${_src}: snippet '${_name}' has no '// [/snippet]' line")
    endif()
    string(SUBSTRING "${_rest}" 0 ${_end} _body)
    string(REGEX REPLACE "[ \t]+$" "" _body "${_body}")  # drop the end marker's indentation
    # Dedent: remove the indentation all non-empty lines share (snippets cut from inside a function).
    set(_body "\n${_body}")
    while(_body MATCHES "\n " AND NOT _body MATCHES "\n[^ \n]")
      string(REPLACE "\n " "\n" _body "${_body}")
    endwhile()
    string(SUBSTRING "${_body}" 1 -1 _body)
    if(DEFINED _snippet_${_name})
      message(FATAL_ERROR "${_src}: snippet '${_name}' is defined twice")
    endif()
    set(_snippet_${_name} "${_body}")
    set(_source_${_name} "${_src}")
    list(APPEND _names ${_name})
    string(SUBSTRING "${_rest}" ${_end} -1 _rest)
  endwhile()
endforeach()

# --- check (or update) every marked block in the markdown files ----------------------------------
set(_checked 0)
file(GLOB _docs ${ROOT}/README.md ${ROOT}/docs/*.md)
foreach(_doc IN LISTS _docs)
  # every ```cpp block carries a marker: code in the docs is compiled code
  file(STRINGS "${_doc}" _doc_lines)
  set(_prev "")
  set(_line_no 0)
  foreach(_l IN LISTS _doc_lines)
    math(EXPR _line_no "${_line_no} + 1")
    if(_l MATCHES "^ *```(cpp|c\\+\\+|cxx|C\\+\\+) *$" AND NOT _prev MATCHES "^<!-- snippet:")
      message(FATAL_ERROR "${_doc}:${_line_no}: a ```cpp block without a <!-- snippet:NAME --> marker line; "
                          "put its code in an example or a tests/<family>/test_docs_*.cpp between "
                          "// [snippet:NAME] and // [/snippet], then mark the block")
    endif()
    if(NOT _l STREQUAL "")
      set(_prev "${_l}")
    endif()
  endforeach()
  file(READ "${_doc}" _rest)
  set(_out "")
  set(_changed FALSE)
  while(TRUE)
    string(FIND "${_rest}" "<!-- snippet:" _at)
    if(_at EQUAL -1)
      string(APPEND _out "${_rest}")
      break()
    endif()
    string(SUBSTRING "${_rest}" 0 ${_at} _before)
    string(APPEND _out "${_before}")
    string(SUBSTRING "${_rest}" ${_at} -1 _rest)
    string(FIND "${_rest}" " -->" _close)
    math(EXPR _name_len "${_close} - 13")
    string(SUBSTRING "${_rest}" 13 ${_name_len} _name)
    if(NOT DEFINED _snippet_${_name})
      message(FATAL_ERROR "${_doc}: snippet '${_name}' is not defined in any example (// [snippet:${_name}])")
    endif()
    set(_head "<!-- snippet:${_name} -->\n```cpp\n")
    string(LENGTH "${_head}" _head_len)
    string(SUBSTRING "${_rest}" 0 ${_head_len} _actual_head)
    if(NOT _actual_head STREQUAL _head)
      message(FATAL_ERROR "${_doc}: the marker for '${_name}' must be followed by a line ```cpp")
    endif()
    string(SUBSTRING "${_rest}" ${_head_len} -1 _rest)
    string(FIND "${_rest}" "```" _end)
    string(SUBSTRING "${_rest}" 0 ${_end} _block)
    string(SUBSTRING "${_rest}" ${_end} -1 _rest)
    if(NOT _block STREQUAL _snippet_${_name})
      if(UPDATE)
        set(_changed TRUE)
      else()
        message(FATAL_ERROR "${_doc}: the code block of snippet '${_name}' differs from ${_source_${_name}}; "
                            "run: cmake -DROOT=. -DUPDATE=ON -P tests/structural/snippets.cmake")
      endif()
    endif()
    string(APPEND _out "${_head}${_snippet_${_name}}")
    math(EXPR _checked "${_checked} + 1")
  endwhile()
  if(_changed)
    file(WRITE "${_doc}" "${_out}")
    message(STATUS "updated ${_doc}")
  endif()
endforeach()
list(LENGTH _names _defined)
message(STATUS "snippets: ${_checked} markdown blocks match the examples (${_defined} snippets defined)")
