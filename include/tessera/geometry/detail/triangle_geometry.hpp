// tessera/geometry/detail/triangle_geometry.hpp: exact-arithmetic-free primitives on triangles used by
// the BVH and the geometric-texture checks: closest point on a triangle (with barycentrics), ray /
// triangle intersection (Moller-Trumbore), triangle / triangle intersection (Moller 1997 interval test
// with a 2D fallback for coplanar pairs), segment / triangle and box distances.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../../core/config.hpp"
#include "../../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Positive floor of the squared lengths and lengths that scale the predicates below, so a degenerate
/// (zero-size) input still gives a positive scale instead of 0 or a 0 * inf.
inline constexpr double predicate_scale_floor = 1e-300;
/// Ray / triangle: |det| at or below this fraction of |e1|^2 |d| (edges e1, e2, direction d) treats the
/// ray as parallel to the triangle's plane (a miss).
inline constexpr double ray_parallel_tolerance = 1e-14;
/// Triangle / triangle: a vertex's distance to the other triangle's plane at or below this fraction of
/// |n| times the triangles' extent is snapped to zero (the vertex lies on the plane).
inline constexpr double plane_distance_snap = 1e-12;
/// Triangle / triangle: |n1 x n2|^2 at or below this fraction of |n1|^2 |n2|^2 treats the two planes as
/// parallel (coplanar test or apart).
inline constexpr double parallel_planes_tolerance = 1e-30;

/// Closest point on triangle (a, b, c) to p, with barycentric coordinates (Ericson, RTCD 5.1.5).
struct triangle_closest {
  vec3 point;
  vec3 bary;  ///< weights of a, b, c
};

inline triangle_closest closest_point_on_triangle(vec3 p, vec3 a, vec3 b, vec3 c) noexcept {
  const vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}};
  const vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {a + ab * v, {1 - v, v, 0}};
  }
  const vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {a + ac * w, {1 - w, 0, w}};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + (c - b) * w, {0, 1 - w, w}};
  }
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) return {a, {1, 0, 0}};  // degenerate triangle
  const double v = vb / denom, w = vc / denom;
  return {a + ab * v + ac * w, {1 - v - w, v, w}};
}

/// Squared distance from p to an axis-aligned box (0 inside).
inline double squared_distance_to_box(vec3 p, const aabb& b) noexcept {
  double d = 0;
  for (int i = 0; i < 3; ++i) {
    const double lo = b.min[i] - p[i], hi = p[i] - b.max[i];
    const double e = lo > 0 ? lo : hi > 0 ? hi : 0.0;
    d += e * e;
  }
  return d;
}

/// True when two boxes overlap (touching counts).
inline bool boxes_overlap(const aabb& a, const aabb& b) noexcept {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z &&
         b.min.z <= a.max.z;
}

/// Ray (origin o, direction d) against triangle (a, b, c), both sides. Returns the ray parameter t in
/// [t_min, t_max] and the barycentrics (1-u-v, u, v) of the hit, or t = +inf for a miss.
struct ray_triangle_hit {
  double t = std::numeric_limits<double>::infinity();
  double u = 0, v = 0;
};

inline ray_triangle_hit ray_triangle(vec3 o, vec3 d, vec3 a, vec3 b, vec3 c, double t_min, double t_max) noexcept {
  const vec3 e1 = b - a, e2 = c - a;
  const vec3 pv = cross(d, e2);
  const double det = dot(e1, pv);
  const double scale = std::max({squared_norm(e1), squared_norm(e2), predicate_scale_floor}) *
                       std::sqrt(std::max(squared_norm(d), predicate_scale_floor));
  if (std::abs(det) <= ray_parallel_tolerance * scale) return {};
  const double inv = 1.0 / det;
  const vec3 tv = o - a;
  const double u = dot(tv, pv) * inv;
  if (u < 0 || u > 1) return {};
  const vec3 qv = cross(tv, e1);
  const double v = dot(d, qv) * inv;
  if (v < 0 || u + v > 1) return {};
  const double t = dot(e2, qv) * inv;
  if (t < t_min || t > t_max) return {};
  return {t, u, v};
}

// --- triangle / triangle --------------------------------------------------------------------------

