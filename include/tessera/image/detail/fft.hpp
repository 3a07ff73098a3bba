// tessera/image/detail/fft.hpp: a small radix-2 complex FFT (1D and 2D, double precision) for the
// correlation sums of image/metrics.hpp and image/patch_size.hpp. Internal; no stability promise.
#pragma once

#include <cmath>
#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

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
  explicit fft_plan(index_t n) : n_(n), twiddle_(static_cast<std::size_t>(n / 2)), rev_(static_cast<std::size_t>(n)) {
    TESSERA_ASSERT(n >= 1 && (n & (n - 1)) == 0);
    const double pi = 3.14159265358979323846;
    for (index_t k = 0; k < n / 2; ++k)
      twiddle_[static_cast<std::size_t>(k)] = std::polar(1.0, -2.0 * pi * static_cast<double>(k) / static_cast<double>(n));
    int bits = 0;
    while ((index_t{1} << bits) < n) ++bits;
    for (index_t i = 0; i < n; ++i) {
      index_t r = 0;
      for (int b = 0; b < bits; ++b)
        if (i & (index_t{1} << b)) r |= index_t{1} << (bits - 1 - b);
      rev_[static_cast<std::size_t>(i)] = r;
    }
  }
  [[nodiscard]] index_t size() const noexcept { return n_; }

  void run(std::complex<double>* a, bool inverse) const noexcept {
    for (index_t i = 0; i < n_; ++i) {
      const index_t r = rev_[static_cast<std::size_t>(i)];
      if (i < r) std::swap(a[i], a[r]);
    }
    for (index_t len = 2; len <= n_; len <<= 1) {
      const index_t half = len / 2, step = n_ / len;
      for (index_t start = 0; start < n_; start += len)
        for (index_t k = 0; k < half; ++k) {
          std::complex<double> w = twiddle_[static_cast<std::size_t>(k * step)];
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
  std::vector<std::complex<double>> column(static_cast<std::size_t>(height));
  for (index_t x = 0; x < width; ++x) {
    for (index_t y = 0; y < height; ++y) column[static_cast<std::size_t>(y)] = grid[static_cast<std::size_t>(y * width + x)];
    cols.run(column.data(), inverse);
    for (index_t y = 0; y < height; ++y) grid[static_cast<std::size_t>(y * width + x)] = column[static_cast<std::size_t>(y)];
  }
}

/// Circular autocorrelation r(dx, dy) = sum f(x, y) f(x + dx, y + dy) of a real `width` x `height`
/// signal zero-padded into a `pw` x `ph` grid (powers of two, pw >= width + max |dx| and likewise
/// for ph so no wrap-around mixes in). Returns the pw x ph grid of r, indexed (dx mod pw, dy mod ph).
inline std::vector<double> autocorrelation(const double* f, index_t width, index_t height, index_t pw, index_t ph) {
  std::vector<std::complex<double>> grid(static_cast<std::size_t>(pw * ph));
  for (index_t y = 0; y < height; ++y)
    for (index_t x = 0; x < width; ++x) grid[static_cast<std::size_t>(y * pw + x)] = f[y * width + x];
  fft_2d(grid, pw, ph, false);
  for (auto& v : grid) v = std::norm(v);
  fft_2d(grid, pw, ph, true);
  std::vector<double> out(grid.size());
  const double scale = 1.0 / static_cast<double>(pw * ph);
  for (std::size_t i = 0; i < grid.size(); ++i) out[i] = grid[i].real() * scale;
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
