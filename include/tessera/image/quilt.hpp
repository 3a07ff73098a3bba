// tessera/image/quilt.hpp: image quilting (Efros & Freeman, "Image Quilting for Texture Synthesis
// and Transfer", SIGGRAPH 2001), the patch method paper 002 §1 cites as [4], and the method Cohen et
// al. build Wang tiles with (paper 000 §1.2).
//
// Square patches are placed in raster order with a fixed overlap. For each one, the overlap error
// (sum of squared differences over the pixels already synthesized) is computed for every exemplar
// window; one window is drawn at random among those whose error is within (1 + tolerance) of the
// best, and it is joined to what is there by a minimum-error boundary cut found by dynamic
// programming on the error surface: a vertical cut for the left overlap, a horizontal one for the
// top overlap and, where both exist, the L-shaped cut made of the two paths meeting at their
// cheapest common point. With `seamless` the output is synthesized on a torus, so that it tiles with
// itself without seams.
//
//   auto ex = tessera::read_png<std::uint8_t, 3>("grass.png");
//   tessera::image_buffer<std::uint8_t, 3> out(512, 512);
//   auto s = tessera::quilt(*ex, out, {.patch_size = 32, .seamless = true});
#pragma once

#include <cmath>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "detail/quilt_kernel.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of quilt() and constrained_quilt().
struct quilt_options {
  index_t patch_size = 0;  ///< side of the square patches; 0 = a quarter of the exemplar's smaller side, in [8, 64]
  index_t overlap = 0;     ///< overlap between neighbouring patches; 0 = patch_size / 6 (at least 2, Efros & Freeman)
  double tolerance = 0.1;  ///< candidates within (1 + tolerance) of the best overlap error are drawn from
  bool seamless = false;   ///< quilt(): synthesize on a torus so the output tiles with itself
  double boundary_weight = 64;  ///< constrained_quilt(): weight, in the overlap error, of fixed pixels bordering the
                                ///< region to fill, where the cut cannot move (1 = plain Efros & Freeman)
  /// Seed of the patch choices.
  std::uint64_t seed = 1;
  /// Progress callback and cancellation token.
  tessera::progress progress = {};
};

/// Largest image quilt() synthesizes and constrained_quilt() fills, in pixels (2^28, e.g. 16384²):
/// the working canvas holds the pixels plus one state byte each, and the time grows with the area
/// (about 1 s per 512² from a 128² exemplar). Larger sizes return size_overflow.
inline constexpr index_t max_quilt_pixels = index_t{1} << 28;
/// Largest exemplar quilting searches, in pixels (2^26, e.g. 8192²): every patch compares against
/// every exemplar window, and the search keeps the exemplar as float planes (4 bytes per channel,
/// at most 1 GiB). Also the limit of an image inpainted from itself. Larger sizes return size_overflow.
inline constexpr index_t max_quilt_exemplar_pixels = index_t{1} << 26;

namespace detail {
/// Checks `img` against a pixel cap (width · height <= cap), naming it and the cap.
template <Image I>
status validate_quilt_extent(const I& img, std::string_view what, index_t cap, std::string_view cap_name) {
  if (auto s = validate_image(img, what); !s) return s;
  const index_t w = width_of(img), h = height_of(img);
  if (w > cap / h)
    return status::size_overflow(detail::cat(what, ": ", w, " x ", h, " pixels exceed ", cap_name, " = ", cap,
                                             " (split the work into windows or use a smaller image)"));
  return {};
}

/// Resolves automatic patch size and overlap and validates them against an exemplar of ew × eh.
inline status resolve_quilt_sizes(const quilt_options& o, index_t ew, index_t eh, index_t& patch, index_t& overlap) {
  const index_t smaller = std::min(ew, eh);
  patch = o.patch_size > 0 ? o.patch_size : std::min(smaller, std::clamp<index_t>(smaller / 4, 8, 64));
  if (o.patch_size < 0)
    return status::invalid_argument(detail::cat("patch_size must be >= 0 (0 = automatic), got ", o.patch_size));
  if (patch < 2) return status::invalid_argument(detail::cat("patch_size must be at least 2, got ", patch));
  if (patch > ew || patch > eh)
    return status::invalid_argument(
        detail::cat("patch_size ", patch, " does not fit the ", ew, " x ", eh, " exemplar"));
  if (o.overlap < 0)
    return status::invalid_argument(detail::cat("overlap must be >= 0 (0 = automatic), got ", o.overlap));
  overlap = o.overlap > 0 ? o.overlap : std::max<index_t>(std::min<index_t>(2, patch / 2), patch / 6);
  if (overlap < 1 || 2 * overlap > patch)
    return status::invalid_argument(
        detail::cat("overlap ", overlap, " must be in [1, patch_size / 2 = ", patch / 2, "]"));
  if (!(o.tolerance >= 0) || !std::isfinite(o.tolerance))
    return status::invalid_argument(detail::cat("tolerance must be a finite number >= 0, got ", o.tolerance));
  if (!(o.boundary_weight >= 1) || !(o.boundary_weight <= 1e6))
    return status::invalid_argument(detail::cat("boundary_weight must be in [1, 1e6], got ", o.boundary_weight));
  return {};
}
}  // namespace detail

