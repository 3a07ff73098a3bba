// tessera/geometry/detail/element_merge.hpp: deforming and merging a pair of corresponding elements,
// §3.3.5-3.3.6 of paper 000 (after Zhou et al. 2006): correspondences by closest points, Laplacian
// deformation of both elements towards the midpoints (eq. 6 and 7) with border vertices fixed, a
// graph cut of each element on its triangle dual graph with the eq. 8 weights and the SOURCE/SINK
// rules, and a join of the two cut paths by a ladder of new triangles, smoothed by uniform-Laplacian
// sweeps around the seam (element_seam.hpp; the paper joins by Poisson mesh merging, Yu et al. 2004,
// which this is not). The result is checked (manifold, closed except on the tile border, no self-intersection,
// inside the domain) and rejected otherwise, so callers can fall back without ever storing a bad
// element. merge_pair runs the steps in the paper's order: find_correspondences (§3.3.4),
// deform_to_midpoints (§3.3.5; both in element_correspondence.hpp), ct_terminals / cin_terminals and
// dual_graph_cut (§3.3.6, eq. 8), join_cut_paths (element_seam.hpp), merged_element_valid.
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
#include "element_correspondence.hpp"
#include "element_seam.hpp"
#include "plane_cut_join.hpp"
#include "mesh_clip.hpp"
#include "triangle_geometry.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

/// Non-fixed vertices of a constrained merge stay this fraction of the grid cell (of the tile side,
/// for frames) inside the domain: rounding cannot then put them on or across a tile border.
inline constexpr double inside_margin_fraction = 1e-7;
/// Vertices this fraction of a grid cell (of a tile side, for strips) from a clipping line are moved
/// onto it, so that clipping leaves no sliver triangles.
inline constexpr double clip_snap_fraction = 1e-9;

struct merge_params {
  xy_rect domain;
  bool constrained = false;                ///< the domain sides are tile borders: nothing non-fixed may reach them
  double corr_dist = 0.25;                 ///< correspondence search radius (§3.3.4)
  double mu = 1.0;                         ///< soft-constraint weight of eq. 6-7
  int smooth_rings = 2;                    ///< rings around the seam relaxed after joining
  double margin = inside_margin_fraction;  ///< non-fixed vertices stay this far inside a constrained domain
  /// Regions: "old" is what was synthesized before this patch (occupied cells), "patch" is P_T. The
  /// overlap of §3.3.6 is old and patch; the new region is patch but not old.
  std::function<bool(vec3)> is_old, in_patch;
  merge_rules rules = merge_rules::tessera;
  /// Two pieces of one thread (a long element clipped by patches): joined first across a plane
  /// (plane_cut_join.hpp), and their caps take no part in the correspondences of the graph-cut merge.
  bool thread_pieces = false;
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
  index_t plane_cut = 0;  ///< of the merged, thread pieces joined across a plane
};

/// Fewer correspondences than this (a triangle's worth) cannot place C_in against C_T (§3.3.4).
inline constexpr std::size_t min_merge_correspondences = 3;
/// Dist(v, other element) of eq. 8 is searched up to this many correspondence radii, capped there.
inline constexpr double eq8_distance_radii = 4;
/// Thread pieces: the gap between the two cut planes, in correspondence radii (the ladder joining
/// the cut loops spans it), and the largest sideways offset of two pieces, in correspondence radii.
inline constexpr double plane_cut_gap_radii = 0.5, plane_cut_offset_radii = 1.0;
/// Thread pieces: a vertex corresponds only to a face whose normal is within 60 degrees of its own,
/// so that the flat caps of clipped pieces correspond to nothing (they would pull the other piece's
/// walls into a neck).
inline constexpr double thread_normal_cos = 0.5;
/// The weak keep/remove preference of free faces in the element cuts (see dual_graph_cut).
inline constexpr double cut_bias_weight = 0.05;

/// SOURCE (+1), SINK (-1) or free (0) per face of one element's cut graph (§3.3.6).
struct cut_terminals {
  std::vector<signed char> term;
  bool any_source = false, any_sink = false, conflict = false;
};

inline bool strictly_inside(const xy_rect& d, vec3 p, double m) {
  return p.x > d.x0 + m && p.x < d.x1 - m && p.y > d.y0 + m && p.y < d.y1 - m;
}

