// tessera/render/detail/raster_kernel.hpp: the exact part of the triangle rasterizer. Vertices are
// snapped to a 1/256-pixel grid and coverage is decided with 64-bit integer edge functions, so the
// result does not depend on floating-point evaluation order: two triangles sharing an edge (same
// snapped end points) cover each pixel centre on it exactly once (top-left rule). Spans are solved
// per row with exact integer division, then walked with incremental edge values.
//
// Also: polygon clipping (near / far planes in clip space, a guard band in screen space) whose new
// vertices carry the weights of the ORIGINAL triangle's corners, so fragments of clipped pieces
// report barycentrics of the triangle the caller gave.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail::raster {

inline constexpr int subpixel_bits = 8;
inline constexpr std::int64_t subpixel_one = std::int64_t{1} << subpixel_bits;
/// Screen coordinates are clipped to [-guard_band, guard_band] pixels before snapping; with 8
/// sub-pixel bits every edge-function product stays below 2^60, far from int64 overflow.
inline constexpr double guard_band = 1048576.0;  // 2^20
/// Polygons are clipped to w >= this fraction of the largest clip coordinate: keeps 1/w finite; the
/// plane is linear (a constant), so clipping stays exact.
inline constexpr double min_w_fraction = 1e-12;

/// A polygon vertex during clipping: screen (or clip) position, depth, 1/w, and the weights of the
/// original triangle's three corners (linear in clip space, i.e. in 3D). Deliberately without
/// default member initializers: polygons are built for every triangle, and every field is written
/// before it is read.
struct poly_vertex {
  double x, y, z, w;             ///< clip space (x, y, z, w), or screen (x, y, depth, 1/w)
  std::array<double, 3> corner;  ///< weights of the original corners, sum 1
};

/// Up to 3 + 7 clip planes worth of vertices; only the first n are meaningful (no zero-fill).
struct polygon {
  std::array<poly_vertex, 12> v;
  int n = 0;
};

inline bool canonical_less(const poly_vertex& a, const poly_vertex& b) noexcept {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  if (a.z != b.z) return a.z < b.z;
  return a.w < b.w;
}

/// Sutherland-Hodgman against one plane: keeps the part where dist(v) >= 0. Each crossing point is
/// computed from the edge's end points in a canonical order, so two triangles sharing an edge get
/// bit-identical new vertices. `lerp(a, b, t)` returns the point a + t (b - a).
template <class Dist, class Lerp>
void clip_polygon(polygon& p, Dist&& dist, Lerp&& lerp) {
  if (p.n == 0) return;
  bool all_inside = true;
  for (int i = 0; i < p.n && all_inside; ++i) all_inside = dist(p.v[to_size(i)]) >= 0;
  if (all_inside) return;
  polygon out;
  for (int i = 0; i < p.n; ++i) {
    const poly_vertex& a = p.v[to_size(i)];
    const poly_vertex& b = p.v[to_size((i + 1) % p.n)];
    const double da = dist(a), db = dist(b);
    if (da >= 0) out.v[to_size(out.n++)] = a;
    if ((da >= 0) != (db >= 0)) {
      const bool swap = canonical_less(b, a);
      const poly_vertex& s = swap ? b : a;
      const poly_vertex& e = swap ? a : b;
      const double ds = swap ? db : da, de = swap ? da : db;
      out.v[to_size(out.n++)] = lerp(s, e, ds / (ds - de));
    }
  }
  p = out;
}

/// Linear interpolation of every field (clip space: everything is linear there).
inline poly_vertex lerp_clip(const poly_vertex& a, const poly_vertex& b, double t) noexcept {
  poly_vertex r;
  r.x = a.x + t * (b.x - a.x);
  r.y = a.y + t * (b.y - a.y);
  r.z = a.z + t * (b.z - a.z);
  r.w = a.w + t * (b.w - a.w);
  for (int k = 0; k < 3; ++k)
    r.corner[to_size(k)] = a.corner[to_size(k)] + t * (b.corner[to_size(k)] - a.corner[to_size(k)]);
  return r;
}

