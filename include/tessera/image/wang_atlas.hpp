// tessera/image/wang_atlas.hpp: a Wang tile set packed into one GPU texture (Wei, "Tile-Based
// Texture Mapping on Graphics Hardware", Graphics Hardware 2004; paper 000 §1.2 [4]), and the
// mapping from a texture coordinate of the infinite tiled plane to atlas coordinates.
//
// Edge-ordered layout (Wei 2004), for complete sets. Colour pairs (a, b) are ordered along a cycle
// in which each pair's second colour is the next pair's first:
//     (0,0) (0,1) (1,1) (1,0) (0,2) (2,1) (1,2) (2,2) (2,0) (0,3) ...      (edge_order_index)
// The tile with edges (n, e, s, w) goes to atlas column edge_order_index(w, e) and row
// edge_order_index(n, s), so the atlas is nv² × nh² tiles and every two neighbouring tiles of the
// atlas, wrapping around, match along their shared edge: the atlas is itself a valid toroidal
// tiling. Its neighbours of a tile are not the plane's, though (in the plane the tile east of A has
// any north and south colour); sampling across a border or corner reads the same texels only as
// deep as every tile with a given edge colour agrees with every other near that edge, and every
// tile agrees with every other near its corners: wang_tile_set::shared_border(), which
// build_wang_tiles makes 2^(mip_levels − 1). So levels 0 .. L − 1 of box-filtered mip maps, sampled
// bilinearly with REPEAT addressing anywhere in a tile, equal the tiled plane's own mip maps, for
// L = wang_atlas::mip_levels (tested with a model of GPU filtering). Take the mip level from the
// derivatives of the plane coordinate (textureGrad), not of the atlas one, and clamp it to L − 1
// (GL_TEXTURE_MAX_LEVEL).
//
// Padded layout, for any set (subsets, variants): each tile gets `padding` texels on each side
// copied from neighbouring tiles that match its edges; exact for the levels 2^k <= padding allows
// (padding a multiple of 2^k) and the set's shared border allows. The atlas is larger.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "../core/config.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "../tiling/tile_lookup.hpp"
#include "../tiling/tile_set_edges.hpp"
#include "wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN

/// Position of the colour pair (a, b) in Wei's edge ordering: consecutive pairs (and the last and
/// the first, for n colours: n² − 1 and 0) share a colour: pair i's b is pair i+1's a. O(1),
/// constexpr, suitable for shaders. Wei 2004 §4.
constexpr index_t edge_order_index(int a, int b) noexcept {
  if (a == 0 && b == 0) return 0;
  if (a < b) return static_cast<index_t>(b) * b + 2 * a;
  if (a == b) return static_cast<index_t>(a + 1) * (a + 1) - 2;
  if (b == 0) return static_cast<index_t>(a + 1) * (a + 1) - 1;
  return static_cast<index_t>(a) * a + 2 * b - 1;  // a > b > 0
}

/// Atlas packing: edge_ordered (Wei 2004) or padded (each tile in a slot with padding texels).
enum class atlas_layout { edge_ordered, padded };

/// Options of build_wang_atlas().
struct wang_atlas_options {
  /// Which packing.
  atlas_layout layout = atlas_layout::edge_ordered;
  int mip_levels = 0;   ///< mip levels (level 0 included) that must sample exactly; 0 = all the set allows
                        ///< (wang_tile_set::exact_mip_levels()); more than the set allows is an error
  index_t padding = 0;  ///< padded layout: texels on each side; 0 = 2^(mip_levels − 1) (at least 1)
};

/// A tile set packed into one texture plus where each tile is.
template <Channel T, int C>
struct wang_atlas {
  image_buffer<T, C> image;  ///< the texture
  /// The packing used.
  atlas_layout layout = atlas_layout::edge_ordered;
  /// Tile side in texels.
  index_t tile_size = 0;
  index_t padding = 0;    ///< 0 for the edge-ordered layout
  index_t slot_size = 0;  ///< tile_size + 2 · padding
  int mip_levels = 0;     ///< box-filtered levels 0 .. mip_levels − 1 sample exactly across tile borders and corners
  tile_set_edges edges;   ///< the set's edges (for tile lookups)
  std::vector<index_t> slot_col;  ///< atlas slot of each tile (edge-ordered: of each tile's edges)
  /// Atlas slot row of each tile (like slot_col).
  std::vector<index_t> slot_row;

  /// Atlas texel coordinates of offset (fx, fy) ∈ [0, tile_size)² inside tile `tile`.
  [[nodiscard]] vec2 texel(index_t tile, double fx, double fy) const noexcept {
    return {static_cast<double>(slot_col[detail::to_size(tile)] * slot_size + padding) + fx,
            static_cast<double>(slot_row[detail::to_size(tile)] * slot_size + padding) + fy};
  }
};

