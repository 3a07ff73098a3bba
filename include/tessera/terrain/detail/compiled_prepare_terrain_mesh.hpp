// tessera/terrain/detail/compiled_prepare_terrain_mesh.hpp: prepare_terrain_mesh of a tri_mesh, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../prepare_terrain_mesh.hpp"

TESSERA_NAMESPACE_BEGIN
TESSERA_COMPILED_EXTERN template result<terrain_mesh> prepare_terrain_mesh<tri_mesh>(const tri_mesh&, std::string_view);
TESSERA_NAMESPACE_END
