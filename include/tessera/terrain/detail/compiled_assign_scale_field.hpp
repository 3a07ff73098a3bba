// tessera/terrain/detail/compiled_assign_scale_field.hpp: assign_scale_field, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../assign_scale_field.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(E)                                                                                           \
  TESSERA_COMPILED_EXTERN template status assign_scale_field<E>(const terrain_mesh&, const screen_projection&, \
                                                                const scale_field_options&, scale_field&, E&&);
TESSERA_COMPILED_FOR_EACH_EXECUTOR(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
