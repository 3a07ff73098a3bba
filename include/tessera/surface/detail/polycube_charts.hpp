// tessera/surface/detail/polycube_charts.hpp: charts of a face labelling (connected faces of one label),
// their validity as polycube faces (no two adjacent charts with opposite labels, every chart of genus 0
// and not an island inside one other chart, at least four corners per chart, valence-3 corners with
// three different axes) and the bounded repair loop that relabels charts until the labelling is valid.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

struct polycube_chart_set {
  std::vector<index_t> face_chart;
  std::vector<std::uint8_t> chart_label;
  std::vector<index_t> chart_size;
  std::vector<std::vector<index_t>> chart_neighbors;  ///< ascending
  std::vector<std::vector<index_t>> vertex_charts;    ///< ascending, per vertex
};

/// Charts by flood fill over face adjacency, numbered in order of their smallest face.
inline polycube_chart_set find_polycube_charts(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                               const std::vector<std::uint8_t>& lab) {
  polycube_chart_set cs;
  const auto nf = to_size(m.num_faces());
  cs.face_chart.assign(nf, -1);
  std::vector<index_t> stack;
  for (std::size_t f0 = 0; f0 < nf; ++f0) {
    if (cs.face_chart[f0] >= 0) continue;
    const auto c = static_cast<index_t>(cs.chart_label.size());
    cs.chart_label.push_back(lab[f0]);
    cs.chart_size.push_back(0);
    cs.face_chart[f0] = c;
    stack.assign(1, static_cast<index_t>(f0));
    while (!stack.empty()) {
      const auto f = to_size(stack.back());
      stack.pop_back();
      ++cs.chart_size[to_size(c)];
      for (index_t g : nb[f])
        if (g >= 0 && cs.face_chart[to_size(g)] < 0 && lab[to_size(g)] == lab[f]) {
          cs.face_chart[to_size(g)] = c;
          stack.push_back(g);
        }
    }
  }
  cs.chart_neighbors.resize(cs.chart_label.size());
  cs.vertex_charts.resize(to_size(m.num_vertices()));
  for (std::size_t f = 0; f < nf; ++f) {
    const index_t c = cs.face_chart[f];
    for (int k = 0; k < 3; ++k) {
      const index_t g = nb[f][to_size(k)];
      if (g >= 0 && cs.face_chart[to_size(g)] != c) cs.chart_neighbors[to_size(c)].push_back(cs.face_chart[to_size(g)]);
      cs.vertex_charts[to_size(m.faces[f][to_size(k)])].push_back(c);
    }
  }
  auto uniq = [](std::vector<index_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  for (auto& v : cs.chart_neighbors) uniq(v);
  for (auto& v : cs.vertex_charts) uniq(v);
  return cs;
}

/// One polycube edge of a labelling: the boundary path between charts c < d from corner to corner
/// (vertices with at least three charts), in the orientation of chart c's faces.
struct polycube_edge_path {
  index_t c = -1, d = -1;
  std::vector<index_t> vertices;  ///< front and back are corners
  double convexity = 0;           ///< > 0: the base mesh bends outwards along the path (summed over its edges)
};

/// Every polycube edge of a labelling, in order of its first corner, then of its first half-edge's face
/// and side. Boundary loops without a corner are left out (find_label_problem names them). O(F).
inline std::vector<polycube_edge_path> find_polycube_edge_paths(const tri_mesh& m,
                                                                const std::vector<std::array<index_t, 3>>& nb,
                                                                const polycube_chart_set& cs) {
  struct half {
    index_t to, c, d;
    double bend;  // how far the face across lies below this face's plane (> 0: convex edge)
  };
  const auto nv = to_size(m.num_vertices());
  std::vector<std::vector<half>> out(nv);
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const index_t g = nb[f][to_size(k)];
      if (g < 0) continue;
      const index_t c = cs.face_chart[f], d = cs.face_chart[to_size(g)];
      if (c >= d) continue;
      const index_t u = m.faces[f][to_size(k)];
      index_t w = -1;  // the vertex of face g across the edge
      for (index_t x : m.faces[to_size(g)])
        if (x != u && x != m.faces[f][to_size((k + 1) % 3)]) w = x;
      const double bend = -dot(normalized(face_area_normal(m, static_cast<index_t>(f))), m.position(w) - m.position(u));
      out[to_size(u)].push_back({m.faces[f][to_size((k + 1) % 3)], c, d, bend});
    }
  auto corner = [&](index_t v) { return cs.vertex_charts[to_size(v)].size() >= 3; };
  std::vector<polycube_edge_path> paths;
  for (std::size_t u = 0; u < nv; ++u) {
    if (!corner(static_cast<index_t>(u))) continue;
    for (const half& h0 : out[u]) {
      polycube_edge_path p{h0.c, h0.d, {static_cast<index_t>(u), h0.to}, h0.bend};
      for (std::size_t guard = 0; guard < nv && !corner(p.vertices.back()); ++guard) {
        const half* next = nullptr;
        for (const half& h : out[to_size(p.vertices.back())])
          if (h.c == h0.c && h.d == h0.d) next = &h;
        if (!next) break;
        p.vertices.push_back(next->to);
        p.convexity += next->bend;
      }
      if (corner(p.vertices.back())) paths.push_back(std::move(p));
    }
  }
  return paths;
}

