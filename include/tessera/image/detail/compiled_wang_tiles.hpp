// tessera/image/detail/compiled_wang_tiles.hpp: build_wang_tiles, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(T, C, E)                                                                              \
  TESSERA_COMPILED_EXTERN template result<wang_tile_set<T, C>> build_wang_tiles<image_buffer<T, C>, E>( \
      const image_buffer<T, C>&, const wang_tile_options&, E&&);
TESSERA_COMPILED_FOR_EACH_FORMAT(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
