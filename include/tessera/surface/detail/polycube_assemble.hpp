// tessera/surface/detail/polycube_assemble.hpp: from a base mesh, a labelling and polycube positions to
// a verified polycube_map: charts and their integer planes, every face flat in its chart plane and
// positively oriented there (no flipped face) and not squeezed below min_area_ratio of its share of
// the area (no degenerate map), corners on the tile grid, polycube edges of at least one
// tile, no self-intersection of the polycube surface, and a closed quad layout. Any failure is a status
// naming the face, chart, corner or edge; a map is returned only when everything holds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/executor.hpp"
#include "../../core/mesh_topology.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../geometry/bvh.hpp"
#include "../polycube_map.hpp"
#include "../quad_layout.hpp"
#include "polycube_charts.hpp"
#include "tolerances.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// A vertex farther than this fraction of tile_size from its chart's plane makes the chart not flat.
inline constexpr double chart_flatness_fraction = 1e-7;

/// Verifies and assembles the map (see the file comment). `min_area_ratio` is the degeneracy bound: a
/// face whose normalized area ratio r = (its chart-plane area / the polycube's area) / (its base area /
/// the base's area) is below it counts as collapsed, and the map is refused naming the chart; those
/// faces are written to `collapsed` when given (for the relabel rounds).
template <Executor E>
result<polycube_map> assemble_polycube_map(tri_mesh base, const std::vector<std::uint8_t>& lab,
                                           std::vector<vec3> positions, double t, double min_area_ratio, E& exec,
                                           std::vector<index_t>* collapsed = nullptr) {
  const auto adj = face_adjacency(base);
  const auto cs = find_polycube_charts(base, adj.neighbor, lab);
  const index_t nf = base.num_faces(), nv = base.num_vertices();
  const double tol = chart_flatness_fraction * t;
  polycube_map pm;
  pm.tile_size = t;
  pm.charts.resize(cs.chart_label.size());
  for (std::size_t c = 0; c < pm.charts.size(); ++c)
    pm.charts[c].label = static_cast<polycube_label>(cs.chart_label[c]);
  for (index_t f = 0; f < nf; ++f) {
    auto& ch = pm.charts[to_size(cs.face_chart[to_size(f)])];
    if (ch.faces.empty())
      ch.plane = std::llround(positions[to_size(base.faces[to_size(f)][0])][label_axis(ch.label)] / t);
    ch.faces.push_back(f);
  }
  // flatness, then orientation (in parallel; first offender by smallest face)
  std::vector<std::int8_t> bad(to_size(nf), 0);
  std::vector<double> area_base(to_size(nf)), area_chart(to_size(nf));
  exec.parallel_for(0, nf, [&](index_t f) {
    const auto& ch = pm.charts[to_size(cs.face_chart[to_size(f)])];
    const int a = label_axis(ch.label);
    const auto ax = quad_plane_axes(ch.label);
    std::array<vec2, 3> q;
    for (int k = 0; k < 3; ++k) {
      const vec3& p = positions[to_size(base.faces[to_size(f)][to_size(k)])];
      if (!(std::abs(p[a] - static_cast<double>(ch.plane) * t) <= tol)) bad[to_size(f)] = 1;
      q[to_size(k)] = {p[ax[0]], p[ax[1]]};
    }
    const double a2 = cross(q[1] - q[0], q[2] - q[0]);
    if (bad[to_size(f)] == 0 && !(a2 > min_chart_area_fraction * t * t)) bad[to_size(f)] = 2;
    const auto& fv = base.faces[to_size(f)];
    area_base[to_size(f)] =
        norm(cross(base.position(fv[1]) - base.position(fv[0]), base.position(fv[2]) - base.position(fv[0])));
    area_chart[to_size(f)] = a2;
  });
  index_t flipped = 0, first_flip = -1;
  for (index_t f = 0; f < nf; ++f) {
    if (bad[to_size(f)] == 1)
      return status::not_converged(
          cat("polycube: face ", f, " is not flat in the plane of its chart ", cs.face_chart[to_size(f)], " (",
              "XYZ"[label_axis(pm.charts[to_size(cs.face_chart[to_size(f)])].label)], " = ",
              static_cast<double>(pm.charts[to_size(cs.face_chart[to_size(f)])].plane) * t, ")"));
    if (bad[to_size(f)] == 2 && flipped++ == 0) first_flip = f;
  }
  if (flipped > 0)
    return status::not_converged(cat("polycube: ", flipped,
                                     " faces are flipped or collapsed in their chart plane (first: face ", first_flip,
                                     " in chart ", cs.face_chart[to_size(first_flip)], ")"));
  // degeneracy: faces squeezed far below their share of the area (summed serially: deterministic)
  {
    double tb = 0, tp = 0;
    for (index_t f = 0; f < nf; ++f) {
      tb += area_base[to_size(f)];
      tp += area_chart[to_size(f)];
    }
    index_t n_small = 0, worst = -1;
    double worst_r = 0;
    for (index_t f = 0; f < nf; ++f) {
      const double r = (area_chart[to_size(f)] / tp) / (area_base[to_size(f)] / tb);
      if (!(r >= min_area_ratio)) {
        ++n_small;
        if (collapsed) collapsed->push_back(f);
        if (worst < 0 || r < worst_r) {
          worst = f;
          worst_r = r;
        }
      }
    }
    if (n_small > 0)
      return status::not_converged(cat("polycube: degenerate map: ", n_small, " faces keep less than min_area_ratio = ",
                                       min_area_ratio, " of their share of the area (worst: face ", worst, " in chart ",
                                       cs.face_chart[to_size(worst)], ", ratio ", worst_r, ")"));
  }
  // corners on the grid
  std::map<grid_point, index_t> corner_at;
  for (index_t v = 0; v < nv; ++v) {
    const auto& vc = cs.vertex_charts[to_size(v)];
    if (vc.size() < 3) continue;
    polycube_corner c;
    c.vertex = v;
    c.charts = vc;
    for (int a = 0; a < 3; ++a) {
      const double x = positions[to_size(v)][a] / t;
      c.grid[to_size(a)] = std::llround(x);
      if (!(std::abs(x - static_cast<double>(c.grid[to_size(a)])) * t <= tol))
        return status::not_converged(cat("polycube: corner at vertex ", v, " is off the tile grid along ", "XYZ"[a]));
    }
    if (!corner_at.emplace(c.grid, static_cast<index_t>(pm.corners.size())).second)
      return status::not_converged(cat("polycube: corners at vertices ", pm.corners[to_size(corner_at[c.grid])].vertex,
                                       " and ", v, " coincide: the polycube touches itself"));
    pm.corners.push_back(std::move(c));
  }
  // polycube edges: boundary mesh edges between two charts, grouped by chart pair and line, merged into
  // segments and split at the corners on them
  std::map<std::tuple<index_t, index_t, std::int64_t, std::int64_t>, std::vector<std::array<double, 2>>> runs;
  for (index_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const index_t g = adj.neighbor[to_size(f)][to_size(k)];
      const index_t ca = cs.face_chart[to_size(f)], cb = cs.face_chart[to_size(g)];
      if (ca >= cb) continue;
      const int aa = cs.chart_label[to_size(ca)] / 2, ab = cs.chart_label[to_size(cb)] / 2;
      const int axis = 3 - aa - ab;
      const vec3& p = positions[to_size(base.faces[to_size(f)][to_size(k)])];
      const vec3& q = positions[to_size(base.faces[to_size(f)][to_size((k + 1) % 3)])];
      runs[{ca, cb, pm.charts[to_size(ca)].plane, pm.charts[to_size(cb)].plane}].push_back(
          {std::min(p[axis], q[axis]) / t, std::max(p[axis], q[axis]) / t});
    }
  for (auto& [key, iv] : runs) {
    const auto [ca, cb, pa, pb] = key;
    const int aa = cs.chart_label[to_size(ca)] / 2, ab = cs.chart_label[to_size(cb)] / 2;
    const int axis = 3 - aa - ab;
    std::sort(iv.begin(), iv.end());
    for (std::size_t i = 0; i < iv.size();) {
      double lo = iv[i][0], hi = iv[i][1];
      std::size_t j = i + 1;
      while (j < iv.size() && iv[j][0] <= hi + tile_grid_rounding) {
        hi = std::max(hi, iv[j][1]);
        ++j;
      }
      i = j;
      grid_point g{};
      g[to_size(aa)] = pa;
      g[to_size(ab)] = pb;
      std::vector<index_t> on;
      for (auto x = static_cast<std::int64_t>(std::llround(lo)); x <= std::llround(hi); ++x) {
        g[to_size(axis)] = x;
        if (auto it = corner_at.find(g); it != corner_at.end()) on.push_back(it->second);
      }
      if (on.size() < 2 || pm.corners[to_size(on.front())].grid[to_size(axis)] != std::llround(lo) ||
          pm.corners[to_size(on.back())].grid[to_size(axis)] != std::llround(hi))
        return status::not_converged(cat("polycube: the boundary between charts ", ca, " and ", cb,
                                         " does not run from corner to corner (collapsed polycube edge)"));
      for (std::size_t k = 0; k + 1 < on.size(); ++k) {
        const auto len =
            pm.corners[to_size(on[k + 1])].grid[to_size(axis)] - pm.corners[to_size(on[k])].grid[to_size(axis)];
        pm.edges.push_back({ca, cb, axis, on[k], on[k + 1], len});
      }
    }
  }
  // no self-intersection: faces that share no vertex must not touch
  pm.base = std::move(base);
  pm.polycube = std::move(positions);
  {
    const triangle_bvh bvh(pm.deformed_mesh());
    index_t fa = -1, fb = -1;
    bvh.for_each_self_intersection(
        [&](index_t f, index_t g) {
          for (index_t u : pm.base.faces[to_size(f)])
            for (index_t w : pm.base.faces[to_size(g)])
              if (u == w) return true;
          return false;
        },
        [&](index_t f, index_t g) {
          if (fa < 0 || f < fa || (f == fa && g < fb)) {
            fa = f;
            fb = g;
          }
        });
    if (fa >= 0)
      return status::not_converged(cat("polycube: the surface intersects itself (faces ", fa, " and ", fb, ", charts ",
                                       cs.face_chart[to_size(fa)], " and ", cs.face_chart[to_size(fb)], ")"));
  }
  pm.labels.resize(lab.size());
  for (std::size_t f = 0; f < lab.size(); ++f) pm.labels[f] = static_cast<polycube_label>(lab[f]);
  pm.face_chart = cs.face_chart;
  auto layout = build_quad_layout(pm);
  if (!layout) return layout.error();
  pm.layout = std::move(*layout);
  return pm;
}

}  // namespace detail
TESSERA_NAMESPACE_END
