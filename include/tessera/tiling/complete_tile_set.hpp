// tessera/tiling/complete_tile_set.hpp: the combinatorics of complete Wang tile sets, shared by image
// Wang tiles (image/wang_tiles.hpp) and geometric Wang tiles (geometry/).
//
// A Wang tile is a square whose four sides carry colours; two tiles may sit side by side when the
// touching sides carry the same colour (paper 000 §1.2; Cohen et al. 2003). North and south sides are
// horizontal edges and draw from `nh` colours; east and west sides are vertical edges with `nv`
// colours (the core/tile_coloring.hpp conventions). The complete set holds one tile for every
// combination, nh² · nv² tiles (16 for two colours each way), numbered
//
//     index = ((north · nv + east) · nh + south) · nv + west
//
// so west varies fastest. Subsets (Cohen's 8 tiles for 2 × 2 colours) are described by
// tiling/tile_set_edges.hpp.
#pragma once

#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"

TESSERA_NAMESPACE_BEGIN

/// The four edge colours of a tile, in side order (core/tile_coloring.hpp): north, east, south, west.
struct wang_edges {
  /// North edge colour (a horizontal colour).
  int north = 0;
  /// East edge colour (a vertical colour).
  int east = 0;
  /// South edge colour (a horizontal colour).
  int south = 0;
  /// West edge colour (a vertical colour).
  int west = 0;

  /// The colour of side `side` (0 north, 1 east, 2 south, 3 west).
  [[nodiscard]] constexpr int operator[](int side) const noexcept {
    return side == side_north ? north : side == side_east ? east : side == side_south ? south : west;
  }
  friend constexpr bool operator==(const wang_edges&, const wang_edges&) = default;
};

/// Largest colour count per edge direction tessera accepts (keeps nh² · nv² and every table
/// indexed by colour combinations far inside index_t).
inline constexpr int max_wang_colors = 4096;

/// Checks a pair of colour counts: each must be in [1, max_wang_colors]. The message names the
/// offending count ("horizontal colours must be >= 1, got 0").
inline status validate_color_counts(int nh, int nv) {
  if (nh < 1 || nh > max_wang_colors)
    return status::invalid_argument(
        detail::cat("horizontal (north/south) colours must be in [1, ", max_wang_colors, "], got ", nh));
  if (nv < 1 || nv > max_wang_colors)
    return status::invalid_argument(
        detail::cat("vertical (east/west) colours must be in [1, ", max_wang_colors, "], got ", nv));
  return {};
}

/// Number of tiles of the complete set, nh² · nv² (paper 000 §3: 16 for two colours each way).
/// Precondition: validate_color_counts(nh, nv) is ok. O(1).
constexpr index_t complete_tile_count(int nh, int nv) noexcept { return static_cast<index_t>(nh) * nh * nv * nv; }

/// Checks that every colour of `e` lies in range: north/south in [0, nh), east/west in [0, nv).
inline status validate_wang_edges(const wang_edges& e, int nh, int nv) {
  if (auto s = validate_color_counts(nh, nv); !s) return s;
  for (int side = 0; side < 4; ++side) {
    const int n = is_horizontal_side(side) ? nh : nv;
    if (e[side] < 0 || e[side] >= n)
      return status::out_of_range(
          detail::cat("wang edges: ", side_name(side), " colour ", e[side], " is outside [0, ", n, ")"));
  }
  return {};
}

/// Checks that `tile` is an index of the complete set for (nh, nv).
inline status validate_complete_tile(index_t tile, int nh, int nv) {
  if (auto s = validate_color_counts(nh, nv); !s) return s;
  if (tile < 0 || tile >= complete_tile_count(nh, nv))
    return status::out_of_range(detail::cat("tile index ", tile, " is outside the complete set [0, ",
                                            complete_tile_count(nh, nv), ") for ", nh, " x ", nv, " colours"));
  return {};
}

/// The edges of tile `tile` of the complete set (inverse of complete_tile_index).
/// Precondition: validate_complete_tile(tile, nh, nv) is ok. O(1).
constexpr wang_edges complete_tile_edges(index_t tile, int nh, int nv) noexcept {
  wang_edges e;
  e.west = static_cast<int>(tile % nv);
  tile /= nv;
  e.south = static_cast<int>(tile % nh);
  tile /= nh;
  e.east = static_cast<int>(tile % nv);
  e.north = static_cast<int>(tile / nv);
  return e;
}

/// The index of the tile with edges `e` in the complete set: ((north·nv + east)·nh + south)·nv + west.
/// Precondition: validate_wang_edges(e, nh, nv) is ok. O(1).
constexpr index_t complete_tile_index(const wang_edges& e, int nh, int nv) noexcept {
  return ((static_cast<index_t>(e.north) * nv + e.east) * nh + e.south) * nv + e.west;
}

/// The edges of every tile of the complete set, in index order. Fails on bad colour counts.
/// O(nh² · nv²).
inline result<std::vector<wang_edges>> complete_tile_set_edges(int nh, int nv) {
  if (auto s = validate_color_counts(nh, nv); !s) return s;
  const index_t n = complete_tile_count(nh, nv);
  if (n > (index_t{1} << 26))
    return status::size_overflow(detail::cat("the complete set for ", nh, " x ", nv, " colours has ", n,
                                             " tiles, more than tessera builds (2^26)"));
  std::vector<wang_edges> out(detail::to_size(n));
  for (index_t i = 0; i < n; ++i) out[detail::to_size(i)] = complete_tile_edges(i, nh, nv);
  return out;
}

TESSERA_NAMESPACE_END
