// tessera/image/patch_size.hpp: choosing the patch size and overlap width for patch synthesis
// (paper 002 §2.1, after its ref. [9]). Every measure is returned, so callers can plot them:
//
//   auto a = tessera::analyze_patch_size(exemplar).value();
//   for (const auto& m : a.sizes) std::printf("%td x %td: %.2f %.2f\n", m.width, m.height, m.containment, m.periodicity);
//   tessera::patch_model_options o{.patch_width = a.patch_width, .patch_height = a.patch_height, .overlap = a.overlap};
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "detail/patch_size_kernels.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of analyze_patch_size (paper 002 §2.1).
struct patch_size_options {
  index_t min_size = 0;                ///< smallest candidate side; 0: a quarter of the exemplar side (§2.1)
  index_t max_size = 0;                ///< largest candidate side; 0: half the exemplar side (§2.1)
  index_t candidates_per_axis = 9;     ///< sides tried per axis, evenly spaced in [min_size, max_size]
  bool rectangular = true;             ///< also try shapes with width != height
  int histogram_bins = 16;             ///< grey histogram bins of the containment measure
  double containment_tolerance = 0.5;  ///< a patch "contains" the exemplar when the L2 distance of the normalized
                                       ///< histograms is below this share of the exemplar histogram's L2 norm
  double containment_fraction = 0.9;   ///< share of patches that must contain it (§2.1.1: 90 %)
  index_t reference_grid = 4;          ///< one reference block per cell of a grid x grid partition (§2.1.2)
  double similarity = 0.35;         ///< blocks are similar when mean squared grey difference < similarity x 2 variance
  double periodicity_hits = 1.0;    ///< share of reference blocks that must find a similar block (§2.1.2: all)
  double min_alignment = 0.3;       ///< alignment below this counts as none (stochastic textures)
  index_t analysis_size = 64;       ///< the periodicity count runs on a copy downsampled to at most this side
                                    ///< (elongated exemplars: at most this side squared pixels)
  index_t min_overlap = 0;          ///< smallest overlap width tried; 0: a sixth of the patch side (at least 2)
  index_t max_overlap = 0;          ///< largest; 0: a third of the patch side, within the exemplar
  double overlap_efficiency = 0.9;  ///< pick the smallest width reaching this share of the best discrimination
  int overlap_pairs = 400;          ///< random patch pairs for the overlap discrimination
  std::uint64_t seed = 1;           ///< reference blocks and pairs are drawn from it
  tessera::progress progress = {};  ///< fraction done; return false (or raise the token) to cancel
};

/// The measures of one candidate patch shape.
struct patch_size_measure {
  /// Patch width.
  index_t width = 0;
  /// Patch height.
  index_t height = 0;
  double containment = 0;  ///< share of patches whose grey histogram is within tolerance of the exemplar's (§2.1.1)
  double containment_p90 = 0;   ///< 90th percentile of the histogram distances, relative to the exemplar
                                ///< histogram's norm (lower is better)
  double periodicity = 0;       ///< mean number of blocks similar to a reference block (§2.1.2)
  double periodicity_hits = 0;  ///< share of reference blocks that found at least one similar block
  double alignment = 0;         ///< mean autocorrelation at offsets (width, 0) and (0, height): patches of one
                                ///< phase line up when the size is a period of the texture (ours, see docs)
  bool qualified = false;       ///< both paper measures good (containment and periodicity hits reached)
  double score = 0;             ///< the ranking score (higher is better; see analyze_patch_size and
                                ///< detail::patch_size_score); the first shape with the highest score is chosen
};

/// How well overlaps of one width discriminate patches.
struct overlap_measure {
  /// Overlap width.
  index_t overlap = 0;
  double discrimination = 0;  ///< correlation, over random patch pairs, of overlap distance and patch distance
};

/// The result of analyze_patch_size: all measures plus the chosen size and overlap.
struct patch_size_analysis {
  /// Every candidate shape, measured.
  std::vector<patch_size_measure> sizes;
  /// Every overlap width tried, measured.
  std::vector<overlap_measure> overlaps;
  /// The chosen patch width.
  index_t patch_width = 0;
  /// The chosen patch height.
  index_t patch_height = 0;
  /// The chosen overlap width.
  index_t overlap = 0;
};

