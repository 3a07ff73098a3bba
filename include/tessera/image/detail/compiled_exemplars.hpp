// tessera/image/detail/compiled_exemplars.hpp: make_exemplar, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../exemplars.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(T, C, E)                                                                       \
  TESSERA_COMPILED_EXTERN template result<image_buffer<T, C>> make_exemplar<T, C>(exemplar_kind, \
                                                                                  const exemplar_options&);
// the executor plays no part: the serial list only
TESSERA_COMPILED_FORMATS_WITH(TESSERA_X, void)
#undef TESSERA_X
TESSERA_NAMESPACE_END
