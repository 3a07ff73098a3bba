// tessera/terrain/detail/compiled_render_terrain_frame.hpp: render_terrain_frame into image_buffer, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../render_terrain_frame.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(T, C, E)                                                                          \
  TESSERA_COMPILED_EXTERN template status render_terrain_frame<T, C, image_buffer<T, C>, E>(        \
      const terrain_mesh&, const screen_projection&, const scale_field&, const triangle_synthesis&, \
      const exemplar_pyramid<T, C>&, image_buffer<T, C>&, const render_terrain_options&, E&&);
TESSERA_COMPILED_FOR_EACH_FORMAT(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
