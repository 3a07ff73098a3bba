// tessera/image/detail/quilt_kernel.hpp: the image-quilting engine behind image/quilt.hpp,
// image/constrained_quilt.hpp and image/wang_tiles.hpp (Efros & Freeman 2001). Internal.
//
// A canvas holds pixels of (T, C) and a state per pixel: empty (to synthesize), filled (synthesized,
// may still be cut) or fixed (never written). Patches are placed at "sites" in raster order. For each
// site the overlap error against every exemplar window is computed (SSD over the known pixels of the
// site, vectorized over candidate columns), one candidate is drawn among those within a tolerance of
// the best, and it is joined by minimum-error boundary cuts: one dynamic-programming path per side
// whose band holds known pixels, with Efros–Freeman's L-shaped meeting point where the west and north
// paths meet (detail/quilt_cut.hpp). Fixed pixels are never written, whatever the cut.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/executor.hpp"
#include "../../core/image.hpp"
#include "../../core/image_buffer.hpp"
#include "../../core/progress.hpp"
#include "../../core/random.hpp"
#include "../../core/status.hpp"
#include "../../core/tile_coloring.hpp"
#include "quilt_cut.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// The exemplar prepared for the overlap search: channel planes of unit floats, plus an optional
/// mask of allowed candidate origins (used when the exemplar is the image being inpainted).
template <Channel T, int C>
struct quilt_source {
  image_buffer<T, C> pixels;
  std::vector<float> planes;          // C planes of width · height
  std::vector<std::uint8_t> allowed;  // (w - p + 1) · (h - p + 1) flags for patch size `allowed_patch`; empty = all
  index_t allowed_patch = 0;

  explicit quilt_source(image_buffer<T, C> px) : pixels(std::move(px)) {
    const index_t w = pixels.width(), h = pixels.height();
    planes.resize(to_size(C * w * h));
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x)
        for (int c = 0; c < C; ++c) planes[to_size((c * h + y) * w + x)] = channel_to_unit(pixels.pixel_ptr(x, y)[c]);
  }
  [[nodiscard]] index_t width() const noexcept { return pixels.width(); }
  [[nodiscard]] index_t height() const noexcept { return pixels.height(); }

  /// Forbids candidate windows of size p that touch a pixel where `bad` is true (w · h flags).
  void forbid_windows(const std::vector<std::uint8_t>& bad, index_t p) {
    const index_t w = width(), h = height(), U = w - p + 1, V = h - p + 1;
    allowed_patch = p;
    allowed.assign(to_size(std::max<index_t>(U, 0) * std::max<index_t>(V, 0)), 1);
    if (U <= 0 || V <= 0) return;
    // summed-area table of the bad flags (counts fit 32 bits: exemplars are capped at 2^26 pixels)
    std::vector<std::uint32_t> sat(to_size((w + 1) * (h + 1)), 0);
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x)
        sat[to_size((y + 1) * (w + 1) + x + 1)] = bad[to_size(y * w + x)] + sat[to_size(y * (w + 1) + x + 1)] +
                                                  sat[to_size((y + 1) * (w + 1) + x)] - sat[to_size(y * (w + 1) + x)];
    auto at = [&](index_t x, index_t y) { return sat[to_size(y * (w + 1) + x)]; };
    for (index_t v = 0; v < V; ++v)
      for (index_t u = 0; u < U; ++u)
        allowed[to_size(v * U + u)] = (at(u + p, v + p) - at(u, v + p) - at(u + p, v) + at(u, v)) == 0;
  }
  [[nodiscard]] bool any_allowed(index_t p) const {
    if (allowed.empty() || allowed_patch != p) return true;
    return std::find(allowed.begin(), allowed.end(), std::uint8_t{1}) != allowed.end();
  }
};

/// The image under synthesis. With wrap_x / wrap_y, site windows wrap around (toroidal output);
/// otherwise window pixels outside the canvas are ignored.
template <Channel T, int C>
struct quilt_canvas {
  image_buffer<T, C> pixels;
  std::vector<pixel_state> state;
  bool wrap_x = false, wrap_y = false;

