// tessera/surface/detail/polycube_deform.hpp: deformation of a labelled mesh onto its polycube and the
// quantization of chart planes to the tile grid. Per axis a, the vertices of every chart whose label
// has axis a share one unknown coordinate (union-find over vertices and charts); every other vertex
// coordinate is free. All unknowns are fitted in the least-squares sense to the base mesh's edge
// vectors, sum over edges (x_i - x_j - (p_i - p_j))², with Eigen's sparse LDLT on the normal equations
// (the "LDLT deformation" of evocube / fastbndpolycube; ../shared/notes/surface.md). Since chart
// vertices share their unknown, every chart is exactly planar after one solve.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <numeric>
#include <tuple>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../polycube_map.hpp"
#include "polycube_charts.hpp"
#include "tolerances.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Weight of the pull of every free plane coordinate towards its starting value (the mean of its
/// vertices'), so the least-squares system stays positive definite when a coordinate has no constraint.
inline constexpr double plane_solve_regularization = 1e-8;

/// The unknowns of one axis: class of each vertex, chart of each class (-1: free class).
struct polycube_axis_classes {
  std::vector<index_t> vertex_class;
  std::vector<index_t> class_chart;
};

inline result<polycube_axis_classes> polycube_classes(const tri_mesh& m, const std::vector<index_t>& face_chart,
                                                      const std::vector<std::uint8_t>& chart_label, int axis,
                                                      index_t* bad_chart = nullptr, index_t* pinch_vertex = nullptr) {
  const index_t nv = m.num_vertices();
  const auto nc = static_cast<index_t>(chart_label.size());
  std::vector<index_t> parent(to_size(nv + nc));
  std::iota(parent.begin(), parent.end(), index_t{0});
  auto find = [&](index_t x) {
    while (parent[to_size(x)] != x) x = parent[to_size(x)] = parent[to_size(parent[to_size(x)])];
    return x;
  };
  // two charts of the axis that share a vertex (first by face order) would share their plane
  std::vector<index_t> vertex_chart(to_size(nv), -1);
  index_t pinch = -1, pinch_a = -1, pinch_b = -1;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const index_t c = face_chart[f];
    if (chart_label[to_size(c)] / 2 != axis) continue;
    for (index_t v : m.faces[f]) {
      auto& vc = vertex_chart[to_size(v)];
      if (vc < 0) vc = c;
      if (vc != c && pinch < 0) {
        pinch = v;
        pinch_a = vc;
        pinch_b = c;
      }
    }
  }
  if (pinch >= 0) {
    if (bad_chart) *bad_chart = pinch_vertex ? -1 : pinch_b;
    if (pinch_vertex) *pinch_vertex = pinch;
    return status::not_converged(cat("polycube: charts ", std::min(pinch_a, pinch_b), " and ",
                                     std::max(pinch_a, pinch_b), " of axis ", "XYZ"[axis],
                                     " are joined through vertex ", pinch, ": their planes would coincide"));
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const index_t c = face_chart[f];
    if (chart_label[to_size(c)] / 2 != axis) continue;
    for (index_t v : m.faces[f]) {
      const index_t a = find(v), b = find(nv + c);
      if (a != b) parent[to_size(std::max(a, b))] = std::min(a, b);
    }
  }
  polycube_axis_classes out;
  std::vector<index_t> id(parent.size(), -1), root_chart(parent.size(), -1);
  out.vertex_class.resize(to_size(nv));
  for (index_t c = 0; c < nc; ++c) {
    if (chart_label[to_size(c)] / 2 != axis) continue;
    const auto r = to_size(find(nv + c));
    root_chart[r] = c;  // one chart per class: charts of the axis share no vertex (checked above)
  }
  for (index_t v = 0; v < nv; ++v) {
    const auto r = to_size(find(v));
    if (id[r] < 0) {
      id[r] = static_cast<index_t>(out.class_chart.size());
      out.class_chart.push_back(root_chart[r]);
    }
    out.vertex_class[to_size(v)] = id[r];
  }
  return out;
}

