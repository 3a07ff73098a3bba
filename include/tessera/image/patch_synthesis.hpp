// tessera/image/patch_synthesis.hpp: real-time synthesis of large textures by patch distribution and
// compatible-set intersection (paper 002 §2). Any window of an infinite texture, from a prepared
// patch_model (image/patch_model.hpp):
//
//   auto model = tessera::build_patch_model(exemplar).value();
//   tessera::image_buffer<std::uint8_t, 4> tile(1024, 1024);
//   tessera::synthesize(model, tile, {.origin = {4096, -2048}, .seed = 7}, pool);   // tile of a terrain
//   tessera::synthesize_aligned(model, normal_exemplar, normal_tile, {.origin = {4096, -2048}, .seed = 7});
//
// Every decision is a pure function of (seed, cell coordinates), so windows rendered separately are
// bit-identical to the same region of one large render, on any executor.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/image_rows.hpp"
#include "../core/image_view.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "detail/patch_plan.hpp"
#include "detail/patch_render.hpp"
#include "metrics.hpp"
#include "patch_model.hpp"

TESSERA_NAMESPACE_BEGIN

/// How neighbouring patches are joined in their overlap.
enum class seam_mode {
  feather,  ///< linear cross-fade by the distance to the overlap border (paper 002 §2)
  cut       ///< minimum-error seam (the improvement paper 002 names for structured textures)
};

/// How a vacant cell is filled when the compatible sets of its four neighbours share no patch (on
/// photographs the common case: the paper's k = 8 sets rarely intersect four ways). Default: most_sets.
enum class fill_fallback {
  overlap_error,  ///< the union's patch with the smallest true overlap error against all four neighbours
                  ///< (quality mode: a few times slower synthesis on stochastic exemplars)
  most_sets,  ///< paper 002 §2 (default): the patch in the most sets (ties: smallest lower bound of its error, index)
  estimated_error  ///< the union's patch with the smallest overlap error against all four neighbours, the errors
                   ///< the sets do not hold estimated from the strips' PCA descriptors (ours; about 2.4
                   ///< times the default's CPU time)
};

/// A pixel position in the infinite texture plane.
struct texture_offset {
  /// Texture column.
  index_t x = 0;
  /// Texture row.
  index_t y = 0;
};

/// Options of synthesize, synthesize_aligned and synthesize_source_map.
struct patch_synthesis_options {
  texture_offset origin = {};  ///< texture coordinates of the output's top-left pixel
  std::uint64_t seed = 0;      ///< the texture: same seed, same infinite texture
  /// How overlaps join: feather (the paper's linear blend) or cut (minimum-error seams).
  seam_mode seams = seam_mode::feather;
  /// Feathering: width in pixels of the linear blend band, centred in each overlap (clamped to the
  /// overlap); 0: the whole overlap, the paper's weights. The default 5 (ours) blends less of two unrelated
  /// patches: on photographs it lowers the neighbourhood energy at full resolution without raising it
  /// at half (docs/patch_synthesis.md, "Narrow feathering").
  index_t feather_width = 5;
  index_t phase_radius = -1;     ///< distributed patches come from phases within this distance of one
                                 ///< phase (any value >= max(patch_width, patch_height) means every
                                 ///< phase); -1: the phases most similar to it (detail::phase_group)
  index_t min_phase_group = 16;  ///< with phase_radius -1: at least this many patches to draw from
  /// Which patch fills a cell whose four sets share none (docs/patch_synthesis.md, "Filling").
  fill_fallback fallback = fill_fallback::most_sets;
  int fallback_budget = 8;          ///< overlap_error: at most this many candidates get missing errors computed (1-256)
  tessera::progress progress = {};  ///< fraction done; return false (or raise the token) to cancel
};