  quilt_canvas(index_t w, index_t h) : pixels(w, h), state(to_size(w * h), pixel_state::empty) {}
  [[nodiscard]] index_t width() const noexcept { return pixels.width(); }
  [[nodiscard]] index_t height() const noexcept { return pixels.height(); }
  [[nodiscard]] pixel_state& at(index_t x, index_t y) noexcept { return state[to_size(y * width() + x)]; }
  [[nodiscard]] pixel_state at(index_t x, index_t y) const noexcept { return state[to_size(y * width() + x)]; }
};

/// One patch placement: window top-left (x, y) in canvas coordinates (may wrap) and the width of
/// the cut band on each side (index side_north..side_west; 0 = no cut on that side).
struct quilt_site {
  index_t x = 0, y = 0;
  index_t band[4] = {0, 0, 0, 0};
};

struct quilt_params {
  index_t patch = 32;
  double tolerance = 0.1;
  counter_rng rng{1};
  std::uint64_t key = 0;         // distinguishes independent fills (e.g. one per Wang tile)
  float frontier_weight = 1.0f;  // overlap-error weight of fixed pixels touching an empty one
  index_t min_candidates = 1;    // draw among at least this many best candidates
};

/// Positions of windows of size p covering [lo, hi) of an axis of length `size` with overlaps of at
/// least `ov`; with `wrap` the axis is a circle of length `size` (lo = 0, hi = size).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<index_t> plan_axis(index_t lo, index_t hi, index_t p, index_t ov, index_t size, bool wrap) {
  std::vector<index_t> pos;
  if (wrap) {
    const index_t n = std::max<index_t>(2, (size + (p - ov) - 1) / (p - ov));
    for (index_t i = 0; i < n; ++i) pos.push_back(i * size / n);
    return pos;
  }
  const index_t len = hi - lo;
  if (len <= p) {
    pos.push_back(std::clamp<index_t>(lo - (p - len) / 2, 0, std::max<index_t>(0, size - p)));
    return pos;
  }
  const index_t n = (len - ov + (p - ov) - 1) / (p - ov);
  for (index_t i = 0; i < n; ++i) pos.push_back(lo + i * (len - p) / (n - 1));
  return pos;
}

/// Sites covering the rectangle [x0, x1) × [y0, y1) in raster order. West/north bands are the
/// actual overlaps with the previous site; the first row/column and the east/south sides use `ov`
/// (they meet fixed pixels or nothing); with wrapping the last site's east/south band is its overlap
/// with the first one.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<quilt_site> plan_sites(index_t x0, index_t y0, index_t x1, index_t y1, index_t p, index_t ov, index_t w,
                                   index_t h, bool wrap_x, bool wrap_y) {
  const std::vector<index_t> xs = plan_axis(x0, x1, p, ov, w, wrap_x), ys = plan_axis(y0, y1, p, ov, h, wrap_y);
  auto bands = [&](const std::vector<index_t>& v, std::size_t i, index_t size, bool wrap, index_t& before,
                   index_t& after) {
    before = i > 0 ? v[i - 1] + p - v[i] : ov;
    after = wrap && i + 1 == v.size() ? v[i] + p - size - v[0] : ov;
    before = std::clamp<index_t>(before, 0, p - 1);
    after = std::clamp<index_t>(after, 0, p - 1);
  };
  std::vector<quilt_site> sites;
  for (std::size_t j = 0; j < ys.size(); ++j)
    for (std::size_t i = 0; i < xs.size(); ++i) {
      quilt_site s;
      s.x = xs[i];
      s.y = ys[j];
      bands(xs, i, w, wrap_x, s.band[3], s.band[1]);
      bands(ys, j, h, wrap_y, s.band[0], s.band[2]);
      sites.push_back(s);
    }
  return sites;
}

// ---------------------------------------------------------------------------------------------
// Overlap error of every candidate window (Efros & Freeman §2.1: SSD over the overlap region).

struct template_element {
  index_t offset;  // plane offset of (i, j, c) relative to the candidate origin
  float value;
  float weight = 1.0f;
};

