#include <tessera/terrain/make_terrain.hpp>

#include <catch2/catch.hpp>

using tessera::index_t;

TEST_CASE("make_terrain: grid, orientation, relief", "[terrain][scene]") {
  const auto m = tessera::make_terrain({.cells_x = 20, .cells_y = 12, .size_x = 40, .size_y = 24, .height = 8}).value();
  REQUIRE(m.num_vertices() == 21 * 13);
  REQUIRE(m.num_faces() == 2 * 20 * 12);
  REQUIRE(tessera::validate_mesh(m));
  const auto b = tessera::bounding_box(m);
  REQUIRE(b.min.x == Approx(-20));
  REQUIRE(b.max.y == Approx(12));
  REQUIRE(b.min.z >= 0);
  REQUIRE(b.max.z <= 8 + 1e-9);
  REQUIRE(b.max.z - b.min.z > 1);  // there is relief
  for (index_t f = 0; f < m.num_faces(); ++f)
    REQUIRE(tessera::face_area_normal(m, f).z > 0);  // counter-clockwise from above
  const auto flat = tessera::make_terrain({.cells_x = 5, .cells_y = 5, .height = 0}).value();
  for (const auto& p : flat.positions) REQUIRE(p.z == 0);
}

TEST_CASE("make_terrain: a pure function of the options, on any executor", "[terrain][scene]") {
  const auto a = tessera::make_terrain({.cells_x = 30, .cells_y = 30, .seed = 4}).value();
  tessera::thread_pool_executor pool(3);
  REQUIRE(tessera::make_terrain({.cells_x = 30, .cells_y = 30, .seed = 4}, pool).value() == a);
  REQUIRE_FALSE(tessera::make_terrain({.cells_x = 30, .cells_y = 30, .seed = 5}).value() == a);
}

TEST_CASE("make_terrain: bad options", "[terrain][scene]") {
  auto msg = [](const tessera::terrain_options& o) { return tessera::make_terrain(o).error().message(); };
  REQUIRE(msg({.cells_x = 0}).find("cells") != std::string::npos);
  REQUIRE(tessera::make_terrain({.cells_x = 1 << 15}).error().code() == tessera::status_code::size_overflow);
  REQUIRE(msg({.size_x = -1}).find("size") != std::string::npos);
  REQUIRE(msg({.height = -2}).find("height") != std::string::npos);
  REQUIRE(msg({.feature_size = 0}).find("feature_size") != std::string::npos);
  // a tiny wavelength would make noise coordinates infinite (floor(inf) to int64 is undefined)
  REQUIRE(msg({.feature_size = 1e-300}).find("feature_size must be in [1e-6, 1e6], got 1e-300") != std::string::npos);
  REQUIRE(msg({.feature_size = 1e7}).find("feature_size") != std::string::npos);
  REQUIRE(msg({.size_x = 1e300}).find("size must be in (0, 1e15]") != std::string::npos);
  REQUIRE(msg({.height = 1e300}).find("height") != std::string::npos);
  // the extreme accepted values give finite positions
  for (const double fs : {1e-6, 1e6}) {
    const auto m = tessera::make_terrain(
        {.cells_x = 3, .cells_y = 3, .size_x = 1e15, .size_y = 1e15, .feature_size = fs, .octaves = 16});
    REQUIRE(m);
    for (const auto& p : m->positions) REQUIRE(tessera::is_finite(p));
  }
  REQUIRE(msg({.octaves = 0}).find("octaves") != std::string::npos);
}