/// Interpolation in screen space: position, depth and 1/w are linear there; corner weights are
/// linear in 3D, so they interpolate perspective-correctly through 1/w.
inline poly_vertex lerp_screen(const poly_vertex& a, const poly_vertex& b, double t) noexcept {
  poly_vertex r = lerp_clip(a, b, t);
  for (std::size_t k = 0; k < 3; ++k)
    r.corner[k] = (a.corner[k] * a.w + t * (b.corner[k] * b.w - a.corner[k] * a.w)) / r.w;
  return r;
}

/// Clips a screen-space polygon (x, y in pixels, w = 1/w) to the guard band.
inline void clip_guard_band(polygon& p) {
  bool inside = true;
  for (int i = 0; i < p.n; ++i) {
    const auto& v = p.v[to_size(i)];
    inside = inside && std::abs(v.x) <= guard_band && std::abs(v.y) <= guard_band;
  }
  if (inside) return;
  clip_polygon(
      p, [](const poly_vertex& v) { return guard_band - v.x; }, lerp_screen);
  clip_polygon(
      p, [](const poly_vertex& v) { return v.x + guard_band; }, lerp_screen);
  clip_polygon(
      p, [](const poly_vertex& v) { return guard_band - v.y; }, lerp_screen);
  clip_polygon(
      p, [](const poly_vertex& v) { return v.y + guard_band; }, lerp_screen);
}

/// floor(a / b) and ceil(a / b) for b > 0.
constexpr std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
constexpr std::int64_t ceil_div(std::int64_t a, std::int64_t b) noexcept { return -floor_div(-a, b); }

/// A snapped triangle ready for scan conversion, positively oriented (interior where all edge
/// functions are > 0), with its vertex attributes.
struct triangle_setup {
  std::array<std::int64_t, 3> x{}, y{};  ///< fixed point, 1/256 pixel
  std::array<double, 3> z{}, inv_w{};
  std::array<std::array<double, 3>, 3> corner{};  ///< original-corner weights per vertex (rows)
  std::int64_t twice_area = 0;                    ///< > 0 after setup
};

/// Snaps and orients; returns false for a triangle of zero area after snapping, or whose signed
/// area (cross product in y-down pixel coordinates: positive is clockwise as seen on screen) has
/// the wrong sign when keep_orientation is +1 or -1 (0 keeps both).
inline bool setup_triangle(const poly_vertex& a, const poly_vertex& b, const poly_vertex& c, int keep_orientation,
                           triangle_setup& s) {
  const poly_vertex* v[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const auto i = to_size(k);
    // round half up; any fixed rule works, what matters is the same input snapping the same way
    s.x[i] = static_cast<std::int64_t>(std::floor(v[k]->x * static_cast<double>(subpixel_one) + 0.5));
    s.y[i] = static_cast<std::int64_t>(std::floor(v[k]->y * static_cast<double>(subpixel_one) + 0.5));
    s.z[i] = v[k]->z;
    s.inv_w[i] = v[k]->w;
    s.corner[i] = v[k]->corner;
  }
  s.twice_area = (s.x[1] - s.x[0]) * (s.y[2] - s.y[0]) - (s.y[1] - s.y[0]) * (s.x[2] - s.x[0]);
  if (s.twice_area == 0) return false;
  if (keep_orientation != 0 && (s.twice_area > 0) != (keep_orientation > 0)) return false;
  if (s.twice_area < 0) {
    std::swap(s.x[1], s.x[2]);
    std::swap(s.y[1], s.y[2]);
    std::swap(s.z[1], s.z[2]);
    std::swap(s.inv_w[1], s.inv_w[2]);
    std::swap(s.corner[1], s.corner[2]);
    s.twice_area = -s.twice_area;
  }
  return true;
}

