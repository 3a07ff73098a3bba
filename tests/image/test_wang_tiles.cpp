#include <tessera/image/wang_tiles.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/tiling/tile_set_edges.hpp>

#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;
using tessera::wang_edges;
using tessera::wang_tile_options;

namespace {
template <class T, int C>
bool same_pixels(const tessera::wang_tile_set<T, C>& set, index_t a, index_t ax, index_t ay, index_t b, index_t bx,
                 index_t by) {
  return std::memcmp(set.tile(a).pixel_ptr(ax, ay), set.tile(b).pixel_ptr(bx, by), sizeof(T) * C) == 0;
}
}  // namespace

TEST_CASE("wang tiles: the complete set, in complete-index order, edges shared within the border", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::grass, 64, 3);
  const wang_tile_options o{.tile_size = 32, .horizontal_colors = 2, .vertical_colors = 3, .seed = 4};
  auto set = tessera::build_wang_tiles(ex, o);
  REQUIRE(set.ok());
  REQUIRE(set->size() == 36);
  REQUIRE(set->tile_size() == 32);
  REQUIRE(set->edges().is_complete());
  for (index_t t = 0; t < 36; ++t) REQUIRE(set->edges()[t] == tessera::complete_tile_edges(t, 2, 3));
  // defaults for tiles of 32: 3 exact mip levels, so a border of 2^2 = 4 texels
  const index_t ts = 32, border = 4;
  REQUIRE(set->shared_border() >= border);
  REQUIRE(set->exact_mip_levels() == 3);
  // Each edge colour is one edge sample: all tiles with the same colour on a side have identical
  // pixels within the border there, over the whole side (corners included), so any two tiles whose
  // touching edges share a colour meet along consecutive rows of one sample.
  for (index_t a = 0; a < 36; ++a)
    for (index_t b = a + 1; b < 36; ++b)
      for (index_t k = 0; k < ts; ++k)
        for (index_t depth = 0; depth < border; ++depth) {
          if (set->edges()[a].north == set->edges()[b].north) REQUIRE(same_pixels(*set, a, k, depth, b, k, depth));
          if (set->edges()[a].south == set->edges()[b].south)
            REQUIRE(same_pixels(*set, a, k, ts - 1 - depth, b, k, ts - 1 - depth));
          if (set->edges()[a].west == set->edges()[b].west) REQUIRE(same_pixels(*set, a, depth, k, b, depth, k));
          if (set->edges()[a].east == set->edges()[b].east)
            REQUIRE(same_pixels(*set, a, ts - 1 - depth, k, b, ts - 1 - depth, k));
        }
  // ... while tiles with different colours differ there (each colour is its own sample)
  REQUIRE_FALSE(same_pixels(*set, 0, ts / 2, 0, tessera::complete_tile_index({1, 0, 0, 0}, 2, 3), ts / 2, 0));
  // beyond the border the frame is cut per tile: some pair of tiles with equal north colours differs
  // at depth `border` (the shared border is not the whole tile)
  REQUIRE(set->shared_border() < ts / 2);
}

TEST_CASE("wang tiles: all four tiles meeting at a corner show the same exemplar window", "[wang]") {
  // Every choice of four tiles that can meet at a corner point (A north-west, B north-east, C
  // south-west, D south-east: A.east = B.west, C.east = D.west, A.south = C.north, B.south = D.north)
  // gives the same 2·border x 2·border block around the point, and that block is a window of the
  // exemplar: corners are consistent for every combination that can touch.
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::cells, 64, 5);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 32, .horizontal_colors = 3, .vertical_colors = 2, .seed = 6});
  REQUIRE(set.ok());
  const index_t ts = 32, d = 4, n = set->size();
  const tessera::tile_set_edges& e = set->edges();
  std::vector<std::array<std::uint8_t, 3>> reference;
  index_t combinations = 0;
  for (index_t a = 0; a < n; ++a)
    for (index_t b : e.with_west(e[a].east))
      for (index_t c : e.with_north(e[a].south))
        for (index_t dd : e.matching(e[b].south, e[c].east)) {
          std::vector<std::array<std::uint8_t, 3>> block;
          for (index_t y = 0; y < 2 * d; ++y)
            for (index_t x = 0; x < 2 * d; ++x) {
              const index_t t = y < d ? (x < d ? a : b) : (x < d ? c : dd);
              const index_t tx = x < d ? ts - d + x : x - d, ty = y < d ? ts - d + y : y - d;
              block.push_back(set->tile(t).read(tx, ty));
            }
          if (reference.empty()) reference = block;
          REQUIRE(block == reference);
          ++combinations;
        }
  REQUIRE(combinations == 36 * 18 * 12 * 6);  // a: any; b: west fixed; c: north fixed; d: north and west fixed
  bool in_exemplar = false;
  for (index_t y = 0; y + 2 * d <= 64 && !in_exemplar; ++y)
    for (index_t x = 0; x + 2 * d <= 64 && !in_exemplar; ++x) {
      bool all = true;
      for (index_t k = 0; k < 4 * d * d && all; ++k)
        all = ex.read(x + k % (2 * d), y + k / (2 * d)) == reference[static_cast<std::size_t>(k)];
      in_exemplar = all;
    }
  REQUIRE(in_exemplar);
}

