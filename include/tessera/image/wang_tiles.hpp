// tessera/image/wang_tiles.hpp: image Wang tile sets built from an exemplar (Cohen et al., "Wang
// Tiles for Image and Texture Generation", SIGGRAPH 2003; paper 000 §1.2 and §3 for the same
// pipeline on geometry: edge extraction, frame construction, interior synthesis).
//
// Every edge colour stands for one edge sample: a strip of tile_size × 2·overlap pixels for a
// horizontal colour (2·overlap × tile_size for a vertical one) centred on the edge, its first half
// inside the tile above (left of) the edge and its second half inside the tile below (right of) it.
// Every tile corner shows the same corner sample, a calm exemplar window that also forms the ends of
// every strip (detail/wang_edge_samples.hpp: Cohen et al.'s strips would disagree at corners). A
// tile's frame is the inner half of its four edge samples (each pixel from the nearest edge); the
// outermost `border` pixels are fixed, the rest of the frame stays cuttable. The tile is then
// synthesized by constrained quilting (image/constrained_quilt.hpp): patches chosen by their overlap
// error against the frame, joined by minimum-error cuts that never touch the fixed border. So two
// tiles whose touching edges share a colour meet along consecutive rows of the same edge sample:
// they continue each other without a seam, and each tile's interior is its own. Within `border` of
// a side a tile depends only on that side's colour, and within `border` of a corner not at all, so
// an atlas of the set is exact under bilinear filtering and mip levels up to `border` texels deep
// (wang_tile_set::exact_mip_levels, image/wang_atlas.hpp).
//
//   auto set = tessera::build_wang_tiles(exemplar, {.tile_size = 64, .horizontal_colors = 2, .vertical_colors = 2});
//   // set->size() == 16; set->tile(i) is an image_view of tile i; set->edges()[i] its colours
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>
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
#include "detail/quilt_kernel.hpp"
#include "quilt.hpp"
#include "detail/wang_edge_samples.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "../tiling/tile_set_edges.hpp"

TESSERA_NAMESPACE_BEGIN

/// Largest Wang tile set, in bytes of tile pixels (2^32 = 4 GiB; e.g. 65536 tiles of 64² RGBA8).
/// build_wang_tiles() and wang_tile_set::create() return size_overflow beyond it (64 x 64 colours
/// would be 2^24 tiles).
inline constexpr std::uint64_t max_wang_tile_set_bytes = std::uint64_t{1} << 32;

template <Channel T, int C>
class wang_tile_set;

namespace detail {
/// Checks a tile count and size against max_wang_tile_set_bytes for pixels of `pixel_bytes`.
inline status validate_tile_set_extent(index_t tiles, index_t tile_size, std::size_t pixel_bytes) {
  if (tile_size <= 0)
    return status::invalid_argument(detail::cat("wang tile set: tile_size must be positive, got ", tile_size));
  if (tiles <= 0)
    return status::invalid_argument(detail::cat("wang tile set: the set must hold at least one tile, got ", tiles));
  const double bytes = static_cast<double>(tiles) * static_cast<double>(tile_size) * static_cast<double>(tile_size) *
                       static_cast<double>(pixel_bytes);
  if (!(bytes <= static_cast<double>(max_wang_tile_set_bytes)))
    return status::size_overflow(
        detail::cat("wang tile set: ", tiles, " tiles of ", tile_size, " x ", tile_size, " pixels (", pixel_bytes,
                    " bytes each) need ", bytes,
                    " bytes, more than max_wang_tile_set_bytes = 2^32; use fewer colours or smaller tiles"));
  return {};
}

/// The only way to make a wang_tile_set with uninitialized pixels (used by build_wang_tiles and
/// wang_tile_set::create; the set is immutable once handed out).
struct wang_tile_set_access {
  template <Channel T, int C>
  static result<wang_tile_set<T, C>> allocate(tile_set_edges edges, index_t tile_size) {
    if (auto s = validate_tile_set_extent(edges.size(), tile_size, sizeof(T) * C); !s) return s;
#if TESSERA_HAS_EXCEPTIONS
    try {
      return wang_tile_set<T, C>(std::move(edges), tile_size);
    } catch (const std::bad_alloc&) {
      return status::size_overflow(detail::cat("wang tile set: cannot allocate ", edges.size(), " tiles of ", tile_size,
                                               " x ", tile_size, " pixels"));
    }
#else
    return wang_tile_set<T, C>(std::move(edges), tile_size);
#endif
  }
  template <Channel T, int C>
  static T* tile_data(wang_tile_set<T, C>& s, index_t i) noexcept {
    return s.pixels_.data() + i * s.tile_size_ * s.tile_size_ * C;
  }
  /// Measures and stores the set's shared border once its pixels are final.
  template <Channel T, int C>
  static void finish(wang_tile_set<T, C>& s) noexcept {
    s.shared_border_ = measure_shared_border(s);
  }

