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
    for (index_t c = 0; c < 6; ++c)
      REQUIRE(tessera::cell_edges(*window, c, r) == tessera::cell_edges(*plane, c - 3, r + 5));
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

// explain_grid_tile_coloring / explain_plane_tile_coloring: the diagnosis is a constexpr value, so
// positive and negative cases are checked here; tests/structural/compile_fail checks a message.
namespace {
struct no_members {};
struct tile_coloring_only {  // a TileColoring without a grid size
  tessera::index_t num_faces() const { return 4; }
  int num_colors(int) const { return 2; }
  int edge_color(tessera::index_t, int) const { return 0; }
};
struct plane_without_edge_color_at {
  int num_colors(int) const { return 2; }
};
struct plane_ok {
  int num_colors(int) const { return 2; }
  int edge_color_at(tessera::index_t, tessera::index_t, int) const { return 0; }
};
using problem = tessera::detail::tiling_coloring_problem;
static_assert(tessera::detail::grid_coloring_problem_of<tessera::scanline_coloring>() == problem::none);
static_assert(tessera::detail::grid_coloring_problem_of<tessera::hash_coloring_window>() == problem::none);
static_assert(tessera::detail::grid_coloring_problem_of<no_members>() == problem::not_tile_coloring);
static_assert(tessera::detail::grid_coloring_problem_of<tile_coloring_only>() == problem::no_grid_size);
static_assert(tessera::detail::grid_coloring_problem_of<tessera::stored_tile_coloring>() == problem::no_grid_size);
static_assert(tessera::detail::plane_coloring_problem_of<tessera::hash_coloring>() == problem::none);
static_assert(tessera::detail::plane_coloring_problem_of<plane_ok>() == problem::none);
static_assert(tessera::detail::plane_coloring_problem_of<plane_without_edge_color_at>() == problem::no_edge_color_at);
static_assert(tessera::detail::plane_coloring_problem_of<no_members>() == problem::no_num_colors);
static_assert(tessera::detail::plane_coloring_problem_of<tessera::scanline_coloring>() == problem::is_grid);
static_assert(tessera::PlaneTileColoring<plane_ok> && !tessera::PlaneTileColoring<plane_without_edge_color_at>);

// the explain helpers compile to nothing (no static_assert fires) for types that fit
constexpr bool explain_fitting_types() {
  tessera::explain_grid_tile_coloring<tessera::scanline_coloring>();
  tessera::explain_grid_tile_coloring<tessera::grid_coloring_view<tessera::stored_tile_coloring>>();
  tessera::explain_plane_tile_coloring<tessera::hash_coloring>();
  tessera::explain_plane_tile_coloring<plane_ok>();
  return true;
}
static_assert(explain_fitting_types());
}  // namespace