// One candidate row of overlap errors: acc[u] += Σ_k w_k (base[offset_k + u] − value_k)². Elements are
// taken four at a time so each pass over acc serves four of them. Always inlined into the
// per-instruction-set entry points below, so one source gives an SSE2 and an AVX2 version whose
// results are bit-identical (no FMA contraction; the same operations per lane in the same order).
#if defined(__GNUC__)
#define TESSERA_DETAIL_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define TESSERA_DETAIL_ALWAYS_INLINE inline
#endif
template <bool Weighted>
TESSERA_DETAIL_ALWAYS_INLINE void overlap_row_pass(float* __restrict acc, const float* base, const template_element* el,
                                                   std::size_t n, index_t U) {
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const float* __restrict r0 = base + el[k].offset;
    const float* __restrict r1 = base + el[k + 1].offset;
    const float* __restrict r2 = base + el[k + 2].offset;
    const float* __restrict r3 = base + el[k + 3].offset;
    const float t0 = el[k].value, t1 = el[k + 1].value, t2 = el[k + 2].value, t3 = el[k + 3].value;
    const float w0 = el[k].weight, w1 = el[k + 1].weight, w2 = el[k + 2].weight, w3 = el[k + 3].weight;
    for (index_t u = 0; u < U; ++u) {
      const float d0 = r0[u] - t0, d1 = r1[u] - t1, d2 = r2[u] - t2, d3 = r3[u] - t3;
      if constexpr (Weighted)
        acc[u] += (w0 * (d0 * d0) + w1 * (d1 * d1)) + (w2 * (d2 * d2) + w3 * (d3 * d3));
      else
        acc[u] += (d0 * d0 + d1 * d1) + (d2 * d2 + d3 * d3);
    }
  }
  for (; k < n; ++k) {
    const float* __restrict r0 = base + el[k].offset;
    const float t0 = el[k].value, w0 = el[k].weight;
    for (index_t u = 0; u < U; ++u) {
      const float d0 = r0[u] - t0;
      acc[u] += w0 * (d0 * d0);
    }
  }
}
TESSERA_DETAIL_ALWAYS_INLINE void overlap_row_body(float* acc, const float* base, const template_element* el,
                                                   std::size_t n, index_t U, bool weighted) {
  if (weighted)
    overlap_row_pass<true>(acc, base, el, n, U);
  else
    overlap_row_pass<false>(acc, base, el, n, U);
}
#undef TESSERA_DETAIL_ALWAYS_INLINE

inline void overlap_row_generic(float* acc, const float* base, const template_element* el, std::size_t n, index_t U,
                                bool weighted) {
  overlap_row_body(acc, base, el, n, U, weighted);
}

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX2__)
#define TESSERA_DETAIL_HAS_AVX2_PATH 1
__attribute__((target("avx2"))) inline void overlap_row_avx2(float* acc, const float* base, const template_element* el,
                                                             std::size_t n, index_t U, bool weighted) {
  overlap_row_body(acc, base, el, n, U, weighted);
}
#endif

using overlap_row_fn = void (*)(float*, const float*, const template_element*, std::size_t, index_t, bool);

/// The fastest row kernel this CPU runs (AVX2 when available and not already the baseline).
inline overlap_row_fn best_overlap_row() noexcept {
#ifdef TESSERA_DETAIL_HAS_AVX2_PATH
  static const overlap_row_fn fn = __builtin_cpu_supports("avx2") ? overlap_row_avx2 : overlap_row_generic;
  return fn;
#else
  return overlap_row_generic;
#endif
}
#undef TESSERA_DETAIL_HAS_AVX2_PATH

/// err[v · U + u] = Σ over known template pixels and channels of weight · (E(u + i, v + j) − value)²;
/// forbidden candidates get +inf. Parallel over candidate rows; bit-identical for any executor and
/// for either row kernel.
template <Channel T, int C, class X>
void overlap_errors(const quilt_source<T, C>& src, const std::vector<template_element>& elements, index_t p,
                    std::vector<float>& err, X& exec, overlap_row_fn row = best_overlap_row()) {
  const index_t w = src.width(), U = w - p + 1, V = src.height() - p + 1;
  err.assign(to_size(U * V), 0.0f);
  if (!elements.empty()) {
    bool weighted = false;
    for (const auto& e : elements) weighted = weighted || e.weight != 1.0f;
    exec.parallel_for(0, V, [&](index_t v) {
      row(err.data() + v * U, src.planes.data() + v * w, elements.data(), elements.size(), U, weighted);
    });
  }
  if (!src.allowed.empty() && src.allowed_patch == p)
    for (std::size_t i = 0; i < err.size(); ++i)
      if (!src.allowed[i]) err[i] = std::numeric_limits<float>::infinity();
}