/// The regions of §3.3.6 at a point: "new" is in P_T but not synthesized before; "kept old" was
/// synthesized before and lies outside P_T (the overlap is old and in P_T).
inline bool in_new_region(const merge_params& p, vec3 c) { return p.in_patch(c) && !p.is_old(c); }
inline bool in_kept_old_region(const merge_params& p, vec3 c) { return p.is_old(c) && !p.in_patch(c); }

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
    if (term[to_size(f)] > 0) g.add_terminal(f, inf, 0);
    if (term[to_size(f)] < 0) g.add_terminal(f, 0, inf);
    if (term[to_size(f)] == 0) {
      const double b = bias[to_size(f)];
      g.add_terminal(f, b > 0 ? b : 0.0, b < 0 ? -b : 0.0);
    }
  }
  for (const mesh_edge& e : mesh_edges(m)) {
    if (e.faces.size() != 2) continue;
    const double len = norm(m.positions[to_size(e.v0)] - m.positions[to_size(e.v1)]);
    const double w = (1 + len) * (1 + dist[to_size(e.v0)] + dist[to_size(e.v1)]);  // eq. 8
    g.add_edge(e.faces[0][0], e.faces[1][0], w, w);
  }
  const auto flow = g.solve();
  if (!flow || std::isinf(*flow)) return std::nullopt;
  std::vector<unsigned char> keep(to_size(nf));
  for (index_t f = 0; f < nf; ++f) keep[to_size(f)] = g.in_source_set(f) ? 1 : 0;
  return keep;
}

/// §3.3.6, SINK vertices of C_T: those whose corresponding face on C_in is in the new region or on
/// C_in's frontier inside P_T, or (paper rules only; see merge_rules) a border triangle of C_in.
inline std::vector<unsigned char> ct_sink_vertices(const merge_params& p, const merge_side& t, const merge_side& in) {
  const bool paper = p.rules == merge_rules::paper;
  std::vector<unsigned char> sink(t.mesh.positions.size(), 0);
  for (std::size_t v = 0; v < t.mesh.positions.size(); ++v) {
    const index_t fi = t.corr_face[v];
    if (fi < 0) continue;
    if (in.border[to_size(fi)]) {
      sink[v] = paper ? 1 : 0;
      continue;
    }
    const vec3 c = centroid(in.mesh, fi);
    if (in_new_region(p, c) || (in.frontier[to_size(fi)] && p.in_patch(c))) sink[v] = 1;
  }
  return sink;
}

/// §3.3.6, the terminal links of C_T. SOURCE: faces outside the overlap (paper: outside P_T;
/// tessera: kept old), its border triangles, faces with a held vertex. SINK: the faces around each
/// SINK vertex (ct_sink_vertices), and (tessera) its corresponded faces in the new region. A face
/// both SOURCE and SINK stays SOURCE (the seam goes around it); the paper's graph has an infinite cut
/// there (`conflict`). When C_T lies entirely in the patch it is anchored on its old part.
inline cut_terminals ct_terminals(const merge_params& p, const merge_side& t, const merge_side& in) {
  const bool paper = p.rules == merge_rules::paper;
  const std::size_t nf = t.mesh.faces.size();
  cut_terminals r;
  r.term.assign(nf, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const vec3 c = centroid(t.mesh, static_cast<index_t>(f));
    bool src = (paper ? !p.in_patch(c) : in_kept_old_region(p, c)) || t.border[f];
    for (index_t v : t.mesh.faces[f]) src = src || t.fixed[to_size(v)];
    if (src) {
      r.term[f] = 1;
      r.any_source = true;
    }
  }
  const std::vector<unsigned char> sink_vertex = ct_sink_vertices(p, t, in);
  for (std::size_t f = 0; f < nf; ++f) {
    bool sink = !paper && in_new_region(p, centroid(t.mesh, static_cast<index_t>(f))) &&
                t.corr_face[to_size(t.mesh.faces[f][0])] >= 0;
    for (index_t v : t.mesh.faces[f]) sink = sink || sink_vertex[to_size(v)];
    if (!sink) continue;
    if (r.term[f] > 0) {
      r.conflict = r.conflict || paper;
      continue;
    }
    r.term[f] = -1;
    r.any_sink = true;
  }
  if (!r.any_source)
    for (std::size_t f = 0; f < nf; ++f)
      if (r.term[f] == 0 && p.is_old(centroid(t.mesh, static_cast<index_t>(f)))) {
        r.term[f] = 1;
        r.any_source = true;
      }
  return r;
}

