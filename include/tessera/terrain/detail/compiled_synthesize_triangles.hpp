// tessera/terrain/detail/compiled_synthesize_triangles.hpp: synthesize_triangles, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../synthesize_triangles.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(E)                                                                       \
  TESSERA_COMPILED_EXTERN template status synthesize_triangles<E>(                         \
      const terrain_mesh&, const screen_projection&, const scale_field&, index_t, index_t, \
      const triangle_synthesis_options&, triangle_synthesis&, E&&);
TESSERA_COMPILED_FOR_EACH_EXECUTOR(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
