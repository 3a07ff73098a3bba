// tessera/image/detail/patch_model_sets.hpp: the heavy steps of build_patch_model (paper 002 §2,
// preprocessing steps 2 and 3): the exemplar's autocorrelation per phase offset, the compatible sets
// of every patch side (PCA + nanoflann, exact re-ranking, coherence propagation) and the table of
// minimum-error seams. Patches are indexed p = y * nx + x by their exemplar origin (x, y); sides are
// numbered 0 north, 1 east, 2 south, 3 west (the sides of core/tile_coloring.hpp). Internal; no stability promise.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/image_buffer.hpp"
#include "fft.hpp"
#include "nearest.hpp"
#include "patch_model_kernels.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Geometry of a patch model: pitch pw x ph, overlap v, patch origins on an nx x ny grid.
struct patch_geometry {
  index_t pw = 0, ph = 0, v = 0, nx = 0, ny = 0;
  [[nodiscard]] index_t x(index_t p) const noexcept { return p % nx; }
  [[nodiscard]] index_t y(index_t p) const noexcept { return p / nx; }
};

/// Exact sum of squared differences over the overlap strip when patch b sits on `side` of patch a, or
/// a partial sum above `bound` once it exceeds `bound` (window_ssd).
template <class T, int C>
double strip_error(const image_buffer<T, C>& ex, const patch_geometry& g, index_t a, index_t b, int side,
                   double bound) {
  const index_t ax = g.x(a), ay = g.y(a), bx = g.x(b), by = g.y(b);
  switch (side) {
    case 1: return window_ssd(ex, ax + g.pw, ay, bx, by, g.v, g.ph + g.v, bound);   // east
    case 3: return window_ssd(ex, bx + g.pw, by, ax, ay, g.v, g.ph + g.v, bound);   // west
    case 2: return window_ssd(ex, ax, ay + g.ph, bx, by, g.pw + g.v, g.v, bound);   // south
    default: return window_ssd(ex, bx, by + g.ph, ax, ay, g.pw + g.v, g.v, bound);  // north
  }
}

/// The grey exemplar's normalized autocorrelation at every shift (dx, dy) with |dx| <= pw, 0 <= dy <= ph
/// (NaN where undefined is returned as -1), as a function object.
struct pitch_correlation {
  std::vector<double> corr;
  index_t mx = 0, my = 0;
  template <class T, int C>
  pitch_correlation(const image_buffer<T, C>& ex, index_t pw, index_t ph)
      : mx(std::min(pw, ex.width() - 1)), my(std::min(ph, ex.height() - 1)) {
    const index_t W = ex.width(), H = ex.height();
    std::vector<double> grey(to_size(W * H));
    for (index_t i = 0; i < W * H; ++i) {
      pixel<T, C> px;
      for (int c = 0; c < C; ++c) px[to_size(c)] = ex.data()[i * C + c];
      grey[to_size(i)] = convert_pixel<float>(px);
    }
    corr = correlation_field(grey.data(), W, H, 1, mx, my);
  }
  /// The correlation at (dx, dy), |dx| <= mx, |dy| <= my (negative dy by symmetry).
  [[nodiscard]] double operator()(index_t dx, index_t dy) const {
    if (dy < 0) {
      dx = -dx;
      dy = -dy;
    }
    const double r = corr[to_size(dy * (2 * mx + 1) + dx + mx)];
    return std::isnan(r) ? -1.0 : r;
  }
};

/// Options of compatible_sets (see patch_model_options).
struct compatible_set_options {
  index_t k = 8;
  bool exact = false;
  int pca_dims = 8;
  index_t pca_samples = 384;
  int pool = 16;
  int refine = 4;
};

/// The compatible sets of one side: per patch, k ids ascending by (exact error, index), and the errors.
struct side_sets {
  std::vector<std::uint32_t> ids;
  std::vector<double> dist;
};

