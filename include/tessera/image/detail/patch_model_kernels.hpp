// tessera/image/detail/patch_model_kernels.hpp: the preprocessing kernels of image/patch_model.hpp
// (paper 002 §2, preprocessing steps 2 and 3): exact overlap errors, compatible sets through PCA +
// nanoflann, and minimum-error seams. Internal; no stability promise.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "../../core/config.hpp"
#include "../../core/image_buffer.hpp"
#include "nearest.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Sum of squared differences between two windows of `cols` x `rows` pixels of `img`, exact: integer
/// arithmetic for uint8 and uint16 channels (64-bit totals; uint8 rows in 32-bit chunks of at most
/// 65536 values, which cannot overflow), double accumulation in a fixed order for float. Stops early
/// (returning a partial sum above `bound`) once the sum exceeds `bound`.
template <class T, int C>
double window_ssd(const image_buffer<T, C>& img, index_t ax, index_t ay, index_t bx, index_t by, index_t cols,
                  index_t rows, double bound = std::numeric_limits<double>::infinity()) {
  const index_t n = cols * C;
  if constexpr (std::is_same_v<T, std::uint8_t>) {
    // 32-bit sums over at most 65536 values (65536 x 255^2 < 2^32), flushed into a 64-bit total
    constexpr index_t chunk = 65536;
    std::uint64_t total = 0;
    for (index_t r = 0; r < rows; ++r) {
      const std::uint8_t* a = img.pixel_ptr(ax, ay + r);
      const std::uint8_t* b = img.pixel_ptr(bx, by + r);
      for (index_t i0 = 0; i0 < n; i0 += chunk) {
        const index_t i1 = std::min(n, i0 + chunk);
        std::uint32_t s = 0;
        for (index_t i = i0; i < i1; ++i) {
          const int d = static_cast<int>(a[i]) - static_cast<int>(b[i]);
          s += static_cast<std::uint32_t>(d * d);
        }
        total += s;
      }
      if (static_cast<double>(total) > bound) break;
    }
    return static_cast<double>(total);
  } else if constexpr (std::is_same_v<T, std::uint16_t>) {
    std::uint64_t total = 0;
    for (index_t r = 0; r < rows; ++r) {
      const std::uint16_t* a = img.pixel_ptr(ax, ay + r);
      const std::uint16_t* b = img.pixel_ptr(bx, by + r);
      for (index_t i = 0; i < n; ++i) {
        const std::int64_t d = static_cast<std::int64_t>(a[i]) - static_cast<std::int64_t>(b[i]);
        total += static_cast<std::uint64_t>(d * d);
      }
      if (static_cast<double>(total) > bound) break;
    }
    return static_cast<double>(total);
  } else {
    double total = 0;
    for (index_t r = 0; r < rows; ++r) {
      const float* a = img.pixel_ptr(ax, ay + r);
      const float* b = img.pixel_ptr(bx, by + r);
      for (index_t i = 0; i < n; ++i) {
        const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
        total += d * d;
      }
      if (total > bound) break;
    }
    return total;
  }
}

/// A family of equally sized exemplar windows (the vertical or the horizontal overlap strips) with
/// their PCA projections.
template <class T, int C>
struct strip_family {
  index_t cols = 0, rows = 0;        ///< window size in pixels
  index_t count_x = 0, count_y = 0;  ///< window positions: x in [0, count_x), y in [0, count_y)
  // Eigen types through dependent_t: compiled only where a strip family is built
  using real = dependent_t<double, T>;
  using matrix = Eigen::Matrix<real, Eigen::Dynamic, Eigen::Dynamic>;
  using row_major = Eigen::Matrix<real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  matrix basis;                   ///< D x d
  std::vector<double> projected;  ///< count_x * count_y rows of d values
  std::vector<double> residual;   ///< per window: its squared distance to the PCA subspace (centred strips)
  int d = 0;