/// Packs `set` into an atlas (Wei 2004 edge-ordered layout, or padded) whose first
/// `wang_atlas::mip_levels` box-filtered mip levels sample exactly across tile borders and corners.
/// Errors: edge_ordered with a set that is not complete (names the first missing combination and
/// suggests the padded layout); mip_levels outside [0, 16] or more than the set allows (names the
/// set's shared border and the build option that gives more); padding < 0, >= tile_size, or not a
/// multiple of 2^(mip_levels − 1); an atlas too large.
/// Complexity: O(atlas texels). Thread safety: reads `set` only.
template <Channel T, int C>
[[nodiscard]] result<wang_atlas<T, C>> build_wang_atlas(const wang_tile_set<T, C>& set,
                                                        const wang_atlas_options& options = {}) {
  const tile_set_edges& edges = set.edges();
  const index_t ts = set.tile_size();
  if (set.size() == 0) return status::invalid_argument("wang atlas: the tile set is empty");
  if (auto s = validate_enum(options.layout, {"edge_ordered", "padded"}, "wang atlas: options.layout"); !s) return s;
  if (options.mip_levels < 0 || options.mip_levels > 16)
    return status::invalid_argument(
        detail::cat("wang atlas: mip_levels must be in [0, 16] (0 = all the set allows), got ", options.mip_levels));
  if (options.mip_levels > set.exact_mip_levels())
    return status::invalid_argument(detail::cat(
        "wang atlas: mip_levels ", options.mip_levels, " needs tiles that agree within ",
        index_t{1} << (options.mip_levels - 1), " texels of their edges and corners, but this set's shared border is ",
        set.shared_border(), " (exact for ", set.exact_mip_levels(),
        " levels); build it with wang_tile_options::mip_levels = ", options.mip_levels));
  int levels = options.mip_levels > 0 ? options.mip_levels : set.exact_mip_levels();
  wang_atlas<T, C> a;
  a.layout = options.layout;
  a.tile_size = ts;
  a.edges = edges;
  a.slot_col.resize(detail::to_size(set.size()));
  a.slot_row.resize(detail::to_size(set.size()));
  const int nh = edges.horizontal_colors(), nv = edges.vertical_colors();
  index_t cols = 0, rows = 0;
  if (options.layout == atlas_layout::edge_ordered) {
    if (!edges.is_complete()) {
      for (index_t i = 0; i < complete_tile_count(nh, nv); ++i)
        if (edges.find(complete_tile_edges(i, nh, nv)) < 0) {
          const wang_edges e = complete_tile_edges(i, nh, nv);
          return status::invalid_argument(
              detail::cat("wang atlas: the edge-ordered layout needs the complete set; tile [", e.north, ", ", e.east,
                          ", ", e.south, ", ", e.west, "] is missing (use atlas_layout::padded for subsets)"));
        }
    }
    a.padding = 0;
    cols = static_cast<index_t>(nv) * nv;
    rows = static_cast<index_t>(nh) * nh;
    for (index_t t = 0; t < set.size(); ++t) {
      const wang_edges e = edges[t];
      a.slot_col[detail::to_size(t)] = edge_order_index(e.west, e.east);
      a.slot_row[detail::to_size(t)] = edge_order_index(e.north, e.south);
    }
  } else {
    a.padding = options.padding > 0 ? options.padding : levels > 0 ? index_t{1} << (levels - 1) : 1;
    if (options.padding < 0 || a.padding >= ts)
      return status::invalid_argument(
          detail::cat("wang atlas: padding must be in [0, tile_size = ", ts, "), got ", options.padding));
    int allowed = 0;  // levels the padding serves: 2^k <= padding and 2^k dividing it
    while (allowed < 62 && (index_t{1} << allowed) <= a.padding && a.padding % (index_t{1} << allowed) == 0) ++allowed;
    if (options.mip_levels > allowed)
      return status::invalid_argument(detail::cat("wang atlas: padding ", a.padding, " serves ", allowed,
                                                  " exact mip levels, mip_levels asks for ", options.mip_levels,
                                                  "; use a multiple of ", index_t{1} << (options.mip_levels - 1)));
    levels = std::min(levels, allowed);
    cols = static_cast<index_t>(std::ceil(std::sqrt(static_cast<double>(set.size()))));
    rows = (set.size() + cols - 1) / cols;
    for (index_t t = 0; t < set.size(); ++t) {
      a.slot_col[detail::to_size(t)] = t % cols;
      a.slot_row[detail::to_size(t)] = t / cols;
    }
  }
  a.slot_size = ts + 2 * a.padding;
  a.mip_levels = levels;
  auto img = image_buffer<T, C>::create(cols * a.slot_size, rows * a.slot_size);
  if (!img) return img.error();
  a.image = std::move(*img);
  auto copy_block = [&](index_t tile, index_t sx, index_t sy, index_t w, index_t h, index_t dx, index_t dy) {
    for (index_t y = 0; y < h; ++y)
      std::memcpy(a.image.pixel_ptr(dx, dy + y), set.tile_row(tile, sy + y) + sx * C,
                  detail::to_size(w * C) * sizeof(T));
  };
  // a neighbour of tile t across `side`, matching its edge (and, for corners, a second edge when possible)
  auto neighbour = [&](index_t t, int side) -> index_t {
    const wang_edges e = edges[t];
    for (index_t k = 0; k < edges.size(); ++k)
      if (edges[k][opposite_side(side)] == e[side]) return k;
    return t;
  };
  // the tile diagonally across the corner in directions (horizontal, vertical) of t, given t's
  // neighbours `v` across `vertical` and `h` across `horizontal`: it sits `horizontal` of v and
  // `vertical` of h (both edges matched when the set allows, else the first)
  auto diagonal = [&](index_t v, index_t h, int horizontal, int vertical) -> index_t {
    index_t fallback = -1;
    for (index_t k = 0; k < edges.size(); ++k) {
      const bool m1 = edges[k][opposite_side(horizontal)] == edges[v][horizontal];
      const bool m2 = edges[k][opposite_side(vertical)] == edges[h][vertical];
      if (m1 && m2) return k;
      if (m1 && fallback < 0) fallback = k;
    }
    return fallback >= 0 ? fallback : v;
  };
  const index_t p = a.padding;
  for (index_t t = 0; t < set.size(); ++t) {
    const index_t ox = a.slot_col[detail::to_size(t)] * a.slot_size, oy = a.slot_row[detail::to_size(t)] * a.slot_size;
    if (options.layout == atlas_layout::edge_ordered && set.edges().find(edges[t]) != t)
      continue;  // first variant only
    copy_block(t, 0, 0, ts, ts, ox + p, oy + p);
    if (p == 0) continue;
    const index_t n = neighbour(t, side_north), s = neighbour(t, side_south), w = neighbour(t, side_west),
                  e = neighbour(t, side_east);
    copy_block(n, 0, ts - p, ts, p, ox + p, oy);
    copy_block(s, 0, 0, ts, p, ox + p, oy + p + ts);
    copy_block(w, ts - p, 0, p, ts, ox, oy + p);
    copy_block(e, 0, 0, p, ts, ox + p + ts, oy + p);
    copy_block(diagonal(n, w, side_west, side_north), ts - p, ts - p, p, p, ox, oy);
    copy_block(diagonal(n, e, side_east, side_north), 0, ts - p, p, p, ox + p + ts, oy);
    copy_block(diagonal(s, w, side_west, side_south), ts - p, 0, p, p, ox, oy + p + ts);
    copy_block(diagonal(s, e, side_east, side_south), 0, 0, p, p, ox + p + ts, oy + p + ts);
  }
  return a;
}