/// Synthesizes `out` (its current size) from `exemplar` by image quilting (Efros & Freeman 2001,
/// §2.1: overlap-error search, selection within a tolerance of the best, minimum-error boundary cuts
/// by dynamic programming, vertical / horizontal / L-shaped).
///
/// - exemplar: any Image; out: any WritableImage (pixels converted with convert_pixel; the kernel
///   runs on the exemplar's channel type and count).
/// - options: patch size, overlap, tolerance, `seamless` (toroidal output), seed, progress.
/// - exec: parallelizes the overlap search over candidate rows; output is bit-identical for any
///   executor and thread count.
/// Errors: empty or overflowing images; an output larger than max_quilt_pixels or an exemplar
/// larger than max_quilt_exemplar_pixels (size_overflow); a float exemplar with a NaN or infinite
/// value (names the pixel); patch size not fitting the exemplar; overlap outside [1, patch/2];
/// negative or non-finite tolerance; seamless output smaller than a patch; cancelled.
/// Complexity: O(sites · candidates · overlap pixels · channels), sites ≈ (W·H) / (patch − overlap)²,
/// candidates = (ew − patch + 1)(eh − patch + 1). Thread safety: reads `exemplar`, writes `out` only.
template <Image E, WritableImage O, Executor X = serial_executor>
[[nodiscard]] status quilt(const E& exemplar, O& out, const quilt_options& options = {}, X&& exec = {}) {
  if (auto s =
          detail::validate_quilt_extent(exemplar, "exemplar", max_quilt_exemplar_pixels, "max_quilt_exemplar_pixels");
      !s)
    return s;
  if (auto s = detail::validate_quilt_extent(out, "output", max_quilt_pixels, "max_quilt_pixels"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  index_t patch = 0, overlap = 0;
  if (auto s = detail::resolve_quilt_sizes(options, width_of(exemplar), height_of(exemplar), patch, overlap); !s)
    return s;
  const index_t w = width_of(out), h = height_of(out);
  if (options.seamless && (w < patch || h < patch))
    return status::invalid_argument(
        detail::cat("seamless output must be at least one patch (", patch, ") in each direction, got ", w, " x ", h));
  using T = channel_t<E>;
  constexpr int C = channels_v<E>;
  auto ex = to_buffer<T, C>(exemplar, "exemplar");
  if (!ex) return ex.error();
  const detail::quilt_source<T, C> src(std::move(*ex));
  detail::quilt_canvas<T, C> canvas(w, h);
  canvas.wrap_x = canvas.wrap_y = options.seamless;
  detail::quilt_params prm;
  prm.patch = patch;
  prm.tolerance = options.tolerance;
  prm.rng = counter_rng(options.seed, stream_id("image.quilt"));
  if (!options.progress.report(0.0, "quilting")) return status::cancelled();
  if (auto s = detail::fill_canvas(src, canvas, prm, overlap, exec, &options.progress); !s) return s;
  return copy_image(canvas.pixels, out);
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_quilt.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