namespace detail {
/// The overlap measures for patches of pw x ph and the chosen width (see analyze_patch_size).
inline result<std::pair<std::vector<overlap_measure>, index_t>> choose_overlap(const grey_image& grey, index_t pw,
                                                                               index_t ph,
                                                                               const patch_size_options& opts) {
  const index_t side = std::min(pw, ph);
  const index_t vmin = opts.min_overlap > 0 ? opts.min_overlap : std::max<index_t>(2, side / 6);
  const index_t vmax = std::min(
      {opts.max_overlap > 0 ? opts.max_overlap : std::max<index_t>(vmin, side / 3), grey.w - pw, grey.h - ph, side});
  if (vmax < vmin)
    return status::invalid_argument(cat("analyze_patch_size: no overlap width in [", vmin, ", ", vmax,
                                        "] fits patches of ", pw, " x ", ph, " in the ", grey.w, " x ", grey.h,
                                        " exemplar"));
  std::vector<overlap_measure> measures;
  for (const auto& [v, d] : overlap_measures(grey, pw, ph, vmin, vmax, opts.overlap_pairs, opts.seed))
    measures.push_back({.overlap = v, .discrimination = d});
  double top = -1;
  for (const auto& o : measures) top = std::max(top, o.discrimination);
  index_t chosen = measures.back().overlap;
  for (const auto& o : measures)
    if (o.discrimination >= opts.overlap_efficiency * top) {
      chosen = o.overlap;
      break;
    }
  return std::pair{std::move(measures), chosen};
}

/// The ranking score of analyze_patch_size: 100 per paper measure passed (containment, periodicity),
/// plus the alignment level floor(20 alignment) in [0, 20] (0 below `min_alignment`), plus
/// 1 - area / (max_area + 1) in (0, 1) for the smaller area. Comparing scores compares these keys in
/// order; equal scores mean equal keys.
inline double patch_size_score(bool contains, bool periodic, double alignment, double min_alignment, index_t area,
                               index_t max_area) {
  const double level = alignment >= min_alignment ? std::clamp(std::floor(alignment * 20.0), 0.0, 20.0) : 0.0;
  return 100.0 * ((contains ? 1 : 0) + (periodic ? 1 : 0)) + level +
         (1.0 - static_cast<double>(area) / static_cast<double>(max_area + 1));
}

inline status validate_patch_size_options(const patch_size_options& opts) {
  if (opts.candidates_per_axis < 1)
    return status::invalid_argument(
        cat("analyze_patch_size: candidates_per_axis must be >= 1, got ", opts.candidates_per_axis));
  if (opts.histogram_bins < 2 || opts.histogram_bins > 4096)
    return status::invalid_argument(
        cat("analyze_patch_size: histogram_bins must be in [2, 4096], got ", opts.histogram_bins));
  if (!(opts.containment_fraction >= 0 && opts.containment_fraction <= 1) || !(opts.containment_tolerance >= 0))
    return status::invalid_argument(
        cat("analyze_patch_size: containment_fraction must be in [0, 1] and containment_tolerance >= 0, got ",
            opts.containment_fraction, " and ", opts.containment_tolerance));
  if (opts.reference_grid < 1 || opts.reference_grid > 64)
    return status::invalid_argument(
        cat("analyze_patch_size: reference_grid must be in [1, 64], got ", opts.reference_grid));
  if (!(opts.periodicity_hits >= 0 && opts.periodicity_hits <= 1))
    return status::invalid_argument(
        cat("analyze_patch_size: periodicity_hits must be in [0, 1], got ", opts.periodicity_hits));
  if (!(opts.similarity > 0))
    return status::invalid_argument(cat("analyze_patch_size: similarity must be > 0, got ", opts.similarity));
  if (opts.analysis_size < 16)
    return status::invalid_argument(cat("analyze_patch_size: analysis_size must be >= 16, got ", opts.analysis_size));
  if (opts.min_overlap < 0 || opts.max_overlap < 0 || (opts.max_overlap != 0 && opts.max_overlap < opts.min_overlap))
    return status::invalid_argument(cat("analyze_patch_size: overlap range [", opts.min_overlap, ", ", opts.max_overlap,
                                        "] is invalid (0 for automatic, else max_overlap >= min_overlap >= 1)"));
  if (!(opts.overlap_efficiency > 0 && opts.overlap_efficiency <= 1) || opts.overlap_pairs < 8)
    return status::invalid_argument(
        cat("analyze_patch_size: overlap_efficiency must be in (0, 1] and overlap_pairs >= 8, got ",
            opts.overlap_efficiency, " and ", opts.overlap_pairs));
  return {};
}
}  // namespace detail

