#include <catch2/catch.hpp>

#include <tessera/surface/build_polycube_map.hpp>

#include "shapes.hpp"

using namespace tessera;

TEST_CASE("polycube: voxel solids") {
  for (auto [name, vox] : {std::pair{"cube", shapes::cube()}, {"l", shapes::l_shape()}, {"ring", shapes::ring()},
                           {"genus2", shapes::genus2()}}) {
    INFO(name);
    const auto m = shapes::voxel_surface(vox, 3);
    polycube_options o;
    o.tile_size = 1.0 / 3;
    auto r = build_polycube_map(m, o);
    INFO(r.error().to_string());
    REQUIRE(r);
    CHECK(r->layout.quads.size() > 0);
  }
}

TEST_CASE("polycube: smooth shapes") {
  polycube_options o;
  o.tiles_across = 6;
  auto s = build_polycube_map(shapes::sphere(8), o);
  INFO(s.error().to_string());
  CHECK(s);
  auto t = build_polycube_map(shapes::torus(2, 0.7, 48, 16), o);
  INFO(t.error().to_string());
  CHECK(t);
}
