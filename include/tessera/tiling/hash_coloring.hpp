// tessera/tiling/hash_coloring.hpp: a colouring of the infinite plane where each edge's colour is a
// hash of (seed, edge coordinates), so the tile at any cell (col, row) is known in O(1) without
// generating its neighbours (the approach of Wei 2004 for GPU tiling; here keyed through
// counter_rng, so it is the same on every platform and easy to port to a shader).
//
// Cells follow the grid convention of core/tile_coloring.hpp on the whole plane (row grows south,
// negative coordinates allowed). The horizontal edge on the north side of cell (col, row) and the
// vertical edge on its west side are the two edges "owned" by the cell; its south and east sides are
// the edges owned by (col, row + 1) and (col + 1, row), so neighbours agree by construction.
//
// With modulus m = 1 every colour is an independent uniform draw and every combination occurs: the
// complete set is needed. With m > 1 (m dividing nh and nv) each tile corner (x, y) gets a random
// potential p(x, y) in Z_m and an edge from corner a to corner b gets the colour
//     ((p(b) − p(a)) mod m) + m · r,   r uniform in [0, n / m)
// so around every cell north + east − south − west ≡ 0 (mod m): only tiles of the modular subset
// (tiling/tile_set_edges.hpp; Cohen's 8 tiles for 2 × 2 colours and m = 2) are ever asked for, and
// every colour is still uniform.
#pragma once

#include <cstdint>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "complete_tile_set.hpp"
#include "tile_set_edges.hpp"

TESSERA_NAMESPACE_BEGIN

class hash_coloring_window;

/// The hash colouring of the infinite plane. Cheap to copy; all queries O(1) and thread-safe.
class hash_coloring {
 public:
  hash_coloring() = default;

  /// A hash colouring with nh horizontal and nv vertical colours. `modulus` 1 asks for every tile
  /// combination (complete set); m > 1 only for the modular subset of m. Errors: bad colour counts,
  /// a modulus < 1 or not dividing both counts. O(1).
  static result<hash_coloring> create(int nh, int nv, std::uint64_t seed = 1, int modulus = 1) {
    if (auto s = validate_color_counts(nh, nv); !s) return s;
    if (modulus < 1 || nh % modulus != 0 || nv % modulus != 0)
      return status::invalid_argument(detail::cat("hash colouring: modulus ", modulus,
                                                  " must be >= 1 and divide both the ", nh, " horizontal and ", nv,
                                                  " vertical colour counts"));
    hash_coloring c;
    c.nh_ = nh;
    c.nv_ = nv;
    c.m_ = modulus;
    c.rng_ = counter_rng(seed, stream_id("tiling.hash_coloring"));
    return c;
  }

  /// A hash colouring that only asks for tiles `set` has: the set must contain the complete set or
  /// a whole modular subset (tile_set_edges::hash_modulus() > 0). Otherwise an unsupported status
  /// suggests the scanline colouring, which handles any set with a tile per (north, west) pair.
  static result<hash_coloring> for_set(const tile_set_edges& set, std::uint64_t seed = 1) {
    if (set.hash_modulus() == 0)
      return status::unsupported(detail::cat(
          "hash colouring: the tile set (", set.size(), " tiles over ", set.horizontal_colors(), " x ",
          set.vertical_colors(),
          " colours) contains neither the complete set nor a whole modular subset, so O(1) hashing could ask for a "
          "missing tile; use scanline_coloring for this set"));
    return create(set.horizontal_colors(), set.vertical_colors(), seed, set.hash_modulus());
  }

  /// Colours of this side's edges (horizontal for north/south, vertical for east/west).
  [[nodiscard]] int num_colors(int side) const noexcept { return is_horizontal_side(side) ? nh_ : nv_; }
  /// m: colours are drawn so that every cell satisfies a modular subset's congruence (1: the complete set).
  [[nodiscard]] int modulus() const noexcept { return m_; }

  /// Colour of `side` of cell (col, row) of the infinite plane. O(1).
  [[nodiscard]] int edge_color_at(index_t col, index_t row, int side) const noexcept {
    switch (side) {
      case side_north: return horizontal(col, row);
      case side_south: return horizontal(col, next(row));
      case side_west: return vertical(col, row);
      default: return vertical(next(col), row);
    }
  }
  /// All four colours of cell (col, row). O(1).
  [[nodiscard]] wang_edges edges_at(index_t col, index_t row) const noexcept {
    return {horizontal(col, row), vertical(next(col), row), horizontal(col, next(row)), vertical(col, row)};
  }

  /// The same colouring made periodic: colours repeat every `period_cols` cells eastwards and
  /// `period_rows` cells southwards (hashes are taken of coordinates modulo the period, potentials
  /// included), so the colouring is consistent on the torus of that size. Errors: a period < 1.
  [[nodiscard]] result<hash_coloring> with_period(index_t period_cols, index_t period_rows) const {
    if (period_cols < 1 || period_rows < 1)
      return status::invalid_argument(
          detail::cat("hash colouring: period must be at least 1 x 1 cells, got ", period_cols, " x ", period_rows));
    hash_coloring c = *this;
    c.period_cols_ = period_cols;
    c.period_rows_ = period_rows;
    return c;
  }
  /// The period (0 x 0 when aperiodic).
  [[nodiscard]] index_t period_cols() const noexcept { return period_cols_; }
  /// The period in rows (0 when aperiodic).
  [[nodiscard]] index_t period_rows() const noexcept { return period_rows_; }