/// Analyzes an exemplar to choose the patch size and the overlap width of patch synthesis, as paper
/// 002 §2.1 describes. For every candidate shape between a quarter and a half of the exemplar (§2.1:
/// "1/4 to 1/2 of the exemplar size"; of its smaller side, for both axes), computes
///  - the information-containment measure (§2.1.1): the grey histogram of every patch of that shape
///    (patches every max(1, min(w, h) / 8) pixels in x and y), normalized, against the exemplar's by
///    Euclidean distance; the shape contains the exemplar's information when `containment_fraction`
///    (90 %) of the patches are within `containment_tolerance`;
///  - the periodicity measure (§2.1.2): one random reference block per cell of a coarse grid, the number
///    of blocks of the exemplar similar to it (mean squared grey difference at most `similarity` times
///    twice the grey variance, the expected difference of unrelated blocks; blocks overlapping the
///    reference by more than half are not counted), averaged over the references. It runs on a box-
///    filtered copy whose larger side is at most `analysis_size` (shapes scaled alike); for elongated
///    exemplars the copy is shrunk less, keeping its smaller side at 8 pixels or more (the default
///    smallest candidate at 2 or more), and then cut to its first analysis_size^2 pixels along the
///    longer axis, which bounds the work;
///  - the alignment measure (ours): the exemplar's autocorrelation at a shift of one patch width and one
///    patch height. Synthesis places patches on a grid of that pitch, so a high value means patches of one
///    phase continue each other (bricks, weaves, dots).
/// A shape qualifies when both paper measures are good (containment reached and at least
/// `periodicity_hits` of the references matched: all of them by default, as §2.1.2 asks). Shapes are
/// ranked by how many of the two paper measures they pass (qualified shapes first), then by alignment
/// (so alignment only decides among shapes the paper measures rank equal), then by the smaller area
/// (see `score`; the mean periodicity count is reported, not ranked: within the 1/4-1/2 range it mostly
/// falls as shapes grow, so it would repeat the area preference). The overlap width is then the smallest
/// width whose discrimination (the correlation, over random patch pairs, between the distance of their
/// overlap strips and the distance of the rest of the patches) reaches `overlap_efficiency` (90 %) of
/// the best width's (§2.1: "one width for all sides").
///
/// Errors: invalid_argument for an empty exemplar, one smaller than 8 x 8, option values outside their
/// domain (each named); cancelled when `progress` says so. Complexity about O(S N) for S shapes and N
/// exemplar pixels, plus O(n^2 S) for the periodicity count on the n-pixel analysis copy; well under a
/// second for 128 x 128. Runs on `exec`; results do not depend on it. Thread safety: pure function.
template <Image I, Executor E = serial_executor>
result<patch_size_analysis> analyze_patch_size(const I& exemplar, const patch_size_options& opts = {}, E&& exec = {}) {
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  const index_t W = width_of(exemplar), H = height_of(exemplar);
  if (W < 8 || H < 8)
    return status::invalid_argument(
        detail::cat("analyze_patch_size: exemplar must be at least 8 x 8, got ", W, " x ", H));
  const index_t lo = opts.min_size > 0 ? opts.min_size : std::max<index_t>(2, std::min(W, H) / 4);
  const index_t hi = opts.max_size > 0 ? opts.max_size : std::max<index_t>(lo, std::min(W, H) / 2);
  if (lo < 2 || hi < lo || hi > std::min(W, H) - 1)
    return status::invalid_argument(detail::cat("analyze_patch_size: candidate sizes [", lo, ", ", hi,
                                                "] must satisfy 2 <= min_size <= max_size < ", std::min(W, H),
                                                " (the exemplar's smaller side)"));
  if (auto s = detail::validate_patch_size_options(opts); !s) return s;

  auto grey_buffer = to_buffer<float, 1>(exemplar, "exemplar");
  if (!grey_buffer) return grey_buffer.error();
  const detail::grey_image grey{std::vector<double>(grey_buffer->data(), grey_buffer->data() + W * H), W, H};

  std::vector<index_t> sides;
  const index_t count = std::min(opts.candidates_per_axis, hi - lo + 1);
  for (index_t i = 0; i < count; ++i) sides.push_back(count == 1 ? lo : lo + (hi - lo) * i / (count - 1));
  patch_size_analysis out;
  for (index_t h : sides)
    for (index_t w : sides)
      if (opts.rectangular || w == h) out.sizes.push_back({.width = w, .height = h});

  if (!opts.progress.report(0.0, "patch size: containment")) return status::cancelled();
  detail::containment_measures(grey, out.sizes, opts.histogram_bins, opts.containment_tolerance, exec);
  if (!opts.progress.report(0.3, "patch size: periodicity")) return status::cancelled();
  detail::periodicity_measures(grey, out.sizes, opts.reference_grid, opts.similarity, opts.analysis_size, opts.seed,
                               exec);
  if (!opts.progress.report(0.7, "patch size: alignment")) return status::cancelled();
  detail::alignment_measures(grey, out.sizes);

  // Rank (paper 002 §2.1: "a size for which both measures are good"): first by how many of the two
  // paper measures a shape passes (qualified shapes, passing both, first); among equals by alignment
  // (in steps of 0.05, none below min_alignment); then by the smaller area: the smallest patch that
  // still contains the exemplar's information keeps the most patches, hence variety (§2.1: "too large
  // a size reduces the number of patches and the richness of the result"); then the first in `sizes`.
  index_t max_area = 1;
  for (const auto& m : out.sizes) max_area = std::max(max_area, m.width * m.height);
  const patch_size_measure* best = nullptr;
  for (auto& m : out.sizes) {
    const bool contains = m.containment >= opts.containment_fraction,
               periodic = m.periodicity_hits >= opts.periodicity_hits;
    m.qualified = contains && periodic;
    m.score =
        detail::patch_size_score(contains, periodic, m.alignment, opts.min_alignment, m.width * m.height, max_area);
    if (best == nullptr || m.score > best->score) best = &m;
  }
  out.patch_width = best->width;
  out.patch_height = best->height;

  if (!opts.progress.report(0.85, "patch size: overlap")) return status::cancelled();
  auto ov = detail::choose_overlap(grey, out.patch_width, out.patch_height, opts);
  if (!ov) return ov.error();
  out.overlaps = std::move(ov->first);
  out.overlap = ov->second;
  if (!opts.progress.report(1.0, "patch size")) return status::cancelled();
  return out;
}