  /// The largest d <= tile_size / 2 such that, in every tile, the pixels within d of a side equal
  /// those of every other tile with that side's colour, and the d × d corner squares equal those of
  /// tile 0. O(tiles · tile_size · d).
  template <Channel T, int C>
  static index_t measure_shared_border(const wang_tile_set<T, C>& s) noexcept {
    const index_t ts = s.tile_size_, n = s.size();
    if (n == 0) return 0;
    index_t d = ts / 2;
    auto px = [&](index_t t, index_t x, index_t y) { return s.pixels_.data() + ((t * ts + y) * ts + x) * C; };
    auto same = [&](index_t a, index_t ax, index_t ay, index_t b, index_t bx, index_t by) {
      return std::memcmp(px(a, ax, ay), px(b, bx, by), sizeof(T) * C) == 0;
    };
    const tile_set_edges& edges = s.edges();
    for (int side = 0; side < 4; ++side) {
      std::vector<index_t> first(to_size(edges.num_colors(side)), -1);
      for (index_t t = 0; t < n; ++t) {
        index_t& r = first[to_size(edges[t][side])];
        if (r < 0) {
          r = t;
          continue;
        }
        for (index_t a = 0; a < d; ++a)
          for (index_t b = 0; b < ts; ++b) {
            const index_t x = side == side_west ? a : side == side_east ? ts - 1 - a : b;
            const index_t y = side == side_north ? a : side == side_south ? ts - 1 - a : b;
            if (!same(t, x, y, r, x, y)) {
              d = a;
              break;
            }
          }
      }
    }
    for (index_t t = 1; t < n; ++t)
      for (int corner = 0; corner < 4; ++corner)
        for (index_t j = 0; j < d; ++j)
          for (index_t i = 0; i < d; ++i) {
            const index_t x = corner & 1 ? ts - 1 - i : i, y = corner & 2 ? ts - 1 - j : j;
            if (!same(t, x, y, 0, x, y)) d = std::max(i, j);
          }
    return d;
  }
};
}  // namespace detail

/// A set of square image tiles of one size with their edge colours. Tile i's pixels are rows of
/// tile_size · C values, tiles stored one after another. Made only by build_wang_tiles() or the
/// checked create(); immutable afterwards; thread-safe reads.
template <Channel T, int C>
class wang_tile_set {
 public:
  /// An empty set (size() == 0); algorithms given one return invalid_argument.
  wang_tile_set() = default;

