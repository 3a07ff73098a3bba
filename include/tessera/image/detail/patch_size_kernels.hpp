// tessera/image/detail/patch_size_kernels.hpp: the measures behind image/patch_size.hpp (paper 002
// §2.1): histogram containment, periodicity counts, lattice alignment and overlap discrimination.
// Internal; no stability promise.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/random.hpp"
#include "fft.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// A grey image in unit range, row-major doubles.
struct grey_image {
  std::vector<double> v;
  index_t w = 0, h = 0;
  [[nodiscard]] double at(index_t x, index_t y) const { return v[to_size(y * w + x)]; }
};

/// Per shape: the share of patches whose normalized grey histogram lies within `tolerance` times the
/// exemplar histogram's L2 norm (L2 distance) of the exemplar's, and the 90th percentile of those
/// relative distances. Patches are taken at every position
/// (every `step` for large shapes) with sliding histograms.
template <class Measure, class Ex>
void containment_measures(const grey_image& g, std::vector<Measure>& shapes, int bins, double tolerance, Ex&& exec) {
  std::vector<std::uint16_t> bin(g.v.size());
  std::vector<double> global(to_size(bins), 0.0);
  for (std::size_t i = 0; i < g.v.size(); ++i) {
    const double u = std::clamp(g.v[i], 0.0, 1.0);
    bin[i] = static_cast<std::uint16_t>(std::min<index_t>(bins - 1, static_cast<index_t>(u * bins)));
    global[bin[i]] += 1.0 / static_cast<double>(g.v.size());
  }
  double norm = 0;
  for (double v : global) norm += v * v;
  norm = std::sqrt(norm);
  exec.parallel_for(0, static_cast<index_t>(shapes.size()), [&](index_t s) {
    Measure& m = shapes[to_size(s)];
    const index_t w = m.width, h = m.height, step = std::max<index_t>(1, std::min(w, h) / 8);
    const double inv = 1.0 / static_cast<double>(w * h);
    std::vector<index_t> hist(to_size(bins));
    std::vector<double> dist;
    auto column = [&](index_t x, index_t y, index_t sign) {
      for (index_t r = 0; r < h; ++r) hist[bin[to_size((y + r) * g.w + x)]] += sign;
    };
    for (index_t y = 0; y + h <= g.h; y += step) {
      std::fill(hist.begin(), hist.end(), 0);
      for (index_t x = 0; x < w; ++x) column(x, y, 1);
      for (index_t x = 0;;) {
        double d2 = 0;
        for (int b = 0; b < bins; ++b) {
          const double d = static_cast<double>(hist[to_size(b)]) * inv - global[to_size(b)];
          d2 += d * d;
        }
        dist.push_back(std::sqrt(d2) / norm);
        if (x + step + w > g.w) break;
        for (index_t k = 0; k < step; ++k) {
          column(x + k, y, -1);
          column(x + w + k, y, 1);
        }
        x += step;
      }
    }
    std::sort(dist.begin(), dist.end());
    const auto within = std::upper_bound(dist.begin(), dist.end(), tolerance) - dist.begin();
    m.containment = static_cast<double>(within) / static_cast<double>(dist.size());
    m.containment_p90 = dist[std::min(dist.size() - 1, to_size(0.9 * static_cast<double>(dist.size())))];
  });
}

/// Box-filtered copy shrunk by an integer factor (returned in `factor`) so that its larger side is at
/// most `max_side`, but never below 8 pixels on its smaller side (elongated exemplars keep a usable
/// width); a copy that still holds more than max_side^2 pixels is cut to its first max_side^2 pixels
/// along the longer axis, which bounds the periodicity count's O(pixels^2) work.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
grey_image analysis_copy(const grey_image& g, index_t max_side, index_t& factor) {
  const index_t small = std::min(g.w, g.h);
  factor = std::max<index_t>(1, std::min((std::max(g.w, g.h) + max_side - 1) / max_side, small / 8));
  grey_image out{{}, g.w / factor, g.h / factor};
  const index_t budget = max_side * max_side;
  if (out.w * out.h > budget) (out.w > out.h ? out.w : out.h) = std::max<index_t>(budget / std::min(out.w, out.h), 1);
  out.v.resize(to_size(out.w * out.h));
  for (index_t y = 0; y < out.h; ++y)
    for (index_t x = 0; x < out.w; ++x) {
      double s = 0;
      for (index_t j = 0; j < factor; ++j)
        for (index_t i = 0; i < factor; ++i) s += g.at(x * factor + i, y * factor + j);
      out.v[to_size(y * out.w + x)] = s / static_cast<double>(factor * factor);
    }
  return out;
}

