#include <tessera/tiling/periodic_coloring.hpp>

#include <tessera/core/tile_coloring.hpp>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::periodic_coloring;
using tessera::tile_set_edges;
using tessera::wang_edges;

static_assert(tessera::TileColoring<periodic_coloring>);

TEST_CASE("periodic colouring: repeats, is toroidal-consistent, uses the set", "[tiling]") {
  std::vector<tessera::result<tile_set_edges>> sets;
  sets.push_back(tile_set_edges::complete(2, 2));
  sets.push_back(tile_set_edges::modular_subset(2, 2, 2));
  // an arbitrary subset (not hashable): found by search
  sets.push_back(tile_set_edges::create(
      2, 2, {{0, 0, 0, 0}, {0, 1, 1, 0}, {1, 0, 1, 1}, {1, 1, 0, 1}, {0, 1, 0, 0}, {1, 0, 0, 1}}));
  REQUIRE(sets[2]->hash_modulus() == 0);
  for (auto& set : sets) {
    REQUIRE(set.ok());
    auto c = periodic_coloring::create(*set, 3, 2, 9, 6, 11);
    REQUIRE(c.ok());
    REQUIRE(tessera::check_grid_coloring(*c, 9, 6, /*toroidal=*/true).ok());
    REQUIRE(tessera::check_coloring_against_set(*c, *set).ok());
    for (index_t r = -4; r < 8; ++r)
      for (index_t col = -4; col < 12; ++col) REQUIRE(c->edges_at(col, r) == c->edges_at(col + 3, r + 2));
  }
}

TEST_CASE("periodic colouring: period 1 needs a self-matching tile, impossible periods are reported", "[tiling]") {
  auto complete = tile_set_edges::complete(2, 2);
  auto one = periodic_coloring::create(*complete, 1, 1, 4, 4);
  REQUIRE(one.ok());
  const wang_edges e = one->edges_at(0, 0);
  REQUIRE(e.north == e.south);
  REQUIRE(e.east == e.west);
  // a set whose only tiles swap colours: no period-1 pattern exists
  auto swap = tile_set_edges::create(2, 2, {{0, 1, 1, 0}, {1, 0, 0, 1}});
  auto none = periodic_coloring::create(*swap, 1, 1, 4, 4);
  REQUIRE(none.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(none.error().message(), Catch::Contains("1 x 1"));
  auto two = periodic_coloring::create(*swap, 2, 2, 4, 4);
  REQUIRE(two.ok());
  REQUIRE(tessera::check_grid_coloring(*two, 4, 4, true).ok());
  REQUIRE(periodic_coloring::create(*swap, 3, 3, 6, 6, 1).error().code() == tessera::status_code::invalid_argument);
}

TEST_CASE("periodic colouring: bad input", "[tiling]") {
  auto set = tile_set_edges::complete(2, 2);
  REQUIRE_FALSE(periodic_coloring::create(*set, 0, 2, 4, 4).ok());
  REQUIRE_FALSE(periodic_coloring::create(*set, 2, 2, 4, 0).ok());
  // periods and grids beyond max_coloring_cells (2^26): size_overflow, nothing allocated
  REQUIRE(periodic_coloring::create(*set, index_t{1} << 16, index_t{1} << 16, 4, 4).error().code() ==
          tessera::status_code::size_overflow);
  auto grid = periodic_coloring::create(*set, 2, 2, index_t{1} << 16, index_t{1} << 16);
  REQUIRE(grid.error().code() == tessera::status_code::size_overflow);
  REQUIRE_THAT(grid.error().message(), Catch::Contains("max_coloring_cells"));
  // a search budget too small reports not_converged
  auto arbitrary = tile_set_edges::create(2, 2, {{0, 0, 1, 0}, {1, 0, 0, 0}, {0, 1, 1, 1}, {1, 1, 0, 1}});
  REQUIRE(periodic_coloring::create(*arbitrary, 4, 4, 4, 4, 1, 3).error().code() ==
          tessera::status_code::not_converged);
}
