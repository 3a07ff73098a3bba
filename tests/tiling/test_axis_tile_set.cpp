#include <tessera/tiling/axis_tile_set.hpp>

#include <catch2/catch.hpp>

#include <set>
#include <tuple>

using namespace tessera;

TEST_CASE("three-axis sets: counts follow 2 (nX^2 nY^2 + nX^2 nZ^2 + nY^2 nZ^2)", "[axis_tile_set]") {
  REQUIRE(axis_tile_count({1, 1, 1}) == 6);
  REQUIRE(axis_tile_count({2, 2, 2}) == 96);
  REQUIRE(axis_tile_count({2, 3, 1}) == 2 * (4 * 9 + 4 * 1 + 9 * 1));
  // per face: (colours of its first axis)^2 (of its second)^2; opposite faces hold the same pair of axes
  const axis_color_counts n{2, 3, 1};
  for (int f = 0; f < cube_faces; ++f) {
    const auto ax = cube_face_axes(f);
    REQUIRE(axis_face_tile_count(f, n) == complete_tile_count(n[ax[0]], n[ax[1]]));
    REQUIRE(axis_face_tile_count(f, n) == axis_face_tile_count(f ^ 1, n));
  }
}

TEST_CASE("three-axis sets: face frames are right-handed and in-plane", "[axis_tile_set]") {
  for (int f = 0; f < cube_faces; ++f) {
    const auto ax = cube_face_axes(f);
    const int a = f / 2, sign = f % 2 == 0 ? 1 : -1;
    REQUIRE(ax[0] != a);
    REQUIRE(ax[1] != a);
    REQUIRE(ax[0] != ax[1]);
    // e_u x e_v = sign e_a: (a+1, a+2) is cyclic
    const int cyclic = (ax[0] + 1) % 3 == ax[1] ? 1 : -1;
    REQUIRE(cyclic == sign);
    REQUIRE(cube_face_side_axis(f, side_north) == ax[0]);
    REQUIRE(cube_face_side_axis(f, side_south) == ax[0]);
    REQUIRE(cube_face_side_axis(f, side_east) == ax[1]);
    REQUIRE(cube_face_side_axis(f, side_west) == ax[1]);
  }
  REQUIRE(cube_face_name(5) == "-Z");
  REQUIRE(cube_face_name(6) == "invalid face");
}

TEST_CASE("three-axis sets: index and tile are inverse, every combination once", "[axis_tile_set]") {
  const axis_color_counts n{2, 3, 1};
  std::set<std::tuple<int, int, int, int, int>> seen;
  for (index_t t = 0; t < axis_tile_count(n); ++t) {
    const axis_tile at = axis_tile_at(t, n);
    REQUIRE(validate_axis_tile(at, n).ok());
    REQUIRE(axis_tile_index(at, n) == t);
    REQUIRE(t >= axis_face_first_tile(at.face, n));
    REQUIRE(t < axis_face_first_tile(at.face, n) + axis_face_tile_count(at.face, n));
    seen.insert({at.face, at.edges.north, at.edges.east, at.edges.south, at.edges.west});
  }
  REQUIRE(static_cast<index_t>(seen.size()) == axis_tile_count(n));
  REQUIRE(axis_tile_at(0, n).face == 0);
  REQUIRE(axis_tile_at(axis_tile_count(n) - 1, n).face == 5);
}

TEST_CASE("three-axis sets: bad counts and tiles return a status naming the axis or side", "[axis_tile_set]") {
  auto s = validate_axis_color_counts({2, 0, 2});
  REQUIRE_FALSE(s.ok());
  REQUIRE(s.message().find("parallel to Y") != std::string::npos);
  REQUIRE_FALSE(validate_axis_color_counts({1, 1, max_wang_colors + 1}).ok());
  REQUIRE(validate_axis_color_counts({1, 1, max_wang_colors}).ok());
  // +Z tiles: north/south from X (2 colours), east/west from Y (1 colour)
  REQUIRE(validate_axis_tile({4, {1, 0, 1, 0}}, {2, 1, 3}).ok());
  auto bad = validate_axis_tile({4, {0, 1, 0, 0}}, {2, 1, 3});
  REQUIRE(bad.code() == status_code::out_of_range);
  REQUIRE(bad.message().find("east colour 1") != std::string::npos);
  REQUIRE(bad.message().find("along Y") != std::string::npos);
  REQUIRE(validate_axis_tile({6, {}}, {1, 1, 1}).code() == status_code::out_of_range);
  REQUIRE(validate_axis_tile({-1, {}}, {1, 1, 1}).code() == status_code::out_of_range);
}
