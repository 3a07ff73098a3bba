// tessera/terrain/build_exemplar_pyramid.hpp: the exemplar resampled to every scale of the scale
// field (paper 003, §2.2 step 4: "shrink the exemplar like a pyramid into many gradually smaller
// levels"). Unlike a mipmap's factors of two, the levels are finely spaced between 1 and
// min_scale (by default consecutive scales differ by at most 0.008), because §2.3 carries texture
// coordinates unchanged (the identity map) between adjacent levels and that is only seamless when
// adjacent levels are nearly the same image. Each level is a proper low-pass resampling: a
// separable Lanczos-3 kernel widened by 1 / scale, so detail finer than the level can hold is
// filtered out rather than aliased.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "detail/resample.hpp"
#include "detail/tolerances.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of build_exemplar_pyramid (§2.2 step 4).
struct exemplar_pyramid_options {
  double min_scale = 0.5;   ///< scale of the last level, in (0, 1]
  index_t levels = 0;       ///< number of levels (1 to 4096); 0 = as few as keep steps <= max_step
  double max_step = 0.008;  ///< largest scale step between consecutive levels when levels = 0
  /// Progress callback and cancellation token.
  tessera::progress progress = {};
};

template <Channel T, int C>
class exemplar_pyramid;

namespace detail {
template <Channel T, int C, class E>
result<exemplar_pyramid<T, C>> build_pyramid_from_buffer(const image_buffer<T, C>& ex,
                                                         const exemplar_pyramid_options& opts, E& exec);
}  // namespace detail

/// Levels k = 0 .. K-1 at scales 1 - (1 - min_scale) k / (K - 1) (level 0 is the exemplar), each an
/// image_buffer of round(width * scale) x round(height * scale) pixels. Read-only after building:
/// safe to share between threads.
template <Channel T, int C>
class exemplar_pyramid {
 public:
  /// The pixel type, C channels of T.
  using pixel_type = pixel<T, C>;
  exemplar_pyramid() = default;

  /// Number of levels.
  [[nodiscard]] index_t num_levels() const noexcept { return static_cast<index_t>(levels_.size()); }
  [[nodiscard]] index_t width() const noexcept { return width_; }    ///< of the exemplar (level 0)
  [[nodiscard]] index_t height() const noexcept { return height_; }  ///< of the exemplar (level 0)
  /// Scale of the last level.
  [[nodiscard]] double min_scale() const noexcept { return min_scale_; }
  /// Scale of level k (1 for level 0, decreasing to min_scale).
  [[nodiscard]] double scale(index_t k) const noexcept {
    const index_t n = num_levels();
    return n <= 1 ? 1.0 : 1.0 - (1.0 - min_scale_) * static_cast<double>(k) / static_cast<double>(n - 1);
  }
  /// The image of level k (the exemplar shrunk by scale(k)).
  [[nodiscard]] const image_buffer<T, C>& level(index_t k) const noexcept { return levels_[detail::to_size(k)]; }

  /// Fractional level index of scale s (clamped to [0, K - 1]; 0 for NaN).
  [[nodiscard]] double level_position(double s) const noexcept {
    const index_t n = num_levels();
    if (n <= 1 || min_scale_ >= 1 || std::isnan(s)) return 0.0;
    return std::clamp((1.0 - s) / (1.0 - min_scale_) * static_cast<double>(n - 1), 0.0, static_cast<double>(n - 1));
  }

  /// The exemplar shrunk by scale s, sampled at (u, v) in pixels of that shrunk image (pixel
  /// centres at +0.5, so [0, width * s] x [0, height * s] is the image): bilinear inside the two
  /// levels nearest to s, linear between them, clamped at the borders. Channels as unit floats
  /// (0..1 for integer channels, unchanged for float). O(1); thread-safe.
  [[nodiscard]] std::array<float, C> sample(double s, double u, double v) const noexcept {
    // positions within single_level_snap of a level (a stepped scale field matched to the pyramid,
    // scales stored as float) sample that level alone
    const double pos = level_position(s), near = std::floor(pos + 0.5);
    const bool exact = std::abs(pos - near) < detail::single_level_snap;
    const auto k0 = static_cast<index_t>(exact ? near : std::floor(pos));
    const double f = exact ? 0.0 : pos - static_cast<double>(k0);
    std::array<float, C> a = bilinear(k0, u / s, v / s);
    if (f > 0 && k0 + 1 < num_levels()) {
      const std::array<float, C> b = bilinear(k0 + 1, u / s, v / s);
      for (int c = 0; c < C; ++c)
        a[detail::to_size(c)] += static_cast<float>(f) * (b[detail::to_size(c)] - a[detail::to_size(c)]);
    }
    return a;
  }