  /// Wraps tiles made elsewhere (e.g. read from a tile directory), copying their pixels and
  /// measuring shared_border(). Errors: tile count different from the edge set's, a tile not
  /// tile_size × tile_size (the message names the tile), tile_size <= 0, more than
  /// max_wang_tile_set_bytes (size_overflow). O(pixels).
  static result<wang_tile_set> create(tile_set_edges edges, index_t tile_size,
                                      const std::vector<image_buffer<T, C>>& tiles) {
    if (tile_size <= 0)
      return status::invalid_argument(detail::cat("wang tile set: tile_size must be positive, got ", tile_size));
    if (static_cast<index_t>(tiles.size()) != edges.size())
      return status::invalid_argument(
          detail::cat("wang tile set: ", tiles.size(), " tile images for ", edges.size(), " tile edges"));
    for (std::size_t i = 0; i < tiles.size(); ++i)
      if (tiles[i].width() != tile_size || tiles[i].height() != tile_size)
        return status::invalid_argument(detail::cat("wang tile set: tile ", i, " is ", tiles[i].width(), " x ",
                                                    tiles[i].height(), ", expected ", tile_size, " x ", tile_size));
    auto s = detail::wang_tile_set_access::allocate<T, C>(std::move(edges), tile_size);
    if (!s) return s.error();
    for (std::size_t i = 0; i < tiles.size(); ++i)
      std::memcpy(detail::wang_tile_set_access::tile_data(*s, static_cast<index_t>(i)), tiles[i].data(),
                  tiles[i].size_bytes());
    detail::wang_tile_set_access::finish(*s);
    return s;
  }

  /// Side of every tile in pixels (0 for an empty set).
  [[nodiscard]] index_t tile_size() const noexcept { return tile_size_; }
  /// Number of tiles.
  [[nodiscard]] index_t size() const noexcept { return edges_.size(); }
  /// Depth d (measured on the pixels, at most tile_size / 2) within which every tile's pixels near
  /// a side depend only on that side's colour and its corner squares are the same in all tiles:
  /// bilinear samples of an atlas reading up to d texels across a tile border or corner equal those
  /// of the tiled plane. build_wang_tiles guarantees d >= its border; tiles made elsewhere may have 0.
  [[nodiscard]] index_t shared_border() const noexcept { return shared_border_; }
  /// Number of mip levels (level 0 = full resolution included) whose box-filtered texels, sampled
  /// bilinearly anywhere in a tile, equal those of the tiled plane: L such that 2^(L−1) <=
  /// shared_border() and 2^(L−1) divides tile_size() (0 when shared_border() is 0). O(1).
  [[nodiscard]] int exact_mip_levels() const noexcept {
    int levels = 0;
    while (levels < 62 && (index_t{1} << levels) <= shared_border_ && tile_size_ % (index_t{1} << levels) == 0)
      ++levels;
    return levels;
  }
  /// The tiles' edge colours (tile i has edges()[i]) with their lookups.
  [[nodiscard]] const tile_set_edges& edges() const noexcept { return edges_; }
  /// Tile i as a read-only view (tile_size × tile_size). Precondition: 0 <= i < size().
  [[nodiscard]] image_view<const T, C> tile(index_t i) const noexcept {
    TESSERA_ASSERT(i >= 0 && i < size());
    return {tile_row(i, 0), tile_size_, tile_size_};
  }
  /// First value of tile i's row `y`. Precondition: 0 <= i < size(), 0 <= y < tile_size().
  [[nodiscard]] const T* tile_row(index_t i, index_t y) const noexcept {
    TESSERA_ASSERT(i >= 0 && i < size() && y >= 0 && y < tile_size_);
    return pixels_.data() + (i * tile_size_ + y) * tile_size_ * C;
  }

 private:
  friend struct detail::wang_tile_set_access;
  wang_tile_set(tile_set_edges edges, index_t tile_size)
      : edges_(std::move(edges)),
        tile_size_(tile_size),
        pixels_(detail::to_size(edges_.size() * tile_size * tile_size * C)) {}

  tile_set_edges edges_;
  index_t tile_size_ = 0;
  index_t shared_border_ = 0;
  std::vector<T> pixels_;
};

