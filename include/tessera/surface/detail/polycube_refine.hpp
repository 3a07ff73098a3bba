// tessera/surface/detail/polycube_refine.hpp: base-mesh refinement for the polycube construction. A
// *chord* is a mesh edge inside one chart whose two end vertices both lie on the boundary between that
// chart and one same other chart: after the deformation both ends sit on one straight polycube edge,
// so the edge and every face between it and the chart boundary collapse onto that line (a face with
// all three vertices on another chart is the smallest case). Such an edge needs a vertex that does not
// exist; splitting it at its midpoint adds one inside the chart (Floater 2003: a convex Tutte map is
// one-to-one when no interior edge joins two vertices of one straight boundary side). Faces are split
// in place and appended, vertices appended: the input's vertices and faces keep their indices (face f
// keeps one half of input face f) and `face_origin` names the input face of every face.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "polycube_charts.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Splits at its midpoint, in place, every edge inside one chart for which `splits_edge(chart, a, b)`
/// holds (u and w: its end vertices, a and b: the charts around them, sorted); `m`, its face adjacency `nb`, the
/// labels, the per-face label costs `data` (halved between the two halves) and `face_origin` (empty on
/// entry: identity) follow. A new vertex lies inside its chart (its charts: that one alone). Returns
/// the number of edges split. O(F + splits).
template <class SplitsEdge>
index_t split_chart_edges(tri_mesh& m, std::vector<std::array<index_t, 3>>& nb, std::vector<std::uint8_t>& lab,
                          std::vector<std::array<double, 6>>& data, std::vector<index_t>& face_origin,
                          SplitsEdge&& splits_edge) {
  const auto cs = find_polycube_charts(m, nb, lab);
  auto vc = cs.vertex_charts;
  std::vector<index_t> chart = cs.face_chart;
  auto chord = [&](std::size_t f, int k) {
    const index_t g = nb[f][to_size(k)];
    if (g < 0 || chart[to_size(g)] != chart[f]) return false;
    const index_t u = m.faces[f][to_size(k)], w = m.faces[f][to_size((k + 1) % 3)];
    return splits_edge(chart[f], u, w, vc[to_size(u)], vc[to_size(w)]);
  };
  index_t splits = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      if (!chord(f, k)) continue;
      if (face_origin.empty())
        for (std::size_t i = 0; i < m.faces.size(); ++i) face_origin.push_back(static_cast<index_t>(i));
      const auto ks = to_size(k), k1 = to_size((k + 1) % 3), k2 = to_size((k + 2) % 3);
      const index_t u = m.faces[f][ks], w = m.faces[f][k1], a = m.faces[f][k2];
      const auto g = to_size(nb[f][ks]);
      std::size_t j = 0;
      while (j < 3 && !(m.faces[g][j] == w && m.faces[g][(j + 1) % 3] == u)) ++j;
      const std::size_t j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const index_t b = m.faces[g][j2];
      const auto mid = static_cast<index_t>(m.positions.size());
      m.positions.push_back(0.5 * (m.position(u) + m.position(w)));
      vc.push_back({chart[f]});
      const auto f2 = static_cast<index_t>(m.faces.size()), g2 = f2 + 1;
      const index_t nf_out = nb[f][k1], ng_out = nb[g][j1];
      // f = (u, mid, a), f2 = (mid, w, a); g = (w, mid, b), g2 = (mid, u, b)
      m.faces[f][k1] = mid;
      m.faces[g][j1] = mid;
      m.faces.push_back({mid, w, a});
      m.faces.push_back({mid, u, b});
      nb[f][ks] = g2;
      nb[f][k1] = f2;
      nb[g][j] = f2;
      nb[g][j1] = g2;
      nb.push_back({static_cast<index_t>(g), nf_out, static_cast<index_t>(f)});
      nb.push_back({static_cast<index_t>(f), ng_out, static_cast<index_t>(g)});
      // the outer faces across (w, a) and (u, b) now border f2 and g2
      auto repoint = [&](index_t h, index_t p, index_t q, index_t to) {  // h's side p -> q
        if (h < 0) return;
        for (std::size_t s = 0; s < 3; ++s)
          if (m.faces[to_size(h)][s] == p && m.faces[to_size(h)][(s + 1) % 3] == q) nb[to_size(h)][s] = to;
      };
      repoint(nf_out, a, w, f2);
      repoint(ng_out, b, u, g2);
      lab.push_back(lab[f]);
      lab.push_back(lab[g]);
      chart.push_back(chart[f]);
      chart.push_back(chart[g]);
      for (auto& x : data[f]) x *= 0.5;
      for (auto& x : data[g]) x *= 0.5;
      data.push_back(data[f]);
      data.push_back(data[g]);
      face_origin.push_back(face_origin[f]);
      face_origin.push_back(face_origin[g]);
      ++splits;
    }
  return splits;
}

/// Splits every chord of the labelling `lab` (see the file comment) at its midpoint (split_chart_edges).
/// A split adds no chord (the new vertex lies inside the chart), so the loop ends after at most as many
/// splits as there were chords.
inline index_t split_chart_chords(tri_mesh& m, std::vector<std::array<index_t, 3>>& nb, std::vector<std::uint8_t>& lab,
                                  std::vector<std::array<double, 6>>& data, std::vector<index_t>& face_origin) {
  return split_chart_edges(
      m, nb, lab, data, face_origin,
      [](index_t c, index_t, index_t, const std::vector<index_t>& a, const std::vector<index_t>& b) {
        if (a.size() < 2 || b.size() < 2) return false;
        for (index_t d : a)
          if (d != c && std::binary_search(b.begin(), b.end(), d)) return true;
        return false;
      });
}

/// Splits every edge inside one of `charts` (sorted) whose two end vertices both lie on the chart's
/// boundary, at its midpoint (split_chart_edges): a chart meshed without interior vertices (a CAD face
/// triangulated between its boundary loops) then has some, connected across it, for the cuts into
/// rectangles (polycube_chart_cuts.hpp) to run along. Returns the number of edges split.
inline index_t split_boundary_spanning_edges(tri_mesh& m, std::vector<std::array<index_t, 3>>& nb,
                                             std::vector<std::uint8_t>& lab, std::vector<std::array<double, 6>>& data,
                                             std::vector<index_t>& face_origin, const std::vector<index_t>& charts) {
  return split_chart_edges(
      m, nb, lab, data, face_origin,
      [&](index_t c, index_t, index_t, const std::vector<index_t>& a, const std::vector<index_t>& b) {
        return a.size() >= 2 && b.size() >= 2 && std::binary_search(charts.begin(), charts.end(), c);
      });
}

/// Splits the edges `edges` (each {smaller, larger} end vertex, sorted) that lie inside one chart, at
/// their midpoints (split_chart_edges). Returns the number of edges split.
inline index_t split_listed_edges(tri_mesh& m, std::vector<std::array<index_t, 3>>& nb, std::vector<std::uint8_t>& lab,
                                  std::vector<std::array<double, 6>>& data, std::vector<index_t>& face_origin,
                                  const std::vector<std::array<index_t, 2>>& edges) {
  if (edges.empty()) return 0;
  return split_chart_edges(
      m, nb, lab, data, face_origin,
      [&](index_t, index_t u, index_t w, const std::vector<index_t>&, const std::vector<index_t>&) {
        return std::binary_search(edges.begin(), edges.end(), std::array<index_t, 2>{std::min(u, w), std::max(u, w)});
      });
}

}  // namespace detail
TESSERA_NAMESPACE_END