/// Euler characteristic V - E + F of each chart's faces.
inline std::vector<index_t> chart_euler(const tri_mesh&, const std::vector<std::array<index_t, 3>>& nb,
                                        const polycube_chart_set& cs) {
  const std::size_t nc = cs.chart_label.size();
  std::vector<index_t> chi(nc, 0);
  for (std::size_t f = 0; f < cs.face_chart.size(); ++f) {
    const auto c = to_size(cs.face_chart[f]);
    chi[c] += 1;  // F
    for (int k = 0; k < 3; ++k) {
      const index_t g = nb[f][to_size(k)];
      // an edge counts once: from its smaller face when both are in the chart
      if (g < 0 || cs.face_chart[to_size(g)] != cs.face_chart[f] || g > static_cast<index_t>(f)) chi[c] -= 1;
    }
  }
  for (std::size_t v = 0; v < cs.vertex_charts.size(); ++v)
    for (index_t c : cs.vertex_charts[v]) chi[to_size(c)] += 1;
  return chi;
}

/// What is wrong with a labelling (first problem found, in a fixed order), or kind none.
struct polycube_label_problem {
  enum kind_t { none, opposite, genus, island, few_corners, corner_axes, pinned_face } kind = none;
  index_t chart = -1, other = -1, vertex = -1;
  [[nodiscard]] status to_status() const {
    switch (kind) {
      case none: return {};
      case opposite:
        return status::not_converged(cat("polycube: charts ", chart, " and ", other,
                                         " are adjacent with opposite labels (their planes would coincide)"));
      case genus: return status::not_converged(cat("polycube: chart ", chart, " has a handle (genus > 0): not planar"));
      case island:
        return status::not_converged(cat("polycube: chart ", chart, " is an island inside chart ", other,
                                         " (its boundary has no polycube corner)"));
      case few_corners:
        return status::not_converged(
            cat("polycube: chart ", chart, " has ", other, " corners; a polycube face needs at least 4"));
      case pinned_face:
        return status::not_converged(cat("polycube: face ", vertex, " of chart ", chart,
                                         " has all three vertices on chart ", other, ": it would collapse"));
      case corner_axes:
        return status::not_converged(
            cat("polycube: corner at vertex ", vertex, " joins 3 charts but not 3 different axes (chart ", chart, ")"));
    }
    return {};
  }
};