inline bool segments_intersect_2d(const double p0[2], const double p1[2], const double q0[2],
                                  const double q1[2]) noexcept {
  auto orient = [](const double a[2], const double b[2], const double c[2]) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  };
  const double o1 = orient(p0, p1, q0), o2 = orient(p0, p1, q1), o3 = orient(q0, q1, p0), o4 = orient(q0, q1, p1);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  auto on_segment = [](const double a[2], const double b[2], const double c[2]) {
    return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= c[1] &&
           c[1] <= std::max(a[1], b[1]);
  };
  if (o1 == 0 && on_segment(p0, p1, q0)) return true;
  if (o2 == 0 && on_segment(p0, p1, q1)) return true;
  if (o3 == 0 && on_segment(q0, q1, p0)) return true;
  if (o4 == 0 && on_segment(q0, q1, p1)) return true;
  return false;
}

inline bool point_in_triangle_2d(const double p[2], const double a[2], const double b[2], const double c[2]) noexcept {
  auto orient = [](const double u[2], const double v[2], const double w[2]) {
    return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0]);
  };
  const double d1 = orient(a, b, p), d2 = orient(b, c, p), d3 = orient(c, a, p);
  const bool neg = d1 < 0 || d2 < 0 || d3<0, pos = d1> 0 || d2 > 0 || d3 > 0;
  return !(neg && pos);
}

/// Coplanar triangles: project onto the plane where the normal is largest and test in 2D.
inline bool coplanar_triangles_intersect(vec3 n, const std::array<vec3, 3>& t, const std::array<vec3, 3>& u) noexcept {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  int i0 = 0, i1 = 1;
  if (ax >= ay && ax >= az) {
    i0 = 1;
    i1 = 2;
  } else if (ay >= az) {
    i0 = 0;
    i1 = 2;
  }
  double p[3][2], q[3][2];
  for (int k = 0; k < 3; ++k) {
    p[k][0] = t[k][i0];
    p[k][1] = t[k][i1];
    q[k][0] = u[k][i0];
    q[k][1] = u[k][i1];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_intersect_2d(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3])) return true;
  return point_in_triangle_2d(p[0], q[0], q[1], q[2]) || point_in_triangle_2d(q[0], p[0], p[1], p[2]);
}

/// Interval of triangle t on the line of intersection (Moller 1997), given the projections pv of its
/// vertices on the line and their signed distances dv to the other plane.
inline bool triangle_line_interval(const double pv[3], const double dv[3], double& lo, double& hi) noexcept {
  // find the vertex alone on its side
  int solo;
  if ((dv[0] > 0) == (dv[1] > 0) && dv[0] != 0 && dv[1] != 0)
    solo = 2;
  else if ((dv[0] > 0) == (dv[2] > 0) && dv[0] != 0 && dv[2] != 0)
    solo = 1;
  else if ((dv[1] > 0) == (dv[2] > 0) && dv[1] != 0 && dv[2] != 0)
    solo = 0;
  else if (dv[0] != 0)
    solo = 0;
  else if (dv[1] != 0)
    solo = 1;
  else if (dv[2] != 0)
    solo = 2;
  else
    return false;  // coplanar
  const int a = (solo + 1) % 3, b = (solo + 2) % 3;
  const double ta = pv[solo] + (pv[a] - pv[solo]) * dv[solo] / (dv[solo] - dv[a]);
  const double tb = pv[solo] + (pv[b] - pv[solo]) * dv[solo] / (dv[solo] - dv[b]);
  lo = std::min(ta, tb);
  hi = std::max(ta, tb);
  return true;
}

