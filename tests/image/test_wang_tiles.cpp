#include <tessera/image/wang_tiles.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/tiling/tile_set_edges.hpp>

#include <cstring>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;
using tessera::wang_edges;
using tessera::wang_tile_options;

namespace {
template <class T, int C>
bool same_pixels(const tessera::wang_tile_set<T, C>& set, index_t a, index_t ax, index_t ay, index_t b, index_t bx, index_t by) {
  return std::memcmp(set.tile(a).pixel_ptr(ax, ay), set.tile(b).pixel_ptr(bx, by), sizeof(T) * C) == 0;
}
}  // namespace

TEST_CASE("wang tiles: the complete set, in complete-index order, with exact shared borders", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::grass, 64, 3);
  const wang_tile_options o{.tile_size = 32, .horizontal_colors = 2, .vertical_colors = 3, .seed = 4};
  auto set = tessera::build_wang_tiles(ex, o);
  REQUIRE(set.ok());
  REQUIRE(set->size() == 36);
  REQUIRE(set->tile_size() == 32);
  REQUIRE(set->edges().is_complete());
  for (index_t t = 0; t < 36; ++t) REQUIRE(set->edges()[t] == tessera::complete_tile_edges(t, 2, 3));
  // Each edge colour is one exemplar strip: all tiles with the same colour on a side have identical
  // fixed border pixels there (outside the corners), so any two tiles whose touching edges share a
  // colour meet along consecutive rows of one strip.
  const index_t ts = 32, ov = 3 /* max(2, 32 / 10) */;
  for (index_t a = 0; a < 36; ++a)
    for (index_t b = 0; b < 36; ++b)
      for (index_t k = ov; k < ts - ov; ++k) {
        if (set->edges()[a].north == set->edges()[b].north) REQUIRE(same_pixels(*set, a, k, 0, b, k, 0));
        if (set->edges()[a].south == set->edges()[b].south) REQUIRE(same_pixels(*set, a, k, ts - 1, b, k, ts - 1));
        if (set->edges()[a].west == set->edges()[b].west) REQUIRE(same_pixels(*set, a, 0, k, b, 0, k));
        if (set->edges()[a].east == set->edges()[b].east) REQUIRE(same_pixels(*set, a, ts - 1, k, b, ts - 1, k));
      }
  // ... and the strip continues across the edge: the south row of a tile with south colour c and the
  // north row of a tile with north colour c are vertically adjacent rows of the exemplar
  for (index_t a = 0; a < 36; ++a)
    for (index_t b = 0; b < 36; ++b) {
      if (set->edges()[a].south != set->edges()[b].north) continue;
      bool found = false;
      for (index_t y = 0; y + 1 < 64 && !found; ++y)
        for (index_t x = 0; x + (ts - 2 * ov) <= 64 && !found; ++x) {
          bool all = true;
          for (index_t k = ov; k < ts - ov && all; ++k)
            all = ex.read(x + k - ov, y) == set->tile(a).read(k, ts - 1) && ex.read(x + k - ov, y + 1) == set->tile(b).read(k, 0);
          found = all;
        }
      REQUIRE(found);
      break;  // one pair per tile is enough for the search's cost
    }
}

TEST_CASE("wang tiles: subsets, odd sizes, pixel types, executors", "[wang]") {
  const auto ex = quilt_test::exemplar<float, 3>(tessera::exemplar_kind::cells, 56, 2);
  auto cohen = tessera::tile_set_edges::modular_subset(2, 2, 2);
  wang_tile_options o{.tile_size = 27, .tiles = std::vector<wang_edges>(cohen->tiles().begin(), cohen->tiles().end()), .seed = 8};
  auto serial = tessera::build_wang_tiles(ex, o);
  REQUIRE(serial.ok());
  REQUIRE(serial->size() == 8);
  for (index_t t = 0; t < 8; ++t) REQUIRE(serial->edges()[t] == (*cohen)[t]);
  tessera::thread_pool_executor pool(3);
  auto pooled = tessera::build_wang_tiles(ex, o, pool);
  REQUIRE(pooled.ok());
  for (index_t t = 0; t < 8; ++t)
    REQUIRE(std::memcmp(serial->tile(t).data(), pooled->tile(t).data(), sizeof(float) * 3 * 27 * 27) == 0);
  const auto grey = quilt_test::exemplar<std::uint16_t, 1>(tessera::exemplar_kind::rock, 40, 2);
  auto g = tessera::build_wang_tiles(grey, {.tile_size = 20, .horizontal_colors = 1, .vertical_colors = 2});
  REQUIRE(g.ok());
  REQUIRE(g->size() == 4);
  // the tiles differ from each other (interiors are synthesized per tile)
  REQUIRE(std::memcmp(g->tile(0).data(), g->tile(1).data(), 2 * 20 * 20) != 0);
}

TEST_CASE("wang tiles: wang_tile_set::create checks the images", "[wang]") {
  auto edges = tessera::tile_set_edges::complete(1, 1);
  std::vector<tessera::image_buffer<std::uint8_t, 3>> one = {tessera::image_buffer<std::uint8_t, 3>(8, 8, {1, 2, 3})};
  using set3 = tessera::wang_tile_set<std::uint8_t, 3>;
  auto ok = set3::create(*edges, 8, one);
  REQUIRE(ok.ok());
  REQUIRE(ok->tile(0).read(7, 7) == std::array<std::uint8_t, 3>{1, 2, 3});
  REQUIRE_THAT(set3::create(*edges, 9, one).error().message(), Catch::Contains("tile 0 is 8 x 8"));
  REQUIRE_FALSE(set3::create(*edges, 8, {}).ok());
  REQUIRE_FALSE(set3::create(*edges, 0, one).ok());
}

TEST_CASE("wang tiles: bad input", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::sand, 48);
  auto code = [&](const wang_tile_options& o) { return tessera::build_wang_tiles(ex, o).error().code(); };
  auto big = tessera::build_wang_tiles(ex, {.tile_size = 64});
  REQUIRE(big.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(big.error().message(), Catch::Contains("tile_size 64 is larger than the 48 x 48 exemplar"));
  REQUIRE(code({.tile_size = 3}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .horizontal_colors = 0}) == tessera::status_code::invalid_argument);
  REQUIRE_THAT(tessera::build_wang_tiles(ex, {.tile_size = 32, .vertical_colors = -1}).error().message(), Catch::Contains("got -1"));
  REQUIRE(code({.tile_size = 32, .tiles = {{0, 0, 2, 0}}}) == tessera::status_code::out_of_range);
  REQUIRE(code({.tile_size = 32, .overlap = 10, .patch_size = 12}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .overlap = 4, .border = 4}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .patch_size = 40}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .tolerance = -1}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .boundary_weight = 0}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .min_candidates = 0}) == tessera::status_code::invalid_argument);
  tessera::image_view<std::uint8_t, 3> empty;
  REQUIRE(tessera::build_wang_tiles(empty, {}).error().code() == tessera::status_code::invalid_argument);
  tessera::cancellation_token stop;
  stop.cancel();
  wang_tile_options cancelled{.tile_size = 16};
  cancelled.progress.token = &stop;
  REQUIRE(code(cancelled) == tessera::status_code::cancelled);
}