TEST_CASE("wang tiles: mip_levels sets the shared border", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::bricks, 64, 2);
  auto four = tessera::build_wang_tiles(ex, {.tile_size = 32, .mip_levels = 4, .seed = 2});
  REQUIRE(four.ok());
  REQUIRE(four->shared_border() >= 8);
  REQUIRE(four->exact_mip_levels() >= 4);
  auto one = tessera::build_wang_tiles(ex, {.tile_size = 30, .seed = 2});  // 30 = 2 x 15: automatic levels stop at 2
  REQUIRE(one.ok());
  REQUIRE(one->shared_border() >= 2);
  REQUIRE(one->exact_mip_levels() == 2);
  auto odd = tessera::build_wang_tiles(ex, {.tile_size = 36, .mip_levels = 4});
  REQUIRE(odd.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(odd.error().message(), Catch::Contains("tile_size 36 must be a multiple of 2^(mip_levels - 1) = 8"));
  auto thin = tessera::build_wang_tiles(ex, {.tile_size = 32, .mip_levels = 3, .border = 2});
  REQUIRE_THAT(thin.error().message(), Catch::Contains("border 2 is smaller than the 2^(mip_levels - 1) = 4"));
  REQUIRE(tessera::build_wang_tiles(ex, {.tile_size = 32, .mip_levels = -1}).error().code() ==
          tessera::status_code::invalid_argument);
  REQUIRE(tessera::build_wang_tiles(ex, {.tile_size = 32, .mip_levels = 17}).error().code() ==
          tessera::status_code::invalid_argument);
}

TEST_CASE("wang tiles: subsets, odd sizes, pixel types, executors", "[wang]") {
  const auto ex = quilt_test::exemplar<float, 3>(tessera::exemplar_kind::cells, 56, 2);
  auto cohen = tessera::tile_set_edges::modular_subset(2, 2, 2);
  wang_tile_options o{
      .tile_size = 27, .tiles = std::vector<wang_edges>(cohen->tiles().begin(), cohen->tiles().end()), .seed = 8};
  auto serial = tessera::build_wang_tiles(ex, o);
  REQUIRE(serial.ok());
  REQUIRE(serial->size() == 8);
  REQUIRE(serial->exact_mip_levels() == 1);  // odd tiles: one exact level (bilinear at full resolution)
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
  REQUIRE(set3::create(*edges, -5, one).error().code() == tessera::status_code::invalid_argument);
  // the only other way in is build_wang_tiles: no public unchecked constructor or pixel access
  static_assert(!std::is_constructible_v<set3, tessera::tile_set_edges, index_t>);
  static_assert(std::is_same_v<decltype(std::declval<const set3&>().tile_row(0, 0)), const std::uint8_t*>);
  // sizes are checked before anything is allocated
  REQUIRE(tessera::detail::validate_tile_set_extent(index_t{1} << 24, 32, 3).code() ==
          tessera::status_code::size_overflow);
  REQUIRE(tessera::detail::validate_tile_set_extent(16, index_t{1} << 40, 3).code() ==
          tessera::status_code::size_overflow);
  REQUIRE(tessera::detail::validate_tile_set_extent(16, 64, 4).ok());
  // a set made from arbitrary images measures its shared border: one tile, so everything is shared
  REQUIRE(ok->shared_border() == 4);
  REQUIRE(ok->exact_mip_levels() == 3);
  // two tiles sharing their north and south colours: every pixel lies within 7 of one of those sides
  auto pair = tessera::tile_set_edges::create(1, 2, {{0, 0, 0, 1}, {0, 1, 0, 0}});
  std::vector<tessera::image_buffer<std::uint8_t, 3>> two(2, tessera::image_buffer<std::uint8_t, 3>(16, 16, {1, 2, 3}));
  REQUIRE(set3::create(*pair, 16, two)->shared_border() == 8);
  REQUIRE(set3::create(*pair, 16, two)->exact_mip_levels() == 4);
  two[1].write(6, 6, {9, 9, 9});  // north band depth 6 (and the north-west corner square)
  REQUIRE(set3::create(*pair, 16, two)->shared_border() == 6);
  REQUIRE(set3::create(*pair, 16, two)->exact_mip_levels() == 3);
  two[1].write(5, 15, {9, 9, 9});  // south band depth 0
  REQUIRE(set3::create(*pair, 16, two)->shared_border() == 0);
  REQUIRE(set3::create(*pair, 16, two)->exact_mip_levels() == 0);
  // two tiles sharing no colour: only their corner squares are compared
  auto apart = tessera::tile_set_edges::create(2, 2, {{0, 0, 0, 0}, {1, 1, 1, 1}});
  std::vector<tessera::image_buffer<std::uint8_t, 3>> corners(
      2, tessera::image_buffer<std::uint8_t, 3>(16, 16, {1, 2, 3}));
  corners[1].write(12, 14, {9, 9, 9});  // south-east corner square, 3 from the east side and 1 from the south
  REQUIRE(set3::create(*apart, 16, corners)->shared_border() == 3);
  REQUIRE(set3::create(*apart, 16, corners)->exact_mip_levels() == 2);
}