/// Walks the pixels of a set-up triangle inside [x0, x1) x [y0, y1), calling
/// emit(px, py, lambda[3]) with the exact integer edge values (lambda_k / twice_area is the
/// screen-space weight of vertex k). Pixel centres on an edge belong to the triangle only when the
/// edge is a top or left edge.
template <class Emit>
void scan_triangle(const triangle_setup& s, std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1,
                   Emit&& emit) {
  // Edge k is opposite vertex k: from vertex k+1 to vertex k+2.
  std::array<std::int64_t, 3> ea{}, eb{}, ec{};  // E_k(px, py) = ea*px + eb*py + ec (fixed point)
  std::array<std::int64_t, 3> bias{};
  for (int k = 0; k < 3; ++k) {
    const auto i = to_size(k), j = to_size((k + 1) % 3), l = to_size((k + 2) % 3);
    const std::int64_t dx = s.x[l] - s.x[j], dy = s.y[l] - s.y[j];
    ea[i] = -dy;
    eb[i] = dx;
    ec[i] = dy * s.x[j] - dx * s.y[j];
    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
    bias[i] = top_left ? 0 : 1;  // inside: E > 0, or E == 0 on a top-left edge, i.e. E >= bias
  }
  const std::int64_t minx = std::min({s.x[0], s.x[1], s.x[2]}), maxx = std::max({s.x[0], s.x[1], s.x[2]});
  const std::int64_t miny = std::min({s.y[0], s.y[1], s.y[2]}), maxy = std::max({s.y[0], s.y[1], s.y[2]});
  // pixel i has its centre at i*256 + 128: covered pixels satisfy min <= centre <= max
  const std::int64_t half = subpixel_one / 2;
  const std::int64_t px0 = std::max(x0, ceil_div(minx - half, subpixel_one));
  const std::int64_t px1 = std::min(x1 - 1, floor_div(maxx - half, subpixel_one));
  const std::int64_t py0 = std::max(y0, ceil_div(miny - half, subpixel_one));
  const std::int64_t py1 = std::min(y1 - 1, floor_div(maxy - half, subpixel_one));
  if (px0 > px1 || py0 > py1) return;
  for (std::int64_t py = py0; py <= py1; ++py) {
    const std::int64_t cy = py * subpixel_one + half;
    std::int64_t lo = px0, hi = px1;
    std::array<std::int64_t, 3> base{};  // E_k at the centre of pixel column 0 in this row
    for (std::size_t k = 0; k < 3 && lo <= hi; ++k) {
      base[k] = ea[k] * half + eb[k] * cy + ec[k];
      const std::int64_t step = ea[k] * subpixel_one;  // per pixel to the right
      // need base + i * step >= bias
      if (step > 0)
        lo = std::max(lo, ceil_div(bias[k] - base[k], step));
      else if (step < 0)
        hi = std::min(hi, floor_div(base[k] - bias[k], -step));
      else if (base[k] < bias[k])
        hi = lo - 1;
    }
    if (lo > hi) continue;
    std::array<std::int64_t, 3> e{};
    for (std::size_t k = 0; k < 3; ++k) e[k] = base[k] + lo * ea[k] * subpixel_one;
    for (std::int64_t px = lo; px <= hi; ++px) {
      emit(px, py, e);
      for (std::size_t k = 0; k < 3; ++k) e[k] += ea[k] * subpixel_one;
    }
  }
}

/// Screen-space triangle (x, y, depth, 1/w per vertex) -> polygon clipped to the guard band. False
/// when a value is non-finite or a 1/w is not positive.
inline bool screen_polygon(const std::array<std::array<double, 4>, 3>& t, polygon& p) {
  p.n = 3;
  for (int k = 0; k < 3; ++k) {
    const auto& v = t[to_size(k)];
    if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && std::isfinite(v[3]) && v[3] > 0))
      return false;
    auto& q = p.v[to_size(k)];
    q = {v[0], v[1], v[2], v[3], {}};
    q.corner[to_size(k)] = 1;
  }
  clip_guard_band(p);
  return true;
}

