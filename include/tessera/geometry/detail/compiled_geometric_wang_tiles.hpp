// tessera/geometry/detail/compiled_geometric_wang_tiles.hpp: build_geometric_wang_tiles, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../geometric_wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(E)                                                                         \
  TESSERA_COMPILED_EXTERN template result<geometric_tile_set> build_geometric_wang_tiles<E>( \
      const quilt_exemplar&, const geometric_wang_options&, E&&);
TESSERA_COMPILED_FOR_EACH_EXECUTOR(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
