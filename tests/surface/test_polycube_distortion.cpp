#include <catch2/catch.hpp>

#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_distortion.hpp>

#include "shapes.hpp"

using namespace tessera;

TEST_CASE("polycube distortion: none on a voxel solid, bounded on a sphere") {
  auto cube = build_polycube_map(shapes::voxel_surface(shapes::l_shape(), 2), polycube_options{0.5});
  REQUIRE(cube);
  const auto d = polycube_distortion(*cube);
  CHECK(d.area_distortion == Approx(1).margin(1e-9));
  CHECK(d.angle_distortion == Approx(1).margin(1e-9));
  polycube_options o;
  o.tiles_across = 6;
  auto s = build_polycube_map(shapes::sphere(8), o);
  REQUIRE(s);
  const auto ds = polycube_distortion(*s);
  CHECK(ds.area_distortion > 1);
  CHECK(ds.area_distortion < 2);
  CHECK(ds.angle_distortion > 1);
  CHECK(ds.angle_distortion < 2);
  CHECK(ds.area.size() == s->base.faces.size());
}