/// Least-squares coordinates along `axis`. `fixed[k]` (NaN: free) pins class k. Returns the value of
/// every class. Gauge and free components are held by a 1e-8 pull towards the classes' mean input
/// coordinate.
template <class Dep>
result<std::vector<double>> polycube_axis_solve(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                                const polycube_axis_classes& cl, int axis,
                                                const std::vector<double>& fixed) {
  using real = dependent_t<double, Dep>;
  using sparse = Eigen::SparseMatrix<real>;
  using vector = Eigen::Matrix<real, Eigen::Dynamic, 1>;
  const auto ncl = static_cast<index_t>(cl.class_chart.size());
  std::vector<int> col(to_size(ncl), -1);
  int nfree = 0;
  for (index_t k = 0; k < ncl; ++k)
    if (std::isnan(fixed[to_size(k)])) col[to_size(k)] = nfree++;
  std::vector<double> mean(to_size(ncl), 0.0), cnt(to_size(ncl), 0.0);
  for (index_t v = 0; v < m.num_vertices(); ++v) {
    const auto k = to_size(cl.vertex_class[to_size(v)]);
    mean[k] += m.position(v)[axis];
    cnt[k] += 1;
  }
  std::vector<double> x(to_size(ncl));
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::isnan(fixed[k]) ? mean[k] / cnt[k] : fixed[k];
  if (nfree == 0) return x;
  std::vector<Eigen::Triplet<real>> t;
  vector rhs = vector::Zero(nfree);
  const double eps = plane_solve_regularization;
  for (index_t k = 0; k < ncl; ++k)
    if (col[to_size(k)] >= 0) {
      t.emplace_back(col[to_size(k)], col[to_size(k)], eps);
      rhs[col[to_size(k)]] += eps * x[to_size(k)];
    }
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int s = 0; s < 3; ++s) {
      const index_t g = nb[f][to_size(s)];
      if (g < static_cast<index_t>(f)) continue;  // each edge once (closed mesh)
      const index_t i = m.faces[f][to_size(s)], j = m.faces[f][to_size((s + 1) % 3)];
      const auto ci = to_size(cl.vertex_class[to_size(i)]), cj = to_size(cl.vertex_class[to_size(j)]);
      if (ci == cj) continue;
      // residual x_i - x_j - d
      const double d = m.position(i)[axis] - m.position(j)[axis];
      const int a = col[ci], b = col[cj];
      double known = -d;
      if (a < 0) known += x[ci];
      if (b < 0) known -= x[cj];
      if (a >= 0) {
        t.emplace_back(a, a, 1.0);
        rhs[a] -= known;
      }
      if (b >= 0) {
        t.emplace_back(b, b, 1.0);
        rhs[b] += known;
      }
      if (a >= 0 && b >= 0) {
        t.emplace_back(a, b, -1.0);
        t.emplace_back(b, a, -1.0);
      }
    }
  sparse A(nfree, nfree);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<sparse> solver(A);
  if (solver.info() != Eigen::Success) return status::internal_error("polycube: sparse factorisation failed");
  const vector sol = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !sol.allFinite())
    return status::internal_error("polycube: sparse solve failed");
  for (index_t k = 0; k < ncl; ++k)
    if (col[to_size(k)] >= 0) x[to_size(k)] = sol[col[to_size(k)]];
  return x;
}

/// A polycube edge whose corners differ along its axis by less than this fraction of its path length
/// takes its direction from the base mesh's convexity along it instead.
inline constexpr double edge_direction_min_fraction = 0.1;

/// A polycube edge along some axis runs from the plane of chart `from` to the plane of chart `to`
/// (both of that axis): `to` must lie at least one tile above `from`.
struct polycube_plane_order {
  index_t from = -1, to = -1;
};

