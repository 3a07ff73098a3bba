// tessera/image/wang_tiles.hpp: image Wang tile sets built from an exemplar (Cohen et al., "Wang
// Tiles for Image and Texture Generation", SIGGRAPH 2003; paper 000 §1.2 and §3 for the same
// pipeline on geometry: edge extraction, frame construction, interior synthesis).
//
// Every edge colour stands for one exemplar sample: a strip of tile_size × 2·overlap pixels for a
// horizontal colour (2·overlap × tile_size for a vertical one) centred on the edge, its first half
// inside the tile above (left of) the edge and its second half inside the tile below (right of) it. A tile's
// frame is the inner half of its four edge samples (each pixel from the nearest edge); the
// outermost `border` pixels are fixed, the rest of the frame stays cuttable. The tile is then
// synthesized by constrained quilting (image/constrained_quilt.hpp): patches chosen by their overlap
// error against the frame, joined by minimum-error cuts that never touch the fixed border. So two
// tiles whose touching edges share a colour meet along rows that are consecutive rows of the same
// exemplar sample: they continue each other without a seam, and each tile's interior is its own.
//
//   auto set = tessera::build_wang_tiles(exemplar, {.tile_size = 64, .horizontal_colors = 2, .vertical_colors = 2});
//   // set->size() == 16; set->tile(i) is an image_view of tile i; set->edges()[i] its colours
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/image_view.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../detail/quilt_kernel.hpp"
#include "../detail/wang_edge_samples.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "../tiling/tile_set_edges.hpp"

TESSERA_NAMESPACE_BEGIN

/// A set of square image tiles of one size with their edge colours. Tile i's pixels are rows of
/// tile_size · C values, tiles stored one after another. Immutable after creation; thread-safe reads.
template <Channel T, int C>
class wang_tile_set {
 public:
  wang_tile_set() = default;

  /// Wraps tiles made elsewhere (e.g. read from a tile directory). Errors: tile count different from
  /// the edge set's, a tile not tile_size × tile_size (the message names the tile), tile_size <= 0.
  static result<wang_tile_set> create(tile_set_edges edges, index_t tile_size, const std::vector<image_buffer<T, C>>& tiles) {
    if (tile_size <= 0) return status::invalid_argument(detail::cat("wang tile set: tile_size must be positive, got ", tile_size));
    if (static_cast<index_t>(tiles.size()) != edges.size())
      return status::invalid_argument(detail::cat("wang tile set: ", tiles.size(), " tile images for ", edges.size(), " tile edges"));
    wang_tile_set s(std::move(edges), tile_size);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      if (tiles[i].width() != tile_size || tiles[i].height() != tile_size)
        return status::invalid_argument(detail::cat("wang tile set: tile ", i, " is ", tiles[i].width(), " x ", tiles[i].height(),
                                                    ", expected ", tile_size, " x ", tile_size));
      std::memcpy(s.tile_data(static_cast<index_t>(i)), tiles[i].data(), tiles[i].size_bytes());
    }
    return s;
  }

  [[nodiscard]] index_t tile_size() const noexcept { return tile_size_; }
  [[nodiscard]] index_t size() const noexcept { return edges_.size(); }
  [[nodiscard]] const tile_set_edges& edges() const noexcept { return edges_; }
  /// Tile i as a read-only view (tile_size × tile_size).
  [[nodiscard]] image_view<const T, C> tile(index_t i) const noexcept {
    TESSERA_ASSERT(i >= 0 && i < size());
    return {tile_data(i), tile_size_, tile_size_};
  }
  /// First value of tile i's row `y`.
  [[nodiscard]] const T* tile_row(index_t i, index_t y) const noexcept { return tile_data(i) + y * tile_size_ * C; }

  // construction (used by build_wang_tiles)
  wang_tile_set(tile_set_edges edges, index_t tile_size)
      : edges_(std::move(edges)), tile_size_(tile_size),
        pixels_(static_cast<std::size_t>(edges_.size() * tile_size * tile_size * C)) {}
  [[nodiscard]] T* tile_data(index_t i) noexcept { return pixels_.data() + i * tile_size_ * tile_size_ * C; }
  [[nodiscard]] const T* tile_data(index_t i) const noexcept { return pixels_.data() + i * tile_size_ * tile_size_ * C; }

 private:
  tile_set_edges edges_;
  index_t tile_size_ = 0;
  std::vector<T> pixels_;
};

