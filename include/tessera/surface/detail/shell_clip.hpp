// tessera/surface/detail/shell_clip.hpp: exact clipping of texture-space triangles at the tetrahedra of
// the shell map (paper 000 §4; Porumbescu et al. 2005, "Shell maps": the texture mesh is split at the
// boundaries of the texture-space tetrahedra so that every piece lies in one tetrahedron, where the shell
// map is affine). The output is then the exact image of the tiles under the piecewise-linear shell map:
// two tile triangles that do not cross do not cross after mapping (the map is one-to-one where no shell
// tetrahedron is inverted), which midpoint refinement (detail/shell_refine.hpp) only approaches.
//
// Texture space over a chart is (P, h): P on the chart's plane of the polycube, h in [0, H]. The prism
// of base face f is its polycube triangle times [0, H]; with β the barycentric weights of P in that
// triangle (affine in P) and t = h / H, its three tetrahedra are (detail/shell_prism.hpp, sorted corners
// s0 < s1 < s2): T1 t <= β_s2, T2 β_s2 <= t <= β_s1 + β_s2, T3 t >= β_s1 + β_s2. Every bounding surface
// (prism sides β_k = 0, split planes t = β_s2 and t = β_s1 + β_s2) is a plane, linear in the barycentric
// weights λ of the tile triangle's corners, so each piece "triangle ∩ tetrahedron" is the convex polygon
// Sutherland-Hodgman clipping gives in λ (three to five half-planes).
//
// Steps: (A, per triangle, in parallel) a triangle whose corners lie in one tetrahedron is kept (the
// common case, no work); otherwise the prisms it overlaps are found by a walk over base faces sharing a
// vertex (only faces of the triangle's chart), starting at its corners' faces, and the triangle is
// clipped at each. Piece vertices within `tolerance` (texture-space distance) of a triangle side are
// snapped onto it, and onto a corner within it of one; the remaining (interior) vertices of one
// triangle are merged within it. (B) The points on triangle sides are gathered over all triangles and
// merged per side, keyed by the side's two vertex ids and measured from its lower-id end, so the two
// triangles of a side, in one chart or in two across a polycube edge, get the same points; each merged
// point is mapped once, from the side's ends. (C) Every triangle (pieces, or the whole triangle when it
// lay in one tetrahedron) takes all merged points of its sides between its piece corners, so the
// result is conforming (no T-junctions: closed elements stay closed), and each polygon is cut into
// triangles by ear clipping that picks the best-shaped ear of positive area (no zero-area face unless
// the tile triangle itself had none to give). Deterministic for any executor: the per-triangle work is
// independent, merges follow sorted keys, new vertices are numbered in triangle order.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/executor.hpp"
#include "../../core/vec.hpp"
#include "../polycube_map.hpp"
#include "shell_prism.hpp"
#include "shell_refine.hpp"
#include "shell_weld.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Counts of clip_shell_mesh.
struct shell_clip_stats {
  index_t clipped_faces = 0;  ///< tile triangles that overlapped several tetrahedra
  index_t side_points = 0;    ///< distinct points added on tile triangle sides
  index_t inner_points = 0;   ///< points added inside tile triangles
  index_t flat_faces = 0;     ///< output faces of zero area (only where a tile triangle was degenerate)
};

/// A polygon vertex of a piece: λ over the tile triangle's corners.
using clip_lambda = std::array<double, 3>;

/// Clips the convex λ-polygon `in` to g(λ) = Σ λ_i g_i >= 0 (Sutherland-Hodgman; |g| <= eps counts as on
/// the plane, kept on both sides).
inline void clip_lambda_polygon(const std::vector<clip_lambda>& in, const std::array<double, 3>& g, double eps,
                                std::vector<clip_lambda>& out) {
  out.clear();
  const std::size_t n = in.size();
  auto value = [&](const clip_lambda& l) {
    const double d = l[0] * g[0] + l[1] * g[1] + l[2] * g[2];
    return std::abs(d) <= eps ? 0.0 : d;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const clip_lambda &a = in[i], &b = in[(i + 1) % n];
    const double da = value(a), db = value(b);
    if (da >= 0) out.push_back(a);
    if ((da > 0 && db < 0) || (da < 0 && db > 0)) {
      const double w = da / (da - db);
      out.push_back({a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])});
    }
  }
}