  /// A cols × rows window whose cell (0, 0) is plane cell (origin_col, origin_row); models
  /// TileColoring. Errors: non-positive size.
  [[nodiscard]] result<hash_coloring_window> window(index_t origin_col, index_t origin_row, index_t cols,
                                                    index_t rows) const;

 private:
  // v + 1, wrapping at the ends of the index range (coordinates are only hash keys)
  [[nodiscard]] static index_t next(index_t v) noexcept {
    return static_cast<index_t>(static_cast<std::uint64_t>(v) + 1u);
  }
  [[nodiscard]] static index_t wrap(index_t v, index_t period) noexcept {
    if (period == 0) return v;
    const index_t r = v % period;
    return r < 0 ? r + period : r;
  }
  // a uniform integer in [0, n) for (kind, x, y), coordinates taken modulo the period
  [[nodiscard]] std::uint64_t below(index_t n, int kind, index_t x, index_t y) const noexcept {
    return rng_.below(static_cast<std::uint64_t>(n), kind, wrap(x, period_cols_), wrap(y, period_rows_));
  }
  // potential of tile corner (x, y) (the north-west corner of cell (x, y)) in Z_m
  [[nodiscard]] int potential(index_t x, index_t y) const noexcept { return static_cast<int>(below(m_, 0, x, y)); }
  [[nodiscard]] int structured(int a, int b) const noexcept { return ((b - a) % m_ + m_) % m_; }
  // the horizontal edge from corner (col, row) to (col + 1, row): north side of cell (col, row)
  [[nodiscard]] int horizontal(index_t col, index_t row) const noexcept {
    const int free = static_cast<int>(below(nh_ / m_, 1, col, row));
    if (m_ == 1) return free;
    return structured(potential(col, row), potential(next(col), row)) + m_ * free;
  }
  // the vertical edge from corner (col, row) to (col, row + 1): west side of cell (col, row)
  [[nodiscard]] int vertical(index_t col, index_t row) const noexcept {
    const int free = static_cast<int>(below(nv_ / m_, 2, col, row));
    if (m_ == 1) return free;
    return structured(potential(col, row), potential(col, next(row))) + m_ * free;
  }

  int nh_ = 1, nv_ = 1, m_ = 1;
  index_t period_cols_ = 0, period_rows_ = 0;
  counter_rng rng_{0};
};

/// A finite window of a hash_coloring: face = row · cols + col, cell (col, row) of the window is
/// plane cell (origin_col + col, origin_row + row), the sum wrapping at the ends of the index range
/// (a window may straddle them). Models TileColoring; O(1) queries.
class hash_coloring_window {
 public:
  /// Unchecked: use hash_coloring::window().
  hash_coloring_window(const hash_coloring& plane, index_t origin_col, index_t origin_row, index_t cols,
                       index_t rows) noexcept
      : plane_(plane), origin_col_(origin_col), origin_row_(origin_row), cols_(cols), rows_(rows) {}

  /// Columns of the window.
  [[nodiscard]] index_t cols() const noexcept { return cols_; }
  /// Rows of the window.
  [[nodiscard]] index_t rows() const noexcept { return rows_; }
  /// Plane column of window column 0.
  [[nodiscard]] index_t origin_col() const noexcept { return origin_col_; }
  /// Plane row of window row 0.
  [[nodiscard]] index_t origin_row() const noexcept { return origin_row_; }
  /// cols * rows.
  [[nodiscard]] index_t num_faces() const noexcept { return cols_ * rows_; }
  /// Colours of this side's edges.
  [[nodiscard]] int num_colors(int side) const noexcept { return plane_.num_colors(side); }
  /// Colour of edge `side` of face (row * cols + col).
  [[nodiscard]] int edge_color(index_t face, int side) const noexcept {
    return edge_color_at(face % cols_, face / cols_, side);
  }
  /// Colour of edge `side` of window cell (col, row).
  [[nodiscard]] int edge_color_at(index_t col, index_t row, int side) const noexcept {
    return plane_.edge_color_at(add(origin_col_, col), add(origin_row_, row), side);
  }
  /// The four edge colours of window cell (col, row).
  [[nodiscard]] wang_edges edges_at(index_t col, index_t row) const noexcept {
    return plane_.edges_at(add(origin_col_, col), add(origin_row_, row));
  }
  /// The infinite colouring the window shows.
  [[nodiscard]] const hash_coloring& plane() const noexcept { return plane_; }

 private:
  // origin + offset, wrapping at the ends of the index range like the plane's own coordinates
  [[nodiscard]] static index_t add(index_t a, index_t b) noexcept {
    return static_cast<index_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
  }
  hash_coloring plane_;
  index_t origin_col_, origin_row_, cols_, rows_;
};

inline result<hash_coloring_window> hash_coloring::window(index_t origin_col, index_t origin_row, index_t cols,
                                                          index_t rows) const {
  if (cols <= 0 || rows <= 0)
    return status::invalid_argument(
        detail::cat("hash colouring window: size must be at least 1 x 1 cells, got ", cols, " x ", rows));
  if (cols > (index_t{1} << 32) / rows)
    return status::size_overflow(
        detail::cat("hash colouring window: ", cols, " x ", rows, " cells exceed the supported 2^32"));
  return hash_coloring_window(*this, origin_col, origin_row, cols, rows);
}

TESSERA_NAMESPACE_END