/// Options of build_wang_tiles().
struct wang_tile_options {
  index_t tile_size = 64;
  int horizontal_colors = 2;          ///< colours of north/south edges (nh)
  int vertical_colors = 2;            ///< colours of east/west edges (nv)
  std::vector<wang_edges> tiles = {}; ///< tiles to build; empty = the complete set of nh² · nv² tiles.
                                      ///< tile_set_edges::modular_subset(2, 2, 2) gives Cohen's 8.
  index_t overlap = 0;     ///< quilting overlap, also the depth of each edge sample inside a tile; 0 = max(2, tile_size / 10)
  index_t patch_size = 0;  ///< quilting patch; 0 = about tile_size / 3, adjusted so patches cover the tile evenly
  index_t border = 0;      ///< outermost pixels copied from the edge samples and never cut; 0 = max(1, overlap / 4)
  double tolerance = 0.1;  ///< candidate selection tolerance (as in quilt())
  double boundary_weight = 64;  ///< overlap-error weight of fixed border pixels next to unsynthesized ones (as in quilt_options)
  index_t min_candidates = 4;   ///< draw each patch among at least this many best candidates, so tiles sharing
                                ///< edges still get different interiors (1 = pure tolerance rule)
  std::uint64_t seed = 1;
  tessera::progress progress = {};
};

namespace detail {
struct wang_sizes {
  index_t tile, overlap, patch, border;
};

inline result<wang_sizes> resolve_wang_sizes(const wang_tile_options& o, index_t ew, index_t eh) {
  wang_sizes z{o.tile_size, o.overlap, o.patch_size, o.border};
  if (z.tile < 4) return status::invalid_argument(detail::cat("tile_size must be at least 4, got ", z.tile));
  if (z.tile > ew || z.tile > eh)
    return status::invalid_argument(detail::cat("tile_size ", z.tile, " is larger than the ", ew, " x ", eh,
                                                " exemplar allows (each edge sample is a tile_size-long strip of it); use a "
                                                "larger exemplar (quilt() can make one) or smaller tiles"));
  if (z.overlap < 0 || z.patch < 0 || z.border < 0)
    return status::invalid_argument(detail::cat("overlap, patch_size and border must be >= 0 (0 = automatic), got ", z.overlap,
                                                ", ", z.patch, ", ", z.border));
  if (z.overlap == 0) z.overlap = std::max<index_t>(2, z.tile / 10);
  if (z.patch == 0) {
    // about tile/3, then the smallest patch covering the tile with the same number of patches
    const index_t target = std::max<index_t>(3 * z.overlap, z.tile / 3);
    const index_t n = std::max<index_t>(1, (z.tile - z.overlap + (target - z.overlap) / 2) / std::max<index_t>(1, target - z.overlap));
    z.patch = std::min(z.tile, (z.tile - z.overlap + n - 1) / n + z.overlap);
  }
  if (z.border == 0) z.border = std::max<index_t>(1, z.overlap / 4);
  if (2 * z.overlap > z.patch || z.overlap < 1)
    return status::invalid_argument(detail::cat("overlap ", z.overlap, " must be in [1, patch_size / 2 = ", z.patch / 2, "]"));
  if (z.patch > z.tile) return status::invalid_argument(detail::cat("patch_size ", z.patch, " exceeds tile_size ", z.tile));
  if (z.patch > ew || z.patch > eh || 2 * z.overlap > std::min(ew, eh))
    return status::invalid_argument(detail::cat("patch_size ", z.patch, " does not fit the ", ew, " x ", eh, " exemplar"));
  if (z.border >= z.overlap)
    return status::invalid_argument(detail::cat("border ", z.border, " must be smaller than overlap ", z.overlap,
                                                " (the cut needs room inside each edge sample)"));
  return z;
}
}  // namespace detail