 private:
  template <Channel T2, int C2, class E>
  friend result<exemplar_pyramid<T2, C2>> detail::build_pyramid_from_buffer(const image_buffer<T2, C2>&,
                                                                            const exemplar_pyramid_options&, E&);

  /// Bilinear sample of level k at exemplar coordinates (ex, ey), clamped at the border.
  [[nodiscard]] std::array<float, C> bilinear(index_t k, double ex, double ey) const noexcept {
    const image_buffer<T, C>& img = levels_[detail::to_size(k)];
    return detail::bilinear_sample(img, ex * static_cast<double>(img.width()) / static_cast<double>(width_) - 0.5,
                                   ey * static_cast<double>(img.height()) / static_cast<double>(height_) - 0.5,
                                   detail::clamp_index{});
  }

  std::vector<image_buffer<T, C>> levels_;
  index_t width_ = 0, height_ = 0;
  double min_scale_ = 1;
};

namespace detail {
template <Channel T, int C, class E>
result<exemplar_pyramid<T, C>> build_pyramid_from_buffer(const image_buffer<T, C>& ex,
                                                         const exemplar_pyramid_options& opts, E& exec) {
  index_t n = opts.levels;
  if (n == 0)
    n = opts.min_scale >= 1
            ? 1
            : static_cast<index_t>(std::ceil((1 - opts.min_scale) / opts.max_step - detail::level_count_rounding)) + 1;
  if (n > 4096)
    return status::invalid_argument(
        detail::cat("exemplar pyramid: ", n, " levels requested; at most 4096 (raise max_step)"));
  exemplar_pyramid<T, C> p;
  p.width_ = ex.width();
  p.height_ = ex.height();
  p.min_scale_ = opts.min_scale;
  p.levels_.resize(to_size(n));
  p.levels_[0] = ex;
  std::vector<float> src(to_size(ex.width() * ex.height() * C));
  for (std::size_t i = 0; i < src.size(); ++i) src[i] = channel_to_unit(ex.data()[i]);
  auto rows = [&](index_t count, auto&& body) { exec.parallel_for(0, count, body); };
  for (index_t k = 1; k < n; ++k) {
    if (!opts.progress.report(static_cast<double>(k) / static_cast<double>(n), "exemplar pyramid"))
      return status::cancelled();
    const double s = p.scale(k);
    const index_t w = std::max<index_t>(1, static_cast<index_t>(std::llround(static_cast<double>(ex.width()) * s)));
    const index_t h = std::max<index_t>(1, static_cast<index_t>(std::llround(static_cast<double>(ex.height()) * s)));
    const std::vector<float> r = detail::resample_image(src.data(), ex.width(), ex.height(), C, w, h, rows);
    image_buffer<T, C> lv(w, h);
    for (std::size_t i = 0; i < r.size(); ++i) lv.data()[i] = unit_to_channel<T>(r[i]);
    p.levels_[to_size(k)] = std::move(lv);
  }
  if (!opts.progress.report(1.0, "exemplar pyramid")) return status::cancelled();
  return p;
}
}  // namespace detail

/// Builds the pyramid of any Image (paper 003, §2.2 step 4). Levels are resampled from the
/// exemplar itself (not from each other), so no blur accumulates. Errors: an invalid exemplar,
/// min_scale outside (0, 1], levels outside 0..4096, max_step outside (0, 1], cancelled through
/// opts.progress. Work: about K * 0.6 * width * height * 30 multiply-adds per channel for K levels at
/// min_scale 0.5; rows run in parallel through `exec` (bit-identical for any executor).
template <Image I, Executor E = serial_executor>
result<exemplar_pyramid<channel_t<I>, channels_v<I>>> build_exemplar_pyramid(const I& exemplar,
                                                                             const exemplar_pyramid_options& opts = {},
                                                                             E&& exec = {}) {
  if (!(opts.min_scale > 0 && opts.min_scale <= 1))
    return status::invalid_argument(detail::cat("exemplar pyramid: min_scale must be in (0, 1], got ", opts.min_scale));
  if (opts.levels < 0 || opts.levels > 4096)
    return status::invalid_argument(
        detail::cat("exemplar pyramid: levels must be 0 (automatic) to 4096, got ", opts.levels));
  if (!(opts.max_step > 0 && opts.max_step <= 1))
    return status::invalid_argument(detail::cat("exemplar pyramid: max_step must be in (0, 1], got ", opts.max_step));
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  auto buf = to_buffer(exemplar, "exemplar");
  if (!buf) return buf.error();
  return detail::build_pyramid_from_buffer(*buf, opts, exec);
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_build_exemplar_pyramid.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