/// What a synthesis call did (for statistics; the pixels do not depend on it).
struct patch_synthesis_stats {
  index_t cells = 0;                ///< cells touching the window
  index_t placed = 0;               ///< of which distributed on the checkerboard
  index_t filled = 0;               ///< of which filled from their neighbours' compatible sets
  index_t empty_intersections = 0;  ///< filled cells whose four sets had no common patch (fallback used)
  index_t computed_seams = 0;       ///< seam cuts computed during synthesis (pairs outside the compatible sets)
  index_t phase_group = 0;          ///< patches the distribution drew from
  index_t evaluated_errors = 0;     ///< overlap errors the overlap_error fallback computed from the exemplar
  /// RMS channel difference (unit range) over the four overlap strips of the filled cells whose errors
  /// are known (all of them with the overlap_error fallback, the intersected ones with most_sets): how
  /// well the filled patches fit. The
  /// exemplar's own value is 0; a few hundredths hide under feathering, 0.1 and more show as seams.
  double fill_overlap_rms = 0;
};

/// Largest |texture coordinate| a window may reach.
inline constexpr index_t max_texture_coordinate = index_t{1} << 52;

namespace detail {
template <class O, class T, int C>
inline constexpr bool direct_rows_v = false;
template <class T, int C>
inline constexpr bool direct_rows_v<image_view<T, C>, T, C> = true;
template <class T, int C>
inline constexpr bool direct_rows_v<image_buffer<T, C>, T, C> = true;

inline status validate_window(index_t w, index_t h, const patch_synthesis_options& opts, std::string_view fn) {
  const texture_offset o = opts.origin;
  if (o.x < -max_texture_coordinate || o.y < -max_texture_coordinate || o.x > max_texture_coordinate - w ||
      o.y > max_texture_coordinate - h)
    return status::out_of_range(cat(fn, ": window at origin (", o.x, ", ", o.y, ") of ", w, " x ", h,
                                    " leaves the supported texture plane [-2^52, 2^52]"));
  if (opts.phase_radius < -1)
    return status::invalid_argument(cat(fn, ": phase_radius must be >= -1, got ", opts.phase_radius));
  if (opts.min_phase_group < 1)
    return status::invalid_argument(cat(fn, ": min_phase_group must be >= 1, got ", opts.min_phase_group));
  if (opts.feather_width < 0)
    return status::invalid_argument(cat(fn, ": feather_width must be >= 0, got ", opts.feather_width));
  if (opts.fallback_budget < 1 || opts.fallback_budget > 256)
    return status::invalid_argument(cat(fn, ": fallback_budget must be in [1, 256], got ", opts.fallback_budget));
  if (auto s = validate_enum(opts.fallback, {"overlap_error", "most_sets", "estimated_error"},
                             cat(fn, ": options.fallback"));
      !s)
    return s;
  return validate_enum(opts.seams, {"feather", "cut"}, cat(fn, ": options.seams"));
}

template <Channel T, int C, class Ex>
result<patch_plan> plan_window(const patch_model<T, C>& model, index_t w, index_t h,
                               const patch_synthesis_options& opts, std::string_view fn, Ex&& exec) {
  if (model.num_patches() == 0)
    return status::invalid_argument(cat(fn, ": the patch model is empty (default-constructed)"));
  if (auto s = validate_window(w, h, opts, fn); !s) return s;
  if (opts.progress.cancelled()) return status::cancelled();
  patch_plan plan = make_plan(model, opts.origin.x, opts.origin.y, w, h, opts.seed, opts.seams == seam_mode::cut,
                              opts.phase_radius, opts.min_phase_group, exec,
                              fill_policy{opts.fallback == fill_fallback::overlap_error,
                                          opts.fallback == fill_fallback::estimated_error, opts.fallback_budget});
  if (opts.feather_width > 0) plan.band = std::min(opts.feather_width, plan.v);
  return plan;
}

template <Channel T, int C>
patch_synthesis_stats to_stats(const plan_counts& c, const patch_model<T, C>& m) {
  // the overlap strips of one filled cell: two vertical (ph + v) x v, two horizontal (pw + v) x v
  const double strip_values =
      2.0 * static_cast<double>((m.patch_height() + m.patch_width() + 2 * m.overlap()) * m.overlap() * C);
  const double unit = std::is_floating_point_v<T> ? 1.0 : static_cast<double>(std::numeric_limits<T>::max());
  const double rms = c.fill_error_known > 0
                         ? std::sqrt(c.fill_error / (strip_values * static_cast<double>(c.fill_error_known))) / unit
                         : 0.0;
  return {c.cells, c.placed, c.filled, c.empty_intersections, c.computed_seams, c.phase_group, c.evaluated, rms};
}

/// Renders a plan from exemplar `ex` into `out`, in bands of rows on `exec`, in one parallel loop.
/// Progress is reported from the calling thread, after a band it rendered, when at least 1/16 of the
/// bands were finished since its last report (and once at the end): no barrier between groups of bands,
/// which cost a 1024² synthesis on 2 threads about as much as the synthesis itself. A cancellation
/// (the token, or a report returning false) skips the bands not yet started.
template <class T, int C, class O, class Ex>
status render_window(const patch_plan& plan, const image_buffer<T, C>& ex, O& out, const tessera::progress& progress,
                     Ex&& exec) {
  using OT = std::remove_cvref_t<O>;
  if constexpr (ContiguousImage<OT>) {  // adapted image over rows of memory: render through its view
    auto view = checked_contiguous_view(out, "synthesize: output");
    if (!view) return view.error();
    return render_window(plan, ex, *view, progress, std::forward<Ex>(exec));
  }
  const plan_renderer<T, C> renderer(plan, ex);
  const index_t w = plan.w, h = plan.h, band = 16, bands = (h + band - 1) / band;
  const auto render_band = [&](index_t b) {
    std::vector<T> tmp(to_size(w * C));
    [[maybe_unused]] std::vector<T> row;
    if constexpr (!direct_rows_v<OT, T, C>) row.resize(to_size(w * C));
    for (index_t y = b * band; y < std::min(h, (b + 1) * band); ++y) {
      if constexpr (direct_rows_v<OT, T, C>) {
        renderer.render(y, out.row(y), tmp.data());
      } else {
        renderer.render(y, row.data(), tmp.data());
        for (index_t x = 0; x < w; ++x) {
          pixel<T, C> p;
          for (int c = 0; c < C; ++c) p[to_size(c)] = row[to_size(x * C + c)];
          image_traits<OT>::write(out, x, y, convert_pixel<pixel_t<OT>>(p));
        }
      }
    }
  };
  if (!progress.callback && progress.token == nullptr) {
    exec.parallel_for(0, bands, render_band);
    return {};
  }
  std::atomic<index_t> done{0};
  std::atomic<bool> stop{false};
  const auto caller = std::this_thread::get_id();
  index_t reported = 0;  // bands done at the caller's last report (only the caller touches it)
  exec.parallel_for(0, bands, [&](index_t b) {
    if (stop.load(std::memory_order_relaxed) || progress.cancelled()) return;
    render_band(b);
    const index_t d = done.fetch_add(1, std::memory_order_relaxed) + 1;
    if (d < bands && (d - reported) * 16 >= bands && std::this_thread::get_id() == caller) {
      reported = d;
      if (!progress.report(static_cast<double>(d) / static_cast<double>(bands), "patch synthesis"))
        stop.store(true, std::memory_order_relaxed);
    }
  });
  if (stop.load() || !progress.report(1.0, "patch synthesis")) return status::cancelled();
  return {};
}
}  // namespace detail