inline polycube_label_problem find_label_problem(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                                 const polycube_chart_set& cs) {
  const std::size_t nc = cs.chart_label.size();
  polycube_label_problem p;
  // candidates are visited by ascending chart size, then index: repairs touch the smallest charts first
  std::vector<index_t> order(nc);
  std::iota(order.begin(), order.end(), index_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](index_t a, index_t b) { return cs.chart_size[to_size(a)] < cs.chart_size[to_size(b)]; });
  for (index_t c : order)
    for (index_t d : cs.chart_neighbors[to_size(c)])
      if ((cs.chart_label[to_size(c)] ^ 1) == cs.chart_label[to_size(d)])
        return {polycube_label_problem::opposite, c, d, -1};
  // a face whose three vertices all lie on one other chart would collapse onto that chart's plane
  for (std::size_t f = 0; f < cs.face_chart.size(); ++f) {
    const index_t c = cs.face_chart[f];
    for (index_t d : cs.vertex_charts[to_size(m.faces[f][0])]) {
      if (d == c) continue;
      bool all = true;
      for (int k = 1; k < 3 && all; ++k) {
        const auto& vc = cs.vertex_charts[to_size(m.faces[f][to_size(k)])];
        all = std::binary_search(vc.begin(), vc.end(), d);
      }
      if (all) return {polycube_label_problem::pinned_face, c, d, static_cast<index_t>(f)};
    }
  }
  for (index_t c : order)
    if (cs.chart_neighbors[to_size(c)].size() == 1 && nc > 1)
      return {polycube_label_problem::island, c, cs.chart_neighbors[to_size(c)][0], -1};
  const auto chi = chart_euler(m, nb, cs);
  // boundary loops per chart are not counted directly: chi = 2 - 2g - b, and b >= 1, so chi > 1 never
  // happens and g > 0 shows as chi <= 2 - 2 - b. A chart of genus 0 has chi = 2 - b, where b is at most
  // the number of its boundary components; count those through its boundary vertices' loops below.
  std::vector<index_t> corners(nc, 0), loops(nc, 0);
  for (std::size_t v = 0; v < cs.vertex_charts.size(); ++v)
    if (cs.vertex_charts[v].size() >= 3)
      for (index_t c : cs.vertex_charts[v]) ++corners[to_size(c)];
  // boundary loops: count boundary edges and boundary vertices per chart; on a chart whose boundary
  // vertices are all visited once, b = number of cycles = components of the boundary graph
  {
    std::vector<index_t> parent(cs.vertex_charts.size());
    std::iota(parent.begin(), parent.end(), index_t{0});
    auto find = [&](index_t x) {
      while (parent[to_size(x)] != x) x = parent[to_size(x)] = parent[to_size(parent[to_size(x)])];
      return x;
    };
    // per chart, union the boundary edge endpoints; loops = distinct roots among its boundary vertices.
    // A vertex on several charts' boundaries would merge different charts' loops, so do it chart by chart.
    std::vector<std::vector<std::array<index_t, 2>>> bedges(nc);
    for (std::size_t f = 0; f < cs.face_chart.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const index_t g = nb[f][to_size(k)];
        if (g >= 0 && cs.face_chart[to_size(g)] != cs.face_chart[f])
          bedges[to_size(cs.face_chart[f])].push_back({m.faces[f][to_size(k)], m.faces[f][to_size((k + 1) % 3)]});
      }
    for (std::size_t c = 0; c < nc; ++c) {
      for (const auto& e : bedges[c]) {
        parent[to_size(e[0])] = e[0];
        parent[to_size(e[1])] = e[1];
      }
      for (const auto& e : bedges[c]) {
        const index_t a = find(e[0]), b = find(e[1]);
        if (a != b) parent[to_size(std::max(a, b))] = std::min(a, b);
      }
      std::vector<index_t> roots;
      for (const auto& e : bedges[c]) roots.push_back(find(e[0]));
      std::sort(roots.begin(), roots.end());
      loops[c] = static_cast<index_t>(std::unique(roots.begin(), roots.end()) - roots.begin());
    }
  }
  for (index_t c : order) {
    const auto cs_ = to_size(c);
    if (nc > 1 && chi[cs_] != 2 - loops[cs_]) return {polycube_label_problem::genus, c, -1, -1};
  }
  for (index_t c : order)
    if (nc > 1 && corners[to_size(c)] < 4) return {polycube_label_problem::few_corners, c, corners[to_size(c)], -1};
  for (std::size_t v = 0; v < cs.vertex_charts.size(); ++v) {
    const auto& vc = cs.vertex_charts[v];
    if (vc.size() != 3) continue;
    std::array<int, 3> axes{};
    for (int i = 0; i < 3; ++i) axes[to_size(i)] = cs.chart_label[to_size(vc[to_size(i)])] / 2;
    std::sort(axes.begin(), axes.end());
    if (axes[0] == axes[1] || axes[1] == axes[2])
      return {polycube_label_problem::corner_axes, vc[0], -1, static_cast<index_t>(v)};
  }
  return p;
}

/// Relabels all faces of chart c to the label minimizing their summed fidelity cost among the labels
/// of its neighbour charts that are neither its own nor opposite to any neighbour it would touch
/// (ties: smallest label). Falls back to the best label of another axis.
inline void relabel_chart(const polycube_chart_set& cs, index_t c, const std::vector<std::array<double, 6>>& data,
                          std::vector<std::uint8_t>& lab, bool to_neighbor_only) {
  const auto cs_ = to_size(c);
  const int own = cs.chart_label[cs_];
  std::array<bool, 6> allowed{};
  for (index_t d : cs.chart_neighbors[cs_]) allowed[cs.chart_label[to_size(d)]] = true;
  std::array<bool, 6> forbidden{};
  forbidden[to_size(own)] = true;
  for (index_t d : cs.chart_neighbors[cs_]) forbidden[to_size(cs.chart_label[to_size(d)] ^ 1)] = true;
  std::array<double, 6> cost{};
  for (std::size_t f = 0; f < lab.size(); ++f)
    if (cs.face_chart[f] == c)
      for (std::size_t l = 0; l < 6; ++l) cost[l] += data[f][l];
  int best = -1;
  for (int pass = 0; pass < 3 && best < 0; ++pass)
    for (int l = 0; l < 6; ++l) {
      const auto ls = to_size(l);
      if (l == own) continue;
      if (pass == 0 && (!allowed[ls] || forbidden[ls])) continue;
      if (pass == 1 && (to_neighbor_only ? !allowed[ls] : forbidden[ls])) continue;
      if (best < 0 || cost[ls] < cost[to_size(best)]) best = l;
    }
  for (std::size_t f = 0; f < lab.size(); ++f)
    if (cs.face_chart[f] == c) lab[f] = static_cast<std::uint8_t>(best);
}

