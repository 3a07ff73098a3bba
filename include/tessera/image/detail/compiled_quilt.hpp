// tessera/image/detail/compiled_quilt.hpp: quilt from and into image_buffer, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../quilt.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(T, C, E)                                                                  \
  TESSERA_COMPILED_EXTERN template status quilt<image_buffer<T, C>, image_buffer<T, C>, E>( \
      const image_buffer<T, C>&, image_buffer<T, C>&, const quilt_options&, E&&);
TESSERA_COMPILED_FOR_EACH_FORMAT(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
