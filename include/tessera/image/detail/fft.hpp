// tessera/image/detail/fft.hpp: a small radix-2 complex FFT (1D and 2D, double precision) for the
// correlation sums of image/metrics.hpp and image/patch_size.hpp. Internal; no stability promise.
#pragma once

#include <cmath>
#include <complex>
#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// An offset whose overlap variance (of either image) is at or below this times the overlap's pixel
/// count is flat: its normalized correlation is undefined (NaN) instead of a ratio of rounding noise.
inline constexpr double flat_variance_per_pixel = 1e-9;

/// Smallest power of two >= n (n >= 1).
inline index_t next_pow2(index_t n) noexcept {
  index_t p = 1;
  while (p < n) p <<= 1;
  return p;
}

/// In-place iterative radix-2 FFT of a power-of-two length sequence with unit stride. `inverse`
/// computes the unscaled inverse transform (callers divide by n). Twiddles come from a table built
/// once per length, so results are deterministic and accurate to about 1e-15 relative.
class fft_plan {
 public:
  explicit fft_plan(index_t n) : n_(n), twiddle_(to_size(n / 2)), rev_(to_size(n)) {
    TESSERA_ASSERT(n >= 1 && (n & (n - 1)) == 0);
    const double pi = 3.14159265358979323846;
    for (index_t k = 0; k < n / 2; ++k)
      twiddle_[to_size(k)] = std::polar(1.0, -2.0 * pi * static_cast<double>(k) / static_cast<double>(n));
    int bits = 0;
    while ((index_t{1} << bits) < n) ++bits;
    for (index_t i = 0; i < n; ++i) {
      index_t r = 0;
      for (int b = 0; b < bits; ++b)
        if (i & (index_t{1} << b)) r |= index_t{1} << (bits - 1 - b);
      rev_[to_size(i)] = r;
    }
  }
  [[nodiscard]] index_t size() const noexcept { return n_; }

  void run(std::complex<double>* a, bool inverse) const noexcept {
    for (index_t i = 0; i < n_; ++i) {
      const index_t r = rev_[to_size(i)];
      if (i < r) std::swap(a[i], a[r]);
    }
    for (index_t len = 2; len <= n_; len <<= 1) {
      const index_t half = len / 2, step = n_ / len;
      for (index_t start = 0; start < n_; start += len)
        for (index_t k = 0; k < half; ++k) {
          std::complex<double> w = twiddle_[to_size(k * step)];
          if (inverse) w = std::conj(w);
          const std::complex<double> u = a[start + k], v = a[start + k + half] * w;
          a[start + k] = u + v;
          a[start + k + half] = u - v;
        }
    }
  }

 private:
  index_t n_;
  std::vector<std::complex<double>> twiddle_;
  std::vector<index_t> rev_;
};

/// 2D FFT of a row-major `width` x `height` grid (both powers of two), in place, unscaled.
inline void fft_2d(std::vector<std::complex<double>>& grid, index_t width, index_t height, bool inverse) {
  TESSERA_ASSERT(static_cast<index_t>(grid.size()) == width * height);
  const fft_plan rows(width), cols(height);
  for (index_t y = 0; y < height; ++y) rows.run(grid.data() + y * width, inverse);
  std::vector<std::complex<double>> column(to_size(height));
  for (index_t x = 0; x < width; ++x) {
    for (index_t y = 0; y < height; ++y) column[to_size(y)] = grid[to_size(y * width + x)];
    cols.run(column.data(), inverse);
    for (index_t y = 0; y < height; ++y) grid[to_size(y * width + x)] = column[to_size(y)];
  }
}

/// Circular autocorrelation r(dx, dy) = sum f(x, y) f(x + dx, y + dy) of a real `width` x `height`
/// signal zero-padded into a `pw` x `ph` grid (powers of two, pw >= width + max |dx| and likewise
/// for ph so no wrap-around mixes in). Returns the pw x ph grid of r, indexed (dx mod pw, dy mod ph).
inline std::vector<double> autocorrelation(const double* f, index_t width, index_t height, index_t pw, index_t ph) {
  std::vector<std::complex<double>> grid(to_size(pw * ph));
  for (index_t y = 0; y < height; ++y)
    for (index_t x = 0; x < width; ++x) grid[to_size(y * pw + x)] = f[y * width + x];
  fft_2d(grid, pw, ph, false);
  for (auto& v : grid) v = std::norm(v);
  fft_2d(grid, pw, ph, true);
  std::vector<double> out(grid.size());
  const double scale = 1.0 / static_cast<double>(pw * ph);
  for (std::size_t i = 0; i < grid.size(); ++i) out[i] = grid[i].real() * scale;
  return out;
}