/// Draws one candidate among those whose error is within (1 + tolerance) of the best (Efros &
/// Freeman's selection rule) or, when that leaves fewer, among the `at_least` best (finite ones);
/// keyed by the site, candidates in index order.
inline index_t pick_candidate(const std::vector<float>& err, double tolerance, const counter_rng& rng,
                              std::uint64_t key, index_t site_x, index_t site_y, index_t at_least = 1) {
  float best = std::numeric_limits<float>::infinity();
  for (float e : err) best = std::min(best, e);
  double limit = static_cast<double>(best) * (1.0 + tolerance);
  if (at_least > 1) {
    std::vector<float> sorted(err);
    const auto k = std::min<std::size_t>(to_size(at_least), sorted.size()) - 1;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    if (std::isfinite(sorted[k])) limit = std::max(limit, static_cast<double>(sorted[k]));
  }
  index_t count = 0;
  for (float e : err) count += static_cast<double>(e) <= limit;
  TESSERA_ASSERT(count > 0);
  index_t pick = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(count), key, site_x, site_y));
  for (std::size_t i = 0; i < err.size(); ++i)
    if (static_cast<double>(err[i]) <= limit && pick-- == 0) return static_cast<index_t>(i);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// Placing one patch and filling a whole canvas.

/// Scratch buffers reused across sites (one per thread of work).
struct quilt_scratch {
  std::vector<template_element> elements;
  std::vector<float> err;
  site_window win;
  std::vector<std::uint8_t> is_new;
};

/// Places one patch at `site`: overlap search, candidate choice, cuts, write. Returns false (and
/// writes nothing) when the window holds no empty pixel.
template <Channel T, int C, class X>
bool place_patch(const quilt_source<T, C>& src, quilt_canvas<T, C>& canvas, const quilt_site& site,
                 const quilt_params& prm, quilt_scratch& s, X& exec) {
  const index_t p = prm.patch, W = canvas.width(), H = canvas.height(), plane = src.width() * src.height();
  auto canvas_xy = [&](index_t i, index_t j, index_t& cx, index_t& cy) {
    cx = site.x + i;
    cy = site.y + j;
    if (canvas.wrap_x) cx = ((cx % W) + W) % W;
    if (canvas.wrap_y) cy = ((cy % H) + H) % H;
    return cx >= 0 && cx < W && cy >= 0 && cy < H;
  };
  site_window& win = s.win;
  win.p = p;
  win.state.assign(to_size(p * p), pixel_state::empty);
  win.outside.assign(to_size(p * p), 0);
  win.error.assign(to_size(p * p), 0.0);
  s.elements.clear();
  bool any_empty = false;
  for (index_t j = 0; j < p; ++j)
    for (index_t i = 0; i < p; ++i) {
      index_t cx = 0, cy = 0;
      if (!canvas_xy(i, j, cx, cy)) {
        win.outside[win.idx(i, j)] = 1;
        continue;
      }
      const pixel_state st = canvas.at(cx, cy);
      win.state[win.idx(i, j)] = st;
      if (st == pixel_state::empty) {
        any_empty = true;
        continue;
      }
      const T* px = canvas.pixels.pixel_ptr(cx, cy);
      // fixed pixels next to an empty one are where the seam will be: the cut cannot move there
      float weight = 1.0f;
      if (st == pixel_state::fixed && prm.frontier_weight != 1.0f) {
        const index_t nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
        for (const auto& q : nb) {
          index_t qx = 0, qy = 0;
          if (q[0] >= 0 && q[0] < p && q[1] >= 0 && q[1] < p && canvas_xy(q[0], q[1], qx, qy) &&
              canvas.at(qx, qy) == pixel_state::empty)
            weight = prm.frontier_weight;
        }
      }
      for (int c = 0; c < C; ++c)
        s.elements.push_back({c * plane + j * src.width() + i, channel_to_unit(px[c]), weight});
    }
  if (!any_empty) return false;
  overlap_errors(src, s.elements, p, s.err, exec);
  const index_t U = src.width() - p + 1;
  const index_t chosen = pick_candidate(s.err, prm.tolerance, prm.rng, prm.key, site.x, site.y, prm.min_candidates);
  const index_t u = chosen % U, v = chosen / U;
  for (index_t j = 0; j < p; ++j)
    for (index_t i = 0; i < p; ++i) {
      const std::size_t k = win.idx(i, j);
      if (win.outside[k] || win.state[k] == pixel_state::empty) continue;
      index_t cx = 0, cy = 0;
      canvas_xy(i, j, cx, cy);
      const T* a = canvas.pixels.pixel_ptr(cx, cy);
      const T* b = src.pixels.pixel_ptr(u + i, v + j);
      double e = 0;
      for (int c = 0; c < C; ++c) {
        const double d = static_cast<double>(channel_to_unit(a[c])) - static_cast<double>(channel_to_unit(b[c]));
        e += d * d;
      }
      win.error[k] = e;
    }
  cut_labels(win, site.band, s.is_new);
  for (index_t j = 0; j < p; ++j)
    for (index_t i = 0; i < p; ++i) {
      const std::size_t k = win.idx(i, j);
      if (win.outside[k] || win.state[k] == pixel_state::fixed) continue;
      if (win.state[k] == pixel_state::filled && !s.is_new[k]) continue;
      index_t cx = 0, cy = 0;
      canvas_xy(i, j, cx, cy);
      const T* b = src.pixels.pixel_ptr(u + i, v + j);
      T* a = canvas.pixels.pixel_ptr(cx, cy);
      for (int c = 0; c < C; ++c) a[c] = b[c];
      canvas.at(cx, cy) = pixel_state::filled;
    }
  return true;
}