TEST_CASE("wang tiles: bad input", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::sand, 48);
  auto code = [&](const wang_tile_options& o) { return tessera::build_wang_tiles(ex, o).error().code(); };
  auto big = tessera::build_wang_tiles(ex, {.tile_size = 64});
  REQUIRE(big.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(big.error().message(), Catch::Contains("tile_size 64 is larger than the 48 x 48 exemplar"));
  REQUIRE(code({.tile_size = 3}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .horizontal_colors = 0}) == tessera::status_code::invalid_argument);
  REQUIRE_THAT(tessera::build_wang_tiles(ex, {.tile_size = 32, .vertical_colors = -1}).error().message(),
               Catch::Contains("got -1"));
  REQUIRE(code({.tile_size = 32, .tiles = {{0, 0, 2, 0}}}) == tessera::status_code::out_of_range);
  REQUIRE(code({.tile_size = 32, .overlap = 10, .patch_size = 12}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .overlap = 4, .border = 4}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .patch_size = 40}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .tolerance = -1}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .boundary_weight = 0}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tile_size = 32, .min_candidates = 0}) == tessera::status_code::invalid_argument);
  tessera::image_view<std::uint8_t, 3> empty;
  REQUIRE(tessera::build_wang_tiles(empty, {}).error().code() == tessera::status_code::invalid_argument);
  // 64 x 64 colours would be 2^24 tiles: refused before anything is allocated
  auto huge = tessera::build_wang_tiles(ex, {.tile_size = 32, .horizontal_colors = 64, .vertical_colors = 64});
  REQUIRE(huge.error().code() == tessera::status_code::size_overflow);
  REQUIRE_THAT(huge.error().message(), Catch::Contains("16777216 tiles") && Catch::Contains("max_wang_tile_set_bytes"));
  // a float exemplar with a NaN or an infinity
  auto bad = quilt_test::exemplar<float, 3>(tessera::exemplar_kind::sand, 48);
  bad.write(7, 11, {0.5f, std::numeric_limits<float>::quiet_NaN(), 0.5f});
  auto nan = tessera::build_wang_tiles(bad, {.tile_size = 16});
  REQUIRE(nan.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(nan.error().message(), Catch::Contains("exemplar: pixel (7, 11) channel 1 is nan"));
  bad.write(7, 11, {0.5f, 0.5f, std::numeric_limits<float>::infinity()});
  REQUIRE_THAT(tessera::build_wang_tiles(bad, {.tile_size = 16}).error().message(),
               Catch::Contains("channel 2 is inf"));
  tessera::cancellation_token stop;
  stop.cancel();
  wang_tile_options cancelled{.tile_size = 16};
  cancelled.progress.token = &stop;
  REQUIRE(code(cancelled) == tessera::status_code::cancelled);
}
