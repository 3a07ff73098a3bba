// tessera/image/detail/compiled_patch_model.hpp: build_patch_model, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../patch_model.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(T, C, E)                                                                             \
  TESSERA_COMPILED_EXTERN template result<patch_model<T, C>> build_patch_model<image_buffer<T, C>, E>( \
      const image_buffer<T, C>&, const patch_model_options&, E&&);
TESSERA_COMPILED_FOR_EACH_FORMAT(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
