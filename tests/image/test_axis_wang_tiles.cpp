// Three-axis image Wang tile sets (image/axis_wang_tiles.hpp); their use on surfaces is tested in
// tests/surface/test_map_wang_tiles_to_surface.cpp.
#include <tessera/image/axis_wang_tiles.hpp>
#include <tessera/image/exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

TEST_CASE("axis wang tiles: the complete set's size, and clear errors for bad colour counts", "[axis_wang_tiles]") {
  auto ex = make_exemplar<std::uint8_t, 3>(exemplar_kind::cells, {.width = 64, .height = 64, .seed = 2});
  REQUIRE(ex.ok());
  auto one = build_axis_wang_tiles(*ex, {1, 1, 1}, {.tile_size = 16, .seed = 1});
  REQUIRE(one.ok());
  REQUIRE(one->size() == 6);  // 2 (nX²nY² + nX²nZ² + nY²nZ²)
  auto two = build_axis_wang_tiles(*ex, {1, 2, 1}, {.tile_size = 16, .seed = 1});
  REQUIRE(two.ok());
  REQUIRE(two->size() == 2 * (4 + 1 + 4));
  for (index_t i = 0; i < two->size(); ++i) REQUIRE(two->tile(i).width() == 16);
  auto bad = build_axis_wang_tiles(*ex, {1, 0, 1}, {.tile_size = 16});
  REQUIRE_FALSE(bad.ok());
  REQUIRE(bad.error().message().find("build_axis_wang_tiles") != std::string::npos);
}