/// Clip-space triangle (x, y, z, w per vertex) -> polygon clipped to the near and far planes (and to
/// w > 0 for unusual projections), mapped to pixels by the viewport (x, y, width, height), clipped to
/// the guard band. Window depth is in [0, 1]; `zero_to_one` selects the 0 <= z <= w convention.
inline bool clip_polygon_to_screen(const std::array<std::array<double, 4>, 3>& t, const std::array<double, 4>& vp,
                                   bool zero_to_one, polygon& p) {
  p.n = 3;
  double scale = 0;
  for (int k = 0; k < 3; ++k) {
    const auto& v = t[to_size(k)];
    if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && std::isfinite(v[3]))) return false;
    auto& q = p.v[to_size(k)];
    q = {v[0], v[1], v[2], v[3], {}};
    q.corner[to_size(k)] = 1;
    scale = std::max({scale, std::abs(v[0]), std::abs(v[1]), std::abs(v[2]), std::abs(v[3])});
  }
  clip_polygon(
      p, [zero_to_one](const poly_vertex& v) { return zero_to_one ? v.z : v.z + v.w; }, lerp_clip);  // near
  clip_polygon(
      p, [](const poly_vertex& v) { return v.w - v.z; }, lerp_clip);  // far
  const double w_min = min_w_fraction * scale;
  clip_polygon(
      p, [w_min](const poly_vertex& v) { return v.w - w_min; }, lerp_clip);
  for (int i = 0; i < p.n; ++i) {
    auto& q = p.v[to_size(i)];
    const double iw = 1.0 / q.w;
    q.x = vp[0] + (q.x * iw + 1) * 0.5 * vp[2];
    q.y = vp[1] + (1 - q.y * iw) * 0.5 * vp[3];
    q.z = zero_to_one ? q.z * iw : (q.z * iw + 1) * 0.5;
    q.w = iw;
  }
  clip_guard_band(p);
  return true;
}

/// One covered pixel as the kernel reports it (mirrors tessera::fragment).
struct covered {
  std::int64_t x = 0, y = 0;
  std::array<double, 3> bary{};
  double depth = 0;
  double w = 1;
};

/// Rasterizes a polygon (as a fan) inside [x0, x1) x [y0, y1), calling fn(const covered&) with
/// perspective-correct weights of the original corners. The fan's inner edges share snapped
/// vertices, so they too are covered exactly once.
template <class F>
void draw_polygon(const polygon& p, int keep_orientation, std::int64_t x0, std::int64_t y0, std::int64_t x1,
                  std::int64_t y1, F&& fn) {
  triangle_setup s;
  for (int i = 1; i + 1 < p.n; ++i) {
    if (!setup_triangle(p.v[0], p.v[to_size(i)], p.v[to_size(i + 1)], keep_orientation, s)) continue;
    const double inv_area = 1.0 / static_cast<double>(s.twice_area);
    scan_triangle(s, x0, y0, x1, y1, [&](std::int64_t px, std::int64_t py, const std::array<std::int64_t, 3>& e) {
      covered c;
      c.x = px;
      c.y = py;
      const double l0 = static_cast<double>(e[0]) * inv_area, l1 = static_cast<double>(e[1]) * inv_area,
                   l2 = static_cast<double>(e[2]) * inv_area;
      c.depth = l0 * s.z[0] + l1 * s.z[1] + l2 * s.z[2];
      const double q0 = l0 * s.inv_w[0], q1 = l1 * s.inv_w[1], q2 = l2 * s.inv_w[2];
      const double inv_q = 1.0 / (q0 + q1 + q2);
      c.w = inv_q;
      const double b0 = q0 * inv_q, b1 = q1 * inv_q, b2 = q2 * inv_q;
      for (std::size_t k = 0; k < 3; ++k) c.bary[k] = b0 * s.corner[0][k] + b1 * s.corner[1][k] + b2 * s.corner[2][k];
      fn(static_cast<const covered&>(c));
    });
  }
}

/// Conservative pixel bounds [x0, x1) x [y0, y1) of a polygon; all zero when it has no area.
inline std::array<std::int64_t, 4> polygon_bounds(const polygon& p) {
  if (p.n < 3) return {0, 0, 0, 0};
  double minx = p.v[0].x, maxx = minx, miny = p.v[0].y, maxy = miny;
  for (int i = 1; i < p.n; ++i) {
    const auto& v = p.v[to_size(i)];
    minx = std::min(minx, v.x);
    maxx = std::max(maxx, v.x);
    miny = std::min(miny, v.y);
    maxy = std::max(maxy, v.y);
  }
  return {static_cast<std::int64_t>(std::floor(minx)) - 1, static_cast<std::int64_t>(std::floor(miny)) - 1,
          static_cast<std::int64_t>(std::ceil(maxx)) + 1, static_cast<std::int64_t>(std::ceil(maxy)) + 1};
}

}  // namespace detail::raster

TESSERA_NAMESPACE_END
