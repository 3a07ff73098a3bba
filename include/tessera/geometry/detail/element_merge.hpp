// tessera/geometry/detail/element_merge.hpp: deforming and merging a pair of corresponding elements,
// §3.3.5-3.3.6 of paper 000 (after Zhou et al. 2006): correspondences by closest points, Laplacian
// deformation of both elements towards the midpoints (eq. 6 and 7) with border vertices fixed, a
// graph cut of each element on its triangle dual graph with the eq. 8 weights and the SOURCE/SINK
// rules, and a join of the two cut paths by a ladder of new triangles, smoothed by uniform-Laplacian
// sweeps around the seam (element_seam.hpp; the paper joins by Poisson mesh merging, Yu et al. 2004,
// which this is not). The result is checked (manifold, closed except on the tile border, no self-intersection,
// inside the domain) and rejected otherwise, so callers can fall back without ever storing a bad
// element.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/mesh_topology.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../bvh.hpp"
#include "../laplacian.hpp"
#include "../max_flow.hpp"
#include "../mesh_elements.hpp"
#include "../mesh_quilt_types.hpp"
#include "element_seam.hpp"
#include "mesh_clip.hpp"
#include "triangle_geometry.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

struct merge_params {
  xy_rect domain;
  bool constrained = false;  ///< the domain sides are tile borders: nothing non-fixed may reach them
  double corr_dist = 0.25;   ///< correspondence search radius (§3.3.4)
  double mu = 1.0;           ///< soft-constraint weight of eq. 6-7
  int smooth_rings = 2;      ///< rings around the seam relaxed after joining
  double margin = 1e-7;      ///< non-fixed vertices stay this far inside a constrained domain
  /// Regions: "old" is what was synthesized before this patch (occupied cells), "patch" is P_T. The
  /// overlap of §3.3.6 is old and patch; the new region is patch but not old.
  std::function<bool(vec3)> is_old, in_patch;
  merge_rules rules = merge_rules::tessera;
};

/// What merge_pair decided, for tests and diagnostics: terminal links per face (+1 SOURCE, -1 SINK,
/// 0 free), the kept faces of each element after its cut, Dist(v, other element) per vertex (eq. 8,
/// capped), and the number of seams joined.
struct merge_trace {
  std::vector<signed char> term_t, term_in;
  std::vector<unsigned char> keep_t, keep_in;
  std::vector<double> dist_t, dist_in;
  tri_mesh deformed_t, deformed_in;
  index_t seams = 0;
};

struct merge_counters {
  index_t attempted = 0, merged = 0;
  index_t fail_correspondence = 0, fail_deform = 0, fail_cut = 0, fail_loops = 0, fail_check = 0;
};

inline bool strictly_inside(const xy_rect& d, vec3 p, double m) {
  return p.x > d.x0 + m && p.x < d.x1 - m && p.y > d.y0 + m && p.y < d.y1 - m;
}

// Minimum cut of a mesh's triangle dual graph with the eq. 8 weights. `dist[v]` is Dist(v, other
// element); `term[f]` is +1 (SOURCE: keep), -1 (SINK: remove) or 0. Free faces get a weak preference
// `bias` (keep on the old side, remove on the new side): the paper's graph has only infinite terminal
// links, so all cuts of equal eq. 8 cost tie and max-flow would return the one hugging the SOURCE;
// the bias places the seam at the old/new boundary among them. Returns keep flags, or nothing when
// the cut is infinite.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::optional<std::vector<unsigned char>> dual_graph_cut(const tri_mesh& m, const std::vector<double>& dist,
                                                         const std::vector<signed char>& term,
                                                         const std::vector<double>& bias) {
  const index_t nf = m.num_faces();
  max_flow_graph g(nf);
  const double inf = std::numeric_limits<double>::infinity();
  for (index_t f = 0; f < nf; ++f) {
    if (term[static_cast<std::size_t>(f)] > 0) g.add_terminal(f, inf, 0);
    if (term[static_cast<std::size_t>(f)] < 0) g.add_terminal(f, 0, inf);
    if (term[static_cast<std::size_t>(f)] == 0) {
      const double b = bias[static_cast<std::size_t>(f)];
      g.add_terminal(f, b > 0 ? b : 0.0, b < 0 ? -b : 0.0);
    }
  }
  for (const mesh_edge& e : mesh_edges(m)) {
    if (e.faces.size() != 2) continue;
    const double len = norm(m.positions[static_cast<std::size_t>(e.v0)] - m.positions[static_cast<std::size_t>(e.v1)]);
    const double w =
        (1 + len) * (1 + dist[static_cast<std::size_t>(e.v0)] + dist[static_cast<std::size_t>(e.v1)]);  // eq. 8
    g.add_edge(e.faces[0][0], e.faces[1][0], w, w);
  }
  const auto flow = g.solve();
  if (!flow || std::isinf(*flow)) return std::nullopt;
  std::vector<unsigned char> keep(static_cast<std::size_t>(nf));
  for (index_t f = 0; f < nf; ++f) keep[static_cast<std::size_t>(f)] = g.in_source_set(f) ? 1 : 0;
  return keep;
}