/// §3.3.6, the terminal links of C_in (`cin_fixed`: the vertices an earlier merge fixed). Both rule
/// sets: nothing non-fixed may cross a constrained domain's sides (§3.3.5: the part of C_in merged
/// into M_T must not cross them), and its faces over old output outside P_T go (the exemplar only
/// fills P_T). Paper rules: "the same method" as for C_T with the roles swapped (t.frontier must be
/// computed). Tessera rules: fixed faces SOURCE, border triangles SINK (they cross the tile border),
/// the new region SOURCE, the rest consistent with C_T's cut `keep_t` (dropped where C_T is kept,
/// kept where it was removed).
inline cut_terminals cin_terminals(const merge_params& p, const std::vector<unsigned char>& cin_fixed,
                                   const merge_side& t, const merge_side& in,
                                   const std::vector<unsigned char>& keep_t) {
  const bool paper = p.rules == merge_rules::paper;
  cut_terminals r;
  r.term.assign(in.mesh.faces.size(), 0);
  std::vector<unsigned char> sink_in(in.mesh.positions.size(), 0);
  if (paper)
    for (std::size_t v = 0; v < in.mesh.positions.size(); ++v) {
      const index_t ft = in.corr_face[v];
      if (ft < 0) continue;
      const vec3 c = centroid(t.mesh, ft);
      sink_in[v] = in_kept_old_region(p, c) || t.border[to_size(ft)] || (t.frontier[to_size(ft)] && p.in_patch(c));
    }
  for (std::size_t f = 0; f < in.mesh.faces.size(); ++f) {
    const auto& face = in.mesh.faces[f];
    bool has_fixed = false;
    for (index_t v : face) has_fixed = has_fixed || (to_size(v) < cin_fixed.size() && cin_fixed[to_size(v)]);
    bool must_go = false;
    if (p.constrained)
      for (index_t v : face) must_go = must_go || !strictly_inside(p.domain, in.mesh.positions[to_size(v)], p.margin);
    const vec3 c = centroid(in.mesh, static_cast<index_t>(f));
    must_go = must_go || in_kept_old_region(p, c);
    if (paper) {
      const bool src = has_fixed || in_new_region(p, c) || in.border[f];
      bool sink = must_go;
      for (index_t v : face) sink = sink || sink_in[to_size(v)];
      r.term[f] = src ? 1 : sink ? -1 : 0;
      if (src && sink) {
        r.conflict = true;
        break;
      }
      continue;
    }
    if (has_fixed) {  // a border part it brought from an earlier merge: keep
      r.term[f] = 1;
    } else if (must_go || in.border[f]) {
      r.term[f] = -1;
    } else if (in_new_region(p, c)) {
      r.term[f] = 1;
    } else {
      int to_kept = 0, to_removed = 0;
      for (index_t v : face) {
        const index_t ft = in.corr_face[to_size(v)];
        if (ft < 0) continue;
        (keep_t[to_size(ft)] ? to_kept : to_removed)++;
      }
      if (to_kept > 0 && to_removed == 0)
        r.term[f] = -1;
      else if (to_removed > 0 && to_kept == 0)
        r.term[f] = 1;
    }
  }
  return r;
}

/// The weak preference of an element's free faces (see dual_graph_cut): `old_side` on faces over
/// old output, its opposite elsewhere.
inline std::vector<double> cut_bias(const merge_params& p, const tri_mesh& m, double old_side) {
  std::vector<double> bias(m.faces.size());
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    bias[f] = p.is_old(centroid(m, static_cast<index_t>(f))) ? old_side : -old_side;
  return bias;
}

/// A usable cut keeps some faces and removes some.
inline bool cut_splits(const std::vector<unsigned char>& keep) {
  const auto kept = std::count(keep.begin(), keep.end(), 1);
  return kept != 0 && kept != static_cast<std::ptrdiff_t>(keep.size());
}

/// The checks every merged element passes before it is stored: manifold, open only along fixed
/// (tile-border) vertices, inside a constrained domain except fixed vertices, no self-intersection.
template <class Deferred = void>
bool merged_element_valid(const texture_element& out, const merge_params& p) {
  const edge_defects d = count_edge_defects(out.mesh);
  bool ok = d.nonmanifold_edges == 0;
  if (ok && d.open_edges > 0)
    for (const auto& e : boundary_edges(out.mesh)) ok = ok && out.fixed[to_size(e[0])] && out.fixed[to_size(e[1])];
  if (ok && p.constrained)
    for (std::size_t v = 0; v < out.mesh.positions.size() && ok; ++v)
      ok = out.fixed[v] || strictly_inside(p.domain, out.mesh.positions[v], p.margin);
  return ok && !self_intersects(out.mesh);
}