/// Builds a Wang tile set from `exemplar` (Cohen et al. 2003 §4 with paper 000 §3's frame +
/// interior pipeline): one exemplar strip per edge colour, each tile framed by its four edge strips
/// and synthesized by constrained image quilting whose minimum-error cuts never alter the fixed
/// border. Any two tiles whose touching edges share a colour continue each other without a seam.
///
/// - exemplar: any Image; tiles keep its channel type and count.
/// - options: tile size, colour counts, the tiles to build (complete set by default; any subset),
///   quilting sizes, seed, progress (reported between batches of tiles; cancelling returns cancelled).
/// - exec: tiles are built in parallel; output is bit-identical for any executor.
/// Errors: bad colour counts (zero, negative); an edge colour out of range in `tiles`; tile size
/// below 4 or larger than the exemplar allows; patch, overlap or border inconsistent; cancelled.
/// Complexity: O(tiles · patches per tile · candidates · window pixels).
/// Thread safety: reads `exemplar` only.
template <Image E, Executor X = serial_executor>
[[nodiscard]] result<wang_tile_set<channel_t<E>, channels_v<E>>> build_wang_tiles(const E& exemplar,
                                                                                   const wang_tile_options& options = {},
                                                                                   X&& exec = {}) {
  using T = channel_t<E>;
  constexpr int C = channels_v<E>;
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_color_counts(options.horizontal_colors, options.vertical_colors); !s) return s;
  const int nh = options.horizontal_colors, nv = options.vertical_colors;
  auto edges = options.tiles.empty() ? tile_set_edges::complete(nh, nv) : tile_set_edges::create(nh, nv, options.tiles);
  if (!edges) return edges.error();
  const index_t ew = width_of(exemplar), eh = height_of(exemplar);
  auto sizes = detail::resolve_wang_sizes(options, ew, eh);
  if (!sizes) return sizes.error();
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    return status::invalid_argument(detail::cat("tolerance must be a finite number >= 0, got ", options.tolerance));
  if (!(options.boundary_weight >= 1) || !(options.boundary_weight <= 1e6))
    return status::invalid_argument(detail::cat("boundary_weight must be in [1, 1e6], got ", options.boundary_weight));
  if (options.min_candidates < 1)
    return status::invalid_argument(detail::cat("min_candidates must be >= 1, got ", options.min_candidates));
  const auto [ts, ov, patch, border] = *sizes;
  auto ex = to_buffer<T, C>(exemplar, "exemplar");
  if (!ex) return ex.error();
  const detail::quilt_source<T, C> src(std::move(*ex));

  // Edge extraction (paper 000 §3.1): one strip per colour. A horizontal colour's strip is
  // ts × 2·ov; its rows [0, ov) end the tile above the edge and rows [ov, 2·ov) start the tile below.
  // Vertical strips are the transpose. Strips are chosen to agree at tile corners
  // (detail/wang_edge_samples.hpp).
  const counter_rng rng(options.seed, stream_id("image.wang_tiles"));
  const detail::edge_samples samples =
      detail::edge_sample_chooser<T, C>(src, ts, ov).choose(nh, nv, options.tolerance, rng.substream(2));
  auto strip = [&](const std::vector<detail::strip_origin>& v, int colour) { return v[static_cast<std::size_t>(colour)]; };

  wang_tile_set<T, C> set(*edges, ts);
  detail::quilt_params prm;
  prm.patch = patch;
  prm.tolerance = options.tolerance;
  prm.frontier_weight = static_cast<float>(options.boundary_weight);
  prm.min_candidates = options.min_candidates;
  prm.rng = rng.substream(1);
  const index_t n = set.size();
  std::vector<status> failures(static_cast<std::size_t>(n));
  auto build_one = [&](index_t t) {
    const wang_edges e = (*edges)[t];
    detail::quilt_canvas<T, C> canvas(ts, ts);
    // Frame construction (paper 000 §3.2): each pixel within ov of the border takes the nearest
    // edge's strip (ties: north, south, west, east); the outer `border` pixels are fixed. Corner
    // squares, where two strips would meet along an unoptimized diagonal, are left to the cut.
    for (index_t j = 0; j < ts; ++j)
      for (index_t i = 0; i < ts; ++i) {
        const index_t dn = j, ds = ts - 1 - j, dw = i, de = ts - 1 - i;
        const index_t d = std::min({dn, ds, dw, de});
        if (d >= ov) continue;
        const bool corner = std::min(dn, ds) < ov && std::min(dw, de) < ov;
        if (corner && d >= border) continue;
        index_t sx = 0, sy = 0;
        if (dn == d) sx = strip(samples.horizontal, e.north).x + i, sy = strip(samples.horizontal, e.north).y + ov + j;
        else if (ds == d) sx = strip(samples.horizontal, e.south).x + i, sy = strip(samples.horizontal, e.south).y + j - (ts - ov);
        else if (dw == d) sx = strip(samples.vertical, e.west).x + ov + i, sy = strip(samples.vertical, e.west).y + j;
        else sx = strip(samples.vertical, e.east).x + i - (ts - ov), sy = strip(samples.vertical, e.east).y + j;
        std::memcpy(canvas.pixels.pixel_ptr(i, j), src.pixels.pixel_ptr(sx, sy), sizeof(T) * C);
        canvas.at(i, j) = d < border ? detail::pixel_state::fixed : detail::pixel_state::filled;
      }
    // Interior synthesis (paper 000 §3.3): constrained quilting of everything not fixed or framed.
    detail::quilt_params local = prm;
    local.key = static_cast<std::uint64_t>(t);
    serial_executor serial;
    failures[static_cast<std::size_t>(t)] = detail::fill_canvas(src, canvas, local, ov, serial);
    std::memcpy(set.tile_data(t), canvas.pixels.data(), canvas.pixels.size_bytes());
  };
  if (!options.progress.report(0.0, "wang tiles")) return status::cancelled();
  constexpr index_t batch = 4;
  for (index_t b = 0; b < n; b += batch) {
    exec.parallel_for(b, std::min(n, b + batch), build_one);
    if (!options.progress.report(static_cast<double>(std::min(n, b + batch)) / static_cast<double>(n), "wang tiles"))
      return status::cancelled();
  }
  for (const status& s : failures)
    if (!s) return s;
  return set;
}

TESSERA_NAMESPACE_END