  void gather(const image_buffer<T, C>& img, index_t x, index_t y, double* out) const {
    for (index_t r = 0; r < rows; ++r) {
      const T* p = img.pixel_ptr(x, y + r);
      for (index_t i = 0; i < cols * C; ++i) *out++ = static_cast<double>(p[i]);
    }
  }

  /// PCA basis from up to `samples` evenly spread windows, then every window projected (in blocks,
  /// through Eigen's matrix product).
  template <class Ex>
  void build(const image_buffer<T, C>& img, index_t cols_, index_t rows_, index_t count_x_, index_t count_y_, int dims,
             index_t samples, Ex&& exec) {
    cols = cols_;
    rows = rows_;
    count_x = count_x_;
    count_y = count_y_;
    const index_t n = count_x * count_y, D = cols * rows * C;
    const index_t m = std::min(n, samples);
    row_major sample(m, D);
    for (index_t s = 0; s < m; ++s) {
      const index_t i = s * n / m;
      gather(img, i % count_x, i / count_x, sample.row(s).data());
    }
    basis = pca_basis(matrix(sample), dims);
    d = static_cast<int>(basis.cols());
    // the sample mean and its projection, for each window's residual |x - mean|^2 - |B^T (x - mean)|^2
    // (the basis is orthonormal): what the d projections miss of the strip
    const Eigen::Matrix<real, 1, Eigen::Dynamic> mean = sample.colwise().mean();
    const Eigen::Matrix<real, 1, Eigen::Dynamic> mean_proj = mean * basis;
    projected.assign(to_size(n * d), 0.0);
    residual.assign(to_size(n), 0.0);
    constexpr index_t block = 128;
    exec.parallel_for(0, (n + block - 1) / block, [&](index_t b) {
      const index_t first = b * block, last = std::min(n, first + block);
      row_major x(last - first, D);
      for (index_t i = first; i < last; ++i) gather(img, i % count_x, i / count_x, x.row(i - first).data());
      Eigen::Map<row_major> out(projected.data() + first * d, last - first, d);
      out.noalias() = x * basis;
      for (index_t i = first; i < last; ++i) {
        const real total = (x.row(i - first) - mean).squaredNorm();
        const real in_span = (out.row(i - first) - mean_proj).squaredNorm();
        residual[to_size(i)] = std::max(0.0, static_cast<double>(total - in_span));
      }
    });
  }
  [[nodiscard]] const double* projection(index_t x, index_t y) const {
    return projected.data() + (y * count_x + x) * d;
  }
};

/// The strips of one family in the compact form the estimated fallback of synthesis reads: per window
/// (x, y), its d PCA projections and its residual (strip_family), as float.
struct strip_descriptors {
  index_t count_x = 0, count_y = 0;
  int d = 0;
  std::vector<float> values;  ///< count_x * count_y windows of d + 1 floats
  template <class T, int C>
  static strip_descriptors of(const strip_family<T, C>& f) {
    strip_descriptors s{f.count_x, f.count_y, f.d, {}};
    const index_t n = f.count_x * f.count_y, stride = f.d + 1;
    s.values.resize(to_size(n * stride));
    for (index_t i = 0; i < n; ++i) {
      for (int j = 0; j < f.d; ++j)
        s.values[to_size(i * stride + j)] = static_cast<float>(f.projected[to_size(i * f.d + j)]);
      s.values[to_size(i * stride + f.d)] = static_cast<float>(f.residual[to_size(i)]);
    }
    return s;
  }
  [[nodiscard]] const float* at(index_t x, index_t y) const noexcept {
    return values.data() + (y * count_x + x) * (d + 1);
  }
  /// Estimated squared error between two windows: the distance of their projections plus both residuals
  /// (what the projections miss, taken as uncorrelated).
  [[nodiscard]] double estimate(const float* a, const float* b) const noexcept {
    float e = a[d] + b[d];
    for (int j = 0; j < d; ++j) e += (a[j] - b[j]) * (a[j] - b[j]);
    return static_cast<double>(e);
  }
  [[nodiscard]] std::size_t bytes() const noexcept { return values.size() * sizeof(float); }
};