/// Twice the area of a λ-polygon (in the (λ1, λ2) plane; the triangle itself has 1).
inline double clip_lambda_area2(const std::vector<clip_lambda>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const clip_lambda &u = p[i], &w = p[(i + 1) % p.size()];
    a += u[1] * w[2] - u[2] * w[1];
  }
  return a;
}

/// Cuts the polygon `ids` (positions `x`, counter-clockwise about `n`; both consumed) into triangles by ear clipping:
/// each step removes the ear of positive area with the best shape (area over the sum of squared sides)
/// whose removal leaves a polygon of positive area; when there is none (a degenerate polygon) the
/// largest ear. Returns the number of zero-area triangles emitted.
template <class Emit>
index_t clip_triangulate(std::vector<index_t>& ids, std::vector<vec3>& x, vec3 n, double area_eps, Emit&& emit) {
  index_t flat = 0;
  auto ear_area = [&](std::size_t a, std::size_t b, std::size_t c) { return dot(cross(x[b] - x[a], x[c] - x[a]), n); };
  double total = 0;
  for (std::size_t i = 1; i + 1 < ids.size(); ++i) total += ear_area(0, i, i + 1);
  while (ids.size() > 3) {
    const std::size_t m = ids.size();
    std::size_t best = m, largest = 0;
    double best_q = -1, largest_a = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t a = (i + m - 1) % m, c = (i + 1) % m;
      const double ar = ear_area(a, i, c);
      if (ar > largest_a) {
        largest_a = ar;
        largest = i;
      }
      if (!(ar > area_eps) || !(total - ar > area_eps)) continue;
      const double q = ar / (squared_norm(x[i] - x[a]) + squared_norm(x[c] - x[i]) + squared_norm(x[a] - x[c]));
      if (q > best_q) {
        best_q = q;
        best = i;
      }
    }
    if (best == m) best = largest;
    const std::size_t a = (best + m - 1) % m, c = (best + 1) % m;
    const double ar = ear_area(a, best, c);
    if (!(ar > area_eps)) ++flat;
    emit(ids[a], ids[best], ids[c]);
    total -= ar;
    ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(best));
    x.erase(x.begin() + static_cast<std::ptrdiff_t>(best));
  }
  if (!(ear_area(0, 1, 2) > area_eps)) ++flat;
  emit(ids[0], ids[1], ids[2]);
  return flat;
}

/// A vertex of a clipped triangle's pieces (clip_shell_mesh).
struct shell_clip_vertex {
  std::int8_t kind = 0;  ///< 0 corner, 1 on a side, 2 inside
  std::int8_t slot = 0;  ///< corner slot, or side k = (v[k], v[k + 1])
  double s = 0;          ///< side parameter from the side's lower-id end
  clip_lambda lambda{};  ///< inside: weights of the corners
  index_t face = -1;     ///< a base face whose prism holds the point
  index_t id = -1;       ///< output vertex (side points: set in step B; inside points: in step C)
};

/// Texture-space position of `y` on the triangle with vertex ids `v` and positions `X`.
inline vec3 clip_vertex_position(const shell_clip_vertex& y, const std::array<index_t, 3>& v,
                                 const std::array<vec3, 3>& X) {
  if (y.kind == 0) return X[to_size(y.slot)];
  if (y.kind == 1) {
    const int i = y.slot, j = (y.slot + 1) % 3;
    const bool i_low = v[to_size(i)] < v[to_size(j)];
    const vec3 lo = X[to_size(i_low ? i : j)], hi = X[to_size(i_low ? j : i)];
    return lo + y.s * (hi - lo);
  }
  return y.lambda[0] * X[0] + y.lambda[1] * X[1] + y.lambda[2] * X[2];
}