/// Per shape: one reference block per cell of a grid x grid partition (at a random position keyed by
/// (seed, shape, cell)); for each, the number of block positions whose mean squared grey difference
/// to it is below similarity x 2 variance, not counting blocks overlapping the reference by more than
/// half in both directions. `periodicity` is the mean count, `periodicity_hits` the share of references
/// with a count > 0. Runs on analysis_copy(full, analysis_size) (at least 8 x 8 for an exemplar of at
/// least 8 x 8; shapes are scaled by its factor and kept in [2, side - 1]): for every displacement,
/// the integral image of squared differences answers every (shape, reference) in O(1). A flat exemplar
/// (zero variance) counts every block as similar (difference 0 <= limit 0).
template <class Measure, class Ex>
void periodicity_measures(const grey_image& full, std::vector<Measure>& shapes, index_t grid, double similarity,
                          index_t analysis_size, std::uint64_t seed, Ex&& exec) {
  index_t f = 1;
  const grey_image g = analysis_copy(full, analysis_size, f);
  const index_t W = g.w, H = g.h, S = static_cast<index_t>(shapes.size()), R = grid * grid;
  double mean = 0, var = 0;
  for (double v : g.v) mean += v;
  mean /= static_cast<double>(g.v.size());
  for (double v : g.v) var += (v - mean) * (v - mean);
  var /= static_cast<double>(g.v.size());
  struct ref {
    index_t x, y, w, h;
    double limit;
  };
  std::vector<ref> refs(to_size(S * R));
  index_t wmin = W, hmin = H;
  const counter_rng rng(seed, stream_id("patch_size.references"));
  for (index_t s = 0; s < S; ++s) {
    const Measure& m = shapes[to_size(s)];
    const index_t w = std::clamp<index_t>((m.width + f / 2) / f, 2, W - 1),
                  h = std::clamp<index_t>((m.height + f / 2) / f, 2, H - 1);
    wmin = std::min(wmin, w);
    hmin = std::min(hmin, h);
    for (index_t gy = 0; gy < grid; ++gy)
      for (index_t gx = 0; gx < grid; ++gx) {
        auto pick = [&](index_t size, index_t extent, index_t cell, index_t key) {
          const index_t a = std::min(extent - size, cell * extent / grid);
          const index_t b = std::min(extent - size, std::max(a, (cell + 1) * extent / grid - 1));
          return a +
                 static_cast<index_t>(rng.below(static_cast<std::uint64_t>(b - a + 1), m.width, m.height, gx, gy, key));
        };
        refs[to_size(s * R + gy * grid + gx)] = {pick(w, W, gx, 0), pick(h, H, gy, 1), w, h,
                                                 similarity * 2.0 * var * static_cast<double>(w * h)};
      }
  }
  const index_t mdx = W - wmin, mdy = H - hmin, ndy = 2 * mdy + 1;
  std::vector<std::int32_t> counts(to_size(ndy * S * R), 0);
  exec.parallel_for(0, ndy, [&](index_t row) {
    const index_t dy = row - mdy;
    std::vector<double> sum(to_size((W + 1) * (H + 1)), 0.0);
    std::int32_t* cnt = counts.data() + row * S * R;
    for (index_t dx = -mdx; dx <= mdx; ++dx) {
      // integral image of (g(x, y) - g(x + dx, y + dy))^2 over the pixels where both are inside (the
      // only ones a valid block pair reads): row prefix sums, then add the row above
      const index_t x0 = std::max<index_t>(0, -dx), x1 = std::min(W, W - dx);
      const index_t y0 = std::max<index_t>(0, -dy), y1 = std::min(H, H - dy);
      for (index_t y = y0; y < y1; ++y) {
        const double* a = g.v.data() + y * W;
        const double* b = g.v.data() + (y + dy) * W + dx;
        double* row = sum.data() + (y + 1) * (W + 1);
        const double* up = row - (W + 1);
        double run = 0;
        for (index_t x = x0; x < x1; ++x) {
          const double t = a[x] - b[x];
          run += t * t;
          row[x + 1] = run + up[x + 1];
        }
      }
      auto at = [&](index_t x, index_t y) {
        // outside the computed band the integral is constant along the clipped direction
        x = std::clamp(x, x0, x1);
        y = std::clamp(y, y0, y1);
        return x == x0 || y == y0 ? 0.0 : sum[to_size(y * (W + 1) + x)];
      };
      for (index_t i = 0; i < S * R; ++i) {
        const ref& r = refs[to_size(i)];
        if (2 * std::abs(dx) < r.w && 2 * std::abs(dy) < r.h) continue;  // overlaps the reference itself
        if (r.x + dx < 0 || r.y + dy < 0 || r.x + dx + r.w > W || r.y + dy + r.h > H) continue;
        const double ssd = at(r.x + r.w, r.y + r.h) - at(r.x, r.y + r.h) - at(r.x + r.w, r.y) + at(r.x, r.y);
        if (ssd <= r.limit) ++cnt[i];
      }
    }
  });
  for (index_t s = 0; s < S; ++s) {
    double total = 0, hits = 0;
    for (index_t r = 0; r < R; ++r) {
      std::int64_t c = 0;
      for (index_t row = 0; row < ndy; ++row) c += counts[to_size(row * S * R + s * R + r)];
      total += static_cast<double>(c);
      hits += c > 0 ? 1.0 : 0.0;
    }
    shapes[to_size(s)].periodicity = total / static_cast<double>(R);
    shapes[to_size(s)].periodicity_hits = hits / static_cast<double>(R);
  }
}