/// One round of coherence propagation over approximate compatible sets (the k-coherence idea of paper
/// 002's ref. [3], in PatchMatch's form): queries are patches on an nx x ny grid whose strips overlap
/// their grid neighbours' strips, so if b fits a's neighbour a + (dx, dy) well, b - (dx, dy) likely fits
/// a. Every patch's set is re-ranked with those shifted candidates by `exact(a, b, bound)` (see
/// lower_bound_knn::search_approximate for `bound`); ties by index. Sets may start empty (entries
/// with a NaN distance are ignored, and neighbours' NaN entries propose nothing); a set that stays
/// short of k gets `refill(a, best)`. Reads the old sets and writes new ones, so the result does not
/// depend on the executor.
template <class Exact, class Refill, class Ex>
void propagate_sets(index_t nx, index_t ny, index_t k, std::vector<std::uint32_t>& ids, std::vector<double>& dists,
                    Exact&& exact, Refill&& refill, Ex&& exec) {
  std::vector<std::uint32_t> new_ids(ids.size());
  std::vector<double> new_dists(dists.size());
  const auto kk = to_size(k);
  exec.parallel_for(0, ny, [&](index_t y) {
    std::vector<neighbor> best;
    std::vector<std::uint32_t> cand;
    for (index_t x = 0; x < nx; ++x) {
      const index_t a = y * nx + x;
      best.clear();
      for (index_t r = 0; r < k; ++r)
        if (!std::isnan(dists[to_size(a * k + r)]))
          best.push_back({dists[to_size(a * k + r)], ids[to_size(a * k + r)]});
      cand.clear();
      constexpr index_t shifts[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
      for (const auto& d : shifts) {
        const index_t qx = x + d[0], qy = y + d[1];
        if (qx < 0 || qy < 0 || qx >= nx || qy >= ny) continue;
        for (index_t r = 0; r < k; ++r) {
          const auto at = to_size((qy * nx + qx) * k + r);
          if (std::isnan(dists[at])) continue;
          const index_t b = ids[at], bx = b % nx - d[0], by = b / nx - d[1];
          if (bx >= 0 && by >= 0 && bx < nx && by < ny) cand.push_back(static_cast<std::uint32_t>(by * nx + bx));
        }
      }
      std::sort(cand.begin(), cand.end());
      cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
      for (std::uint32_t c : cand) {
        bool known = false;
        for (const neighbor& n : best) known = known || n.index == c;
        if (!known) insert_top_k(best, kk, neighbor{exact(a, c, bound_of(best, kk)), c});
      }
      if (best.size() < kk) refill(a, best);
      TESSERA_ASSERT(best.size() == kk);
      for (index_t r = 0; r < k; ++r) {
        new_ids[to_size(a * k + r)] = best[to_size(r)].index;
        new_dists[to_size(a * k + r)] = best[to_size(r)].dist;
      }
    }
  });
  ids.swap(new_ids);
  dists.swap(new_dists);
}

/// Scratch buffers of min_error_seam, reused between calls.
struct seam_scratch {
  std::vector<double> err;   ///< len x v squared differences
  std::vector<double> cost;  ///< len x (v + 2) cumulative path costs
};

/// Squared difference of n consecutive pixels of two rows, pixel by pixel, into out[i * step]: exact
/// integers for uint8 and uint16 channels, double for float (channels summed in order).
template <class T, int C>
inline void pixel_errors(const T* a, const T* b, index_t n, double* out, index_t step) noexcept {
  for (index_t i = 0; i < n; ++i, a += C, b += C) {
    if constexpr (std::is_same_v<T, std::uint8_t>) {
      std::int32_t s = 0;  // at most 4 x 255^2
      for (int c = 0; c < C; ++c)
        s += (static_cast<std::int32_t>(a[c]) - b[c]) * (static_cast<std::int32_t>(a[c]) - b[c]);
      out[i * step] = static_cast<double>(s);
    } else if constexpr (std::is_same_v<T, std::uint16_t>) {
      std::int64_t s = 0;
      for (int c = 0; c < C; ++c)
        s += (static_cast<std::int64_t>(a[c]) - b[c]) * (static_cast<std::int64_t>(a[c]) - b[c]);
      out[i * step] = static_cast<double>(s);
    } else {
      double s = 0;
      for (int c = 0; c < C; ++c) {
        const double d = static_cast<double>(a[c]) - static_cast<double>(b[c]);
        s += d * d;
      }
      out[i * step] = s;
    }
  }
}

/// Minimum-error boundary cut (Efros and Freeman's dynamic programming, the improvement paper 002 §2
/// names) through the overlap of a left patch at exemplar origin (lx, ly) and a right patch at (rx,
/// ry): the overlap is the columns [offset, offset + v) of the left patch and [0, v) of the right one,
/// over `len` rows. For each row, writes the cut c in [0, v): columns < c come from the left patch,
/// >= c from the right. A horizontal seam is the same problem with x and y exchanged (`transpose`).
/// Ties go to the smaller column. The squared differences are gathered row by row of the exemplar
/// (contiguous pixels) before the dynamic programme; integer channels give exact path costs.
template <class T, int C>
void min_error_seam(const image_buffer<T, C>& img, index_t lx, index_t ly, index_t rx, index_t ry, index_t offset,
                    index_t v, index_t len, bool transpose, std::uint8_t* cut, seam_scratch& scratch) {
  scratch.err.resize(to_size(len * v));
  double* e = scratch.err.data();
  if (!transpose) {
    for (index_t r = 0; r < len; ++r)
      pixel_errors<T, C>(img.pixel_ptr(lx + offset, ly + r), img.pixel_ptr(rx, ry + r), v, e + r * v, 1);
  } else {  // overlap row c of the upper patch against row c of the lower one, along `len` columns
    for (index_t c = 0; c < v; ++c)
      pixel_errors<T, C>(img.pixel_ptr(lx, ly + offset + c), img.pixel_ptr(rx, ry + c), len, e + c, v);
  }
  // cumulative costs in rows of v + 2 with +infinity at both ends, so the three-way minimum has no
  // branches and vectorizes
  const index_t stride = v + 2;
  constexpr double inf = std::numeric_limits<double>::infinity();
  scratch.cost.resize(to_size(len * stride));
  double* m = scratch.cost.data();
  for (index_t r = 0; r < len; ++r) m[r * stride] = m[r * stride + v + 1] = inf;
  for (index_t c = 0; c < v; ++c) m[c + 1] = e[c];
  for (index_t r = 1; r < len; ++r) {
    const double* up = m + (r - 1) * stride + 1;
    double* row = m + r * stride + 1;
    const double* er = e + r * v;
    for (index_t c = 0; c < v; ++c) row[c] = er[c] + std::min(std::min(up[c - 1], up[c]), up[c + 1]);
  }
  auto at = [&](index_t r, index_t c) { return m[r * stride + c + 1]; };
  index_t c = 0;
  for (index_t k = 1; k < v; ++k)
    if (at(len - 1, k) < at(len - 1, c)) c = k;
  cut[len - 1] = static_cast<std::uint8_t>(c);
  for (index_t r = len - 1; r > 0; --r) {
    index_t next = c;
    for (index_t k = std::max<index_t>(0, c - 1); k <= std::min(v - 1, c + 1); ++k)
      if (at(r - 1, k) < at(r - 1, next) || (at(r - 1, k) == at(r - 1, next) && k < next)) next = k;
    c = next;
    cut[r - 1] = static_cast<std::uint8_t>(c);
  }
}

}  // namespace detail
TESSERA_NAMESPACE_END