/// Synthesizes the window of the infinite texture that `out` covers (its size, at `opts.origin`), as
/// paper 002 §2 describes: cells of patch_width x patch_height tile the plane; the cells (i, j) with i + j
/// even get a random patch of the phase group (patches whose phase is near one phase drawn from the
/// seed, so they continue each other: "phase-consistent" distribution, §2 and Fig. 2), so every row and
/// column alternates distributed and vacant cells; each vacant cell gets a random patch of the
/// intersection of its four neighbours' compatible sets, or when that is empty the patch present in
/// the most sets (ties: the smallest estimated overlap error - its errors in the sets holding it plus
/// the k-th error of each other set - then the smallest index); overlaps are feathered with the paper's linear
/// weights (or cut along minimum-error seams with `seams = cut`). Random choices are keyed by (seed,
/// cell coordinates), so any window is consistent with any other and with any executor.
///
/// The pixel work copies exemplar row spans (memcpy) and blends only overlap strips with precomputed
/// fixed-point weights; rows run in parallel bands on `exec`. When `out` is an image_view or
/// image_buffer of the model's channel type and count (or a ContiguousImage whose view is, see
/// core/image_rows.hpp), rows are written in place; other writable images receive converted pixels through image_traits::write, from the executor's threads, on
/// disjoint rows.
///
/// Errors: invalid_argument for an empty output or model, phase_radius < -1, min_phase_group < 1;
/// out_of_range when the window leaves [-2^52, 2^52]; cancelled. Complexity O(output pixels + cells k);
/// a model-sized amount of extra memory per worker row. Thread safety: the model is only read.
template <Channel T, int C, class O, Executor E = serial_executor>
requires WritableImage<std::remove_cvref_t<O>> result<patch_synthesis_stats> synthesize(
    const patch_model<T, C>& model, O&& out, const patch_synthesis_options& opts = {}, E&& exec = {}) {
  if (auto s = validate_image(out, "output"); !s) return s;
  auto plan = detail::plan_window(model, width_of(out), height_of(out), opts, "synthesize", exec);
  if (!plan) return plan.error();
  if (auto s = detail::render_window(*plan, model.exemplar(), out, opts.progress, exec); !s) return s;
  return detail::to_stats(plan->counts, model);
}

