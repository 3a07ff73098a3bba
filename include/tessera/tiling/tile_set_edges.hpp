// tessera/tiling/tile_set_edges.hpp: the edges of a Wang tile set (complete or a subset) with the
// lookups colourings and tiled output need, Cohen-style subsets, and the check that a colouring only
// asks for tiles the set has.
//
// A set may hold fewer than nh² · nv² tiles: Cohen et al. (2003) use 8 tiles for 2 × 2 colours, two
// for every (north, west) pair, which is enough for their scanline tiling. A set may also hold several
// tiles with the same edges (variants); tiled output then picks one per cell at random.
//
// Modular subsets. For a modulus m dividing both nh and nv, the tiles with
//     (north + east − south − west) ≡ 0  (mod m)
// form a subset of nh² · nv² / m tiles with nh · nv / m tiles for every (north, west) pair. For
// 2 × 2 colours and m = 2 that is Cohen's 8-tile set. Unlike arbitrary subsets these can be tiled
// by the O(1) hash colouring (tiling/hash_coloring.hpp): colours there are differences of a random
// potential on tile corners, which satisfies the congruence around every cell.
#pragma once

#include <algorithm>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "complete_tile_set.hpp"

TESSERA_NAMESPACE_BEGIN

/// The edges of a tile set plus lookups by full edges, by (north, west), by west and by north.
/// Immutable after creation; all queries are O(log n) and thread-safe.
class tile_set_edges {
 public:
  tile_set_edges() = default;

  /// A set of `tiles` (edges in any order, duplicates allowed as variants) over nh horizontal and nv
  /// vertical colours. Fails on bad colour counts, an empty list, more than 2^26 tiles, or an edge
  /// colour out of range (the message names the tile and side). O(n log n).
  static result<tile_set_edges> create(int nh, int nv, std::vector<wang_edges> tiles) {
    if (auto s = validate_color_counts(nh, nv); !s) return s;
    if (tiles.empty()) return status::invalid_argument("tile set: the set holds no tiles");
    if (tiles.size() > (std::size_t{1} << 26))
      return status::size_overflow(detail::cat("tile set: ", tiles.size(), " tiles exceed the supported 2^26"));
    for (std::size_t i = 0; i < tiles.size(); ++i)
      if (auto s = validate_wang_edges(tiles[i], nh, nv); !s)
        return status(s.code(), detail::cat("tile set: tile ", i, ": ", s.message()));
    tile_set_edges set;
    set.nh_ = nh;
    set.nv_ = nv;
    set.tiles_ = std::move(tiles);
    set.build_lookups();
    return set;
  }

  /// The complete set, tiles in complete_tile_index order. O(nh² · nv²).
  static result<tile_set_edges> complete(int nh, int nv) {
    auto edges = complete_tile_set_edges(nh, nv);
    if (!edges) return edges.error();
    return create(nh, nv, std::move(*edges));
  }

  /// The modular subset for modulus m (see the header comment): tiles with
  /// (north + east − south − west) ≡ 0 (mod m), in complete_tile_index order. m = 2 with 2 × 2
  /// colours gives Cohen's 8 tiles. Fails unless m >= 1 divides both nh and nv. O(nh² · nv²).
  static result<tile_set_edges> modular_subset(int nh, int nv, int modulus) {
    if (auto s = validate_color_counts(nh, nv); !s) return s;
    if (modulus < 1 || nh % modulus != 0 || nv % modulus != 0)
      return status::invalid_argument(detail::cat("tile set: modulus ", modulus, " must be >= 1 and divide both the ",
                                                  nh, " horizontal and ", nv, " vertical colour counts"));
    auto all = complete_tile_set_edges(nh, nv);
    if (!all) return all.error();
    std::vector<wang_edges> kept;
    for (const wang_edges& e : *all)
      if (in_modular_subset(e, modulus)) kept.push_back(e);
    return create(nh, nv, std::move(kept));
  }

  /// True when `e` satisfies (north + east − south − west) ≡ 0 (mod m).
  static constexpr bool in_modular_subset(const wang_edges& e, int modulus) noexcept {
    const int r = (e.north + e.east - e.south - e.west) % modulus;
    return r == 0;
  }