/// Options of build_wang_tiles().
struct wang_tile_options {
  /// Tile side in pixels.
  index_t tile_size = 64;
  int horizontal_colors = 2;           ///< colours of north/south edges (nh)
  int vertical_colors = 2;             ///< colours of east/west edges (nv)
  std::vector<wang_edges> tiles = {};  ///< tiles to build; empty = the complete set of nh² · nv² tiles.
                                       ///< tile_set_edges::modular_subset(2, 2, 2) gives Cohen's 8.
  int mip_levels = 0;      ///< mip levels (level 0 included) an atlas of the set must sample exactly across tile
                           ///< borders and corners: sets border = 2^(mip_levels − 1) and needs tile_size to be a
                           ///< multiple of it. 0 = automatic: the most, up to 4, with 2^(L−1) dividing tile_size
                           ///< and at most max(1, tile_size / 8) (4 for tiles of 64, 3 for 32 or 48, 1 for odd sizes)
  index_t overlap = 0;     ///< quilting overlap, also the depth of each edge sample inside a tile;
                           ///< 0 = max(2, tile_size / 10, border + 2), at most tile_size / 2
  index_t patch_size = 0;  ///< quilting patch; 0 = about tile_size / 3, adjusted so patches cover the tile evenly
  index_t border = 0;      ///< outermost pixels copied from the edge samples and never cut, and the depth of the
                           ///< corner sample every tile corner shares; 0 = 2^(mip_levels − 1)
  double tolerance = 0.1;  ///< candidate selection tolerance (as in quilt())
  double boundary_weight =
      64;  ///< overlap-error weight of fixed border pixels next to unsynthesized ones (as in quilt_options)
  index_t min_candidates = 4;  ///< draw each patch among at least this many best candidates, so tiles sharing
                               ///< edges still get different interiors (1 = pure tolerance rule)
  /// Seed of the edge samples and the quilting.
  std::uint64_t seed = 1;
  /// Progress callback and cancellation token.
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
    return status::invalid_argument(
        detail::cat("tile_size ", z.tile, " is larger than the ", ew, " x ", eh,
                    " exemplar allows (each edge sample is a tile_size-long strip of it); use a "
                    "larger exemplar (quilt() can make one) or smaller tiles"));
  if (z.overlap < 0 || z.patch < 0 || z.border < 0)
    return status::invalid_argument(detail::cat("overlap, patch_size and border must be >= 0 (0 = automatic), got ",
                                                z.overlap, ", ", z.patch, ", ", z.border));
  if (o.mip_levels < 0 || o.mip_levels > 16)
    return status::invalid_argument(detail::cat("mip_levels must be in [0, 16] (0 = automatic), got ", o.mip_levels));
  if (o.mip_levels > 0) {
    const index_t need = index_t{1} << (o.mip_levels - 1);
    if (z.tile % need != 0)
      return status::invalid_argument(detail::cat("tile_size ", z.tile, " must be a multiple of 2^(mip_levels - 1) = ",
                                                  need, " for ", o.mip_levels, " exact mip levels"));
    if (z.border == 0) z.border = need;
    if (z.border < need)
      return status::invalid_argument(detail::cat("border ", z.border, " is smaller than the 2^(mip_levels - 1) = ",
                                                  need, " texels ", o.mip_levels, " exact mip levels need"));
  } else if (z.border == 0) {
    index_t need = 8;  // 4 levels at most
    while (need > 1 && (z.tile % need != 0 || need > std::max<index_t>(1, z.tile / 8))) need /= 2;
    z.border = need;
  }
  if (z.overlap == 0) z.overlap = std::min(z.tile / 2, std::max({index_t{2}, z.tile / 10, z.border + 2}));
  if (z.patch == 0) {
    // about tile/3, then the smallest patch covering the tile with the same number of patches
    const index_t target = std::max<index_t>(3 * z.overlap, z.tile / 3);
    const index_t n = std::max<index_t>(
        1, (z.tile - z.overlap + (target - z.overlap) / 2) / std::max<index_t>(1, target - z.overlap));
    z.patch = std::min(z.tile, (z.tile - z.overlap + n - 1) / n + z.overlap);
  }
  if (2 * z.overlap > z.patch || z.overlap < 1)
    return status::invalid_argument(
        detail::cat("overlap ", z.overlap, " must be in [1, patch_size / 2 = ", z.patch / 2, "]"));
  if (z.patch > z.tile)
    return status::invalid_argument(detail::cat("patch_size ", z.patch, " exceeds tile_size ", z.tile));
  if (z.patch > ew || z.patch > eh || 2 * z.overlap > std::min(ew, eh))
    return status::invalid_argument(
        detail::cat("patch_size ", z.patch, " does not fit the ", ew, " x ", eh, " exemplar"));
  if (z.border >= z.overlap)
    return status::invalid_argument(detail::cat("border ", z.border, " must be smaller than overlap ", z.overlap,
                                                " (the cut needs room inside each edge sample)"));
  return z;
}
}  // namespace detail

