// tessera/tiling/scanline_coloring.hpp: Cohen et al.'s stochastic scanline tiling as a colouring.
//
// Cells are visited in scanline order (row 0 first, west to east). Each cell's north colour is fixed
// by the cell above and its west colour by the cell to its left; it picks uniformly at random among
// the set's tiles with that north and west (for the complete set: its east and south colours are
// free and uniform), and so fixes the colours its east and south neighbours will see. Cells of the
// first row and column have a free north or west side. Every random choice is keyed by the cell
// (counter_rng(seed) with keys (col, row)), so the colouring of a cell depends only on the seed and
// the cells above and to its left: a larger grid agrees with a smaller one on their common part.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "complete_tile_set.hpp"
#include "tile_set_edges.hpp"

TESSERA_NAMESPACE_BEGIN

/// Largest number of cells a stored grid colouring (scanline_coloring, periodic_coloring's period
/// pattern) accepts: 2^26, i.e. 1 GiB of cells at 16 bytes each (8192 x 8192 tiles, far beyond any
/// image tessera composes). Larger grids return size_overflow.
inline constexpr index_t max_coloring_cells = index_t{1} << 26;

namespace detail {
inline status validate_grid(index_t cols, index_t rows, const char* what) {
  if (cols <= 0 || rows <= 0)
    return status::invalid_argument(detail::cat(what, ": grid must be at least 1 x 1 cells, got ", cols, " x ", rows));
  if (cols > max_coloring_cells / rows)
    return status::size_overflow(detail::cat(what, ": ", cols, " x ", rows, " cells exceed max_coloring_cells = 2^26 (",
                                             max_coloring_cells, ")"));
  return {};
}
}  // namespace detail

/// A cols × rows grid colouring (face = row · cols + col) made by Cohen's stochastic scanline
/// algorithm over a given tile set. Models TileColoring. Immutable; queries are O(1), thread-safe.
class scanline_coloring {
 public:
  scanline_coloring() = default;

  /// Colours a cols × rows grid so that every cell's edges name a tile of `set`.
  /// Cohen et al. 2003 §3 (scanline tiling). Errors: non-positive grid; more than
  /// max_coloring_cells cells (size_overflow); a set lacking a tile for some (north, west) pair
  /// (check_scanline_fillable names it). O(cols · rows · log n).
  static result<scanline_coloring> create(const tile_set_edges& set, index_t cols, index_t rows,
                                          std::uint64_t seed = 1) {
    if (auto s = detail::validate_grid(cols, rows, "scanline colouring"); !s) return s;
    if (auto s = set.check_scanline_fillable(); !s) return s;
    scanline_coloring c;
    c.cols_ = cols;
    c.rows_ = rows;
    c.nh_ = set.horizontal_colors();
    c.nv_ = set.vertical_colors();
    c.cells_.resize(detail::to_size(cols * rows));
    const counter_rng rng(seed, stream_id("tiling.scanline_coloring"));
    for (index_t r = 0; r < rows; ++r)
      for (index_t col = 0; col < cols; ++col) {
        index_t pick = 0;
        if (r == 0 && col == 0) {
          pick =
              static_cast<index_t>(rng.below(static_cast<std::uint64_t>(set.size()), col, r));  // first cell: any tile
        } else {
          const std::span<const index_t> options = r > 0 && col > 0
                                                       ? set.matching(c.at(col, r - 1).south, c.at(col - 1, r).east)
                                                   : r > 0 ? set.with_north(c.at(col, r - 1).south)
                                                           : set.with_west(c.at(col - 1, r).east);
          TESSERA_ASSERT(!options.empty());
          pick = options[detail::to_size(rng.below(options.size(), col, r))];
        }
        c.cells_[detail::to_size(r * cols + col)] = set[pick];
      }
    return c;
  }

  /// A scanline colouring of the complete set for (nh, nv): every free edge uniformly random.
  static result<scanline_coloring> create(int nh, int nv, index_t cols, index_t rows, std::uint64_t seed = 1) {
    auto set = tile_set_edges::complete(nh, nv);
    if (!set) return set.error();
    return create(*set, cols, rows, seed);
  }

  /// Columns of the grid.
  [[nodiscard]] index_t cols() const noexcept { return cols_; }
  /// Rows of the grid.
  [[nodiscard]] index_t rows() const noexcept { return rows_; }
  /// cols * rows.
  [[nodiscard]] index_t num_faces() const noexcept { return cols_ * rows_; }
  /// Colours of this side's edges.
  [[nodiscard]] int num_colors(int side) const noexcept { return is_horizontal_side(side) ? nh_ : nv_; }
  /// Colour of edge `side` of face (row * cols + col).
  [[nodiscard]] int edge_color(index_t face, int side) const noexcept { return cells_[detail::to_size(face)][side]; }
  /// Colour of `side` of cell (col, row); 0 <= col < cols, 0 <= row < rows.
  [[nodiscard]] int edge_color_at(index_t col, index_t row, int side) const noexcept { return at(col, row)[side]; }
  /// The four edge colours of cell (col, row).
  [[nodiscard]] const wang_edges& edges_at(index_t col, index_t row) const noexcept { return at(col, row); }

 private:
  [[nodiscard]] const wang_edges& at(index_t col, index_t row) const noexcept {
    TESSERA_ASSERT(col >= 0 && col < cols_ && row >= 0 && row < rows_);
    return cells_[detail::to_size(row * cols_ + col)];
  }

  index_t cols_ = 0, rows_ = 0;
  int nh_ = 1, nv_ = 1;
  std::vector<wang_edges> cells_;
};

TESSERA_NAMESPACE_END
