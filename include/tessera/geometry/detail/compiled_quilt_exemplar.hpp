// tessera/geometry/detail/compiled_quilt_exemplar.hpp: prepare_quilt_exemplar of a tri_mesh, compiled once.
// Included at the end of its public header when TESSERA_COMPILED is defined (tessera::compiled;
// core/compiled.hpp, docs/compile_once.md); src/compiled/ turns the same lines into definitions.
#pragma once

#include "../../core/compiled.hpp"
#include "../quilt_exemplar.hpp"

TESSERA_NAMESPACE_BEGIN
TESSERA_COMPILED_EXTERN template result<quilt_exemplar> prepare_quilt_exemplar<tri_mesh>(const tri_mesh&,
                                                                                         const quilt_exemplar_options&);
TESSERA_NAMESPACE_END
