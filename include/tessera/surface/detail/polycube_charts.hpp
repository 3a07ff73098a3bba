// tessera/surface/detail/polycube_charts.hpp: charts of a face labelling (connected faces of one label),
// their validity as polycube faces (no two adjacent charts with opposite labels, every chart of genus 0
// and not an island inside one other chart, at least four corners per chart, valence-3 corners with
// three different axes) and the bounded repair loop that relabels charts until the labelling is valid.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Fidelity cost added to a face's old label when the relabel rounds change it (a chart the
/// deformation fails on, a folded face): more than any fidelity cost (at most the face's normalized
/// area, about 1), so later repairs do not bring it back.
inline constexpr double relabel_tabu_cost = 100;

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

/// The first (vertex order) vertex where the faces of one label form several fans: more than two of
/// that label's boundary edges end there, so a chart meets itself or another chart of its label there.
/// Returns {a chart of that label at the vertex, vertex}, or -1s.
inline std::array<index_t, 2> find_pinched_vertex(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                                  const polycube_chart_set& cs) {
  auto lab = [&](std::size_t f) { return cs.chart_label[to_size(cs.face_chart[f])]; };
  // per vertex and label: boundary edge ends
  std::vector<std::array<std::uint8_t, 6>> ends(cs.vertex_charts.size(), std::array<std::uint8_t, 6>{});
  for (std::size_t f = 0; f < cs.face_chart.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const index_t g = nb[f][to_size(k)];
      if (g < 0 || lab(to_size(g)) == lab(f)) continue;
      for (int e = 0; e < 2; ++e) {
        auto& n = ends[to_size(m.faces[f][to_size((k + e) % 3)])][lab(f)];
        n = static_cast<std::uint8_t>(std::min(n + 1, 255));
      }
    }
  for (std::size_t v = 0; v < ends.size(); ++v)
    for (int l = 0; l < 6; ++l)
      if (ends[v][to_size(l)] > 2)
        for (index_t c : cs.vertex_charts[v])
          if (cs.chart_label[to_size(c)] == l) return {c, static_cast<index_t>(v)};
  return {-1, -1};
}