/// Clips `faces` (texture triangles over `points`; `face_chart[i]` the chart of face i) at the
/// texture-space tetrahedra of the shell (see the file comment), in place: `points` and `mapped` grow
/// by the new vertices. `map_in_face(face, bary, h)` maps a point of a known base face. `tolerance`:
/// texture-space distance (mesh units) within which piece vertices snap onto sides and corners and
/// merge.
template <class MapInFace, Executor E>
shell_clip_stats clip_shell_mesh(std::vector<shell_texture_point>& points, std::vector<shell_mapped_point>& mapped,
                                 std::vector<std::array<index_t, 3>>& faces, const std::vector<index_t>& face_chart,
                                 const polycube_map& map, double H, double tolerance, MapInFace&& map_in_face,
                                 E& exec) {
  using tri = std::array<index_t, 3>;
  shell_clip_stats stats;
  const auto& base = map.base.faces;
  const std::size_t nv = map.polycube.size(), nf = base.size();
  auto key_of = [](index_t a, index_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
  };
  // faces around each base vertex (CSR) for the walk
  std::vector<index_t> ring_start(nv + 1, 0), ring;
  for (const auto& f : base)
    for (index_t v : f) ++ring_start[to_size(v) + 1];
  for (std::size_t v = 0; v < nv; ++v) ring_start[v + 1] += ring_start[v];
  ring.resize(to_size(ring_start[nv]));
  {
    std::vector<index_t> fill(ring_start.begin(), ring_start.end() - 1);
    for (std::size_t f = 0; f < nf; ++f)
      for (index_t v : base[f]) ring[to_size(fill[to_size(v)]++)] = static_cast<index_t>(f);
  }
  // barycentric weights of polycube point p in base face f's polycube triangle (not clamped)
  auto bary_in = [&](index_t f, vec3 p) {
    const auto& fv = base[to_size(f)];
    const vec3 q0 = map.polycube[to_size(fv[0])], q1 = map.polycube[to_size(fv[1])], q2 = map.polycube[to_size(fv[2])];
    const vec3 n = cross(q1 - q0, q2 - q0);
    const double nn = dot(n, n);
    if (!(nn > 0)) return vec3{1.0 / 3, 1.0 / 3, 1.0 / 3};
    return vec3{dot(cross(q1 - p, q2 - p), n) / nn, dot(cross(q2 - p, q0 - p), n) / nn,
                dot(cross(q0 - p, q1 - p), n) / nn};
  };
  auto clamp_bary = [](vec3 b) {
    b = {std::max(b.x, 0.0), std::max(b.y, 0.0), std::max(b.z, 0.0)};
    const double s = b.x + b.y + b.z;
    return s > 0 ? b / s : vec3{1.0 / 3, 1.0 / 3, 1.0 / 3};
  };
  auto chart_normal = [&](index_t chart) { return label_direction(map.charts[to_size(chart)].label); };

  // A: the pieces of every triangle that is not inside one tetrahedron
  using vertex = shell_clip_vertex;
  struct record {
    std::vector<vertex> verts;
    std::vector<index_t> poly, start{0};  // polygons as vertex lists
  };
  const auto nt = faces.size();
  std::vector<char> clipped(nt, 0);
  exec.parallel_for(0, static_cast<index_t>(nt), [&](index_t t) {
    const tri& v = faces[to_size(t)];
    const auto &m0 = mapped[to_size(v[0])], &m1 = mapped[to_size(v[1])], &m2 = mapped[to_size(v[2])];
    if (m0.face < 0 || m1.face < 0 || m2.face < 0) return;  // unmapped corner: keep (cannot locate)
    clipped[to_size(t)] = !(m0.face == m1.face && m1.face == m2.face && m0.tet == m1.tet && m1.tet == m2.tet);
  });
  std::vector<index_t> todo;
  for (std::size_t t = 0; t < nt; ++t)
    if (clipped[t]) todo.push_back(static_cast<index_t>(t));
  std::vector<record> recs(todo.size());
  const double tol = tolerance, eps = 1e-13;
  exec.parallel_for(0, static_cast<index_t>(todo.size()), [&](index_t r) {
    const tri& v = faces[to_size(todo[to_size(r)])];
    const index_t chart = face_chart[to_size(todo[to_size(r)])];
    const vec3 n = chart_normal(chart);
    std::array<vec3, 3> X;
    std::array<double, 3> t;
    for (int i = 0; i < 3; ++i) {
      const auto& tp = points[to_size(v[to_size(i)])];
      X[to_size(i)] = tp.p + tp.h * n;
      t[to_size(i)] = std::clamp(tp.h / H, 0.0, 1.0);
    }
    // altitudes over each side k = (v[k], v[k + 1]) (opposite corner k + 2)
    const double area2 = norm(cross(X[1] - X[0], X[2] - X[0]));
    std::array<double, 3> len, alt;
    for (int k = 0; k < 3; ++k) {
      len[to_size(k)] = norm(X[to_size((k + 1) % 3)] - X[to_size(k)]);
      alt[to_size(k)] = len[to_size(k)] > 0 ? area2 / len[to_size(k)] : 0;
    }
    // the snap and merge distance of this triangle: the tolerance, or less in a sliver (a thousandth of its
    // smallest altitude), whose pieces would otherwise all snap onto its long side
    const double maxlen = std::max({len[0], len[1], len[2]});
    const double tl = std::min(tol, 1e-3 * area2 / std::max(maxlen, 1e-300));
    // a degenerate triangle is kept whole (with the points of its sides, step C)
    if (!(area2 > 1e-12 * maxlen * maxlen)) return;
    auto& rec = recs[to_size(r)];
    // per-thread scratch, reused from triangle to triangle
    thread_local std::vector<index_t> visited, queue;
    thread_local std::vector<clip_lambda> poly, a, b, piece;
    visited.clear();
    queue.clear();
    auto push_ring = [&](index_t f) {
      for (index_t u : base[to_size(f)])
        for (index_t j = ring_start[to_size(u)]; j < ring_start[to_size(u) + 1]; ++j) {
          const index_t g = ring[to_size(j)];
          if (std::find(visited.begin(), visited.end(), g) == visited.end()) {
            visited.push_back(g);
            queue.push_back(g);
          }
        }
    };
    for (int i = 0; i < 3; ++i) {
      const index_t f = mapped[to_size(v[to_size(i)])].face;
      if (std::find(visited.begin(), visited.end(), f) != visited.end()) continue;
      visited.push_back(f);
      if (map.face_chart[to_size(f)] == chart)
        queue.push_back(f);
      else
        push_ring(f);  // a corner on a polycube edge located in the other chart: start next to it
    }
    // snap a λ vertex onto sides and corners; returns the vertex's index in rec.verts (merged)
    auto add_vertex = [&](clip_lambda l, index_t f) -> index_t {
      int zeros = 0, zk = -1;
      for (int c = 0; c < 3; ++c) {
        // corner c is opposite side (c + 1) % 3
        if (l[to_size(c)] * alt[to_size((c + 1) % 3)] <= tl || l[to_size(c)] <= 0) {
          l[to_size(c)] = 0;
          ++zeros;
          zk = c;
        }
      }
      vertex x;
      x.face = f;
      if (zeros >= 2) {
        x.kind = 0;
        x.slot = static_cast<std::int8_t>(l[0] > 0 ? 0 : l[1] > 0 ? 1 : 2);
        if (zeros == 3) {  // degenerate triangle: the nearest corner of the unsnapped weights
          x.slot = 0;
        }
      } else if (zeros == 1) {
        const int k = (zk + 1) % 3;  // side (v[k], v[k + 1]) opposite corner zk
        const int i = k, j = (k + 1) % 3;
        const double w = l[to_size(i)] + l[to_size(j)];
        const bool i_low = v[to_size(i)] < v[to_size(j)];
        double s = (i_low ? l[to_size(j)] : l[to_size(i)]) / w;
        s = std::clamp(s, 0.0, 1.0);
        if (s * len[to_size(k)] <= tl || (1 - s) * len[to_size(k)] <= tl) {
          x.kind = 0;
          x.slot = static_cast<std::int8_t>((s * len[to_size(k)] <= tl) == i_low ? i : j);
        } else {
          x.kind = 1;
          x.slot = static_cast<std::int8_t>(k);
          x.s = s;
        }
      } else {
        const double w = l[0] + l[1] + l[2];
        x.kind = 2;
        x.lambda = {l[0] / w, l[1] / w, l[2] / w};
      }
      auto pos = [&](const vertex& y) { return clip_vertex_position(y, v, X); };
      const vec3 px = pos(x);
      for (std::size_t q = 0; q < rec.verts.size(); ++q) {
        const vertex& y = rec.verts[q];
        if (y.kind != x.kind || y.slot != x.slot) continue;
        if (x.kind == 0 || (x.kind == 1 && std::abs(y.s - x.s) * len[to_size(x.slot)] <= tl) ||
            (x.kind == 2 && norm(pos(y) - px) <= tl))
          return static_cast<index_t>(q);
      }
      rec.verts.push_back(x);
      return static_cast<index_t>(rec.verts.size() - 1);
    };
    for (std::size_t qi = 0; qi < queue.size(); ++qi) {
      const index_t f = queue[qi];
      if (map.face_chart[to_size(f)] != chart) continue;
      const auto& fv = base[to_size(f)];
      std::array<vec3, 3> beta;
      for (int i = 0; i < 3; ++i) beta[to_size(i)] = bary_in(f, points[to_size(v[to_size(i)])].p);
      poly = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      for (int k = 0; k < 3 && !poly.empty(); ++k) {
        clip_lambda_polygon(poly, {beta[0][k], beta[1][k], beta[2][k]}, eps, a);
        poly.swap(a);
      }
      if (poly.size() < 3) continue;
      push_ring(f);  // the triangle reaches this prism: look at its neighbours too
      if (!(clip_lambda_area2(poly) > 1e-14)) continue;
      const prism_order o = sorted_prism_order(fv);
      std::array<double, 3> s1, s12;  // β_s2 - t and β_s1 + β_s2 - t at the corners
      for (int i = 0; i < 3; ++i) {
        const vec3& bi = beta[to_size(i)];
        s1[to_size(i)] = bi[o.corner[2]] - t[to_size(i)];
        s12[to_size(i)] = bi[o.corner[1]] + bi[o.corner[2]] - t[to_size(i)];
      }
      for (int tet = 0; tet < 3; ++tet) {
        if (tet == 0) {
          clip_lambda_polygon(poly, s1, eps, piece);
        } else if (tet == 1) {
          clip_lambda_polygon(poly, {-s1[0], -s1[1], -s1[2]}, eps, b);
          clip_lambda_polygon(b, s12, eps, piece);
        } else {
          clip_lambda_polygon(poly, {-s12[0], -s12[1], -s12[2]}, eps, piece);
        }
        if (piece.size() < 3 || !(clip_lambda_area2(piece) > 1e-14)) continue;
        for (const auto& l : piece) rec.poly.push_back(add_vertex(l, f));
        rec.start.push_back(static_cast<index_t>(rec.poly.size()));
      }
    }
  });
  // B: points on triangle sides, merged per side over all triangles
  struct side_point {
    std::uint64_t key;
    double s;
    index_t face, rec, vert;
  };
  std::vector<side_point> sp;
  for (std::size_t r = 0; r < recs.size(); ++r) {
    const tri& v = faces[to_size(todo[r])];
    for (std::size_t q = 0; q < recs[r].verts.size(); ++q) {
      const auto& x = recs[r].verts[q];
      if (x.kind == 1)
        sp.push_back({key_of(v[to_size(x.slot)], v[to_size((x.slot + 1) % 3)]), x.s, x.face, static_cast<index_t>(r),
                      static_cast<index_t>(q)});
    }
  }
  std::sort(sp.begin(), sp.end(), [](const side_point& x, const side_point& y) {
    return x.key != y.key     ? x.key < y.key
           : x.s != y.s       ? x.s < y.s
           : x.face != y.face ? x.face < y.face
           : x.rec != y.rec   ? x.rec < y.rec
                              : x.vert < y.vert;
  });
  struct merged_point {
    std::uint64_t key;
    double s;
    index_t face, id;
  };
  std::vector<merged_point> table;
  const auto first_new = static_cast<index_t>(points.size());
  for (std::size_t i = 0; i < sp.size();) {
    const std::uint64_t key = sp[i].key;
    const auto lo = to_size(key >> 32), hi = to_size(key & 0xffffffffu);
    const vec3 d = points[hi].p - points[lo].p;
    const double len = std::sqrt(squared_norm(d) + (points[hi].h - points[lo].h) * (points[hi].h - points[lo].h));
    std::size_t j = i + 1;
    index_t face = sp[i].face;
    while (j < sp.size() && sp[j].key == key && (sp[j].s - sp[j - 1].s) * len <= tol) {
      face = std::min(face, sp[j].face);
      ++j;
    }
    const auto id = static_cast<index_t>(first_new + static_cast<index_t>(table.size()));
    table.push_back({key, sp[i].s, face, id});
    for (std::size_t k = i; k < j; ++k) {
      auto& x = recs[to_size(sp[k].rec)].verts[to_size(sp[k].vert)];
      x.id = id;
      x.s = sp[i].s;
    }
    i = j;
  }
  stats.side_points = static_cast<index_t>(table.size());
  points.resize(points.size() + table.size());
  mapped.resize(mapped.size() + table.size());
  exec.parallel_for(0, static_cast<index_t>(table.size()), [&](index_t i) {
    const auto& m = table[to_size(i)];
    const auto lo = to_size(m.key >> 32), hi = to_size(m.key & 0xffffffffu);
    const shell_texture_point tp{points[lo].p + m.s * (points[hi].p - points[lo].p),
                                 points[lo].h + m.s * (points[hi].h - points[lo].h)};
    points[to_size(m.id)] = tp;
    mapped[to_size(m.id)] = map_in_face(m.face, clamp_bary(bary_in(m.face, tp.p)), tp.h);
  });
  // C: every triangle with the merged points of its sides; pieces cut into triangles
  auto side_range = [&](std::uint64_t key) {
    const auto first = std::lower_bound(table.begin(), table.end(), key,
                                        [](const merged_point& m, std::uint64_t k) { return m.key < k; });
    auto last = first;
    while (last != table.end() && last->key == key) ++last;
    return std::pair{first, last};
  };
  std::vector<tri> out;
  out.reserve(nt + nt / 4);
  std::vector<index_t> ids;
  std::vector<vec3> xs;
  std::size_t next_rec = 0;
  for (std::size_t tt = 0; tt < nt; ++tt) {
    const tri& v = faces[tt];
    const bool is_clipped = next_rec < todo.size() && to_size(todo[next_rec]) == tt;
    if (!is_clipped && table.empty()) {
      out.push_back(v);
      continue;
    }
    // texture-space frame of the triangle (its chart's normal)
    const vec3 n = chart_normal(face_chart[tt]);
    std::array<vec3, 3> X;
    for (int i = 0; i < 3; ++i) X[to_size(i)] = points[to_size(v[to_size(i)])].p + points[to_size(v[to_size(i)])].h * n;
    const vec3 N = cross(X[1] - X[0], X[2] - X[0]);
    const double nn = norm(N);
    const vec3 Nu = nn > 0 ? N / nn : N;
    const double maxlen = std::max({norm(X[1] - X[0]), norm(X[2] - X[1]), norm(X[0] - X[2])});
    const double area_eps = 1e-6 * std::min(tol, 1e-3 * nn / std::max(maxlen, 1e-300)) * maxlen;
    // one simple loop of ids (no id twice) into triangles
    auto emit_loop = [&](std::vector<index_t>& cid, std::vector<vec3>& cx) {
      if (cid.size() < 3) return;
      // a polygon whose vertices all snapped onto one line (a piece thinner than the tolerance along a
      // side or between close planes) has two equal chains of merged points: it encloses nothing
      double total = 0;
      for (std::size_t i = 1; i + 1 < cid.size(); ++i) total += dot(cross(cx[i] - cx[0], cx[i + 1] - cx[0]), Nu);
      if (!(total > area_eps)) return;
      stats.flat_faces += clip_triangulate(cid, cx, Nu, area_eps, [&](index_t a, index_t b, index_t c) {
        out.push_back({a, b, c});
      });
    };
    auto emit_polygon = [&](std::vector<index_t>& pid, std::vector<vec3>& px) {
      // drop repeated ids (merged vertices); a loop that visits an id twice (two vertices of a piece
      // merged) is cut there into simple loops
      std::vector<index_t> cid;
      std::vector<vec3> cx;
      for (std::size_t i = 0; i < pid.size(); ++i)
        if (cid.empty() || cid.back() != pid[i]) {
          cid.push_back(pid[i]);
          cx.push_back(px[i]);
        }
      while (cid.size() > 1 && cid.back() == cid.front()) {
        cid.pop_back();
        cx.pop_back();
      }
      for (bool cut = true; cut && cid.size() >= 3;) {
        cut = false;
        for (std::size_t i = 0; i < cid.size() && !cut; ++i)
          for (std::size_t j = i + 1; j < cid.size() && !cut; ++j) {
            if (cid[i] != cid[j]) continue;
            std::vector<index_t> lid(cid.begin() + static_cast<std::ptrdiff_t>(i),
                                     cid.begin() + static_cast<std::ptrdiff_t>(j));
            std::vector<vec3> lx(cx.begin() + static_cast<std::ptrdiff_t>(i),
                                 cx.begin() + static_cast<std::ptrdiff_t>(j));
            emit_loop(lid, lx);
            cid.erase(cid.begin() + static_cast<std::ptrdiff_t>(i), cid.begin() + static_cast<std::ptrdiff_t>(j));
            cx.erase(cx.begin() + static_cast<std::ptrdiff_t>(i), cx.begin() + static_cast<std::ptrdiff_t>(j));
            cut = true;
          }
      }
      emit_loop(cid, cx);
    };
    // the side points of side k strictly between parameters u0 -> u1 (from v[k]), in that direction
    auto side_points = [&](int k, double u0, double u1, std::vector<index_t>& pid, std::vector<vec3>& px) {
      const index_t a = v[to_size(k)], b = v[to_size((k + 1) % 3)];
      const auto [first, last] = side_range(key_of(a, b));
      if (first == last) return;
      const bool a_low = a < b;
      const vec3 xa = X[to_size(k)], xb = X[to_size((k + 1) % 3)];
      const std::size_t mark = pid.size();
      for (auto it = first; it != last; ++it) {
        const double u = a_low ? it->s : 1 - it->s;
        if (it->id == pid.back()) continue;
        if ((u0 < u1 && u > u0 && u < u1) || (u0 > u1 && u < u0 && u > u1)) {
          pid.push_back(it->id);
          px.push_back(xa + u * (xb - xa));
        }
      }
      // table order is ascending s (from the low end): ascending u when a is low
      const bool ascending = a_low;
      if (ascending != (u0 < u1)) {
        std::reverse(pid.begin() + static_cast<std::ptrdiff_t>(mark), pid.end());
        std::reverse(px.begin() + static_cast<std::ptrdiff_t>(mark), px.end());
      }
    };
    if (!is_clipped || recs[next_rec].start.size() == 1) {
      next_rec += is_clipped ? 1 : 0;
      ids.clear();
      xs.clear();
      for (int k = 0; k < 3; ++k) {
        ids.push_back(v[to_size(k)]);
        xs.push_back(X[to_size(k)]);
        side_points(k, 0, 1, ids, xs);
      }
      if (ids.size() == 3)
        out.push_back(v);
      else
        emit_polygon(ids, xs);
      continue;
    }
    auto& rec = recs[next_rec++];
    ++stats.clipped_faces;
    // output ids of the corners and inside points; position and side parameter of each vertex
    for (auto& x : rec.verts) {
      if (x.kind == 0) x.id = v[to_size(x.slot)];
      if (x.kind == 2) {
        x.id = static_cast<index_t>(points.size());
        const auto& p0 = points[to_size(v[0])];
        const auto& p1 = points[to_size(v[1])];
        const auto& p2 = points[to_size(v[2])];
        const shell_texture_point tp{x.lambda[0] * p0.p + x.lambda[1] * p1.p + x.lambda[2] * p2.p,
                                     x.lambda[0] * p0.h + x.lambda[1] * p1.h + x.lambda[2] * p2.h};
        points.push_back(tp);
        vec3 b{};
        for (int i = 0; i < 3; ++i) b += x.lambda[to_size(i)] * bary_in(x.face, points[to_size(v[to_size(i)])].p);
        mapped.push_back(map_in_face(x.face, clamp_bary(b), tp.h));
        ++stats.inner_points;
      }
    }
    auto pos = [&](const vertex& y) { return clip_vertex_position(y, v, X); };
    // parameter (from v[k]) of vertex y on side k, or -1 when it is not on that side
    auto on_side = [&](const vertex& y, int k) {
      if (y.kind == 0) return y.slot == k ? 0.0 : y.slot == (k + 1) % 3 ? 1.0 : -1.0;
      if (y.kind == 1 && y.slot == k) return v[to_size(k)] < v[to_size((k + 1) % 3)] ? y.s : 1 - y.s;
      return -1.0;
    };
    for (std::size_t p = 0; p + 1 < rec.start.size(); ++p) {
      ids.clear();
      xs.clear();
      const auto b0 = to_size(rec.start[p]), b1 = to_size(rec.start[p + 1]);
      for (std::size_t i = b0; i < b1; ++i) {
        const vertex& y = rec.verts[to_size(rec.poly[i])];
        const vertex& z = rec.verts[to_size(rec.poly[i + 1 < b1 ? i + 1 : b0])];
        ids.push_back(y.id);
        xs.push_back(pos(y));
        for (int k = 0; k < 3; ++k) {
          const double u0 = on_side(y, k), u1 = on_side(z, k);
          if (u0 >= 0 && u1 >= 0 && u0 != u1) side_points(k, u0, u1, ids, xs);
        }
      }
      emit_polygon(ids, xs);
    }
  }
  faces.swap(out);
  return stats;
}

}  // namespace detail
TESSERA_NAMESPACE_END