/// Deforms and merges `ct` (already in the output, may carry fixed vertices and a border set) with
/// `cin` (a new element from the translated exemplar), in the steps of §3.3.4-3.3.6 of paper 000.
/// Returns the merged element or nothing (counted in `stats` by the step that failed).
/// A template (`Deferred` is always void) only so that the Eigen sparse solves inside are compiled
/// by the translation units that quilt, not by every includer of tessera.hpp (its compile-time goal).
template <class Deferred = void>
std::optional<texture_element> merge_pair(const texture_element& ct, const texture_element& cin, const merge_params& p,
                                          merge_counters& stats, merge_trace* trace = nullptr) {
  ++stats.attempted;
  const double corr2 = p.corr_dist * p.corr_dist;
  if (p.thread_pieces) {  // §3.3.6 with the cut placed across the thread
    texture_element cin_b = cin;
    cin_b.border = ct.border | cin.border;
    std::optional<texture_element> out =
        join_across_plane(ct, held_vertices(ct, p.domain), cin, held_vertices(cin_b, p.domain),
                          {.domain = p.domain,
                           .gap = plane_cut_gap_radii * p.corr_dist,
                           .max_offset = plane_cut_offset_radii * p.corr_dist},
                          [&](const texture_element& e) { return merged_element_valid(e, p); });
    if (out) {
      if (trace) ++trace->seams;
      out->update_box();
      ++stats.plane_cut;
      ++stats.merged;
      return out;
    }
  }
  // §3.3.4: C_T's vertices correspond to their closest points on C_in
  const std::vector<element_correspondence> corr =
      p.thread_pieces ? find_correspondences(ct.mesh, triangle_bvh(cin.mesh), corr2, &cin.mesh, thread_normal_cos)
                      : find_correspondences(ct.mesh, triangle_bvh(cin.mesh), corr2);
  if (corr.size() < min_merge_correspondences) {
    ++stats.fail_correspondence;
    return std::nullopt;
  }
  // §3.3.5: B(C_in) = B(C_T) (plus what it already carries); deformation towards the midpoints
  // (eq. 6 and 7) with the border vertices held
  texture_element cin_b = cin;
  cin_b.border = ct.border | cin.border;
  merge_side t, in;
  t.fixed = held_vertices(ct, p.domain);
  in.fixed = held_vertices(cin_b, p.domain);
  if (!deform_to_midpoints(ct.mesh, cin.mesh, corr, p.mu, t, in)) {
    ++stats.fail_deform;
    return std::nullopt;
  }
  t.border = border_triangles(texture_element{t.mesh, t.fixed, ct.border, {}}, p.domain);
  in.border = border_triangles(texture_element{in.mesh, in.fixed, cin_b.border, {}}, p.domain);
  // §3.3.6: the eq. 8 distances, then the cut of C_T
  const double dist_cap = eq8_distance_radii * p.corr_dist;
  measure_distances(t, triangle_bvh(in.mesh), corr2, dist_cap);
  measure_distances(in, triangle_bvh(t.mesh), corr2, dist_cap);
  if (trace) {
    trace->dist_t = t.dist;
    trace->dist_in = in.dist;
    trace->deformed_t = t.mesh;
    trace->deformed_in = in.mesh;
  }
  in.frontier = correspondence_frontier(in.mesh, in.corr_face);
  const cut_terminals term_t = ct_terminals(p, t, in);
  if (trace) trace->term_t = term_t.term;
  if (!term_t.any_sink || !term_t.any_source || term_t.conflict) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  const auto keep_t = dual_graph_cut(t.mesh, t.dist, term_t.term, cut_bias(p, t.mesh, cut_bias_weight));
  if (!keep_t) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  if (trace) trace->keep_t = *keep_t;
  // §3.3.6: the cut of C_in
  if (p.rules == merge_rules::paper) t.frontier = correspondence_frontier(t.mesh, t.corr_face);
  const cut_terminals term_in = cin_terminals(p, cin.fixed, t, in, *keep_t);
  if (trace) trace->term_in = term_in.term;
  if (term_in.conflict) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  const auto keep_in = dual_graph_cut(in.mesh, in.dist, term_in.term, cut_bias(p, in.mesh, -cut_bias_weight));
  if (!keep_in) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  if (trace) trace->keep_in = *keep_in;
  if (!cut_splits(*keep_t) || !cut_splits(*keep_in)) {
    ++stats.fail_cut;
    return std::nullopt;
  }
  // §3.3.6: join along the two cut paths, then check
  std::optional<texture_element> out = join_cut_paths(ct, t.mesh, *keep_t, cin, in.mesh, *keep_in, p.domain,
                                                      p.smooth_rings, trace ? &trace->seams : nullptr);
  if (!out) {
    ++stats.fail_loops;
    return std::nullopt;
  }
  if (!merged_element_valid(*out, p)) {
    ++stats.fail_check;
    return std::nullopt;
  }
  out->update_box();
  ++stats.merged;
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