  /// nh, colours of north/south edges.
  [[nodiscard]] int horizontal_colors() const noexcept { return nh_; }
  /// nv, colours of east/west edges.
  [[nodiscard]] int vertical_colors() const noexcept { return nv_; }
  /// Colour count of a side (north/south: horizontal, east/west: vertical).
  [[nodiscard]] int num_colors(int side) const noexcept { return is_horizontal_side(side) ? nh_ : nv_; }
  /// Number of tiles.
  [[nodiscard]] index_t size() const noexcept { return static_cast<index_t>(tiles_.size()); }
  /// The tiles' edges, in tile order.
  [[nodiscard]] std::span<const wang_edges> tiles() const noexcept { return tiles_; }
  /// The edges of one tile.
  [[nodiscard]] const wang_edges& operator[](index_t tile) const noexcept {
    TESSERA_ASSERT(tile >= 0 && tile < size());
    return tiles_[detail::to_size(tile)];
  }

  /// All tiles with exactly these edges, in increasing index order (empty when none).
  [[nodiscard]] std::span<const index_t> variants(const wang_edges& e) const noexcept {
    if (e.north < 0 || e.north >= nh_ || e.south < 0 || e.south >= nh_ || e.east < 0 || e.east >= nv_ || e.west < 0 ||
        e.west >= nv_)
      return {};
    return range(by_edges_, complete_tile_index(e, nh_, nv_),
                 [&](index_t t) { return complete_tile_index((*this)[t], nh_, nv_); });
  }
  /// The first tile with these edges, or -1.
  [[nodiscard]] index_t find(const wang_edges& e) const noexcept {
    const auto v = variants(e);
    return v.empty() ? index_t{-1} : v.front();
  }
  /// Tiles whose north and west sides carry these colours, in index order.
  [[nodiscard]] std::span<const index_t> matching(int north, int west) const noexcept {
    return range(by_north_west_, static_cast<index_t>(north) * nv_ + west,
                 [&](index_t t) { return static_cast<index_t>((*this)[t].north) * nv_ + (*this)[t].west; });
  }
  /// Tiles whose west side carries this colour (north free), in index order.
  [[nodiscard]] std::span<const index_t> with_west(int west) const noexcept {
    return range(by_west_, west, [&](index_t t) { return index_t{(*this)[t].west}; });
  }
  /// Tiles whose north side carries this colour (west free), in index order.
  [[nodiscard]] std::span<const index_t> with_north(int north) const noexcept {
    return range(by_north_, north, [&](index_t t) { return index_t{(*this)[t].north}; });
  }
  /// Number of distinct edge combinations in the set.
  [[nodiscard]] index_t distinct_combinations() const noexcept { return distinct_; }
  /// True when every one of the nh² · nv² combinations is present.
  [[nodiscard]] bool is_complete() const noexcept { return distinct_ == complete_tile_count(nh_, nv_); }
  /// The smallest modulus m such that the set contains the whole modular subset for m (1 when
  /// complete), or 0 when it contains none: the hash colouring needs it.
  [[nodiscard]] int hash_modulus() const noexcept { return hash_modulus_; }

  /// Ok when every (north, west) pair has at least one tile (what the scanline colouring needs);
  /// otherwise names the first missing pair.
  [[nodiscard]] status check_scanline_fillable() const {
    for (int n = 0; n < nh_; ++n)
      for (int w = 0; w < nv_; ++w)
        if (matching(n, w).empty())
          return status::invalid_argument(detail::cat("tile set has no tile with north colour ", n, " and west colour ",
                                                      w,
                                                      "; a scanline colouring needs one for every (north, west) pair"));
    return {};
  }

 private:
  template <class Key>
  std::span<const index_t> range(const std::vector<index_t>& order, index_t key, Key&& key_of) const noexcept {
    auto lo = std::partition_point(order.begin(), order.end(), [&](index_t t) { return key_of(t) < key; });
    auto hi = std::partition_point(lo, order.end(), [&](index_t t) { return key_of(t) <= key; });
    return {order.data() + (lo - order.begin()), detail::to_size(hi - lo)};
  }