/// The compatible sets of all four sides (paper 002 §2 step 3). Vertical strips (v x (ph + v)) and
/// horizontal strips ((pw + v) x v) are projected on PCA bases; a nanoflann kd-tree over the strips of
/// candidate patches is queried with each patch's own facing strip. Exact mode prunes with exact L2
/// (the exact top k); the default seeds every other patch (a checkerboard) from a re-ranked pool of
/// `pool` kd-tree candidates and then runs `refine` rounds of coherence propagation. `report(f)` gets
/// the fraction done in [0, 1] and returns false to cancel (then the result is empty). The sets do
/// not depend on the executor.
template <class T, int C, class Ex, class Report>
std::vector<side_sets> compatible_sets(const image_buffer<T, C>& ex, const patch_geometry& g,
                                       const compatible_set_options& o, Ex&& exec, Report&& report,
                                       strip_descriptors* descriptors = nullptr) {
  const index_t W = ex.width(), H = ex.height(), n = g.nx * g.ny, k = o.k;
  strip_family<T, C> vertical, horizontal;
  vertical.build(ex, g.v, g.ph + g.v, W - g.v + 1, g.ny, o.pca_dims, o.pca_samples, exec);
  horizontal.build(ex, g.pw + g.v, g.v, g.nx, H - g.v + 1, o.pca_dims, o.pca_samples, exec);
  if (descriptors != nullptr) {
    descriptors[0] = strip_descriptors::of(vertical);
    descriptors[1] = strip_descriptors::of(horizontal);
  }
  if (!report(0.1)) return {};
  double max_value = 0;
  for (index_t i = 0; i < W * H * C; ++i) max_value = std::max(max_value, std::abs(static_cast<double>(ex.data()[i])));
  auto make_points = [&](const strip_family<T, C>& f, index_t dx, index_t dy) {
    std::vector<double> pts(to_size(n * f.d));  // one point per patch: its strip at (x + dx, y + dy)
    for (index_t p = 0; p < n; ++p) {
      const double* src = f.projection(g.x(p) + dx, g.y(p) + dy);
      std::copy(src, src + f.d, pts.data() + p * f.d);
    }
    return pts;
  };

  std::vector<side_sets> sets(4);
  for (int side = 0; side < 4; ++side) {
    // the data points are the strips of candidate patches b facing a; the query is a's own strip
    const bool vert = side == 1 || side == 3;
    const strip_family<T, C>& f = vert ? vertical : horizontal;
    const index_t data_dx = side == 3 ? g.pw : 0, data_dy = side == 0 ? g.ph : 0;
    const index_t query_dx = side == 1 ? g.pw : 0, query_dy = side == 2 ? g.ph : 0;
    const double scale = max_value * max_value * static_cast<double>(f.cols * f.rows * C);
    // the kd-tree with a compile-time dimension for the default PCA size (faster distance loops)
    const bool fixed = f.d == 8;
    using knn8 = dependent_knn<8, T>;
    using knn = dependent_knn<-1, T>;
    const knn8 index8 = fixed ? knn8(make_points(f, data_dx, data_dy), n, 8, scale) : knn8();
    const knn index = fixed ? knn() : knn(make_points(f, data_dx, data_dy), n, f.d, scale);
    auto& out = sets[to_size(side)].ids;
    auto& dist = sets[to_size(side)].dist;
    out.assign(to_size(n * k), 0);
    dist.assign(to_size(n * k), 0.0);
    auto exact = [&](index_t a, index_t b, double bound) { return strip_error(ex, g, a, b, side, bound); };
    const auto kk = to_size(k), pool = to_size(o.pool);
    auto search = [&](index_t a, std::vector<neighbor>& best, std::vector<std::uint32_t>& ids,
                      std::vector<double>& ds) {
      const double* q = f.projection(g.x(a) + query_dx, g.y(a) + query_dy);
      auto exact_a = [&](std::uint32_t b, double bound) { return exact(a, b, bound); };
      if (o.exact)
        fixed ? index8.search(q, kk, exact_a, best) : index.search(q, kk, exact_a, best);
      else if (fixed)
        index8.search_approximate(q, kk, pool, 1.0f, exact_a, best, ids, ds);
      else
        index.search_approximate(q, kk, pool, 1.0f, exact_a, best, ids, ds);
    };
    const double share = 0.9 / 4.0;
    const index_t chunks = std::min<index_t>(o.exact ? 8 : 2, g.ny);
    for (index_t chunk = 0; chunk < chunks; ++chunk) {
      const index_t y0 = chunk * g.ny / chunks, y1 = (chunk + 1) * g.ny / chunks;
      exec.parallel_for(y0, y1, [&](index_t y) {
        std::vector<neighbor> best;
        std::vector<std::uint32_t> ids;
        std::vector<double> ds;
        for (index_t x = 0; x < g.nx; ++x) {
          const index_t a = y * g.nx + x;
          const bool seeded = o.exact || o.refine == 0 || ((x + y) & 1) == 0;
          if (seeded)
            search(a, best, ids, ds);
          else
            best.clear();
          for (index_t r = 0; r < k; ++r) {
            const bool has = r < static_cast<index_t>(best.size());
            out[to_size(a * k + r)] = has ? best[to_size(r)].index : 0;
            dist[to_size(a * k + r)] = has ? best[to_size(r)].dist : std::numeric_limits<double>::quiet_NaN();
          }
        }
      });
      if (!report(0.1 + share * (side + 0.5 * static_cast<double>(chunk + 1) / static_cast<double>(chunks)))) return {};
    }
    auto refill = [&](index_t a, std::vector<neighbor>& best) {
      std::vector<std::uint32_t> ids;
      std::vector<double> ds;
      search(a, best, ids, ds);
    };
    for (int it = 0; it < o.refine && !o.exact; ++it) {
      propagate_sets(g.nx, g.ny, k, out, dist, exact, refill, exec);
      if (!report(0.1 + share * (side + 0.5 + 0.5 * (it + 1) / o.refine))) return {};
    }
  }
  return sets;
}