/// Synthesizes an aligned map (normal, height, roughness...) with exactly the decisions synthesize()
/// makes for the same model, window and options, but taking pixels from `aligned_exemplar`, an image
/// of the model's exemplar size whose pixel (x, y) belongs to exemplar pixel (x, y). Pixel types are
/// free: an 8-bit albedo model can drive a float normal map and a 16-bit height map.
/// Errors: those of synthesize(), plus invalid_argument when the aligned exemplar's size differs from
/// the model's exemplar. Complexity and threading as synthesize().
template <Channel T, int C, Image A, class O, Executor E = serial_executor>
requires WritableImage<std::remove_cvref_t<O>> result<patch_synthesis_stats> synthesize_aligned(
    const patch_model<T, C>& model, const A& aligned_exemplar, O&& out, const patch_synthesis_options& opts = {},
    E&& exec = {}) {
  if (auto s = validate_image(out, "output"); !s) return s;
  if (auto s = validate_image(aligned_exemplar, "aligned_exemplar"); !s) return s;
  if (auto s = validate_same_size(model.exemplar(), "the model's exemplar", aligned_exemplar, "aligned_exemplar"); !s)
    return s;
  auto ex = to_buffer(aligned_exemplar, "aligned_exemplar");
  if (!ex) return ex.error();
  auto plan = detail::plan_window(model, width_of(out), height_of(out), opts, "synthesize_aligned", exec);
  if (!plan) return plan.error();
  if (auto s = detail::render_window(*plan, *ex, out, opts.progress, exec); !s) return s;
  return detail::to_stats(plan->counts, model);
}