/// Deforms and merges `ct` (already in the output, may carry fixed vertices and a border set) with
/// `cin` (a new element from the translated exemplar). Returns the merged element or nothing.
/// A template (`Deferred` is always void) only so that the Eigen sparse solves inside are compiled
/// by the translation units that quilt, not by every includer of tessera.hpp (its compile-time goal).
template <class Deferred = void>
std::optional<texture_element> merge_pair(const texture_element& ct, const texture_element& cin, const merge_params& p,
                                          merge_counters& stats, merge_trace* trace = nullptr) {
  ++stats.attempted;
  const double corr2 = p.corr_dist * p.corr_dist;
  const double dist_cap = 4 * p.corr_dist;  // Dist of eq. 8 is searched up to 4 correspondence radii, capped there
  // --- §3.3.4 correspondences: C_T vertices -> closest points on C_in
  struct corr {
    index_t v, face;
    vec3 bary, point;
  };
  auto correspond = [&](const tri_mesh& from, const triangle_bvh& to) {
    std::vector<corr> out;
    for (index_t v = 0; v < from.num_vertices(); ++v) {
      const auto h = to.closest_point(from.positions[static_cast<std::size_t>(v)], corr2);
      if (h.face >= 0) out.push_back({v, h.face, h.bary, h.point});
    }
    return out;
  };
  const triangle_bvh cin_bvh0(cin.mesh);
  const std::vector<corr> c0 = correspond(ct.mesh, cin_bvh0);
  if (c0.size() < 3) {
    ++stats.fail_correspondence;
    return std::nullopt;
  }
  texture_element cin_b = cin;
  cin_b.border = ct.border | cin.border;  // B(C_in) = B(C_T) (§3.3.5), plus what it already carries
  // --- §3.3.5 deformation towards the midpoints, border vertices fixed (eq. 6 and 7)
  std::vector<unsigned char> fixed_t = border_vertices(ct, p.domain);
  for (std::size_t v = 0; v < fixed_t.size(); ++v) fixed_t[v] = fixed_t[v] || (v < ct.fixed.size() && ct.fixed[v]);
  std::vector<unsigned char> fixed_in = border_vertices(cin_b, p.domain);
  for (std::size_t v = 0; v < fixed_in.size(); ++v) fixed_in[v] = fixed_in[v] || (v < cin.fixed.size() && cin.fixed[v]);
  std::vector<laplacian_constraint> ks_t, ks_in;
  for (const corr& c : c0) {
    const vec3 mid = (ct.mesh.positions[static_cast<std::size_t>(c.v)] + c.point) * 0.5;
    ks_t.push_back({{c.v, -1, -1}, {1, 0, 0}, mid});
    const auto& f = cin.mesh.faces[static_cast<std::size_t>(c.face)];
    ks_in.push_back({{f[0], f[1], f[2]}, {c.bary.x, c.bary.y, c.bary.z}, mid});
  }
  const auto dt = laplacian_deform(ct.mesh, fixed_t, ks_t, {.soft_weight = p.mu});
  const auto din = laplacian_deform(cin.mesh, fixed_in, ks_in, {.soft_weight = p.mu});
  if (!dt || !din) {
    ++stats.fail_deform;
    return std::nullopt;
  }
  tri_mesh t2 = ct.mesh, in2 = cin.mesh;
  t2.positions = *dt;
  in2.positions = *din;
  const triangle_bvh t_bvh(t2), in_bvh(in2);
  texture_element t_el{t2, fixed_t, ct.border, {}}, in_el{in2, fixed_in, cin_b.border, {}};
  const auto border_t = border_triangles(t_el, p.domain), border_in = border_triangles(in_el, p.domain);

  // --- §3.3.6 cut of C_T
  std::vector<double> dist_t(t2.positions.size()), dist_in(in2.positions.size());
  std::vector<index_t> corr_face_t(t2.positions.size(), -1), corr_face_in(in2.positions.size(), -1);
  for (std::size_t v = 0; v < t2.positions.size(); ++v) {
    const auto h = in_bvh.closest_point(t2.positions[v], dist_cap * dist_cap);
    dist_t[v] = h.face >= 0 ? std::sqrt(h.squared_distance) : dist_cap;
    if (h.face >= 0 && h.squared_distance <= corr2) corr_face_t[v] = h.face;
  }
  for (std::size_t v = 0; v < in2.positions.size(); ++v) {
    const auto h = t_bvh.closest_point(in2.positions[v], dist_cap * dist_cap);
    dist_in[v] = h.face >= 0 ? std::sqrt(h.squared_distance) : dist_cap;
    if (h.face >= 0 && h.squared_distance <= corr2) corr_face_in[v] = h.face;
  }
  if (trace) trace->dist_t = dist_t, trace->dist_in = dist_in, trace->deformed_t = t2, trace->deformed_in = in2;
  // The "frontier" of §3.3.6 on each element: faces all of whose corners have the other element
  // within the correspondence distance, next to a face that has not (where the element goes on beyond
  // the other one). The paper asks for the faces whose neighbours no vertex of the other element is
  // closest to; closest-face sets are too sparse on meshes of similar density, so every face near
  // the other element counts as corresponded.
  auto frontier = [](const tri_mesh& m, const std::vector<index_t>& corr_face) {
    std::vector<unsigned char> corresponded(m.faces.size(), 0), out(m.faces.size(), 0);
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      bool all = true;
      for (index_t v : m.faces[f]) all = all && corr_face[static_cast<std::size_t>(v)] >= 0;
      corresponded[f] = all ? 1 : 0;
    }
    const auto adj = face_adjacency(m);
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      if (corresponded[f])
        for (index_t g : adj.neighbor[f])
          if (g >= 0 && !corresponded[static_cast<std::size_t>(g)]) out[f] = 1;
    return out;
  };
  const std::vector<unsigned char> in_frontier = frontier(in2, corr_face_in);
  const bool paper = p.rules == merge_rules::paper;
  // SOURCE of an element: its faces outside the overlap (C_T: old and outside the patch; C_in: the
  // new region), its border triangles, faces with a fixed vertex. SINK: the faces around each vertex
  // whose corresponding face on the other element is outside the overlap, a border triangle (paper
  // rules only; see merge_rules) or on the other element's frontier.
  auto is_new = [&](vec3 c) { return p.in_patch(c) && !p.is_old(c); };
  auto is_kept_old = [&](vec3 c) { return p.is_old(c) && !p.in_patch(c); };
  std::vector<signed char> term_t(t2.faces.size(), 0);
  bool any_source = false;
  for (std::size_t f = 0; f < t2.faces.size(); ++f) {
    const vec3 c = centroid(t2, static_cast<index_t>(f));
    bool src = (paper ? !p.in_patch(c) : is_kept_old(c)) || border_t[f];
    for (index_t v : t2.faces[f]) src = src || fixed_t[static_cast<std::size_t>(v)];
    if (src) term_t[f] = 1, any_source = true;
  }
  std::vector<unsigned char> sink_vertex(t2.positions.size(), 0);
  for (std::size_t v = 0; v < t2.positions.size(); ++v) {
    const index_t fi = corr_face_t[v];
    if (fi < 0) continue;
    if (border_in[static_cast<std::size_t>(fi)]) {
      sink_vertex[v] = paper ? 1 : 0;
      continue;
    }
    const vec3 c = centroid(in2, fi);
    if (is_new(c) || (in_frontier[static_cast<std::size_t>(fi)] && p.in_patch(c))) sink_vertex[v] = 1;
  }
  bool any_sink = false, conflict = false;
  for (std::size_t f = 0; f < t2.faces.size(); ++f) {
    bool sink = !paper && is_new(centroid(t2, static_cast<index_t>(f))) &&
                corr_face_t[static_cast<std::size_t>(t2.faces[f][0])] >= 0;
    for (index_t v : t2.faces[f]) sink = sink || sink_vertex[static_cast<std::size_t>(v)];
    if (!sink) continue;
    if (term_t[f] > 0) {
      // SOURCE and SINK at once: the paper's graph has an infinite cut there; tessera keeps SOURCE
      // (the face is kept, the seam goes around it)
      conflict = conflict || paper;
      continue;
    }
    term_t[f] = -1, any_sink = true;
  }
  if (!any_source) {
    // C_T lies entirely in the patch: anchor it on its old part away from the sinks
    for (std::size_t f = 0; f < t2.faces.size(); ++f)
      if (term_t[f] == 0 && p.is_old(centroid(t2, static_cast<index_t>(f)))) term_t[f] = 1, any_source = true;
  }
  if (trace) trace->term_t = term_t;
  if (!any_sink || !any_source || conflict) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  constexpr double bias_weight = 0.05;
  std::vector<double> bias_t(t2.faces.size());
  for (std::size_t f = 0; f < t2.faces.size(); ++f)
    bias_t[f] = p.is_old(centroid(t2, static_cast<index_t>(f))) ? bias_weight : -bias_weight;
  const auto keep_t = dual_graph_cut(t2, dist_t, term_t, bias_t);
  if (!keep_t) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  if (trace) trace->keep_t = *keep_t;
  // --- cut of C_in. Both rule sets: nothing non-fixed may cross a tile border (§3.3.5: the part of
  // C_in merged into M_T must not cross it), and exemplar content over old output outside the patch
  // goes (the exemplar only fills P_T).
  std::vector<signed char> term_in(in2.faces.size(), 0);
  const std::vector<unsigned char> t_frontier = paper ? frontier(t2, corr_face_t) : std::vector<unsigned char>{};
  std::vector<unsigned char> sink_in(in2.positions.size(), 0);
  if (paper)
    for (std::size_t v = 0; v < in2.positions.size(); ++v) {
      const index_t ft = corr_face_in[v];
      if (ft < 0) continue;
      const vec3 c = centroid(t2, ft);
      sink_in[v] = is_kept_old(c) || border_t[static_cast<std::size_t>(ft)] ||
                   (t_frontier[static_cast<std::size_t>(ft)] && p.in_patch(c));
    }
  for (std::size_t f = 0; f < in2.faces.size() && !conflict; ++f) {
    bool has_fixed = false;
    for (index_t v : in2.faces[f])
      has_fixed =
          has_fixed || (static_cast<std::size_t>(v) < cin.fixed.size() && cin.fixed[static_cast<std::size_t>(v)]);
    bool must_go = false;
    if (p.constrained)
      for (index_t v : in2.faces[f])
        must_go = must_go || !strictly_inside(p.domain, in2.positions[static_cast<std::size_t>(v)], p.margin);
    const vec3 c = centroid(in2, static_cast<index_t>(f));
    must_go = must_go || is_kept_old(c);
    if (paper) {
      // "the same method" as for C_T, with the roles of the two elements swapped
      bool src = has_fixed || is_new(c) || border_in[f];
      bool sink = must_go;
      for (index_t v : in2.faces[f]) sink = sink || sink_in[static_cast<std::size_t>(v)];
      if (src && sink) conflict = true;
      term_in[f] = src ? 1 : sink ? -1 : 0;
      continue;
    }
    if (has_fixed) {  // a border part it brought from an earlier merge: keep
      term_in[f] = 1;
      continue;
    }
    if (must_go || border_in[f]) {  // C_in's border triangles cross the tile border: never kept
      term_in[f] = -1;
      continue;
    }
    if (is_new(c)) {
      term_in[f] = 1;
      continue;
    }
    // consistent with the cut of C_T: drop where C_T is kept, keep where C_T was removed
    int to_kept = 0, to_removed = 0;
    for (index_t v : in2.faces[f]) {
      const index_t ft = corr_face_in[static_cast<std::size_t>(v)];
      if (ft < 0) continue;
      ((*keep_t)[static_cast<std::size_t>(ft)] ? to_kept : to_removed)++;
    }
    if (to_kept > 0 && to_removed == 0)
      term_in[f] = -1;
    else if (to_removed > 0 && to_kept == 0)
      term_in[f] = 1;
  }
  if (trace) trace->term_in = term_in;
  if (conflict) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  std::vector<double> bias_in(in2.faces.size());
  for (std::size_t f = 0; f < in2.faces.size(); ++f)
    bias_in[f] = p.is_old(centroid(in2, static_cast<index_t>(f))) ? -bias_weight : bias_weight;
  const auto keep_in = dual_graph_cut(in2, dist_in, term_in, bias_in);
  if (!keep_in) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  if (trace) trace->keep_in = *keep_in;
  const auto count = [](const std::vector<unsigned char>& k) { return std::count(k.begin(), k.end(), 1); };
  if (count(*keep_t) == 0 || count(*keep_t) == static_cast<std::ptrdiff_t>(keep_t->size()) || count(*keep_in) == 0 ||
      count(*keep_in) == static_cast<std::ptrdiff_t>(keep_in->size())) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  // --- join along the two cut paths
  std::vector<index_t> map_t, map_in;
  const tri_mesh kt = submesh(t2, *keep_t, map_t), ki = submesh(in2, *keep_in, map_in);
  std::vector<std::vector<index_t>> loops_t, loops_in;
  if (!boundary_loops(kt, loops_t) || !boundary_loops(ki, loops_in)) {
    ++stats.fail_loops;
    return std::nullopt;
  }
  // loops that were already boundary before the cut (tile-border cuts) stay open
  std::vector<std::vector<index_t>> new_t;
  if (!cut_loops(t2, map_t, loops_t, new_t) || !cut_loops(in2, map_in, loops_in, loops_in)) {
    ++stats.fail_loops;
    return std::nullopt;
  }
  if (new_t.empty() || new_t.size() != loops_in.size()) {
    ++stats.fail_loops;
    return std::nullopt;
  }
  texture_element out;
  out.mesh = kt;
  const auto base = static_cast<index_t>(kt.positions.size());
  out.mesh.append(ki);
  out.fixed.assign(out.mesh.positions.size(), 0);
  for (std::size_t v = 0; v < map_t.size(); ++v)
    if (map_t[v] >= 0 && v < ct.fixed.size() && ct.fixed[v]) out.fixed[static_cast<std::size_t>(map_t[v])] = 1;
  for (std::size_t v = 0; v < map_in.size(); ++v)
    if (map_in[v] >= 0 && v < cin.fixed.size() && cin.fixed[v])
      out.fixed[static_cast<std::size_t>(base + map_in[v])] = 1;
  out.border = ct.border | cin.border;  // B(C) = B(C1) u B(C2)
  // pair loops greedily by the distance of their centroids; opposite orientation required
  auto loop_centroid = [&](const std::vector<index_t>& l, index_t off) {
    vec3 c;
    for (index_t v : l) c += out.mesh.positions[static_cast<std::size_t>(v + off)];
    return c / double(l.size());
  };
  std::vector<std::tuple<double, std::size_t, std::size_t>> cand;
  for (std::size_t i = 0; i < new_t.size(); ++i)
    for (std::size_t j = 0; j < loops_in.size(); ++j)
      cand.push_back({norm(loop_centroid(new_t[i], 0) - loop_centroid(loops_in[j], base)), i, j});
  std::sort(cand.begin(), cand.end());
  std::vector<unsigned char> used_t(new_t.size(), 0), used_in(loops_in.size(), 0);
  std::vector<index_t> seam_vertices;
  for (const auto& [d, i, j] : cand) {
    if (used_t[i] || used_in[j]) continue;
    used_t[i] = used_in[j] = 1;
    std::vector<index_t> b = loops_in[j];
    for (index_t& v : b) v += base;
    if (dot(vector_area(out.mesh, new_t[i]), vector_area(out.mesh, b)) >= 0) {
      ++stats.fail_loops;
      return std::nullopt;
    }
    stitch_loops(out.mesh, new_t[i], b);
    seam_vertices.insert(seam_vertices.end(), new_t[i].begin(), new_t[i].end());
    seam_vertices.insert(seam_vertices.end(), b.begin(), b.end());
    if (trace) ++trace->seams;
  }
  smooth_seam(out, seam_vertices, p.domain, p.smooth_rings);
  // --- checks
  const edge_defects d = count_edge_defects(out.mesh);
  bool ok = d.nonmanifold_edges == 0;
  if (ok && d.open_edges > 0)
    for (const auto& e : boundary_edges(out.mesh))
      ok = ok && out.fixed[static_cast<std::size_t>(e[0])] && out.fixed[static_cast<std::size_t>(e[1])];
  if (ok && p.constrained)
    for (std::size_t v = 0; v < out.mesh.positions.size() && ok; ++v)
      ok = out.fixed[v] || strictly_inside(p.domain, out.mesh.positions[v], p.margin);
  if (ok) ok = !self_intersects(out.mesh);
  if (!ok) {
    ++stats.fail_check;
    return std::nullopt;
  }
  out.update_box();
  ++stats.merged;
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
