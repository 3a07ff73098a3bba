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
// that uses tile_at_cell agrees on it. explain_grid_tile_coloring<T>() and
// explain_plane_tile_coloring<T>() say in one static_assert what a type lacks.
#pragma once

#include <concepts>
#include <cstdint>
#include <limits>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
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

/// True when a grid colouring agrees with itself: cols() and rows() positive and cols · rows ==
/// num_faces() (a user type may not). O(1).
template <GridTileColoring C>
bool grid_coloring_consistent(const C& c) noexcept {
  const index_t cols = static_cast<index_t>(c.cols()), rows = static_cast<index_t>(c.rows());
  const index_t faces = static_cast<index_t>(c.num_faces());
  return cols > 0 && rows > 0 && cols <= std::numeric_limits<index_t>::max() / rows && cols * rows == faces;
}

/// Checks grid_coloring_consistent; the message names cols(), rows() and num_faces().
template <GridTileColoring C>
status validate_grid_coloring(const C& c) {
  if (grid_coloring_consistent(c)) return {};
  return status::invalid_argument(detail::cat("grid colouring: cols() x rows() = ", static_cast<index_t>(c.cols()),
                                              " x ", static_cast<index_t>(c.rows()),
                                              " does not match num_faces() = ", static_cast<index_t>(c.num_faces()),
                                              " (face = row * cols + col must cover the grid exactly)"));
}

/// Views any TileColoring as a grid with `cols` columns (rows = num_faces / cols).
template <TileColoring C>
struct grid_coloring_view {
  /// The viewed colouring (not owned).
  const C* coloring = nullptr;
  /// Columns of the grid.
  index_t grid_cols = 1;
  /// Columns of the grid.
  [[nodiscard]] index_t cols() const noexcept { return grid_cols; }
  /// num_faces / cols.
  [[nodiscard]] index_t rows() const noexcept { return grid_cols > 0 ? coloring->num_faces() / grid_cols : 0; }
  /// The colouring's face count.
  [[nodiscard]] index_t num_faces() const noexcept { return coloring->num_faces(); }
  /// The colouring's colour count for this side.
  [[nodiscard]] int num_colors(int side) const noexcept { return static_cast<int>(coloring->num_colors(side)); }
  /// The colouring's colour of edge `side` of face.
  [[nodiscard]] int edge_color(index_t face, int side) const noexcept {
    return static_cast<int>(coloring->edge_color(face, side));
  }
};

/// The four colours of cell (col, row). For grid colourings the cell must lie in the grid.
template <class C>
requires GridTileColoring<C> || PlaneTileColoring<C> wang_edges cell_edges(const C& c, index_t col, index_t row)
noexcept {
  if constexpr (GridTileColoring<C>) {
    const index_t f = row * static_cast<index_t>(c.cols()) + col;
    return {static_cast<int>(c.edge_color(f, side_north)), static_cast<int>(c.edge_color(f, side_east)),
            static_cast<int>(c.edge_color(f, side_south)), static_cast<int>(c.edge_color(f, side_west))};
  } else {
    return {static_cast<int>(c.edge_color_at(col, row, side_north)),
            static_cast<int>(c.edge_color_at(col, row, side_east)),
            static_cast<int>(c.edge_color_at(col, row, side_south)),
            static_cast<int>(c.edge_color_at(col, row, side_west))};
  }
}

/// The tile of `set` placed in cell (col, row) whose edges are `e`: the only tile with these edges,
/// or one of its variants drawn by (seed, col, row); -1 when the set has no such tile. O(log n).
inline index_t tile_at_cell(const tile_set_edges& set, const wang_edges& e, std::uint64_t seed, index_t col,
                            index_t row) noexcept {
  const auto v = set.variants(e);
  if (v.empty()) return -1;
  if (v.size() == 1) return v.front();
  const counter_rng rng(seed, stream_id("tiling.variant"));
  return v[detail::to_size(rng.below(v.size(), col, row))];
}