/// The minimum-error seam of every compatible pair of one side (`ids`: k per patch), oriented from the
/// left (top) patch to the right (bottom) one; `len` bytes per seam (min_error_seam). For the west and
/// north sides, `mirror_ids` and `mirror_seams` may give the finished east (south) table: a pair whose
/// mirror is in it (b west of a, with a in b's east set) has the same seam, copied instead of computed.
template <class T, int C, class Ex>
std::vector<std::uint8_t> seam_table(const image_buffer<T, C>& ex, const patch_geometry& g, index_t k, int side,
                                     const std::vector<std::uint32_t>& ids, Ex&& exec,
                                     const std::vector<std::uint32_t>* mirror_ids = nullptr,
                                     const std::vector<std::uint8_t>* mirror_seams = nullptr) {
  const bool vert = side == 1 || side == 3, a_first = side == 1 || side == 2;
  const index_t len = vert ? g.ph + g.v : g.pw + g.v;
  std::vector<std::uint8_t> seams(to_size(g.nx * g.ny * k * len), 0);
  exec.parallel_for(0, g.ny, [&](index_t y) {
    seam_scratch scratch;
    for (index_t x = 0; x < g.nx; ++x) {
      const index_t a = y * g.nx + x;
      for (index_t r = 0; r < k; ++r) {
        const index_t b = ids[to_size(a * k + r)];
        std::uint8_t* out = seams.data() + (a * k + r) * len;
        if (mirror_ids != nullptr && !a_first) {
          const std::uint32_t* set = mirror_ids->data() + b * k;
          const std::uint32_t* hit = std::find(set, set + k, static_cast<std::uint32_t>(a));
          if (hit != set + k) {
            const std::uint8_t* from = mirror_seams->data() + (b * k + (hit - set)) * len;
            std::copy(from, from + len, out);
            continue;
          }
        }
        const index_t first = a_first ? a : b, second = a_first ? b : a;
        min_error_seam(ex, g.x(first), g.y(first), g.x(second), g.y(second), vert ? g.pw : g.ph, g.v, len, !vert, out,
                       scratch);
      }
    }
  });
  return seams;
}

}  // namespace detail
TESSERA_NAMESPACE_END
