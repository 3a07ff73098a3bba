// Packing a three-axis image Wang tile set into one atlas (image/axis_wang_atlas.hpp).
#include <tessera/image/axis_wang_atlas.hpp>
#include <tessera/image/exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

TEST_CASE("axis wang atlas: every tile's texels sit at its origin, an empty set is refused", "[axis_wang_atlas]") {
  auto ex = make_exemplar<std::uint8_t, 3>(exemplar_kind::cells, {.width = 64, .height = 64, .seed = 2});
  REQUIRE(ex.ok());
  auto set = build_axis_wang_tiles(*ex, {1, 1, 1}, {.tile_size = 16, .seed = 1});
  REQUIRE(set.ok());
  auto a = build_axis_wang_atlas(*set);
  REQUIRE(a.ok());
  REQUIRE(a->origin.size() == static_cast<std::size_t>(set->size()));
  for (index_t t = 0; t < set->size(); ++t) {
    const auto tile = set->tile(t);
    const auto o = a->origin[static_cast<std::size_t>(t)];
    for (index_t y = 0; y < tile.height(); ++y)
      for (index_t x = 0; x < tile.width(); ++x)
        for (int c = 0; c < 3; ++c) REQUIRE(a->image.pixel_ptr(o[0] + x, o[1] + y)[c] == tile.pixel_ptr(x, y)[c]);
  }
  REQUIRE_FALSE(build_axis_wang_atlas(axis_wang_tile_set<std::uint8_t, 3>{}).ok());
}