  void build_lookups() {
    const index_t n = size();
    // tile indices ordered by a key, ties by index: one (key, index) sort serves the four keys
    std::vector<std::pair<index_t, index_t>> keyed(detail::to_size(n));
    auto sorted_by = [&](int which) {
      for (index_t t = 0; t < n; ++t) {
        const wang_edges& e = (*this)[t];
        const index_t key = which == 0   ? complete_tile_index(e, nh_, nv_)
                            : which == 1 ? static_cast<index_t>(e.north) * nv_ + e.west
                            : which == 2 ? index_t{e.west}
                                         : index_t{e.north};
        keyed[detail::to_size(t)] = {key, t};
      }
      std::sort(keyed.begin(), keyed.end());
      std::vector<index_t> order(keyed.size());
      for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
      return order;
    };
    by_edges_ = sorted_by(0);
    by_north_west_ = sorted_by(1);
    by_west_ = sorted_by(2);
    by_north_ = sorted_by(3);
    distinct_ = 0;
    for (index_t i = 0; i < n; ++i)
      if (i == 0 || complete_tile_index((*this)[by_edges_[detail::to_size(i)]], nh_, nv_) !=
                        complete_tile_index((*this)[by_edges_[detail::to_size(i - 1)]], nh_, nv_))
        ++distinct_;
    hash_modulus_ = 0;
    const int g = std::gcd(nh_, nv_);
    for (int m = 1; m <= g && hash_modulus_ == 0; ++m) {
      if (g % m != 0) continue;
      index_t members = 0;  // distinct combinations of the set inside the modular subset for m
      for (index_t i = 0; i < n; ++i) {
        const wang_edges& e = (*this)[by_edges_[detail::to_size(i)]];
        const bool first = i == 0 || complete_tile_index(e, nh_, nv_) !=
                                         complete_tile_index((*this)[by_edges_[detail::to_size(i - 1)]], nh_, nv_);
        if (first && in_modular_subset(e, m)) ++members;
      }
      if (members == complete_tile_count(nh_, nv_) / m) hash_modulus_ = m;
    }
  }

  int nh_ = 1;
  int nv_ = 1;
  std::vector<wang_edges> tiles_;
  std::vector<index_t> by_edges_, by_north_west_, by_west_, by_north_;
  index_t distinct_ = 0;
  int hash_modulus_ = 0;
};

/// Checks a colouring against a tile set: colour counts equal the set's, every colour is in range,
/// and every face's edge combination has a tile in the set. The message names the first face without
/// a tile and its four colours. Neighbour consistency is check_grid_coloring's job
/// (core/tile_coloring.hpp). O(faces · log n); thread-safe.
template <TileColoring C>
status check_coloring_against_set(const C& coloring, const tile_set_edges& set) {
  if (coloring.num_colors(side_north) != set.horizontal_colors() ||
      coloring.num_colors(side_east) != set.vertical_colors())
    return status::invalid_argument(detail::cat(
        "colouring uses ", coloring.num_colors(side_north), " horizontal and ", coloring.num_colors(side_east),
        " vertical colours but the tile set has ", set.horizontal_colors(), " and ", set.vertical_colors()));
  if (auto s = check_color_ranges(coloring); !s) return s;
  for (index_t f = 0; f < coloring.num_faces(); ++f) {
    const wang_edges e{
        static_cast<int>(coloring.edge_color(f, side_north)), static_cast<int>(coloring.edge_color(f, side_east)),
        static_cast<int>(coloring.edge_color(f, side_south)), static_cast<int>(coloring.edge_color(f, side_west))};
    if (set.find(e) < 0)
      return status::invalid_argument(detail::cat("colouring violates the tile set: face ", f, " needs edges [north ",
                                                  e.north, ", east ", e.east, ", south ", e.south, ", west ", e.west,
                                                  "] but the set has no such tile"));
  }
  return {};
}

TESSERA_NAMESPACE_END
