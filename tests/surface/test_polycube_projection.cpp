#include <catch2/catch.hpp>

#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_projection.hpp>

#include "shapes.hpp"

using namespace tessera;

TEST_CASE("polycube projection: base -> polycube -> base round trips to 1e-9") {
  for (const auto& m : {shapes::sphere(6), shapes::torus(2, 0.7, 32, 12), shapes::voxel_surface(shapes::genus2(), 2)}) {
    polycube_options o;
    o.tiles_across = 6;
    auto map = build_polycube_map(m, o);
    REQUIRE(map);
    const polycube_projector pj(*map);
    double worst = 0;
    for (index_t f = 0; f < m.num_faces(); f += 3)
      for (const vec3 b : {vec3{1.0 / 3, 1.0 / 3, 1.0 / 3}, vec3{0.7, 0.2, 0.1}, vec3{0.05, 0.05, 0.9}}) {
        const auto& fv = m.faces[static_cast<std::size_t>(f)];
        const vec3 p = b.x * m.position(fv[0]) + b.y * m.position(fv[1]) + b.z * m.position(fv[2]);
        auto fwd = pj.forward(f, b);
        REQUIRE(fwd);
        REQUIRE(fwd->quad >= 0);
        auto back = pj.inverse(fwd->quad, fwd->u, fwd->v);
        REQUIRE(back);
        worst = std::max(worst, distance(back->position, p));
      }
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("polycube projection: every quad corner maps back onto the base surface") {
  auto map = build_polycube_map(shapes::voxel_surface(shapes::l_shape(), 2), polycube_options{0.5});
  REQUIRE(map);
  const polycube_projector pj(*map);
  for (index_t q = 0; q < static_cast<index_t>(map->layout.quads.size()); ++q) {
    auto c = pj.inverse(q, 1, 1);
    REQUIRE(c);
    CHECK(c->face >= 0);
  }
  CHECK(pj.forward(-1, {1, 0, 0}).error().code() == status_code::out_of_range);
  CHECK(pj.inverse(static_cast<index_t>(map->layout.quads.size()), 0, 0).error().code() == status_code::out_of_range);
  CHECK(pj.inverse(0, 1.5, 0).error().code() == status_code::invalid_argument);
}
