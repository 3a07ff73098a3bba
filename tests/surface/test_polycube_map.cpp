#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <tessera/surface/polycube_map.hpp>

#include "shapes.hpp"

using namespace tessera;

namespace {
bool says(const status& s, const char* what) { return s.message().find(what) != std::string::npos; }
}  // namespace

TEST_CASE("polycube input: closed meshes pass") {
  CHECK(validate_polycube_input(shapes::voxel_surface(shapes::ring(), 2)));
  CHECK(validate_polycube_input(shapes::sphere(3)));
  CHECK(validate_polycube_input(shapes::torus(2, 0.5, 12, 6)));
}

TEST_CASE("polycube input: bad meshes get a status naming the problem") {
  const auto cube = shapes::voxel_surface(shapes::cube(), 2);
  auto open = cube;
  open.faces.pop_back();
  CHECK(says(validate_polycube_input(open), "not closed"));
  auto flipped = cube;
  std::swap(flipped.faces[3][0], flipped.faces[3][1]);
  CHECK(says(validate_polycube_input(flipped), "not consistently oriented"));
  auto nan = cube;
  nan.positions[2].y = std::numeric_limits<double>::quiet_NaN();
  CHECK(says(validate_polycube_input(nan), "non-finite"));
  auto degenerate = cube;
  degenerate.faces[0][1] = degenerate.faces[0][0];
  CHECK(says(validate_polycube_input(degenerate), "degenerate"));
  auto flat = cube;  // three distinct but collinear vertices: zero area
  flat.positions[flat.faces[0][2]] = (flat.positions[flat.faces[0][0]] + flat.positions[flat.faces[0][1]]) * 0.5;
  CHECK(!validate_polycube_input(flat).ok());
  auto dup = cube;  // a duplicate face: also makes its edges non-manifold or duplicated
  dup.faces.push_back(dup.faces[0]);
  CHECK(!validate_polycube_input(dup).ok());
  // two cubes sharing one edge: non-manifold edge
  auto two = shapes::voxel_surface({{0, 0, 0}, {1, 1, 0}}, 1);
  CHECK(says(validate_polycube_input(two), "not manifold"));
  // two cubes sharing one vertex: non-manifold vertex
  auto pinch = shapes::voxel_surface({{0, 0, 0}, {1, 1, 1}}, 1);
  CHECK(says(validate_polycube_input(pinch), "not manifold at vertex"));
  tri_mesh tiny;
  CHECK(says(validate_polycube_input(tiny), "at least 4 faces"));
}

TEST_CASE("polycube tile size: from tiles_across, and bad values") {
  const auto cube = shapes::voxel_surface(shapes::cube(), 2, 3.0);
  polycube_options o;
  o.tiles_across = 6;
  CHECK(*polycube_tile_size(cube, o) == Approx(0.5));
  o.tile_size = 0.25;
  CHECK(*polycube_tile_size(cube, o) == 0.25);
  o.tile_size = -1;
  CHECK(says(polycube_tile_size(cube, o).error(), "tile_size"));
  o.tile_size = std::numeric_limits<double>::quiet_NaN();
  CHECK(!polycube_tile_size(cube, o));
  o.tile_size = 4;
  CHECK(says(polycube_tile_size(cube, o).error(), "larger than the mesh"));
  o.tile_size = 0;
  o.tiles_across = 0;
  CHECK(says(polycube_tile_size(cube, o).error(), "tiles_across"));
}

TEST_CASE("polycube labels: axis, sign, opposite") {
  CHECK(label_axis(polycube_label::neg_y) == 1);
  CHECK(label_sign(polycube_label::neg_y) == -1);
  CHECK(opposite(polycube_label::pos_z) == polycube_label::neg_z);
  CHECK(label_direction(polycube_label::neg_x).x == -1);
}
