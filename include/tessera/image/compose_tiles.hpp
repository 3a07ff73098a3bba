// tessera/image/compose_tiles.hpp: tiled output — an image of any size, or any window of the tiled
// plane, composed from a Wang tile set and a colouring (Cohen et al. 2003 §3: tiling is a lookup,
// no synthesis at run time).
//
// Plane pixel (px, py) lies in cell (floor(px / T), floor(py / T)) at offset (px mod T, py mod T)
// of the cell's tile. The output shows the window [x, x + width) × [y, y + height) of the plane.
// With a grid colouring the window must lie inside its cols·T × rows·T pixels; with a plane
// colouring (hash_coloring) any window works, negative coordinates included.
//
// Composition copies whole tile rows (one memcpy per tile per output row) in parallel row bands
// when the output is an image_view / image_buffer of the set's own pixel type, or an adapted image
// exposing such a view (ContiguousImage, core/image_rows.hpp); any other writable image is written
// pixel by pixel through image_traits.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/image_rows.hpp"
#include "../core/image_view.hpp"
#include "../core/status.hpp"
#include "../tiling/tile_lookup.hpp"
#include "wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of compose_tiles().
struct compose_options {
  index_t x = 0;         ///< plane pixel shown at output column 0
  index_t y = 0;         ///< plane pixel shown at output row 0
  bool outline = false;  ///< draw the tile borders (first row and column of every tile)
  std::array<float, 4> outline_color = {1.0f, 0.1f, 0.1f, 1.0f};  ///< RGBA in [0, 1]
  std::uint64_t seed = 1;  ///< picks among variants (tiles with equal edges), per cell
};

namespace detail {
template <class O, class T, int C>
inline constexpr bool is_raw_output = std::is_same_v<O, image_view<T, C>> || std::is_same_v<O, image_buffer<T, C>>;
}  // namespace detail

