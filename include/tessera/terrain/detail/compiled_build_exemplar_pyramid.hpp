// tessera/terrain/detail/compiled_build_exemplar_pyramid.hpp: build_exemplar_pyramid, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../build_exemplar_pyramid.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(T, C, E)                                                                                       \
  TESSERA_COMPILED_EXTERN template result<exemplar_pyramid<T, C>> build_exemplar_pyramid<image_buffer<T, C>, E>( \
      const image_buffer<T, C>&, const exemplar_pyramid_options&, E&&);
TESSERA_COMPILED_FOR_EACH_FORMAT(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
