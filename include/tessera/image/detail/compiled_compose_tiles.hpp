// tessera/image/detail/compiled_compose_tiles.hpp: compose_tiles from the infinite hash colouring, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../../tiling/hash_coloring.hpp"
#include "../compose_tiles.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(T, C, E)                                                                                 \
  TESSERA_COMPILED_EXTERN template status compose_tiles<T, C, hash_coloring, image_buffer<T, C>, E>(       \
      const wang_tile_set<T, C>&, const hash_coloring&, image_buffer<T, C>&, const compose_options&, E&&); \
  TESSERA_COMPILED_EXTERN template status compose_tiles<T, C, hash_coloring, image_view<T, C>, E>(         \
      const wang_tile_set<T, C>&, const hash_coloring&, image_view<T, C>&, const compose_options&, E&&);
TESSERA_COMPILED_FOR_EACH_FORMAT(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
