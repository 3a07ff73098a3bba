// tessera/terrain/detail/compiled_make_terrain.hpp: make_terrain, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../make_terrain.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(E) TESSERA_COMPILED_EXTERN template result<tri_mesh> make_terrain<E>(const terrain_options&, E&&);
TESSERA_COMPILED_FOR_EACH_EXECUTOR(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
