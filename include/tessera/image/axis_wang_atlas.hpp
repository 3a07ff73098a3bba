// tessera/image/axis_wang_atlas.hpp: a three-axis image Wang tile set (image/axis_wang_tiles.hpp)
// packed into one texture for polycube surfaces (surface/map_wang_tiles_to_surface.hpp).
//
// Each face's tiles are packed with the padded layout of image/wang_atlas.hpp: every tile sits in a
// slot with `padding` texels on each side copied from a tile of the same face that matches it across
// that side (or corner). Near a side a tile depends on that side's axis and colour only, whatever
// face it is on, and every corner is the same quarter-turn-symmetric corner sample, so the padding
// equals what lies across the quad border on the surface, also around polycube edges and corners:
// bilinear samples (and box-filtered mip levels up to mip_levels) taken on either side of any quad
// border agree. The six face blocks sit in a 3 × 2 grid: column = axis (X, Y, Z), row 0 for + faces,
// row 1 for − faces.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "../core/config.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "../tiling/axis_tile_set.hpp"
#include "axis_wang_tiles.hpp"
#include "wang_atlas.hpp"

TESSERA_NAMESPACE_BEGIN

/// A three-axis set packed into one texture.
template <Channel T, int C>
struct axis_wang_atlas {
  /// The texture.
  image_buffer<T, C> image;
  /// {nX, nY, nZ} of the set.
  axis_color_counts axis_colors = {0, 0, 0};
  /// Tile side in texels.
  index_t tile_size = 0;
  /// Texels copied around each tile.
  index_t padding = 0;
  /// Box-filtered levels 0 .. mip_levels − 1 sample exactly across quad borders.
  int mip_levels = 0;
  /// Per tile (axis_tile_set.hpp numbering): atlas texel of the tile's pixel (0, 0), its north-west
  /// corner.
  std::vector<std::array<index_t, 2>> origin;

  /// Atlas texel coordinates of offset (fx, fy) ∈ [0, tile_size]² inside tile `tile` (x along the
  /// tile's first axis, y downwards). Precondition: 0 <= tile < origin.size().
  [[nodiscard]] vec2 texel(index_t tile, double fx, double fy) const noexcept {
    const auto& o = origin[detail::to_size(tile)];
    return {static_cast<double>(o[0]) + fx, static_cast<double>(o[1]) + fy};
  }
};

/// Packs `set` (see the file comment). options.layout is not read (always padded per face);
/// options.mip_levels and options.padding as for build_wang_atlas's padded layout. Errors: an empty
/// set; mip_levels outside [0, 16] or more than the set allows; padding < 0 or >= tile_size or not a
/// multiple of 2^(mip_levels − 1); an atlas too large. O(atlas texels). Thread safety: reads `set`.
template <Channel T, int C>
[[nodiscard]] result<axis_wang_atlas<T, C>> build_axis_wang_atlas(const axis_wang_tile_set<T, C>& set,
                                                                  const wang_atlas_options& options = {}) {
  if (set.size() == 0) return status::invalid_argument("axis wang atlas: the tile set is empty");
  wang_atlas_options o = options;
  o.layout = atlas_layout::padded;
  std::array<wang_atlas<T, C>, 6> blocks;
  index_t cell_w = 0, cell_h = 0;
  for (int f = 0; f < cube_faces; ++f) {
    auto a = build_wang_atlas(set.face_set(f), o);
    if (!a) return status(a.error().code(), detail::cat("axis wang atlas: ", a.error().message()));
    cell_w = std::max(cell_w, a->image.width());
    cell_h = std::max(cell_h, a->image.height());
    blocks[detail::to_size(f)] = std::move(*a);
  }
  axis_wang_atlas<T, C> out;
  out.axis_colors = set.axis_colors();
  out.tile_size = set.tile_size();
  out.padding = blocks[0].padding;
  out.mip_levels = blocks[0].mip_levels;
  for (const auto& b : blocks) out.mip_levels = std::min(out.mip_levels, b.mip_levels);
  auto img = image_buffer<T, C>::create(3 * cell_w, 2 * cell_h);
  if (!img) return img.error();
  out.image = std::move(*img);
  out.origin.resize(detail::to_size(set.size()));
  for (int f = 0; f < cube_faces; ++f) {
    const auto& b = blocks[detail::to_size(f)];
    const index_t bx = (f / 2) * cell_w, by = (f % 2) * cell_h;
    for (index_t y = 0; y < b.image.height(); ++y)
      std::memcpy(out.image.pixel_ptr(bx, by + y), b.image.pixel_ptr(0, y),
                  detail::to_size(b.image.width() * C) * sizeof(T));
    const index_t first = axis_face_first_tile(f, set.axis_colors());
    for (index_t i = 0; i < set.face_set(f).size(); ++i)
      out.origin[detail::to_size(first + i)] = {bx + b.slot_col[detail::to_size(i)] * b.slot_size + b.padding,
                                                by + b.slot_row[detail::to_size(i)] * b.slot_size + b.padding};
  }
  return out;
}

TESSERA_NAMESPACE_END