/// Flip-driven relabelling: each of `faces` (folded in the deformation) that borders another chart
/// takes the label of a neighbouring face of another chart with the smallest fidelity cost that is not
/// opposite to any of its neighbours' labels; its old label then costs `tabu` more. Decisions read
/// the labels before the call (order-independent). Returns whether a label changed.
inline bool relabel_folded_faces(const std::vector<std::array<index_t, 3>>& nb, const std::vector<index_t>& faces,
                                 double tabu, std::vector<std::array<double, 6>>& data,
                                 std::vector<std::uint8_t>& lab) {
  const auto old = lab;
  bool changed = false;
  for (index_t f : faces) {
    const auto fs = to_size(f);
    int best = -1;
    for (index_t g : nb[fs]) {
      if (g < 0) continue;
      const int l = old[to_size(g)];
      if (l == old[fs]) continue;
      bool opposite = false;
      for (index_t h : nb[fs])
        if (h >= 0 && (old[to_size(h)] ^ 1) == l) opposite = true;
      if (!opposite && (best < 0 || data[fs][to_size(l)] < data[fs][to_size(best)])) best = l;
    }
    if (best < 0) continue;
    data[fs][old[fs]] += tabu;
    lab[fs] = static_cast<std::uint8_t>(best);
    changed = true;
  }
  return changed;
}

/// `faces` and every face within `rings` steps of them across edges, ascending.
inline std::vector<index_t> grow_face_region(const std::vector<std::array<index_t, 3>>& nb,
                                             const std::vector<index_t>& faces, std::size_t rings) {
  std::vector<std::uint8_t> in(nb.size(), 0);
  std::vector<index_t> out = faces, front = faces;
  for (index_t f : faces) in[to_size(f)] = 1;
  for (std::size_t k = 0; k < rings; ++k) {
    std::vector<index_t> next;
    for (index_t f : front)
      for (index_t g : nb[to_size(f)])
        if (g >= 0 && !in[to_size(g)]) {
          in[to_size(g)] = 1;
          next.push_back(g);
        }
    out.insert(out.end(), next.begin(), next.end());
    front.swap(next);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The repair loop: while a problem remains and fewer than max_iterations steps ran, relabel the
/// chart it names (an island takes its surrounding chart's label). Returns the last problem (kind none
/// when the labelling became valid).
inline polycube_label_problem repair_polycube_labels(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                                     const std::vector<std::array<double, 6>>& data,
                                                     std::vector<std::uint8_t>& lab, int max_iterations) {
  for (int it = 0;; ++it) {
    const auto cs = find_polycube_charts(m, nb, lab);
    const auto p = find_label_problem(m, nb, cs);
    if (p.kind == polycube_label_problem::none || it >= max_iterations) return p;
    switch (p.kind) {
      case polycube_label_problem::pinned_face: {
        const auto dl = cs.chart_label[to_size(p.other)];
        // take the other chart's label unless it is opposite to a neighbour of the face
        bool ok = true;
        for (index_t g : nb[to_size(p.vertex)])
          if (g >= 0 && (lab[to_size(g)] ^ 1) == dl) ok = false;
        if (ok) {
          lab[to_size(p.vertex)] = dl;
        } else {
          return p;
        }
        break;
      }
      case polycube_label_problem::island:
        for (std::size_t f = 0; f < lab.size(); ++f)
          if (cs.face_chart[f] == p.chart) lab[f] = cs.chart_label[to_size(p.other)];
        break;
      case polycube_label_problem::opposite:
      case polycube_label_problem::few_corners: relabel_chart(cs, p.chart, data, lab, true); break;
      default: relabel_chart(cs, p.chart, data, lab, false); break;
    }
  }
}

}  // namespace detail
TESSERA_NAMESPACE_END
