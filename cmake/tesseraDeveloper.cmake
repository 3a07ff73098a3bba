# Settings for tessera's own tests, examples and benchmarks (not applied to consumers).

# ccache speeds up rebuilds when it is installed.
find_program(TESSERA_CCACHE ccache)
if(TESSERA_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER "${TESSERA_CCACHE}")
endif()

add_library(tessera_dev_flags INTERFACE)
target_compile_options(tessera_dev_flags INTERFACE -Wall -Wextra -Wpedantic)
if(TESSERA_WERROR)
  target_compile_options(tessera_dev_flags INTERFACE -Werror)
endif()
if(TESSERA_SANITIZE)
  # GCC's -Wmaybe-uninitialized reports false positives in libstdc++ (std::function, <regex>) once
  # the sanitizers instrument the code; the Release build keeps the warning.
  target_compile_options(tessera_dev_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                     -fno-sanitize-recover=all
                                                     $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
  target_link_options(tessera_dev_flags INTERFACE -fsanitize=address,undefined)
endif()

# tessera_add_program(name sources... [LIBS libs...]): an executable linked to tessera with the
# developer flags.
function(tessera_add_program name)
  cmake_parse_arguments(ARG "" "" "LIBS" ${ARGN})
  add_executable(${name} ${ARG_UNPARSED_ARGUMENTS})
  target_link_libraries(${name} PRIVATE tessera::tessera tessera_dev_flags ${ARG_LIBS})
endfunction()
