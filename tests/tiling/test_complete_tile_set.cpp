#include <tessera/tiling/complete_tile_set.hpp>

#include <set>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::wang_edges;

TEST_CASE("complete tile set: count, index and edges are inverse bijections", "[tiling]") {
  for (int nh = 1; nh <= 4; ++nh)
    for (int nv = 1; nv <= 4; ++nv) {
      const index_t n = tessera::complete_tile_count(nh, nv);
      REQUIRE(n == nh * nh * nv * nv);
      std::set<std::tuple<int, int, int, int>> seen;
      for (index_t i = 0; i < n; ++i) {
        const wang_edges e = tessera::complete_tile_edges(i, nh, nv);
        REQUIRE(tessera::validate_wang_edges(e, nh, nv).ok());
        REQUIRE(tessera::complete_tile_index(e, nh, nv) == i);
        REQUIRE(i == ((e.north * nv + e.east) * nh + e.south) * nv + e.west);
        seen.insert({e.north, e.east, e.south, e.west});
      }
      REQUIRE(static_cast<index_t>(seen.size()) == n);  // every combination exactly once
    }
  REQUIRE(tessera::complete_tile_count(2, 2) == 16);
}

TEST_CASE("complete tile set: wang_edges sides and equality", "[tiling]") {
  constexpr wang_edges e{1, 2, 3, 4};
  static_assert(e[tessera::side_north] == 1 && e[tessera::side_east] == 2 && e[tessera::side_south] == 3 &&
                e[tessera::side_west] == 4);
  REQUIRE(e == wang_edges{1, 2, 3, 4});
  REQUIRE_FALSE(e == wang_edges{1, 2, 3, 0});
  // west varies fastest: tile 1 of 2 x 2 colours has west 1, tile 2 south 1, tile 4 east 1, tile 8 north 1
  REQUIRE(tessera::complete_tile_edges(1, 2, 2) == wang_edges{0, 0, 0, 1});
  REQUIRE(tessera::complete_tile_edges(2, 2, 2) == wang_edges{0, 0, 1, 0});
  REQUIRE(tessera::complete_tile_edges(4, 2, 2) == wang_edges{0, 1, 0, 0});
  REQUIRE(tessera::complete_tile_edges(8, 2, 2) == wang_edges{1, 0, 0, 0});
  auto all = tessera::complete_tile_set_edges(2, 3);
  REQUIRE(all.ok());
  REQUIRE(all->size() == 36u);
  for (std::size_t i = 0; i < all->size(); ++i)
    REQUIRE((*all)[i] == tessera::complete_tile_edges(static_cast<index_t>(i), 2, 3));
}

TEST_CASE("complete tile set: bad input", "[tiling]") {
  auto zero = tessera::validate_color_counts(0, 2);
  REQUIRE(zero.code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(zero.message(), Catch::Contains("horizontal") && Catch::Contains("got 0"));
  REQUIRE_THAT(tessera::validate_color_counts(2, -3).message(),
               Catch::Contains("vertical") && Catch::Contains("got -3"));
  REQUIRE_FALSE(tessera::validate_color_counts(tessera::max_wang_colors + 1, 1).ok());
  REQUIRE(tessera::validate_color_counts(1, 1).ok());
  REQUIRE(tessera::validate_complete_tile(16, 2, 2).code() == tessera::status_code::out_of_range);
  REQUIRE(tessera::validate_complete_tile(-1, 2, 2).code() == tessera::status_code::out_of_range);
  REQUIRE(tessera::validate_complete_tile(15, 2, 2).ok());
  REQUIRE_FALSE(tessera::validate_complete_tile(0, 0, 2).ok());
  auto side = tessera::validate_wang_edges({0, 2, 0, 0}, 2, 2);
  REQUIRE(side.code() == tessera::status_code::out_of_range);
  REQUIRE_THAT(side.message(), Catch::Contains("east colour 2"));
  REQUIRE_FALSE(tessera::validate_wang_edges({0, 0, -1, 0}, 2, 2).ok());
  REQUIRE_FALSE(tessera::complete_tile_set_edges(0, 1).ok());
  REQUIRE(tessera::complete_tile_set_edges(100, 100).error().code() == tessera::status_code::size_overflow);
}