/// True when segment [p, q], whose ends lie at (snapped) signed distances dp, dq from the plane of
/// triangle u, meets the closed triangle u: the ends do not lie strictly on one side, and the point
/// where the segment meets the plane lies in u, tested in 2D on the plane where u's normal is largest
/// (a segment in the plane: it crosses an edge of u or starts inside). The point is always on the
/// segment, so a segment nearly in u's plane (noisy dp, dq) is still judged by where it lies.
inline bool edge_meets_triangle(vec3 p, vec3 q, double dp, double dq, const std::array<vec3, 3>& u) noexcept {
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0)) return false;
  const vec3 n = cross(u[1] - u[0], u[2] - u[0]);
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  const int i0 = ax >= ay && ax >= az ? 1 : 0, i1 = ax >= ay && ax >= az ? 2 : ay >= az ? 2 : 1;
  double w[3][2];
  for (int k = 0; k < 3; ++k) {
    w[k][0] = u[to_size(k)][i0];
    w[k][1] = u[to_size(k)][i1];
  }
  if (dp == 0 && dq == 0) {
    const double a[2] = {p[i0], p[i1]}, b[2] = {q[i0], q[i1]};
    for (int k = 0; k < 3; ++k)
      if (segments_intersect_2d(a, b, w[k], w[(k + 1) % 3])) return true;
    return point_in_triangle_2d(a, w[0], w[1], w[2]);
  }
  const vec3 x = p + (dp / (dp - dq)) * (q - p);
  const double c[2] = {x[i0], x[i1]};
  return point_in_triangle_2d(c, w[0], w[1], w[2]);
}

/// True when the closed triangles t and u share at least one point. Touching counts as
/// intersecting. Degenerate (zero-area) triangles are treated through their edges.
inline bool triangles_intersect(const std::array<vec3, 3>& t, const std::array<vec3, 3>& u) noexcept {
  const vec3 n1 = cross(t[1] - t[0], t[2] - t[0]);
  const vec3 n2 = cross(u[1] - u[0], u[2] - u[0]);
  double du[3], dt[3];
  for (int k = 0; k < 3; ++k) du[k] = dot(n1, u[k] - t[0]);
  // snap tiny distances to zero relative to the triangle sizes
  const double s1 = std::sqrt(squared_norm(n1)) * plane_distance_snap *
                    std::max({norm(u[0] - t[0]), norm(u[1] - t[0]), norm(u[2] - t[0]), predicate_scale_floor});
  for (double& d : du)
    if (std::abs(d) <= s1) d = 0;
  if ((du[0] > 0 && du[1] > 0 && du[2] > 0) || (du[0] < 0 && du[1] < 0 && du[2] < 0)) return false;
  for (int k = 0; k < 3; ++k) dt[k] = dot(n2, t[k] - u[0]);
  const double s2 = std::sqrt(squared_norm(n2)) * plane_distance_snap *
                    std::max({norm(t[0] - u[0]), norm(t[1] - u[0]), norm(t[2] - u[0]), predicate_scale_floor});
  for (double& d : dt)
    if (std::abs(d) <= s2) d = 0;
  if ((dt[0] > 0 && dt[1] > 0 && dt[2] > 0) || (dt[0] < 0 && dt[1] < 0 && dt[2] < 0)) return false;
  const vec3 dir = cross(n1, n2);
  if (squared_norm(dir) <= parallel_planes_tolerance * squared_norm(n1) * squared_norm(n2) ||
      (du[0] == 0 && du[1] == 0 && du[2] == 0)) {
    if (!(du[0] == 0 && du[1] == 0 && du[2] == 0)) return false;  // parallel planes, apart
    return coplanar_triangles_intersect(squared_norm(n1) > 0 ? n1 : n2, t, u);
  }
  // Not coplanar: the triangles meet iff an edge of one meets the other (the ends of their common
  // segment lie on edges). Tested with orientation signs, no division: Möller's intervals along
  // cross(n1, n2) lose all precision for nearly parallel planes (a fine split of one flat facet of an
  // element reported pairs ~10^-4 apart as crossing).
  for (int k = 0; k < 3; ++k) {
    if (edge_meets_triangle(t[to_size(k)], t[to_size((k + 1) % 3)], dt[k], dt[(k + 1) % 3], u)) return true;
    if (edge_meets_triangle(u[to_size(k)], u[to_size((k + 1) % 3)], du[k], du[(k + 1) % 3], t)) return true;
  }
  return false;
}

/// True when segment [p, q] meets the closed triangle (a, b, c) (used as a brute-force oracle).
inline bool segment_hits_triangle(vec3 p, vec3 q, vec3 a, vec3 b, vec3 c) noexcept {
  return ray_triangle(p, q - p, a, b, c, 0.0, 1.0).t <= 1.0;
}

}  // namespace detail
TESSERA_NAMESPACE_END