/// The overlap part of analyze_patch_size alone, for a patch size the caller chose: the
/// discrimination of every width in [min_overlap, max_overlap] (defaults: a sixth and a third of the
/// smaller patch side) and the chosen width (the smallest reaching `overlap_efficiency` of the best).
/// Errors: invalid_argument for an empty exemplar, patch sizes < 2 or leaving no room for an overlap
/// in the exemplar, or invalid options. Complexity O(widths x pairs x patch area).
template <Image I>
result<patch_size_analysis> analyze_overlap(const I& exemplar, index_t patch_width, index_t patch_height,
                                            const patch_size_options& opts = {}) {
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  if (auto s = detail::validate_patch_size_options(opts); !s) return s;
  const index_t W = width_of(exemplar), H = height_of(exemplar);
  if (patch_width < 2 || patch_height < 2 || patch_width >= W || patch_height >= H)
    return status::invalid_argument(detail::cat("analyze_overlap: patch size ", patch_width, " x ", patch_height,
                                                " must be at least 2 and smaller than the exemplar (", W, " x ", H,
                                                ")"));
  auto grey_buffer = to_buffer<float, 1>(exemplar, "exemplar");
  if (!grey_buffer) return grey_buffer.error();
  const detail::grey_image grey{std::vector<double>(grey_buffer->data(), grey_buffer->data() + W * H), W, H};
  auto ov = detail::choose_overlap(grey, patch_width, patch_height, opts);
  if (!ov) return ov.error();
  patch_size_analysis out;
  out.patch_width = patch_width;
  out.patch_height = patch_height;
  out.overlaps = std::move(ov->first);
  out.overlap = ov->second;
  return out;
}

TESSERA_NAMESPACE_END