/// Maps a point of the infinite tiled plane, in plane texels (cell (floor(px / T), floor(py / T))),
/// to atlas texel coordinates: the cell's tile (tile_at_cell with `seed`, as compose_tiles picks it)
/// at the same offset. With the edge-ordered layout a tile's slot depends on its edges only (Wei
/// 2004 §4). Returns (−1, −1) when the colouring asks for a tile the set lacks, for a cell outside a
/// grid colouring (or a grid colouring whose cols · rows is not its face count), and for a NaN point
/// or one beyond ±2^62 cells. O(1) for plane colourings
/// (hash_coloring), plus an O(log n) lookup for the padded layout; thread-safe.
template <Channel T, int C, class Coloring>
requires GridTileColoring<Coloring> || PlaneTileColoring<Coloring>
[[nodiscard]] vec2 atlas_coordinates(const wang_atlas<T, C>& atlas, const Coloring& coloring, double px, double py,
                                     std::uint64_t seed = 1) noexcept {
  const double ts = static_cast<double>(atlas.tile_size);
  const double cf = std::floor(px / ts), rf = std::floor(py / ts);
  if (!(std::fabs(cf) < 0x1p62) || !(std::fabs(rf) < 0x1p62)) return {-1, -1};  // NaN or beyond the index range
  const auto col = static_cast<index_t>(cf), row = static_cast<index_t>(rf);
  if constexpr (GridTileColoring<Coloring>)
    if (!grid_coloring_consistent(coloring) || col < 0 || row < 0 || col >= static_cast<index_t>(coloring.cols()) ||
        row >= static_cast<index_t>(coloring.rows()))
      return {-1, -1};
  const wang_edges e = cell_edges(coloring, col, row);
  if (atlas.layout == atlas_layout::edge_ordered) {
    if (e.north < 0 || e.north >= atlas.edges.horizontal_colors() || e.south < 0 ||
        e.south >= atlas.edges.horizontal_colors() || e.east < 0 || e.east >= atlas.edges.vertical_colors() ||
        e.west < 0 || e.west >= atlas.edges.vertical_colors())
      return {-1, -1};
    return {static_cast<double>(edge_order_index(e.west, e.east)) * ts + (px - cf * ts),
            static_cast<double>(edge_order_index(e.north, e.south)) * ts + (py - rf * ts)};
  }
  const index_t t = tile_at_cell(atlas.edges, e, seed, col, row);
  if (t < 0) return {-1, -1};
  return atlas.texel(t, px - cf * ts, py - rf * ts);
}

TESSERA_NAMESPACE_END
