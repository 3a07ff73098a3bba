// tessera/tiling/tile_lookup.hpp: which tile sits in a cell. Shared by tiled image output
// (image/compose_tiles.hpp), the GPU atlas mapping (image/wang_atlas.hpp) and geometric tiling.
//
// Two kinds of colourings place tiles on a grid of cells:
//   GridTileColoring   a finite cols × rows grid (face = row · cols + col): scanline_coloring,
//                      periodic_coloring, hash_coloring_window, or any TileColoring wrapped in
//                      grid_coloring_view;
//   PlaneTileColoring  the infinite plane, edge_color_at(col, row, side) for any integers:
//                      hash_coloring.
// The tile of a cell is the set's tile with the cell's four edge colours; when the set holds several
// variants with those edges, one is drawn at random keyed by (seed, col, row), so every consumer
// that uses tile_at_cell agrees on it.
#pragma once

#include <concepts>
#include <cstdint>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/tile_coloring.hpp"
#include "complete_tile_set.hpp"
#include "tile_set_edges.hpp"

TESSERA_NAMESPACE_BEGIN

/// A TileColoring of a finite cols × rows grid (face = row · cols + col).
template <class C>
concept GridTileColoring = TileColoring<C> && requires(const C& c) {
  { c.cols() } -> std::convertible_to<index_t>;
  { c.rows() } -> std::convertible_to<index_t>;
};

/// A colouring of every cell of the infinite plane (negative coordinates included).
template <class C>
concept PlaneTileColoring = !GridTileColoring<C> && requires(const C& c, index_t col, index_t row, int side) {
  { c.edge_color_at(col, row, side) } -> std::convertible_to<int>;
  { c.num_colors(side) } -> std::convertible_to<int>;
};

/// Views any TileColoring as a grid with `cols` columns (rows = num_faces / cols).
template <TileColoring C>
struct grid_coloring_view {
  const C* coloring = nullptr;
  index_t grid_cols = 1;
  [[nodiscard]] index_t cols() const noexcept { return grid_cols; }
  [[nodiscard]] index_t rows() const noexcept { return grid_cols > 0 ? coloring->num_faces() / grid_cols : 0; }
  [[nodiscard]] index_t num_faces() const noexcept { return coloring->num_faces(); }
  [[nodiscard]] int num_colors(int side) const noexcept { return static_cast<int>(coloring->num_colors(side)); }
  [[nodiscard]] int edge_color(index_t face, int side) const noexcept { return static_cast<int>(coloring->edge_color(face, side)); }
};

/// The four colours of cell (col, row). For grid colourings the cell must lie in the grid.
template <class C>
  requires GridTileColoring<C> || PlaneTileColoring<C>
wang_edges cell_edges(const C& c, index_t col, index_t row) noexcept {
  if constexpr (GridTileColoring<C>) {
    const index_t f = row * static_cast<index_t>(c.cols()) + col;
    return {static_cast<int>(c.edge_color(f, side_north)), static_cast<int>(c.edge_color(f, side_east)),
            static_cast<int>(c.edge_color(f, side_south)), static_cast<int>(c.edge_color(f, side_west))};
  } else {
    return {static_cast<int>(c.edge_color_at(col, row, side_north)), static_cast<int>(c.edge_color_at(col, row, side_east)),
            static_cast<int>(c.edge_color_at(col, row, side_south)), static_cast<int>(c.edge_color_at(col, row, side_west))};
  }
}

/// The tile of `set` placed in cell (col, row) whose edges are `e`: the only tile with these edges,
/// or one of its variants drawn by (seed, col, row); -1 when the set has no such tile. O(log n).
inline index_t tile_at_cell(const tile_set_edges& set, const wang_edges& e, std::uint64_t seed, index_t col, index_t row) noexcept {
  const auto v = set.variants(e);
  if (v.empty()) return -1;
  if (v.size() == 1) return v.front();
  const counter_rng rng(seed, stream_id("tiling.variant"));
  return v[static_cast<std::size_t>(rng.below(v.size(), col, row))];
}

/// Floor division for cell coordinates of possibly negative plane positions.
constexpr index_t floor_div(index_t a, index_t b) noexcept {
  const index_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

TESSERA_NAMESPACE_END
