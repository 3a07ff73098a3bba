// Fuzz target "remesh": an OFF file that parses and passes validate_polycube_input is remeshed
// (surface/remesh_isotropic.hpp) with few, coarse rounds; a result is again a closed, manifold,
// oriented mesh of the same Euler characteristic. Hostile geometry (near-degenerate faces, huge and
// tiny coordinates, folded sheets) must give a result or a status, never a crash or a hang.
#include <string_view>

#include <tessera/core/mesh_topology.hpp>
#include <tessera/surface/remesh_isotropic.hpp>

#include "mesh_checks.hpp"

TESSERA_FUZZ_TARGET(remesh, data, size) {
  auto m = tessera::parse_off(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.off");
  if (!m.ok() || m->num_faces() > 2000 || !tessera::validate_polycube_input(*m).ok()) return 0;
  tessera::remesh_options o;
  o.edges_across = 6;
  o.iterations = 2;
  o.max_faces = 20000;
  const auto r = tessera::remesh_isotropic(*m, o);
  if (!r.ok()) {
    FUZZ_CHECK(r.error().code() != tessera::status_code::internal_error);
    return 0;
  }
  FUZZ_CHECK(tessera::validate_polycube_input(r->mesh).ok());
  auto euler = [](const tessera::tri_mesh& x) {
    return x.num_vertices() - static_cast<tessera::index_t>(tessera::mesh_edges(x).size()) + x.num_faces();
  };
  FUZZ_CHECK(euler(r->mesh) == euler(*m));
  return 0;
}