/// Normalized autocorrelation of an image of `channels` interleaved channels (any real values): for
/// every offset dx in [-max_dx, max_dx], dy in [0, max_dy] (the other half follows by symmetry), the
/// Pearson correlation between the pixels (x, y) and (x + dx, y + dy) over the pairs inside the image,
/// channels pooled with per-channel means. Needs max_dx < width and max_dy < height. Offsets where either
/// side has no variance hold NaN. Row-major result: index dy * (2 max_dx + 1) + dx + max_dx.
/// O(channels N log N) through FFT correlation sums and integral images.
inline std::vector<double> correlation_field(const double* f, index_t width, index_t height, int channels,
                                             index_t max_dx, index_t max_dy) {
  TESSERA_ASSERT(max_dx >= 0 && max_dy >= 0 && max_dx < width && max_dy < height);
  const index_t w = width, h = height, pw = next_pow2(w + max_dx), ph = next_pow2(h + max_dy);
  const index_t nox = 2 * max_dx + 1, noy = max_dy + 1;
  const auto n_off = to_size(nox * noy);
  std::vector<double> cov(3 * n_off, 0.0);  // covariance, then the two variances, per offset
  double* const var_a = cov.data() + n_off;
  double* const var_b = cov.data() + 2 * n_off;
  std::vector<double> g(to_size(w * h));
  std::vector<double> s1(to_size((w + 1) * (h + 1)), 0.0), s2(s1.size(), 0.0);
  for (int c = 0; c < channels; ++c) {
    double mean = 0;
    for (index_t i = 0; i < w * h; ++i) mean += f[i * channels + c];
    mean /= static_cast<double>(w * h);
    for (index_t i = 0; i < w * h; ++i) g[to_size(i)] = f[i * channels + c] - mean;
    // integral images of g and g^2: S(x, y) = sum over [0, x) x [0, y)
    for (index_t y = 1; y <= h; ++y)
      for (index_t x = 1; x <= w; ++x) {
        const auto at = to_size(y * (w + 1) + x), up = at - to_size(w + 1);
        const double v = g[to_size((y - 1) * w + x - 1)];
        s1[at] = v + s1[at - 1] + s1[up] - s1[up - 1];
        s2[at] = v * v + s2[at - 1] + s2[up] - s2[up - 1];
      }
    auto box = [&](const std::vector<double>& s, index_t x0, index_t y0, index_t x1, index_t y1) {
      auto at = [&](index_t x, index_t y) { return s[to_size(y * (w + 1) + x)]; };
      return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
    };
    const std::vector<double> r = autocorrelation(g.data(), w, h, pw, ph);
    for (index_t dy = 0; dy <= max_dy; ++dy)
      for (index_t dx = -max_dx; dx <= max_dx; ++dx) {
        // pairs (x, y) and (x + dx, y + dy), both inside: x in [x0, x1), y in [0, h - dy)
        const index_t x0 = std::max<index_t>(0, -dx), x1 = std::min(w, w - dx), y1 = h - dy;
        const double n = static_cast<double>((x1 - x0) * y1);
        const double sa = box(s1, x0, 0, x1, y1), sb = box(s1, x0 + dx, dy, x1 + dx, y1 + dy);
        const double saa = box(s2, x0, 0, x1, y1), sbb = box(s2, x0 + dx, dy, x1 + dx, y1 + dy);
        const double sab = r[to_size(dy * pw + (dx + pw) % pw)];
        const auto o = to_size(dy * nox + dx + max_dx);
        cov[o] += sab - sa * sb / n;
        var_a[o] += saa - sa * sa / n;
        var_b[o] += sbb - sb * sb / n;
      }
  }
  for (index_t dy = 0; dy <= max_dy; ++dy)
    for (index_t dx = -max_dx; dx <= max_dx; ++dx) {
      const auto o = to_size(dy * nox + dx + max_dx);
      const double tiny = flat_variance_per_pixel * static_cast<double>((w - (dx < 0 ? -dx : dx)) * (h - dy));
      cov[o] = (var_a[o] > tiny && var_b[o] > tiny) ? std::min(1.0, cov[o] / std::sqrt(var_a[o] * var_b[o]))
                                                    : std::numeric_limits<double>::quiet_NaN();
    }
  cov.resize(n_off);
  return cov;
}

}  // namespace detail
TESSERA_NAMESPACE_END
