// tessera/terrain/detail/resample.hpp: separable image resampling with a low-pass kernel scaled to
// the reduction (the kernel is widened by 1 / scale when shrinking, so frequencies above the new
// Nyquist limit are removed instead of aliased). Borders clamp to the edge. Float in, float out.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/image.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

/// Below this |x| the Lanczos kernel takes its limit 1 instead of the 0 / 0 of sin(px) sin(px/3) / (px)^2.
inline constexpr double lanczos_zero = 1e-12;

/// Lanczos-3 windowed sinc.
inline double lanczos3(double x) noexcept {
  x = std::abs(x);
  if (x < lanczos_zero) return 1.0;
  if (x >= 3.0) return 0.0;
  constexpr double pi = 3.14159265358979323846;
  const double px = pi * x;
  return 3.0 * std::sin(px) * std::sin(px / 3.0) / (px * px);
}

/// Taps of one output coordinate: source indices [first, first + weights.size()) (clamped when
/// used), normalized weights.
struct resample_taps {
  std::vector<index_t> first;
  std::vector<index_t> count;
  std::vector<float> weights;  ///< concatenated, count[i] per output i
  std::vector<index_t> offset;
};

/// Taps mapping `src` samples to `dst` samples (pixel centres aligned: output i at source
/// (i + 0.5) * src / dst - 0.5).
inline resample_taps make_taps(index_t src, index_t dst) {
  resample_taps t;
  const double ratio = static_cast<double>(dst) / static_cast<double>(src);  // < 1 shrinks
  const double support = 3.0 / std::min(1.0, ratio), kscale = std::min(1.0, ratio);
  t.first.resize(to_size(dst));
  t.count.resize(to_size(dst));
  t.offset.resize(to_size(dst));
  for (index_t i = 0; i < dst; ++i) {
    const double c = (static_cast<double>(i) + 0.5) / ratio - 0.5;
    const auto lo = static_cast<index_t>(std::ceil(c - support)), hi = static_cast<index_t>(std::floor(c + support));
    t.first[to_size(i)] = lo;
    t.offset[to_size(i)] = static_cast<index_t>(t.weights.size());
    double sum = 0;
    for (index_t j = lo; j <= hi; ++j) sum += lanczos3((static_cast<double>(j) - c) * kscale);
    for (index_t j = lo; j <= hi; ++j)
      t.weights.push_back(static_cast<float>(lanczos3((static_cast<double>(j) - c) * kscale) / sum));
    t.count[to_size(i)] = hi - lo + 1;
  }
  return t;
}

/// Resamples a float image of `channels` interleaved channels from sw x sh to dw x dh. `rows` runs
/// the per-row loops (an executor's parallel_for); results do not depend on how rows are split.
template <class Rows>
std::vector<float> resample_image(const float* src, index_t sw, index_t sh, int channels, index_t dw, index_t dh,
                                  Rows&& rows) {
  const resample_taps tx = make_taps(sw, dw), ty = make_taps(sh, dh);
  const index_t C = channels;
  std::vector<float> tmp(to_size(dw * sh * C)), out(to_size(dw * dh * C));
  rows(sh, [&](index_t y) {
    const float* s = src + y * sw * C;
    float* d = tmp.data() + y * dw * C;
    for (index_t x = 0; x < dw; ++x) {
      const float* w = tx.weights.data() + tx.offset[to_size(x)];
      const index_t first = tx.first[to_size(x)], n = tx.count[to_size(x)];
      float acc[4] = {0, 0, 0, 0};
      for (index_t k = 0; k < n; ++k) {
        const index_t sx = std::clamp<index_t>(first + k, 0, sw - 1);
        for (index_t c = 0; c < C; ++c) acc[c] += w[k] * s[sx * C + c];
      }
      for (index_t c = 0; c < C; ++c) d[x * C + c] = acc[c];
    }
  });
  rows(dh, [&](index_t y) {
    const float* w = ty.weights.data() + ty.offset[to_size(y)];
    const index_t first = ty.first[to_size(y)], n = ty.count[to_size(y)];
    float* d = out.data() + y * dw * C;
    for (index_t x = 0; x < dw * C; ++x) d[x] = 0;
    for (index_t k = 0; k < n; ++k) {
      const float* s = tmp.data() + std::clamp<index_t>(first + k, 0, sh - 1) * dw * C;
      const float wk = w[k];
      for (index_t x = 0; x < dw * C; ++x) d[x] += wk * s[x];
    }
  });
  return out;
}

/// Bilinear sample of an image of C channels of T (as unit floats) at continuous pixel coordinates
/// (x, y) with pixel centres on integers; `index(i, n)` maps an integer coordinate into [0, n)
/// (clamping or wrapping).
template <class Img, class Index>
std::array<float, Img::channels> bilinear_sample(const Img& img, double x, double y, Index index) noexcept {
  constexpr int C = Img::channels;
  const double fx0 = std::floor(x), fy0 = std::floor(y);
  const auto fx = static_cast<float>(x - fx0), fy = static_cast<float>(y - fy0);
  const index_t w = img.width(), h = img.height();
  const index_t x0 = index(fx0, w), x1 = index(fx0 + 1, w), y0 = index(fy0, h), y1 = index(fy0 + 1, h);
  const auto *p00 = img.pixel_ptr(x0, y0), *p10 = img.pixel_ptr(x1, y0), *p01 = img.pixel_ptr(x0, y1),
             *p11 = img.pixel_ptr(x1, y1);
  std::array<float, C> out;
  for (int c = 0; c < C; ++c) {
    const float top = channel_to_unit(p00[c]) + fx * (channel_to_unit(p10[c]) - channel_to_unit(p00[c]));
    const float bot = channel_to_unit(p01[c]) + fx * (channel_to_unit(p11[c]) - channel_to_unit(p01[c]));
    out[to_size(c)] = top + fy * (bot - top);
  }
  return out;
}

/// Index maps for bilinear_sample (function objects, so the calls inline): clamp to the border, or
/// wrap around. Both map NaN and infinities into range (to 0 or the border) instead of casting them.
struct clamp_index {
  index_t operator()(double i, index_t n) const noexcept {
    return !(i > 0) ? index_t{0} : i >= static_cast<double>(n - 1) ? n - 1 : static_cast<index_t>(i);
  }
};
struct wrap_index {
  index_t operator()(double i, index_t n) const noexcept {
    const double m = std::fmod(i, static_cast<double>(n));  // NaN for NaN or infinite i
    if (!std::isfinite(m)) return 0;
    return static_cast<index_t>(m < 0 ? m + static_cast<double>(n) : m) % n;
  }
};

}  // namespace detail

TESSERA_NAMESPACE_END