namespace detail {
/// What every Wang tile build shares once its colour counts are checked: the resolved sizes, the
/// exemplar prepared for quilting and the quilting parameters.
template <Channel T, int C>
struct wang_build_context {
  wang_sizes sizes;
  quilt_source<T, C> src;
  quilt_params prm;
};

/// Checks everything but the colour counts (exemplar extent and values, sizes, a set of `count` tiles,
/// tolerance, boundary weight, candidates) and prepares the exemplar. Errors: those of
/// build_wang_tiles that do not concern colours.
template <Image E>
result<wang_build_context<channel_t<E>, channels_v<E>>> prepare_wang_build(const E& exemplar,
                                                                           const wang_tile_options& options,
                                                                           index_t count) {
  using T = channel_t<E>;
  constexpr int C = channels_v<E>;
  auto sizes = resolve_wang_sizes(options, width_of(exemplar), height_of(exemplar));
  if (!sizes) return sizes.error();
  if (auto s = validate_tile_set_extent(count, sizes->tile, sizeof(T) * C); !s) return s;
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    return status::invalid_argument(detail::cat("tolerance must be a finite number >= 0, got ", options.tolerance));
  if (!(options.boundary_weight >= 1) || !(options.boundary_weight <= 1e6))
    return status::invalid_argument(detail::cat("boundary_weight must be in [1, 1e6], got ", options.boundary_weight));
  if (options.min_candidates < 1)
    return status::invalid_argument(detail::cat("min_candidates must be >= 1, got ", options.min_candidates));
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  auto ex = to_buffer<T, C>(exemplar, "exemplar");
  if (!ex) return ex.error();
  quilt_params prm;
  prm.patch = sizes->patch;
  prm.tolerance = options.tolerance;
  prm.frontier_weight = static_cast<float>(options.boundary_weight);
  prm.min_candidates = options.min_candidates;
  prm.rng = counter_rng(options.seed, stream_id("image.wang_tiles")).substream(1);
  return wang_build_context<T, C>{*sizes, quilt_source<T, C>(std::move(*ex)), prm};
}

/// Frame construction (paper 000 §3.2) and interior synthesis (§3.3) of `n` tiles: tile t gets the
/// frame of edges(t) from frames(t) (a wang_frame_samples) and is quilted with key t into out(t) (a
/// T* of tile_size² · C values). In batches of 4 through `exec`, progress reported between batches.
template <Channel T, int C, class Edges, class Frames, class Out, class X>
status build_framed_tiles(const wang_build_context<T, C>& ctx, index_t n, Edges&& edges, Frames&& frames, Out&& out,
                          const progress& prog, X& exec) {
  const index_t ts = ctx.sizes.tile, ov = ctx.sizes.overlap;
  std::vector<status> failures(to_size(n));
  auto build_one = [&](index_t t) {
    quilt_canvas<T, C> canvas(ts, ts);
    write_tile_frame(frames(t), edges(t), canvas);
    quilt_params local = ctx.prm;
    local.key = static_cast<std::uint64_t>(t);
    serial_executor serial;
    failures[to_size(t)] = fill_canvas(ctx.src, canvas, local, ov, serial);
    std::memcpy(out(t), canvas.pixels.data(), canvas.pixels.size_bytes());
  };
  constexpr index_t batch = 4;
  for (index_t b = 0; b < n; b += batch) {
    exec.parallel_for(b, std::min(n, b + batch), build_one);
    if (!prog.report(static_cast<double>(std::min(n, b + batch)) / static_cast<double>(n), "wang tiles"))
      return status::cancelled();
  }
  for (const status& s : failures)
    if (!s) return s;
  return {};
}
}  // namespace detail

