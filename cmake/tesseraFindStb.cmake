# Finds Debian's stb (libstb-dev: headers in <include>/stb, implementations compiled into libstb)
# and defines the imported target tessera::stb. Sets TESSERA_STB_FOUND.
if(TARGET tessera::stb)
  set(TESSERA_STB_FOUND ON)
  return()
endif()
find_path(TESSERA_STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb)
find_library(TESSERA_STB_LIBRARY NAMES stb)
if(TESSERA_STB_INCLUDE_DIR AND TESSERA_STB_LIBRARY)
  add_library(tessera::stb UNKNOWN IMPORTED)
  set_target_properties(tessera::stb PROPERTIES
    IMPORTED_LOCATION "${TESSERA_STB_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${TESSERA_STB_INCLUDE_DIR}")
  set(TESSERA_STB_FOUND ON)
else()
  set(TESSERA_STB_FOUND OFF)
  message(STATUS "tessera: stb not found (Debian: libstb-dev); tessera::io is not available")
endif()