/// Per shape: the mean of the exemplar's normalized autocorrelation at (width, 0) and (0, height).
template <class Measure>
void alignment_measures(const grey_image& g, std::vector<Measure>& shapes) {
  index_t mx = 0, my = 0;
  for (const Measure& m : shapes) {
    mx = std::max(mx, m.width);
    my = std::max(my, m.height);
  }
  mx = std::min(mx, g.w - 1);
  my = std::min(my, g.h - 1);
  const std::vector<double> corr = correlation_field(g.v.data(), g.w, g.h, 1, mx, my);
  auto at = [&](index_t dx, index_t dy) {
    const double r = corr[to_size(dy * (2 * mx + 1) + dx + mx)];
    return std::isnan(r) ? 0.0 : r;
  };
  for (Measure& m : shapes) m.alignment = 0.5 * (at(std::min(m.width, mx), 0) + at(0, std::min(m.height, my)));
}

/// For each overlap width v in [vmin, vmax]: the Pearson correlation, over `pairs` random pairs of
/// patches of (pw + v) x (ph + v), between the mean squared difference of their L-shaped overlap
/// strips (the first v columns and rows) and that of the rest of the patches.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<std::pair<index_t, double>> overlap_measures(const grey_image& g, index_t pw, index_t ph, index_t vmin,
                                                         index_t vmax, int pairs, std::uint64_t seed) {
  const counter_rng rng(seed, stream_id("patch_size.overlap_pairs"));
  const index_t nx = g.w - pw - vmax + 1, ny = g.h - ph - vmax + 1;
  std::vector<std::pair<index_t, double>> out;
  std::vector<double> strip(to_size(pairs)), rest(to_size(pairs));
  for (index_t v = vmin; v <= vmax; ++v) {
    for (int p = 0; p < pairs; ++p) {
      const index_t ax = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(nx), p, 0));
      const index_t ay = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(ny), p, 1));
      const index_t bx = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(nx), p, 2));
      const index_t by = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(ny), p, 3));
      double s = 0, r = 0;
      for (index_t y = 0; y < ph + v; ++y)
        for (index_t x = 0; x < pw + v; ++x) {
          const double d = g.at(ax + x, ay + y) - g.at(bx + x, by + y);
          (x < v || y < v ? s : r) += d * d;
        }
      strip[to_size(p)] = s;
      rest[to_size(p)] = r;
    }
    double ms = 0, mr = 0;
    for (int p = 0; p < pairs; ++p) {
      ms += strip[to_size(p)];
      mr += rest[to_size(p)];
    }
    ms /= pairs;
    mr /= pairs;
    double c = 0, vs = 0, vr = 0;
    for (int p = 0; p < pairs; ++p) {
      const double a = strip[to_size(p)] - ms, b = rest[to_size(p)] - mr;
      c += a * b;
      vs += a * a;
      vr += b * b;
    }
    out.emplace_back(v, vs > 0 && vr > 0 ? c / std::sqrt(vs * vr) : 0.0);
  }
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
