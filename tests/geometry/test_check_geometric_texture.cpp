#include <tessera/geometry/check_geometric_texture.hpp>

#include <tessera/geometry/detail/mesh_clip.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

TEST_CASE("texture checks count open, non-manifold and intersecting geometry", "[checks]") {
  tri_mesh a;
  detail::add_torus(a, {1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.1, 12, 6);
  auto r = check_geometric_texture(a);
  REQUIRE(r->open_edges_inside == 0);
  REQUIRE(r->nonmanifold_edges == 0);
  REQUIRE(r->intersecting_pairs == 0);
  REQUIRE(r->elements == 1);
  // a second ring through the first: intersecting pairs between distinct elements
  tri_mesh b = a;
  detail::add_torus(b, {1.3, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.1, 12, 6);
  r = check_geometric_texture(b);
  REQUIRE(r->elements == 2);
  REQUIRE(r->intersecting_pairs > 0);
  // open edges: inside the texture they count, on the outer border they do not
  auto s = detail::split_mesh_by_plane(a, 0, 1.0, 1e-12);
  detail::compact_vertices(s.above);
  r = check_geometric_texture(s.above);
  REQUIRE(r->open_edges_inside > 0);
  r = check_geometric_texture(s.above, {1.0, 0, 5, 5});
  REQUIRE(r->open_edges_inside == 0);
  // non-manifold
  tri_mesh nm = a;
  nm.add_face(nm.faces[0][0], nm.faces[0][1], nm.add_vertex({5, 5, 5}));
  REQUIRE(check_geometric_texture(nm)->nonmanifold_edges == 1);
  tri_mesh bad = a;
  bad.positions[0].z = std::nan("");
  REQUIRE_FALSE(check_geometric_texture(bad).ok());
}