/// Builds a Wang tile set from `exemplar` (Cohen et al. 2003 §4 with paper 000 §3's frame +
/// interior pipeline): one edge sample per colour whose ends are a corner sample shared by all tile
/// corners, each tile framed by its four edge samples and synthesized by constrained image quilting
/// whose minimum-error cuts never alter the fixed border. Any two tiles whose touching edges share a
/// colour continue each other without a seam, and an atlas of the set is exact for
/// exact_mip_levels() mip levels (at least options.mip_levels when given).
///
/// - exemplar: any Image; tiles keep its channel type and count.
/// - options: tile size, colour counts, the tiles to build (complete set by default; any subset),
///   mip levels, quilting sizes, seed, progress (reported between batches of tiles; cancelling
///   returns cancelled).
/// - exec: edge samples and tiles are built in parallel; output is bit-identical for any executor.
/// Errors: bad colour counts (zero, negative); an edge colour out of range in `tiles`; tile size
/// below 4 or larger than the exemplar allows; mip_levels outside [0, 16] or needing a border the
/// tile size does not divide; patch, overlap or border inconsistent; a set larger than
/// max_wang_tile_set_bytes or an exemplar larger than max_quilt_exemplar_pixels (size_overflow); a
/// NaN or infinite value in a float exemplar (names the pixel); cancelled.
/// Complexity: O((tiles + colours) · patches per tile · candidates · window pixels).
/// Thread safety: reads `exemplar` only.
template <Image E, Executor X = serial_executor>
[[nodiscard]] result<wang_tile_set<channel_t<E>, channels_v<E>>> build_wang_tiles(const E& exemplar,
                                                                                  const wang_tile_options& options = {},
                                                                                  X&& exec = {}) {
  using T = channel_t<E>;
  constexpr int C = channels_v<E>;
  if (auto s =
          detail::validate_quilt_extent(exemplar, "exemplar", max_quilt_exemplar_pixels, "max_quilt_exemplar_pixels");
      !s)
    return s;
  if (auto s = validate_color_counts(options.horizontal_colors, options.vertical_colors); !s) return s;
  const int nh = options.horizontal_colors, nv = options.vertical_colors;
  auto sizes = detail::resolve_wang_sizes(options, width_of(exemplar), height_of(exemplar));
  if (!sizes) return sizes.error();
  const index_t count =
      options.tiles.empty() ? complete_tile_count(nh, nv) : static_cast<index_t>(options.tiles.size());
  if (auto s = detail::validate_tile_set_extent(count, sizes->tile, sizeof(T) * C); !s) return s;
  auto edges = options.tiles.empty() ? tile_set_edges::complete(nh, nv) : tile_set_edges::create(nh, nv, options.tiles);
  if (!edges) return edges.error();
  auto ctx = detail::prepare_wang_build(exemplar, options, count);
  if (!ctx) return ctx.error();
  auto set = detail::wang_tile_set_access::allocate<T, C>(*edges, ctx->sizes.tile);
  if (!set) return set.error();
  if (!options.progress.report(0.0, "wang tiles")) return status::cancelled();
  // Edge extraction (paper 000 §3.1): the corner sample and one strip per colour, whose ends are
  // the corner sample's halves (detail/wang_edge_samples.hpp).
  detail::wang_frame_samples<T, C> frame;
  if (auto s = detail::build_frame_samples(ctx->src, ctx->sizes.tile, ctx->sizes.overlap, ctx->sizes.border, nh, nv,
                                           ctx->prm, options.tolerance, exec, frame);
      !s)
    return s;
  if (auto s = detail::build_framed_tiles(
          *ctx, set->size(), [&](index_t t) { return (*edges)[t]; },
          [&](index_t) -> const detail::wang_frame_samples<T, C>& { return frame; },
          [&](index_t t) { return detail::wang_tile_set_access::tile_data(*set, t); }, options.progress, exec);
      !s)
    return s;
  detail::wang_tile_set_access::finish(*set);
  return set;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_wang_tiles.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
