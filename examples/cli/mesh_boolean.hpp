// The tessera command's mesh Booleans: CGAL's corefinement (adapters/cgal_boolean.hpp) when the
// command was built with it (TESSERA_WITH_CGAL and CGAL found; it is then GPL), else a status saying
// how to get it. Defined in cgal/mesh_boolean.cpp, compiled on its own with exceptions and CGAL's flags.
#pragma once

#include <string_view>

#include <tessera/core/progress.hpp>
#include <tessera/core/status.hpp>
#include <tessera/core/tri_mesh.hpp>

namespace cli {
/// True when this build of the command carries CGAL's Booleans.
bool has_mesh_boolean();
/// The Boolean `op` ("union", "difference" or "intersection") of the solids `a` and `b` bound.
tessera::result<tessera::tri_mesh> mesh_boolean(const tessera::tri_mesh& a, const tessera::tri_mesh& b,
                                                std::string_view op, const tessera::progress& progress = {});
}  // namespace cli
