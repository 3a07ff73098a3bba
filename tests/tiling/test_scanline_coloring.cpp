#include <tessera/tiling/scanline_coloring.hpp>

#include <tessera/core/tile_coloring.hpp>

#include <map>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::scanline_coloring;
using tessera::tile_set_edges;

static_assert(tessera::TileColoring<scanline_coloring>);

TEST_CASE("scanline colouring: consistent, uses only tiles of the set, deterministic", "[tiling]") {
  for (int modulus : {1, 2}) {
    auto set = modulus == 1 ? tile_set_edges::complete(2, 3) : tile_set_edges::modular_subset(2, 2, 2);
    REQUIRE(set.ok());
    auto c = scanline_coloring::create(*set, 13, 9, 42);
    REQUIRE(c.ok());
    REQUIRE(c->num_faces() == 13 * 9);
    REQUIRE(tessera::check_grid_coloring(*c, 13, 9).ok());
    REQUIRE(tessera::check_coloring_against_set(*c, *set).ok());
    auto again = scanline_coloring::create(*set, 13, 9, 42);
    auto other = scanline_coloring::create(*set, 13, 9, 43);
    int differ = 0;
    for (index_t f = 0; f < c->num_faces(); ++f)
      for (int s = 0; s < 4; ++s) {
        REQUIRE(c->edge_color(f, s) == again->edge_color(f, s));
        differ += c->edge_color(f, s) != other->edge_color(f, s);
      }
    REQUIRE(differ > 0);
    // a cell depends only on the cells above and to its left: a larger grid agrees on the common part
    auto larger = scanline_coloring::create(*set, 20, 15, 42);
    for (index_t r = 0; r < 9; ++r)
      for (index_t col = 0; col < 13; ++col) REQUIRE(larger->edges_at(col, r) == c->edges_at(col, r));
  }
}

TEST_CASE("scanline colouring: free edges are uniform over the complete set", "[tiling]") {
  auto c = scanline_coloring::create(2, 2, 64, 64, 7);
  REQUIRE(c.ok());
  std::map<index_t, int> counts;
  for (index_t f = 0; f < c->num_faces(); ++f) {
    const auto e = c->edges_at(f % 64, f / 64);
    ++counts[tessera::complete_tile_index(e, 2, 2)];
  }
  REQUIRE(counts.size() == 16u);                              // every tile occurs
  for (auto& [tile, n] : counts) REQUIRE(n > 4096 / 16 / 2);  // and none is rare (expected 256)
}

TEST_CASE("scanline colouring: bad input", "[tiling]") {
  auto set = tile_set_edges::complete(2, 2);
  REQUIRE(scanline_coloring::create(*set, 0, 4).error().code() == tessera::status_code::invalid_argument);
  REQUIRE(scanline_coloring::create(*set, 4, -1).error().code() == tessera::status_code::invalid_argument);
  REQUIRE(scanline_coloring::create(*set, index_t{1} << 20, index_t{1} << 20).error().code() ==
          tessera::status_code::size_overflow);
  // the cap is 2^26 cells (1 GiB of cells), checked before anything is allocated
  auto over = scanline_coloring::create(*set, index_t{1} << 16, (index_t{1} << 10) + 1);
  REQUIRE(over.error().code() == tessera::status_code::size_overflow);
  REQUIRE_THAT(over.error().message(), Catch::Contains("65536 x 1025 cells exceed max_coloring_cells"));
  REQUIRE(tessera::max_coloring_cells == index_t{1} << 26);
  REQUIRE_FALSE(scanline_coloring::create(0, 2, 4, 4).ok());
  auto gappy = tile_set_edges::create(2, 2, {{0, 0, 0, 0}, {1, 1, 1, 1}});
  auto s = scanline_coloring::create(*gappy, 4, 4);
  REQUIRE(s.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(s.error().message(), Catch::Contains("north colour 0 and west colour 1"));
}
