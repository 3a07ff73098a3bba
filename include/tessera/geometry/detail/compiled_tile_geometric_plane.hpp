// tessera/geometry/detail/compiled_tile_geometric_plane.hpp: tile_geometric_plane from a hash colouring window, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../../tiling/hash_coloring.hpp"
#include "../tile_geometric_plane.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(E)                                                                               \
  TESSERA_COMPILED_EXTERN template result<tri_mesh> tile_geometric_plane<hash_coloring_window, E>( \
      const geometric_tile_set&, const hash_coloring_window&, index_t, index_t, E&&);
TESSERA_COMPILED_FOR_EACH_EXECUTOR(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