/// Writes, for every pixel of the window synthesize() would render with the same options, the
/// exemplar coordinates (x in channel 0, y in channel 1, as plain numbers, not normalized) of the patch
/// pixel that dominates it (the larger feather weight, or the seam side). `source_map` needs at least
/// two channels; other channels are set to 0. Use it to transfer any per-texel data, or to debug.
/// Errors: those of synthesize(), plus invalid_argument for fewer than 2 channels or exemplar
/// coordinates that the channel type cannot hold (uint8 and exemplars over 256 pixels).
template <Channel T, int C, class S, Executor E = serial_executor>
requires WritableImage<std::remove_cvref_t<S>> result<patch_synthesis_stats> synthesize_source_map(
    const patch_model<T, C>& model, S&& source_map, const patch_synthesis_options& opts = {}, E&& exec = {}) {
  using ST = std::remove_cvref_t<S>;
  using P = pixel_t<ST>;
  using PC = typename pixel_traits<P>::channel_type;
  if (auto s = validate_image(source_map, "source_map"); !s) return s;
  if constexpr (pixel_traits<P>::channels < 2) {
    return status::invalid_argument("synthesize_source_map: source_map needs at least 2 channels (x, y)");
  } else {
    const index_t largest = std::max(model.exemplar().width(), model.exemplar().height()) - 1;
    if (static_cast<double>(largest) > static_cast<double>(std::numeric_limits<PC>::max()) ||
        (std::is_same_v<PC, float> && largest > (index_t{1} << 24)))
      return status::invalid_argument(detail::cat("synthesize_source_map: exemplar coordinates up to ", largest,
                                                  " do not fit the source map's channel type"));
    auto plan =
        detail::plan_window(model, width_of(source_map), height_of(source_map), opts, "synthesize_source_map", exec);
    if (!plan) return plan.error();
    const index_t w = plan->w, h = plan->h;
    exec.parallel_for(0, h, [&](index_t y) {
      for (index_t x = 0; x < w; ++x) {
        index_t sx = 0, sy = 0;
        detail::source_of(*plan, x, y, sx, sy);
        P p{};
        for (int c = 0; c < pixel_traits<P>::channels; ++c) pixel_traits<P>::set(p, c, PC{0});
        pixel_traits<P>::set(p, 0, static_cast<PC>(sx));
        pixel_traits<P>::set(p, 1, static_cast<PC>(sy));
        image_traits<ST>::write(source_map, x, y, p);
      }
    });
    return detail::to_stats(plan->counts, model);
  }
}

/// The centre lines of the overlaps of a cell grid of pitch pw x ph and overlap `overlap` inside a
/// w x h window at `origin` (where feathered seams are most visible), clipped to the window, as
/// seam_segment for seam_gradient_ratio and seam_step_ratio (image/metrics.hpp). Empty for a pitch < 1.
inline std::vector<seam_segment> patch_seam_lines(index_t pw, index_t ph, index_t overlap, index_t w, index_t h,
                                                  texture_offset origin = {}) {
  std::vector<seam_segment> out;
  const index_t half = overlap / 2;
  if (pw <= 0 || ph <= 0 || w <= 0 || h <= 0) return out;
  for (index_t X = detail::floor_div(origin.x, pw) * pw + half; X < origin.x + w; X += pw)
    if (X - origin.x >= 1) out.push_back({.vertical = true, .position = X - origin.x, .begin = 0, .end = h});
  for (index_t Y = detail::floor_div(origin.y, ph) * ph + half; Y < origin.y + h; Y += ph)
    if (Y - origin.y >= 1) out.push_back({.vertical = false, .position = Y - origin.y, .begin = 0, .end = w});
  return out;
}

/// The seam lines of `model`'s cell grid inside a w x h window at `origin` (the overload above).
template <Channel T, int C>
std::vector<seam_segment> patch_seam_lines(const patch_model<T, C>& model, index_t w, index_t h,
                                           texture_offset origin = {}) {
  return patch_seam_lines(model.patch_width(), model.patch_height(), model.overlap(), w, h, origin);
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_patch_synthesis.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
