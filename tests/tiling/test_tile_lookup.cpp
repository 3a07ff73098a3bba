#include <tessera/tiling/tile_lookup.hpp>

#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/periodic_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include <set>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::wang_edges;

static_assert(tessera::GridTileColoring<tessera::scanline_coloring>);
static_assert(tessera::GridTileColoring<tessera::periodic_coloring>);
static_assert(tessera::GridTileColoring<tessera::hash_coloring_window>);
static_assert(tessera::PlaneTileColoring<tessera::hash_coloring>);
static_assert(!tessera::GridTileColoring<tessera::hash_coloring>);
static_assert(!tessera::PlaneTileColoring<tessera::scanline_coloring>);
static_assert(!tessera::GridTileColoring<tessera::stored_tile_coloring>);  // no cols(): use grid_coloring_view
static_assert(tessera::GridTileColoring<tessera::grid_coloring_view<tessera::stored_tile_coloring>>);

TEST_CASE("tile lookup: cell edges of grid and plane colourings", "[tiling]") {
  auto plane = tessera::hash_coloring::create(2, 3, 4);
  auto window = plane->window(-3, 5, 6, 4);
  for (index_t r = 0; r < 4; ++r)
    for (index_t c = 0; c < 6; ++c) REQUIRE(tessera::cell_edges(*window, c, r) == tessera::cell_edges(*plane, c - 3, r + 5));
  auto scan = tessera::scanline_coloring::create(2, 2, 5, 3, 1);
  const tessera::stored_tile_coloring stored = tessera::store_coloring(*scan);
  const tessera::grid_coloring_view<tessera::stored_tile_coloring> view{&stored, 5};
  REQUIRE(view.rows() == 3);
  for (index_t r = 0; r < 3; ++r)
    for (index_t c = 0; c < 5; ++c) REQUIRE(tessera::cell_edges(view, c, r) == scan->edges_at(c, r));
}

TEST_CASE("tile lookup: variants are drawn per cell, missing tiles are -1", "[tiling]") {
  auto set = tessera::tile_set_edges::create(1, 2, {{0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}});
  REQUIRE(set.ok());
  std::set<index_t> seen;
  for (index_t c = -20; c < 20; ++c) {
    const index_t t = tessera::tile_at_cell(*set, {0, 0, 0, 0}, 9, c, 2);
    REQUIRE(t == tessera::tile_at_cell(*set, {0, 0, 0, 0}, 9, c, 2));  // a pure function of the cell
    seen.insert(t);
  }
  REQUIRE(seen == std::set<index_t>{1, 2, 3});
  REQUIRE(tessera::tile_at_cell(*set, {0, 1, 0, 0}, 9, 0, 0) == 0);
  REQUIRE(tessera::tile_at_cell(*set, {0, 1, 0, 1}, 9, 0, 0) == -1);
  REQUIRE(tessera::floor_div(-1, 4) == -1);
  REQUIRE(tessera::floor_div(-4, 4) == -1);
  REQUIRE(tessera::floor_div(-5, 4) == -2);
  REQUIRE(tessera::floor_div(7, 4) == 1);
}