/// Fills every empty pixel of the canvas: sites over the bounding box of the empty pixels grown by
/// `overlap` (the whole canvas when it wraps), in raster order. Reports progress after each row of
/// sites through `prog` (may be null) mapped into [from, to]; returns cancelled when told to stop.
template <Channel T, int C, class X>
status fill_canvas(const quilt_source<T, C>& src, quilt_canvas<T, C>& canvas, const quilt_params& prm, index_t overlap,
                   X& exec, const progress* prog = nullptr, double from = 0, double to = 1) {
  const index_t W = canvas.width(), H = canvas.height();
  index_t x0 = W, y0 = H, x1 = 0, y1 = 0;
  for (index_t y = 0; y < H; ++y)
    for (index_t x = 0; x < W; ++x)
      if (canvas.at(x, y) == pixel_state::empty) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x + 1);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y + 1);
      }
  if (x1 <= x0) return {};
  if (canvas.wrap_x) {
    x0 = 0;
    x1 = W;
  } else {
    x0 = std::max<index_t>(0, x0 - overlap);
    x1 = std::min(W, x1 + overlap);
  }
  if (canvas.wrap_y) {
    y0 = 0;
    y1 = H;
  } else {
    y0 = std::max<index_t>(0, y0 - overlap);
    y1 = std::min(H, y1 + overlap);
  }
  const std::vector<quilt_site> sites =
      plan_sites(x0, y0, x1, y1, prm.patch, overlap, W, H, canvas.wrap_x, canvas.wrap_y);
  quilt_scratch scratch;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    place_patch(src, canvas, sites[k], prm, scratch, exec);
    const bool row_done = k + 1 == sites.size() || sites[k + 1].y != sites[k].y;
    if (prog != nullptr && row_done &&
        !prog->report(from + (to - from) * static_cast<double>(k + 1) / static_cast<double>(sites.size()), "quilting"))
      return status::cancelled();
  }
  // every empty pixel lies in some site window, so nothing is left empty
  TESSERA_ASSERT(std::find(canvas.state.begin(), canvas.state.end(), pixel_state::empty) == canvas.state.end());
  return {};
}

}  // namespace detail
TESSERA_NAMESPACE_END
