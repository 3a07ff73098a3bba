// tessera/surface/detail/polycube_embed.hpp: the final placement of a polycube once its chart planes are
// on the tile grid. Corners are fixed by their three planes. The vertices of each polycube edge (the
// boundary path between two corners) are spread along it by the arc length of the base mesh's path, so
// they stay in order between the corners. Non-convex charts are cut into rectangles
// (polycube_chart_cuts.hpp). The interior vertices of every chart then solve a Tutte-style system (each
// free coordinate the weighted mean of its neighbours', clamped positive cotangent weights of the base
// mesh, Floater 1997 / Tutte 1963), which is injective inside convex pieces.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "polycube_chart_cuts.hpp"
#include "polycube_charts.hpp"
#include "polycube_deform.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Cotangent weights of the embedding are clamped to [embed_min_weight, embed_max_weight], so
/// obtuse or degenerate faces cannot make the system indefinite or ill-conditioned.
inline constexpr double embed_min_weight = 1e-2;
inline constexpr double embed_max_weight = 1e2;

/// Places edge and interior vertices (see the file comment); `pos` holds the planes' coordinates on
/// entry (from polycube_axis_solve with fixed planes) and is updated in place. `cut_vertices`, when
/// given, receives a mark per vertex on a cut (held by the untangling); `uncut`, what the cuts could
/// not do (cut_charts_into_rectangles).
template <class Dep>
status embed_polycube(const tri_mesh& m, const polycube_chart_set& cs, const std::array<polycube_axis_classes, 3>& cl,
                      const std::vector<polycube_edge_path>& paths,
                      const std::vector<std::vector<std::vector<chart_loop_side>>>& loops, double t, bool cut_charts,
                      std::vector<vec3>& pos, std::vector<std::uint8_t>* cut_vertices = nullptr,
                      polycube_uncut* uncut = nullptr) {
  using real = dependent_t<double, Dep>;
  using sparse = Eigen::SparseMatrix<real>;
  using vector = Eigen::Matrix<real, Eigen::Dynamic, 1>;
  const auto nv = to_size(m.num_vertices());
  auto is_free = [&](std::size_t v, int a) {
    const auto& c = cl[to_size(a)];
    return c.class_chart[to_size(c.vertex_class[v])] < 0;
  };
  // edge weights: clamped cotangents of the base mesh, per directed neighbour list
  std::vector<std::vector<std::pair<index_t, double>>> nbr(nv);
  auto add = [&](index_t i, index_t j, double w) {
    auto& l = nbr[to_size(i)];
    for (auto& e : l)
      if (e.first == j) {
        e.second += w;
        return;
      }
    l.push_back({j, w});
  };
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const index_t o = f[to_size(k)], i = f[to_size((k + 1) % 3)], j = f[to_size((k + 2) % 3)];
      const vec3 a = m.position(i) - m.position(o), b = m.position(j) - m.position(o);
      const double s = norm(cross(a, b));
      const double cot = s > 0 ? dot(a, b) / s : 0;
      add(i, j, 0.5 * cot);
      add(j, i, 0.5 * cot);
    }
  for (auto& l : nbr)
    for (auto& e : l) e.second = std::clamp(e.second, embed_min_weight, embed_max_weight);
  // 1) polycube edges: each path spread by arc length between its corners
  polycube_path_pins pp;
  pp.arc.resize(paths.size());
  pp.pins.resize(paths.size());
  std::vector<std::uint8_t> fixed(nv, 0);
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const auto& pv = paths[i].vertices;
    auto& s = pp.arc[i];
    s.assign(pv.size(), 0.0);
    for (std::size_t k = 1; k < pv.size(); ++k) s[k] = s[k - 1] + distance(m.position(pv[k]), m.position(pv[k - 1]));
    for (auto& x : s) x = s.back() > 0 ? x / s.back() : 0.0;
    spread_path(paths[i], pp, i, pos, is_free);
    for (index_t v : pv) fixed[to_size(v)] = 1;
  }
  // 1b) non-convex charts cut into rectangles (polycube_chart_cuts.hpp)
  if (cut_charts) {
    std::vector<std::vector<index_t>> ring(nv);
    for (std::size_t v = 0; v < nv; ++v)
      for (const auto& e : nbr[v]) ring[v].push_back(e.first);
    cut_charts_into_rectangles(m, cs, paths, loops, ring, t, pp, pos, fixed, is_free, uncut);
  }
  if (cut_vertices) {
    cut_vertices->assign(nv, 0);
    for (std::size_t v = 0; v < nv; ++v) (*cut_vertices)[v] = fixed[v] && cs.vertex_charts[v].size() == 1 ? 1 : 0;
  }
  // 2) chart interiors: per axis, the free coordinates of interior vertices
  for (int a = 0; a < 3; ++a) {
    std::vector<int> col(nv, -1);
    int n = 0;
    for (std::size_t v = 0; v < nv; ++v)
      if (cs.vertex_charts[v].size() == 1 && is_free(v, a) && !fixed[v]) col[v] = n++;
    if (n == 0) continue;
    std::vector<Eigen::Triplet<real>> t;
    vector rhs = vector::Zero(n);
    for (std::size_t v = 0; v < nv; ++v) {
      if (col[v] < 0) continue;
      double sum = 0;
      for (const auto& [u, w] : nbr[v]) {
        sum += w;
        const int cu = col[to_size(u)];
        if (cu >= 0)
          t.emplace_back(col[v], cu, -w);
        else
          rhs[col[v]] += w * pos[to_size(u)][a];
      }
      t.emplace_back(col[v], col[v], sum);
    }
    sparse A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    // symmetric only for symmetric weights: they are (the sum over both sides of each edge)
    Eigen::SimplicialLDLT<sparse> solver(A);
    if (solver.info() != Eigen::Success)
      return status::internal_error("polycube: chart embedding factorisation failed");
    const vector x = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !x.allFinite())
      return status::internal_error("polycube: chart embedding solve failed");
    for (std::size_t v = 0; v < nv; ++v)
      if (col[v] >= 0) pos[v][a] = x[col[v]];
  }
  return {};
}

}  // namespace detail
TESSERA_NAMESPACE_END
