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
#include <map>
#include <utility>
#include <numeric>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../polycube_map.hpp"
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
                                                      const std::vector<std::uint8_t>& chart_label, int axis) {
  const index_t nv = m.num_vertices();
  const auto nc = static_cast<index_t>(chart_label.size());
  std::vector<index_t> parent(to_size(nv + nc));
  std::iota(parent.begin(), parent.end(), index_t{0});
  auto find = [&](index_t x) {
    while (parent[to_size(x)] != x) x = parent[to_size(x)] = parent[to_size(parent[to_size(x)])];
    return x;
  };
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
    if (root_chart[r] >= 0 && root_chart[r] != c) {
      index_t shared = 0;
      while (shared < nv && to_size(find(shared)) != r) ++shared;
      return status::not_converged(cat("polycube: charts ", root_chart[r], " and ", c, " of axis ", "XYZ"[axis],
                                       " are joined through vertex ", shared, ": their planes would coincide"));
    }
    root_chart[r] = c;
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

/// Pairs of charts whose planes must stay at least one tile apart: on the boundary between two
/// adjacent charts C and D (axes a and b), the charts of the third axis met at its corners bound the
/// polycube edges there, so any two of them must not share a plane. Returns each chart's partners.
inline std::vector<std::vector<index_t>> polycube_plane_partners(const std::vector<std::vector<index_t>>& vertex_charts,
                                                                 const std::vector<std::uint8_t>& chart_label) {
  std::map<std::pair<index_t, index_t>, std::vector<index_t>> on_boundary;
  for (const auto& vc : vertex_charts) {
    if (vc.size() < 3) continue;
    for (index_t c : vc)
      for (index_t d : vc) {
        const int a = chart_label[to_size(c)] / 2, b = chart_label[to_size(d)] / 2;
        if (c >= d || a == b) continue;
        for (index_t e : vc)
          if (chart_label[to_size(e)] / 2 == 3 - a - b) on_boundary[{c, d}].push_back(e);
      }
  }
  std::vector<std::vector<index_t>> partners(chart_label.size());
  for (auto& [cd, es] : on_boundary)
    for (index_t e : es)
      for (index_t g : es)
        if (e != g) partners[to_size(e)].push_back(g);
  for (auto& p : partners) {
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
  }
  return partners;
}

/// Integer planes of the charts of one axis from their continuous values `p` (mesh units): each chart
/// plane is rounded to the nearest multiple of the tile, then, in order of p (ties: chart index),
/// raised to at least one tile above each of its partners (polycube_plane_partners) placed before it:
/// a polycube edge never collapses below one tile.
inline std::vector<std::int64_t> quantize_planes(const std::vector<double>& p, const std::vector<int>& axis_of,
                                                 const std::vector<std::vector<index_t>>& partners, int axis,
                                                 double tile) {
  const std::size_t nc = p.size();
  std::vector<index_t> order;
  for (std::size_t c = 0; c < nc; ++c)
    if (axis_of[c] == axis) order.push_back(static_cast<index_t>(c));
  std::stable_sort(order.begin(), order.end(), [&](index_t a, index_t b) { return p[to_size(a)] < p[to_size(b)]; });
  std::vector<std::int64_t> q(nc, 0);
  std::vector<bool> done(nc, false);
  for (index_t c : order) {
    const auto cs = to_size(c);
    std::int64_t v = std::llround(p[cs] / tile);
    for (index_t d : partners[cs])
      if (done[to_size(d)]) v = std::max(v, q[to_size(d)] + 1);
    q[cs] = v;
    done[cs] = true;
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
/// (Jacobi steps of a Tutte embedding, which is injective on convex charts). Chart planes never move.
/// Returns the number of faces still flipped.
inline index_t untangle_polycube(const tri_mesh& m, std::vector<vec3>& pos, const std::vector<index_t>& face_chart,
                                 const std::vector<std::uint8_t>& chart_label,
                                 const std::array<const polycube_axis_classes*, 3>& cl, double t, int iterations) {
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
      if (!mark[v]) continue;
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