/// What is wrong with a labelling (first problem found, in a fixed order), or kind none.
struct polycube_label_problem {
  enum kind_t { none, opposite, genus, island, few_corners, corner_axes, pinned_face, pinched } kind = none;
  index_t chart = -1, other = -1, vertex = -1;
  [[nodiscard]] status to_status() const {
    switch (kind) {
      case none: return {};
      case opposite:
        return status::not_converged(cat("polycube: charts ", chart, " and ", other,
                                         " are adjacent with opposite labels (their planes would coincide)"));
      case genus: return status::not_converged(cat("polycube: chart ", chart, " has a handle (genus > 0): not planar"));
      case pinched:
        return status::not_converged(cat("polycube: chart ", chart,
                                         " meets itself or another chart of its direction at vertex ", vertex,
                                         ": a polycube face there would not be simple"));
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
  if (const auto pinch = find_pinched_vertex(m, nb, cs); pinch[0] >= 0)
    return {polycube_label_problem::pinched, pinch[0], -1, pinch[1]};
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
/// (ties: smallest label). Falls back to the best label of another axis, then (with allow_opposite)
/// to any other label. Returns false, changing nothing, when no label qualifies.
inline bool relabel_chart(const polycube_chart_set& cs, index_t c, const std::vector<std::array<double, 6>>& data,
                          std::vector<std::uint8_t>& lab, bool to_neighbor_only, bool allow_opposite = true) {
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
      if (l == own || (!allow_opposite && l == (own ^ 1))) continue;
      if (pass == 0 && (!allowed[ls] || forbidden[ls])) continue;
      if (pass == 1 && (to_neighbor_only ? !allowed[ls] : forbidden[ls])) continue;
      if (pass == 2 && !allow_opposite) continue;
      if (best < 0 || cost[ls] < cost[to_size(best)]) best = l;
    }
  if (best < 0) return false;
  for (std::size_t f = 0; f < lab.size(); ++f)
    if (cs.face_chart[f] == c) lab[f] = static_cast<std::uint8_t>(best);
  return true;
}

/// Faces of each vertex (CSR: faces[start[v] .. start[v + 1]]).
struct vertex_face_table {
  std::vector<index_t> start, faces;
  vertex_face_table(const tri_mesh& m) : start(to_size(m.num_vertices()) + 1, 0) {
    for (const auto& f : m.faces)
      for (index_t v : f) ++start[to_size(v) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    faces.resize(to_size(start.back()));
    auto next = start;
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      for (index_t v : m.faces[f]) faces[to_size(next[to_size(v)]++)] = static_cast<index_t>(f);
  }
  [[nodiscard]] std::span<const index_t> of(index_t v) const {
    return {faces.data() + start[to_size(v)], faces.data() + start[to_size(v) + 1]};
  }
};

/// Runs of the faces around v: maximal sets joined across edges at v whose faces satisfy same(f, g).
template <class Same>
std::vector<std::vector<index_t>> face_runs_at(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                               std::span<const index_t> ring, index_t v, Same same) {
  std::vector<std::size_t> run(ring.size());
  std::iota(run.begin(), run.end(), std::size_t{0});
  auto find = [&](std::size_t x) {
    while (run[x] != x) x = run[x] = run[run[x]];
    return x;
  };
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& fv = m.faces[to_size(ring[i])];
    for (int k = 0; k < 3; ++k) {
      if (fv[to_size(k)] != v && fv[to_size((k + 1) % 3)] != v) continue;  // not an edge at v
      const index_t g = nb[to_size(ring[i])][to_size(k)];
      const auto j = to_size(std::find(ring.begin(), ring.end(), g) - ring.begin());
      if (g >= 0 && j < ring.size() && same(ring[i], g)) run[find(std::max(i, j))] = find(std::min(i, j));
    }
  }
  std::vector<std::vector<index_t>> runs(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) runs[find(i)].push_back(ring[i]);
  std::erase_if(runs, [](const auto& r) { return r.empty(); });
  return runs;
}

/// How many local label problems lie around the vertices of `faces`: a label in two runs around a
/// vertex, a face whose three vertices all touch one other label, adjacent opposite labels (each
/// counted once per vertex it is seen from).
inline std::size_t label_problems_near(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                       const vertex_face_table& vf, const std::vector<std::uint8_t>& lab,
                                       const std::vector<index_t>& faces) {
  auto touches = [&](index_t u, index_t f, int l) {
    for (index_t g : vf.of(u))
      if (g != f && lab[to_size(g)] == l) return true;
    return false;
  };
  std::vector<index_t> verts;
  for (index_t f : faces) verts.insert(verts.end(), m.faces[to_size(f)].begin(), m.faces[to_size(f)].end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  std::size_t problems = 0;
  for (index_t v : verts) {
    const auto ring = vf.of(v);
    const auto runs =
        face_runs_at(m, nb, ring, v, [&](index_t f, index_t g) { return lab[to_size(f)] == lab[to_size(g)]; });
    for (std::size_t i = 0; i < runs.size(); ++i)
      for (std::size_t j = i + 1; j < runs.size(); ++j)
        problems += lab[to_size(runs[i][0])] == lab[to_size(runs[j][0])];
    for (index_t f : ring) {
      for (index_t g : nb[to_size(f)]) problems += g >= 0 && (lab[to_size(g)] ^ 1) == lab[to_size(f)];
      const auto& fv = m.faces[to_size(f)];
      for (int l = 0; l < 6; ++l)
        problems += l != lab[to_size(f)] && touches(fv[0], f, l) && touches(fv[1], f, l) && touches(fv[2], f, l);
    }
  }
  return problems;
}

/// Frees vertex v where the faces of chart c's label form several fans (find_pinched_vertex),
/// separated by gaps of other labels; a gap may take c's label or a fan the label of a gap face beside it, each grown by up
/// to `max_rings` rings of the faces it relabels until it lowers the count of local label problems
/// around it (pinches, pinned faces, opposite neighbours). Of those, the change of smallest summed
/// fidelity cost is applied, and the labels it took are marked in `barred` (bit l of a face: label l),
/// which the pinned-face repair does not give back. Returns false when there is none.
inline bool repair_pinched_vertex(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& nb,
                                  const vertex_face_table& vf, const polycube_chart_set& cs,
                                  const std::vector<std::array<double, 6>>& data, std::vector<std::uint8_t>& lab,
                                  std::vector<std::uint8_t>& barred, index_t c, index_t v, int max_rings = 3) {
  const auto ring = vf.of(v);
  const int lc = cs.chart_label[to_size(c)];
  auto in_c = [&](index_t f) { return lab[to_size(f)] == lc; };
  const auto runs = face_runs_at(m, nb, ring, v, [&](index_t f, index_t g) { return in_c(f) == in_c(g); });
  std::vector<index_t> best;
  int best_label = -1;
  double best_cost = 0;
  auto consider = [&](std::vector<index_t> region, int l) {
    const bool grow_c = in_c(region[0]);  // a fan grows into c, a gap into the other charts
    for (int r = 0; r <= max_rings; ++r) {
      double cost = 0;
      for (index_t f : region) cost += data[to_size(f)][to_size(l)] - data[to_size(f)][lab[to_size(f)]];
      if (!best.empty() && cost >= best_cost) return;
      // tried in place and put back (a copy of the labels per trial would cost O(F))
      const auto problems = label_problems_near(m, nb, vf, lab, region);
      std::vector<std::uint8_t> old(region.size());
      for (std::size_t i = 0; i < region.size(); ++i) {
        old[i] = lab[to_size(region[i])];
        lab[to_size(region[i])] = static_cast<std::uint8_t>(l);
      }
      const auto after = label_problems_near(m, nb, vf, lab, region);
      for (std::size_t i = 0; i < region.size(); ++i) lab[to_size(region[i])] = old[i];
      if (after < problems) {
        best = region, best_label = l, best_cost = cost;
        return;
      }
      const auto n = region.size();
      for (std::size_t i = 0; i < n; ++i)
        for (index_t g : nb[to_size(region[i])])
          if (g >= 0 && in_c(g) == grow_c && lab[to_size(g)] != l &&
              std::find(region.begin(), region.end(), g) == region.end())
            region.push_back(g);
    }
  };
  for (const auto& r : runs) {
    if (!in_c(r[0])) {
      consider(r, lc);
      continue;
    }
    std::array<bool, 6> tried{};
    for (index_t f : r)  // a fan takes the label of a gap face beside it
      for (index_t g : nb[to_size(f)])
        if (g >= 0 && !in_c(g) && std::find(ring.begin(), ring.end(), g) != ring.end() && !tried[lab[to_size(g)]]) {
          tried[lab[to_size(g)]] = true;
          consider(r, lab[to_size(g)]);
        }
  }
  if (best.empty()) return false;
  for (index_t f : best) {
    barred[to_size(f)] |= static_cast<std::uint8_t>(1u << lab[to_size(f)]);
    lab[to_size(f)] = static_cast<std::uint8_t>(best_label);
  }
  return true;
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
  const vertex_face_table vf(m);
  std::vector<std::uint8_t> barred(lab.size(), 0);  // bit l: a pinch repair took label l from the face
  for (int it = 0;; ++it) {
    const auto cs = find_polycube_charts(m, nb, lab);
    const auto p = find_label_problem(m, nb, cs);
    if (p.kind == polycube_label_problem::none || it >= max_iterations) return p;
    switch (p.kind) {
      case polycube_label_problem::pinned_face: {
        // the face takes the other chart's label, else the cheapest label of a face beside it; never
        // its own, one a repair took from it, or one opposite to a neighbour's
        const auto f = to_size(p.vertex);
        auto usable = [&](int l) {
          if (l == lab[f] || (barred[f] >> l & 1)) return false;
          for (index_t g : nb[f])
            if (g >= 0 && (lab[to_size(g)] ^ 1) == l) return false;
          return true;
        };
        int to = cs.chart_label[to_size(p.other)];
        if (!usable(to)) {
          to = -1;
          for (index_t g : nb[f])
            if (g >= 0 && usable(lab[to_size(g)]) && (to < 0 || data[f][lab[to_size(g)]] < data[f][to_size(to)]))
              to = lab[to_size(g)];
        }
        if (to < 0) return p;
        lab[f] = static_cast<std::uint8_t>(to);
        break;
      }
      case polycube_label_problem::pinched:
        if (!repair_pinched_vertex(m, nb, vf, cs, data, lab, barred, p.chart, p.vertex))
          return p;  // no local change frees it
        break;
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