/// The order constraints of one axis: every polycube edge along `axis` (paths) keeps the direction it
/// has on the base mesh, the sign of its corners' difference along the axis (when that is under a
/// tenth of the path's length: the base mesh's convexity along it), so no edge is inverted or
/// collapsed by the quantization and every chart keeps the turning of its boundary. Constraints are
/// taken most confident first (the difference over the path length); one that would close a cycle
/// falls back to the order of the continuous planes `plane`, or is dropped when that closes one too
/// (the verification then names what fails). `facing` adds constraints between sides of one chart
/// (chart_facing_orders), after those of the edges. not_converged when both corners of an edge lie on
/// the same chart of the axis (the edge would have length zero), naming the charts and the corners.
inline result<std::vector<polycube_plane_order>> polycube_plane_orders(
    const tri_mesh& m, const std::vector<polycube_edge_path>& paths, const std::vector<std::uint8_t>& chart_label,
    const polycube_axis_classes& cl, int axis, const std::vector<double>& plane, index_t* bad_chart = nullptr,
    const std::vector<polycube_plane_order>& facing = {}) {
  std::vector<polycube_plane_order> out;
  std::vector<std::pair<polycube_plane_order, double>> cand;  // constraint, confidence
  for (const auto& p : paths) {
    if (3 - chart_label[to_size(p.c)] / 2 - chart_label[to_size(p.d)] / 2 != axis) continue;
    const index_t a = p.vertices.front(), b = p.vertices.back();
    const index_t ca = cl.class_chart[to_size(cl.vertex_class[to_size(a)])];
    const index_t cb = cl.class_chart[to_size(cl.vertex_class[to_size(b)])];
    if (ca < 0 || cb < 0) continue;
    if (ca == cb) {
      if (bad_chart) *bad_chart = p.c;
      return status::not_converged(cat("polycube: the edge between charts ", p.c, " and ", p.d,
                                       " from the corner at vertex ", a, " to vertex ", b, " has both ends on chart ",
                                       ca, ": it would collapse"));
    }
    double s = m.position(b)[axis] - m.position(a)[axis];
    double len = 0;
    for (std::size_t k = 1; k < p.vertices.size(); ++k)
      len += distance(m.position(p.vertices[k - 1]), m.position(p.vertices[k]));
    double confidence = len > 0 ? std::abs(s) / len : 0.0;
    if (confidence < edge_direction_min_fraction && p.convexity != 0) {
      // a path that returns near its start: the edge runs along n_c x n_d when convex, against it when
      // concave (c on its left)
      const vec3 nc = label_direction(static_cast<polycube_label>(chart_label[to_size(p.c)]));
      const vec3 nd = label_direction(static_cast<polycube_label>(chart_label[to_size(p.d)]));
      s = (p.convexity > 0 ? 1.0 : -1.0) * cross(nc, nd)[axis];
      confidence = edge_direction_min_fraction;
    }
    if (s != 0) cand.push_back({s > 0 ? polycube_plane_order{ca, cb} : polycube_plane_order{cb, ca}, confidence});
    // the fallback when that direction closes a cycle: the continuous planes' order
    double sp = plane[to_size(cb)] - plane[to_size(ca)];
    if (sp == 0) sp = static_cast<double>(cb - ca);
    cand.push_back({sp > 0 ? polycube_plane_order{ca, cb} : polycube_plane_order{cb, ca}, -1.0});
  }
  for (const auto& o : facing) cand.push_back({o, -0.5});
  // most confident first; a constraint that would close a cycle with those before it is dropped
  std::stable_sort(cand.begin(), cand.end(), [](const auto& x, const auto& y) {
    return std::tuple(-x.second, x.first.from, x.first.to) < std::tuple(-y.second, y.first.from, y.first.to);
  });
  std::vector<std::vector<index_t>> succ(chart_label.size());
  std::vector<std::uint8_t> seen(chart_label.size(), 0);
  std::vector<index_t> stack;
  auto reaches = [&](index_t from, index_t to) {
    std::fill(seen.begin(), seen.end(), std::uint8_t{0});
    stack.assign(1, from);
    seen[to_size(from)] = 1;
    while (!stack.empty()) {
      const index_t x = stack.back();
      stack.pop_back();
      if (x == to) return true;
      for (index_t y : succ[to_size(x)])
        if (!seen[to_size(y)]) {
          seen[to_size(y)] = 1;
          stack.push_back(y);
        }
    }
    return false;
  };
  for (const auto& [o, conf] : cand) {
    (void)conf;
    if (reaches(o.to, o.from)) continue;
    succ[to_size(o.from)].push_back(o.to);
    out.push_back(o);
  }
  std::sort(out.begin(), out.end(), [&](const polycube_plane_order& x, const polycube_plane_order& y) {
    return std::tuple(plane[to_size(x.from)], x.from, x.to) < std::tuple(plane[to_size(y.from)], y.from, y.to);
  });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const polycube_plane_order& x, const polycube_plane_order& y) {
                          return x.from == y.from && x.to == y.to;
                        }),
            out.end());
  return out;
}

/// Integer planes of the charts of one axis from their continuous values `p` (mesh units): each chart
/// plane is rounded to the nearest multiple of the tile, then raised until every order constraint
/// holds (`to` at least one tile above `from`): a polycube edge never collapses below one tile nor
/// turns around. Bellman-Ford rounds, at most one per chart plus one; not_converged naming a chart
/// when the constraints form a cycle (no polycube realizes the labelling's edge directions).
inline result<std::vector<std::int64_t>> quantize_planes(const std::vector<double>& p, const std::vector<int>& axis_of,
                                                         const std::vector<polycube_plane_order>& orders, int axis,
                                                         double tile, index_t* bad_chart = nullptr) {
  const std::size_t nc = p.size();
  std::vector<std::int64_t> q(nc, 0);
  std::size_t n = 0;
  for (std::size_t c = 0; c < nc; ++c)
    if (axis_of[c] == axis) {
      q[c] = std::llround(p[c] / tile);
      ++n;
    }
  for (std::size_t round = 0; round <= n; ++round) {
    index_t changed = -1;
    for (const auto& o : orders)
      if (q[to_size(o.to)] < q[to_size(o.from)] + 1) {
        q[to_size(o.to)] = q[to_size(o.from)] + 1;
        changed = o.to;
      }
    if (changed < 0) return q;
    if (round == n) {
      if (bad_chart) *bad_chart = changed;
      return status::not_converged(cat("polycube: the edges along ", "XYZ"[axis], " around chart ", changed,
                                       " form a cycle of directions: no polycube has these edges"));
    }
  }
  return q;
}

