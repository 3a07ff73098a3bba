// tessera/tiling/periodic_coloring.hpp: a colouring whose colours repeat with a given period.
//
// The period pattern (period_cols × period_rows cells) is itself a valid colouring of the torus of
// that size, so any grid whose size is a multiple of the period is consistent when wrapped, and the
// tiled image made from it tiles seamlessly with itself (a periodic texture built from Wang tiles).
// For sets the hash colouring supports (complete, or a whole modular subset) the pattern is the hash
// colouring taken modulo the period; for other subsets it is found by a seeded depth-first search
// over the torus, which may report that no pattern of that period exists.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "complete_tile_set.hpp"
#include "hash_coloring.hpp"
#include "scanline_coloring.hpp"
#include "tile_set_edges.hpp"

TESSERA_NAMESPACE_BEGIN

/// A cols × rows grid colouring (face = row · cols + col) repeating a period pattern; also answers
/// for any cell of the infinite plane. Models TileColoring. Immutable; O(1) queries; thread-safe.
class periodic_coloring {
 public:
  periodic_coloring() = default;

  /// A periodic colouring of a cols × rows grid with a random period pattern of
  /// period_cols × period_rows cells whose edges all name tiles of `set`.
  /// Errors: non-positive sizes; a period or a grid of more than max_coloring_cells cells
  /// (size_overflow); no toroidal pattern of that period for this set (invalid_argument), or the
  /// search budget of `max_search_steps` exhausted (not_converged).
  /// Complexity: O(cols · rows) for hashable sets; the search is exponential in the worst case but
  /// bounded by max_search_steps.
  static result<periodic_coloring> create(const tile_set_edges& set, index_t period_cols, index_t period_rows,
                                          index_t cols, index_t rows, std::uint64_t seed = 1,
                                          index_t max_search_steps = 1'000'000) {
    if (auto s = detail::validate_grid(period_cols, period_rows, "periodic colouring period"); !s) return s;
    if (auto s = detail::validate_grid(cols, rows, "periodic colouring"); !s) return s;
    periodic_coloring c;
    c.period_cols_ = period_cols;
    c.period_rows_ = period_rows;
    c.cols_ = cols;
    c.rows_ = rows;
    c.nh_ = set.horizontal_colors();
    c.nv_ = set.vertical_colors();
    c.pattern_.resize(detail::to_size(period_cols * period_rows));
    if (set.hash_modulus() > 0) {
      auto plane = hash_coloring::for_set(set, seed);
      if (!plane) return plane.error();
      auto periodic = plane->with_period(period_cols, period_rows);
      if (!periodic) return periodic.error();
      for (index_t r = 0; r < period_rows; ++r)
        for (index_t col = 0; col < period_cols; ++col)
          c.pattern_[detail::to_size(r * period_cols + col)] = periodic->edges_at(col, r);
      return c;
    }
    if (auto s = c.search(set, seed, max_search_steps); !s) return s;
    return c;
  }

  /// Columns of the grid.
  [[nodiscard]] index_t cols() const noexcept { return cols_; }
  /// Rows of the grid.
  [[nodiscard]] index_t rows() const noexcept { return rows_; }
  /// Columns of the repeated pattern.
  [[nodiscard]] index_t period_cols() const noexcept { return period_cols_; }
  /// Rows of the repeated pattern.
  [[nodiscard]] index_t period_rows() const noexcept { return period_rows_; }
  /// cols * rows.
  [[nodiscard]] index_t num_faces() const noexcept { return cols_ * rows_; }
  /// Colours of this side's edges.
  [[nodiscard]] int num_colors(int side) const noexcept { return is_horizontal_side(side) ? nh_ : nv_; }
  /// Colour of edge `side` of face (row * cols + col).
  [[nodiscard]] int edge_color(index_t face, int side) const noexcept {
    return edge_color_at(face % cols_, face / cols_, side);
  }
  /// Colour of `side` of cell (col, row) of the infinite periodic plane (any integers).
  [[nodiscard]] int edge_color_at(index_t col, index_t row, int side) const noexcept {
    return edges_at(col, row)[side];
  }
  /// The four edge colours of cell (col, row).
  [[nodiscard]] const wang_edges& edges_at(index_t col, index_t row) const noexcept {
    return pattern_[detail::to_size(wrap(row, period_rows_) * period_cols_ + wrap(col, period_cols_))];
  }

 private:
  static index_t wrap(index_t v, index_t p) noexcept {
    const index_t r = v % p;
    return r < 0 ? r + p : r;
  }

  // Depth-first search over the torus in scanline order. Cell k's candidates: tiles agreeing with the
  // cell above and to the left and, in the last row / column, with the wrapped first row / column.
  status search(const tile_set_edges& set, std::uint64_t seed, index_t max_steps) {
    const index_t P = period_cols_, Q = period_rows_, n = P * Q;
    const counter_rng rng(seed, stream_id("tiling.periodic_coloring"));
    std::vector<std::vector<index_t>> candidates(detail::to_size(n));
    std::vector<std::size_t> next(detail::to_size(n), 0);
    auto tile_at = [&](index_t col, index_t row) -> const wang_edges& {
      return pattern_[detail::to_size(row * P + col)];
    };
    auto gather = [&](index_t k) {
      const index_t col = k % P, row = k / P;
      std::vector<index_t>& out = candidates[detail::to_size(k)];
      out.clear();
      for (index_t t = 0; t < set.size(); ++t) {
        const wang_edges& e = set[t];
        if (row > 0 && e.north != tile_at(col, row - 1).south) continue;
        if (col > 0 && e.west != tile_at(col - 1, row).east) continue;
        if (col == P - 1 && (P == 1 ? e.east != e.west : e.east != tile_at(0, row).west)) continue;
        if (row == Q - 1 && (Q == 1 ? e.south != e.north : e.south != tile_at(col, 0).north)) continue;
        out.push_back(t);
      }
      // a seeded order per cell, keyed by (cell, tile): independent of the search history
      std::sort(out.begin(), out.end(), [&](index_t a, index_t b) {
        const std::uint64_t ha = rng.bits(col, row, a), hb = rng.bits(col, row, b);
        return ha != hb ? ha < hb : a < b;
      });
      next[detail::to_size(k)] = 0;
    };
    index_t k = 0, steps = 0;
    gather(0);
    while (k < n) {
      if (++steps > max_steps)
        return status::not_converged(detail::cat("periodic colouring: no ", P, " x ", Q, " pattern found within ",
                                                 max_steps, " search steps; try another period or a complete set"));
      auto& options = candidates[detail::to_size(k)];
      auto& i = next[detail::to_size(k)];
      if (i < options.size()) {
        pattern_[detail::to_size(k)] = set[options[i++]];
        if (++k < n) gather(k);
      } else if (k == 0) {
        return status::invalid_argument(
            detail::cat("periodic colouring: the tile set admits no periodic pattern of ", P, " x ", Q, " cells"));
      } else {
        --k;  // backtrack
      }
    }
    return {};
  }

  index_t period_cols_ = 1, period_rows_ = 1, cols_ = 0, rows_ = 0;
  int nh_ = 1, nv_ = 1;
  std::vector<wang_edges> pattern_;
};

TESSERA_NAMESPACE_END
