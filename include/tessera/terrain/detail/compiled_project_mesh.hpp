// tessera/terrain/detail/compiled_project_mesh.hpp: project_mesh, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../project_mesh.hpp"

TESSERA_NAMESPACE_BEGIN
#define TESSERA_X(E)                                                                                  \
  TESSERA_COMPILED_EXTERN template status project_mesh<E>(const terrain_mesh&, const terrain_camera&, \
                                                          screen_projection&, const project_options&, E&&);
TESSERA_COMPILED_FOR_EACH_EXECUTOR(TESSERA_X)
#undef TESSERA_X
TESSERA_NAMESPACE_END