/// Faces whose polycube triangle is not positively oriented in its chart plane.
inline std::vector<index_t> polycube_flipped_faces(const tri_mesh& m, const std::vector<vec3>& pos,
                                                   const std::vector<index_t>& face_chart,
                                                   const std::vector<std::uint8_t>& chart_label, double t) {
  std::vector<index_t> out;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const auto l = chart_label[to_size(face_chart[f])];
    const int a = l / 2, u = l % 2 == 0 ? (a + 1) % 3 : (a + 2) % 3, w = l % 2 == 0 ? (a + 2) % 3 : (a + 1) % 3;
    const vec3 &p0 = pos[to_size(m.faces[f][0])], &p1 = pos[to_size(m.faces[f][1])], &p2 = pos[to_size(m.faces[f][2])];
    const double area = (p1[u] - p0[u]) * (p2[w] - p0[w]) - (p1[w] - p0[w]) * (p2[u] - p0[u]);
    if (!(area > min_chart_area_fraction * t * t)) out.push_back(static_cast<index_t>(f));
  }
  return out;
}

/// Untangling after the final solve: while faces are flipped (at most `iterations` rounds), every free
/// coordinate of the vertices within two rings of a flipped face moves to the mean of its neighbours'
/// (Jacobi steps of a Tutte embedding, which is injective on convex charts). Chart planes never move,
/// nor do the chart-interior vertices marked in `hold` (the cuts of polycube_chart_cuts.hpp).
/// Returns the number of faces still flipped.
inline index_t untangle_polycube(const tri_mesh& m, std::vector<vec3>& pos, const std::vector<index_t>& face_chart,
                                 const std::vector<std::uint8_t>& chart_label,
                                 const std::array<const polycube_axis_classes*, 3>& cl, double t, int iterations,
                                 const std::vector<std::uint8_t>* hold = nullptr) {
  const auto nv = to_size(m.num_vertices());
  std::vector<std::vector<index_t>> ring(nv);
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) ring[to_size(f[to_size(k)])].push_back(f[to_size((k + 1) % 3)]);
  auto is_free = [&](std::size_t v, int a) {
    const auto& c = *cl[to_size(a)];
    return c.class_chart[to_size(c.vertex_class[v])] < 0;
  };
  auto flipped = polycube_flipped_faces(m, pos, face_chart, chart_label, t);
  for (int it = 0; it < iterations && !flipped.empty(); ++it) {
    std::vector<std::uint8_t> mark(nv, 0);
    for (index_t f : flipped)
      for (index_t v : m.faces[to_size(f)]) mark[to_size(v)] = 1;
    for (int grow = 0; grow < 2; ++grow) {
      const auto prev = mark;
      for (std::size_t v = 0; v < nv; ++v)
        if (prev[v])
          for (index_t w : ring[v]) mark[to_size(w)] = 1;
    }
    std::vector<vec3> next = pos;
    for (std::size_t v = 0; v < nv; ++v) {
      if (!mark[v] || (hold && (*hold)[v])) continue;
      int free_axes = 0;
      for (int a = 0; a < 3; ++a) free_axes += is_free(v, a) ? 1 : 0;
      if (free_axes == 0) continue;
      // a vertex on a polycube edge (one free axis) averages over its neighbours on the same edge only:
      // a 1D Tutte map between the edge's corners, so it never passes a corner
      vec3 mean;
      index_t n = 0;
      for (index_t w : ring[v]) {
        bool same = true;
        if (free_axes == 1)
          for (int a = 0; a < 3; ++a)
            if (!is_free(v, a) && cl[to_size(a)]->vertex_class[to_size(w)] != cl[to_size(a)]->vertex_class[v])
              same = false;
        if (same) {
          mean += pos[to_size(w)];
          ++n;
        }
      }
      if (n == 0) continue;
      mean = mean / static_cast<double>(n);
      for (int a = 0; a < 3; ++a)
        if (is_free(v, a)) next[v][a] = mean[a];
    }
    pos.swap(next);
    flipped = polycube_flipped_faces(m, pos, face_chart, chart_label, t);
  }
  return static_cast<index_t>(flipped.size());
}

}  // namespace detail
TESSERA_NAMESPACE_END
