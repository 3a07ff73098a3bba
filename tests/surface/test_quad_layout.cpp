#include <catch2/catch.hpp>

#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/quad_layout.hpp>

#include "shapes.hpp"

using namespace tessera;

TEST_CASE("quad layout: grid edges are sorted by axis and origin, ids agree across quads") {
  auto map = build_polycube_map(shapes::voxel_surface(shapes::l_shape(), 2), polycube_options{0.5});
  REQUIRE(map);
  const auto& L = map->layout;
  CHECK(L.edges.size() == 2 * L.quads.size());  // a closed quad surface: 4 sides per quad, 2 quads per edge
  for (std::size_t e = 1; e < L.edges.size(); ++e)
    CHECK(std::pair(L.edges[e - 1].axis, L.edges[e - 1].origin) < std::pair(L.edges[e].axis, L.edges[e].origin));
  for (std::size_t e = 0; e < L.edges.size(); ++e)
    for (index_t q : L.edges[e].quads) {
      const auto& Q = L.quads[static_cast<std::size_t>(q)];
      CHECK(std::count(Q.edges.begin(), Q.edges.end(), static_cast<index_t>(e)) == 1);
    }
}

TEST_CASE("quad layout: as a triangle mesh, and the size limit") {
  auto map = build_polycube_map(shapes::voxel_surface(shapes::cube(), 2), polycube_options{0.5});
  REQUIRE(map);
  const tri_mesh m = quad_layout_mesh(*map);
  CHECK(m.num_faces() == 2 * static_cast<index_t>(map->layout.quads.size()));
  double area = 0;
  for (index_t f = 0; f < m.num_faces(); ++f) area += face_area(m, f);
  CHECK(area == Approx(6.0));
  auto small = build_quad_layout(*map, 10);
  CHECK(small.error().code() == status_code::size_overflow);
}