/// Composes the window (options.x, options.y, width_of(out), height_of(out)) of the plane tiled by
/// `set` under `coloring` into `out` (Cohen et al. 2003 §3).
///
/// - set: tiles and their edges; coloring: a GridTileColoring or a PlaneTileColoring
///   (tiling/tile_lookup.hpp) with the set's colour counts.
/// - out: any WritableImage; fastest as image_view / image_buffer of the set's pixel type, or as a
///   ContiguousImage whose view has that type (core/image_rows.hpp).
/// - options: window origin, tile-border outline, variant seed.
/// - exec: parallel over bands of output rows; output bit-identical for any executor.
/// Errors (nothing is written): empty set or output; colour counts differing from the set's; a grid
/// colouring whose cols() · rows() is not its num_faces(); a window leaving a grid colouring
/// (out_of_range, with the window and the grid in pixels); a cell whose edge combination has no tile
/// in the set (the colouring violates the set; names the cell).
/// Complexity: O(cells in the window · log n + output pixels), the latter as row memcpys.
/// Thread safety: reads set and coloring, writes `out` only.
template <Channel T, int C, class Coloring, WritableImage O, Executor X = serial_executor>
requires GridTileColoring<Coloring> || PlaneTileColoring<Coloring>
[[nodiscard]] status compose_tiles(const wang_tile_set<T, C>& set, const Coloring& coloring, O& out,
                                   const compose_options& options = {}, X&& exec = {}) {
  if (set.size() == 0 || set.tile_size() <= 0) return status::invalid_argument("compose_tiles: the tile set is empty");
  if (auto s = validate_image(out, "output"); !s) return s;
  if constexpr (ContiguousImage<O>) {  // adapted image over rows of memory: write through its view
    auto view = detail::checked_contiguous_view(out, "compose_tiles: output");
    if (!view) return view.error();
    return compose_tiles(set, coloring, *view, options, std::forward<X>(exec));
  }
  const tile_set_edges& edges = set.edges();
  if (coloring.num_colors(side_north) != edges.horizontal_colors() ||
      coloring.num_colors(side_east) != edges.vertical_colors())
    return status::invalid_argument(detail::cat("compose_tiles: the colouring uses ", coloring.num_colors(side_north),
                                                " x ", coloring.num_colors(side_east), " colours but the tile set has ",
                                                edges.horizontal_colors(), " x ", edges.vertical_colors()));
  const index_t ts = set.tile_size(), w = width_of(out), h = height_of(out);
  if (options.x > (index_t{1} << 52) || options.x < -(index_t{1} << 52) || options.y > (index_t{1} << 52) ||
      options.y < -(index_t{1} << 52))
    return status::out_of_range(
        detail::cat("compose_tiles: window origin (", options.x, ", ", options.y, ") is too far out"));
  const index_t c0 = floor_div(options.x, ts), c1 = floor_div(options.x + w - 1, ts);
  const index_t r0 = floor_div(options.y, ts), r1 = floor_div(options.y + h - 1, ts);
  if constexpr (GridTileColoring<Coloring>) {
    if (auto s = validate_grid_coloring(coloring); !s)
      return status(s.code(), detail::cat("compose_tiles: ", s.message()));
    const index_t cols = static_cast<index_t>(coloring.cols()), rows = static_cast<index_t>(coloring.rows());
    if (c0 < 0 || r0 < 0 || c1 >= cols || r1 >= rows)
      return status::out_of_range(detail::cat("compose_tiles: window [", options.x, ", ", options.x + w, ") x [",
                                              options.y, ", ", options.y + h, ") leaves the ", cols * ts, " x ",
                                              rows * ts, " pixels of the ", cols, " x ", rows, " colouring"));
  }
  // Tile of every cell of the window, validated before anything is written.
  const index_t ncols = c1 - c0 + 1, nrows = r1 - r0 + 1;
  std::vector<index_t> cell_tile(detail::to_size(ncols * nrows));
  for (index_t r = r0; r <= r1; ++r)
    for (index_t c = c0; c <= c1; ++c) {
      const wang_edges e = cell_edges(coloring, c, r);
      const index_t t = tile_at_cell(edges, e, options.seed, c, r);
      if (t < 0)
        return status::invalid_argument(detail::cat(
            "compose_tiles: the colouring violates the tile set: cell (", c, ", ", r, ") needs edges [north ", e.north,
            ", east ", e.east, ", south ", e.south, ", west ", e.west, "] and the set has no such tile"));
      cell_tile[detail::to_size((r - r0) * ncols + (c - c0))] = t;
    }
  const pixel<T, C> line = convert_pixel<pixel<T, C>>(pixel<float, 4>{options.outline_color});
  auto outlined = [&](index_t px, index_t py) { return options.outline && (px % ts == 0 || py % ts == 0); };
  constexpr index_t band = 16;
  const index_t bands = (h + band - 1) / band;
  exec.parallel_for(0, bands, [&](index_t b) {
    for (index_t oy = b * band; oy < std::min(h, (b + 1) * band); ++oy) {
      const index_t py = options.y + oy, r = floor_div(py, ts), ty = py - r * ts;
      const index_t* row_tiles = cell_tile.data() + (r - r0) * ncols;
      if constexpr (detail::is_raw_output<O, T, C>) {
        // row spans: one memcpy per tile of this row
        T* dst = out.row(oy);
        index_t ox = 0;
        while (ox < w) {
          const index_t px = options.x + ox, c = floor_div(px, ts), tx = px - c * ts;
          const index_t n = std::min(ts - tx, w - ox);
          std::memcpy(dst + ox * C, set.tile_row(row_tiles[c - c0], ty) + tx * C, detail::to_size(n * C) * sizeof(T));
          ox += n;
        }
        if (options.outline) {
          const bool whole_row = ty == 0;  // a tile's first row; otherwise only first columns
          for (index_t x = whole_row ? 0 : (ts - (options.x % ts + ts) % ts) % ts; x < w; x += whole_row ? 1 : ts)
            for (int k = 0; k < C; ++k) dst[x * C + k] = line[detail::to_size(k)];
        }
      } else {
        for (index_t ox = 0; ox < w; ++ox) {
          const index_t px = options.x + ox, c = floor_div(px, ts), tx = px - c * ts;
          const T* src = set.tile_row(row_tiles[c - c0], ty) + tx * C;
          pixel<T, C> p;
          for (int k = 0; k < C; ++k) p[detail::to_size(k)] = src[k];
          if (outlined(px, py)) p = line;
          image_traits<O>::write(out, ox, oy, convert_pixel<pixel_t<O>>(p));
        }
      }
    }
  });
  return {};
}

/// compose_tiles for any TileColoring laid out as a grid of `cols` columns (face = row · cols + col).
/// Errors as above, plus `cols` not dividing the colouring's face count.
template <Channel T, int C, TileColoring Coloring, WritableImage O, Executor X = serial_executor>
[[nodiscard]] status compose_tiles(const wang_tile_set<T, C>& set, const Coloring& coloring, index_t cols, O& out,
                                   const compose_options& options = {}, X&& exec = {}) {
  if (cols <= 0 || coloring.num_faces() % cols != 0 || coloring.num_faces() == 0)
    return status::invalid_argument(detail::cat("compose_tiles: ", cols, " columns do not divide the colouring's ",
                                                coloring.num_faces(), " faces into a grid"));
  const grid_coloring_view<Coloring> grid{&coloring, cols};
  return compose_tiles(set, grid, out, options, std::forward<X>(exec));
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_compose_tiles.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