namespace detail {
/// The first requirement of GridTileColoring / PlaneTileColoring a type misses.
enum class tiling_coloring_problem {
  none,
  not_tile_coloring,  ///< grid: no num_faces() / num_colors(side) / edge_color(face, side)
  no_grid_size,       ///< grid: no cols() / rows()
  no_num_colors,      ///< plane: no num_colors(side)
  no_edge_color_at,   ///< plane: no edge_color_at(col, row, side)
  is_grid             ///< plane: the type is a GridTileColoring (it has cols() and rows())
};
template <class T>
concept has_grid_size = requires(const T& c) {
  { c.cols() } -> std::convertible_to<index_t>;
  { c.rows() } -> std::convertible_to<index_t>;
};
template <class T>
concept has_num_colors = requires(const T& c, int side) {
  { c.num_colors(side) } -> std::convertible_to<int>;
};
template <class T>
concept has_edge_color_at = requires(const T& c, index_t col, index_t row, int side) {
  { c.edge_color_at(col, row, side) } -> std::convertible_to<int>;
};
template <class T>
constexpr tiling_coloring_problem grid_coloring_problem_of() {
  if constexpr (!TileColoring<T>)
    return tiling_coloring_problem::not_tile_coloring;
  else if constexpr (!has_grid_size<T>)
    return tiling_coloring_problem::no_grid_size;
  else
    return tiling_coloring_problem::none;
}
template <class T>
constexpr tiling_coloring_problem plane_coloring_problem_of() {
  if constexpr (GridTileColoring<T>)
    return tiling_coloring_problem::is_grid;
  else if constexpr (!has_num_colors<T>)
    return tiling_coloring_problem::no_num_colors;
  else if constexpr (!has_edge_color_at<T>)
    return tiling_coloring_problem::no_edge_color_at;
  else
    return tiling_coloring_problem::none;
}
}  // namespace detail

/// Reports, as one readable static_assert, the first reason T is not a GridTileColoring (the
/// colourings compose_tiles and atlas_coordinates take for finite grids); compiles to nothing when
/// T fits. Use it where a compile error about the concept is unclear.
template <class T>
constexpr void explain_grid_tile_coloring() {
  using detail::tiling_coloring_problem;
  constexpr tiling_coloring_problem p = detail::grid_coloring_problem_of<T>();
  static_assert(p != tiling_coloring_problem::not_tile_coloring,
                "tessera::GridTileColoring: the type is not a TileColoring. Add members `index_t num_faces() const`, "
                "`int num_colors(int side) const` and `int edge_color(index_t face, int side) const` (side 0 north, "
                "1 east, 2 south, 3 west; face = row * cols + col); or copy it into a tessera::stored_tile_coloring.");
  static_assert(p != tiling_coloring_problem::no_grid_size,
                "tessera::GridTileColoring: the type has no grid size. Add members `index_t cols() const` and "
                "`index_t rows() const` (cols * rows == num_faces()), or pass the column count to "
                "compose_tiles(set, coloring, cols, out), which wraps it in tessera::grid_coloring_view.");
}

/// Reports, as one readable static_assert, the first reason T is not a PlaneTileColoring (a
/// colouring of every cell of the infinite plane, like hash_coloring); compiles to nothing when T
/// fits.
template <class T>
constexpr void explain_plane_tile_coloring() {
  using detail::tiling_coloring_problem;
  constexpr tiling_coloring_problem p = detail::plane_coloring_problem_of<T>();
  static_assert(
      p != tiling_coloring_problem::is_grid,
      "tessera::PlaneTileColoring: the type has cols() and rows(), so it is a GridTileColoring (a finite "
      "grid); algorithms taking either accept it as such. Remove cols()/rows() to make it a plane colouring.");
  static_assert(p != tiling_coloring_problem::no_num_colors,
                "tessera::PlaneTileColoring: the type has no `int num_colors(int side) const` (colours of north/south "
                "sides for side 0 or 2, of east/west sides for 1 or 3).");
  static_assert(
      p != tiling_coloring_problem::no_edge_color_at,
      "tessera::PlaneTileColoring: the type has no `int edge_color_at(index_t col, index_t row, int side) const` "
      "answering for every cell of the plane (negative coordinates included; side 0 north, 1 east, 2 south, "
      "3 west).");
}

/// Floor division for cell coordinates of possibly negative plane positions.
constexpr index_t floor_div(index_t a, index_t b) noexcept {
  const index_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

TESSERA_NAMESPACE_END
