// tessera/surface/build_polycube_map.hpp: automatic construction of the polycube map of a closed,
// manifold, oriented triangle mesh of any genus (paper 000 §4 after Tarini et al. 2004), and the two
// user-supplied paths: from a per-face labelling, or from a polycube-deformed copy of the mesh.
//
// Pipeline: (1) labelling by α-expansion graph cut (detail/polycube_labeling.hpp); (2) validity repair,
// bounded (detail/polycube_charts.hpp); (3) deformation, one unknown per chart plane, least squares of
// the edge vectors (detail/polycube_deform.hpp); (4) quantization of every chart plane to the tile grid,
// never collapsing a polycube edge below one tile, then a final solve with the planes fixed;
// (5) verification and the quad layout (detail/polycube_assemble.hpp, quad_layout.hpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "detail/polycube_assemble.hpp"
#include "detail/polycube_charts.hpp"
#include "detail/polycube_deform.hpp"
#include "detail/polycube_embed.hpp"
#include "detail/polycube_labeling.hpp"
#include "detail/polycube_refine.hpp"
#include "polycube_distortion.hpp"
#include "polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// A deformed face is axis-aligned when its unit normal's dot with a label direction exceeds 1 minus this.
inline constexpr double axis_aligned_cos_slack = 1e-9;
/// Multiples of polycube_options::compactness tried in turn by build_polycube_map until one gives a
/// valid polycube (the first is the option itself).
inline constexpr double compactness_schedule[] = {1, 4, 3, 8, 2, 0.5};
/// Rounds of an attempt that split edges so that the cuts into rectangles find a path.
inline constexpr int max_cut_splits = 3;
inline tri_mesh polycube_base_copy(const tri_mesh& m) {
  tri_mesh b;
  b.positions = m.positions;
  b.faces = m.faces;
  return b;
}

/// Steps (3) to (5) for a valid labelling. On failure, `bad_chart` names the chart to relabel when
/// the failure is one chart's (an edge cycle, a collapsed edge, a boundary that does not turn as a
/// polycube face), else -1; `folded` receives the faces still folded after the untangling, or the faces
/// around a vertex where two charts of one axis meet; `uncut`, when given, what the cuts into
/// rectangles could not do (polycube_uncut).
template <Executor E>
result<polycube_map> deform_polycube(tri_mesh base, const std::vector<std::array<index_t, 3>>& nb,
                                     const std::vector<std::uint8_t>& lab, double t, const polycube_options& o, E& exec,
                                     index_t& bad_chart, std::vector<index_t>& folded,
                                     polycube_uncut* uncut = nullptr) {
  bad_chart = -1;
  folded.clear();
  if (uncut) *uncut = {};
  const auto cs = find_polycube_charts(base, nb, lab);
  const std::size_t nc = cs.chart_label.size();
  std::vector<int> axis_of(nc);
  for (std::size_t c = 0; c < nc; ++c) axis_of[c] = cs.chart_label[c] / 2;
  const auto paths = find_polycube_edge_paths(base, nb, cs);
  const auto loops = chart_boundary_loops(nc, paths);
  std::vector<vec3> pos(base.positions.size()), cont(base.positions.size());
  std::array<polycube_axis_classes, 3> classes;
  std::array<std::vector<double>, 3> planes;
  for (int a = 0; a < 3; ++a) {  // continuous planes of all three axes first: the facing sides need them
    index_t pinch = -1;
    auto cl_or = polycube_classes(base, cs.face_chart, cs.chart_label, a, &bad_chart, &pinch);
    if (!cl_or) {
      // two charts of one axis meet at a vertex: their faces there are relabelled as folded faces
      for (std::size_t f = 0; f < base.faces.size(); ++f)
        for (index_t v : base.faces[f])
          if (v == pinch) folded.push_back(static_cast<index_t>(f));
      return cl_or.error();
    }
    classes[to_size(a)] = std::move(*cl_or);
    const polycube_axis_classes& cl = classes[to_size(a)];
    const auto ncl = cl.class_chart.size();
    auto x =
        polycube_axis_solve<E>(base, nb, cl, a, std::vector<double>(ncl, std::numeric_limits<double>::quiet_NaN()));
    if (!x) return x.error();
    planes[to_size(a)].assign(nc, 0.0);
    for (std::size_t k = 0; k < ncl; ++k)
      if (cl.class_chart[k] >= 0) planes[to_size(a)][to_size(cl.class_chart[k])] = (*x)[k];
    for (std::size_t v = 0; v < cont.size(); ++v) cont[v][a] = (*x)[to_size(cl.vertex_class[v])];
  }
  for (int a = 0; a < 3; ++a) {
    const polycube_axis_classes* cl = &classes[to_size(a)];
    const auto ncl = cl->class_chart.size();
    const auto& plane = planes[to_size(a)];
    const auto orders = polycube_plane_orders(base, paths, cs.chart_label, *cl, a, plane, &bad_chart,
                                              chart_facing_orders(cs, paths, loops, cont, a));
    if (!orders) return orders.error();
    const auto q = quantize_planes(plane, axis_of, *orders, a, t, &bad_chart);
    if (!q) return q.error();
    std::vector<double> fixed(ncl, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < ncl; ++k)
      if (cl->class_chart[k] >= 0) fixed[k] = static_cast<double>((*q)[to_size(cl->class_chart[k])]) * t;
    auto y = polycube_axis_solve<E>(base, nb, *cl, a, fixed);
    if (!y) return y.error();
    for (std::size_t v = 0; v < pos.size(); ++v) pos[v][a] = (*y)[to_size(cl->vertex_class[v])];
  }
  std::string why;
  if (const index_t c = find_unturnable_chart(cs, paths, loops, pos, t, why); c >= 0) {
    bad_chart = c;
    return status::not_converged(cat("polycube: chart ", c, " is not a polycube face: ", why));
  }
  std::vector<std::uint8_t> cut;
  if (auto s = embed_polycube<E>(base, cs, classes, paths, loops, t, true, pos, &cut, uncut); !s) return s;
  if (untangle_polycube(base, pos, cs.face_chart, cs.chart_label, {&classes[0], &classes[1], &classes[2]}, t,
                        o.untangle_iterations, &cut) > 0)
    folded = polycube_flipped_faces(base, pos, cs.face_chart, cs.chart_label, t);
  // faces squeezed below min_area_ratio are handed back like folded ones
  return assemble_polycube_map(std::move(base), lab, std::move(pos), t, o.min_area_ratio, exec,
                               folded.empty() ? &folded : nullptr);
}
/// How build_polycube_attempt refines the base mesh (with polycube_options::refine).
enum class polycube_attempt { plain, refine_first, split_uncut };

/// One automatic attempt at a given compactness: label, then label -> repair -> deform rounds; a
/// failure of one chart relabels it, and its faces' old label costs more from then on (so the repair
/// cannot bring it back), then runs again (bounded by max_relabel_rounds). With options.refine, the
/// chords of each round's repaired labelling are split before the deformation, and also when the
/// repair cannot free a pinned face by relabelling (detail/polycube_refine.hpp; relabelling comes
/// first: it smooths the chart boundary), or with polycube_attempt::refine_first before every repair
/// (the chords of the graph cut's labels are then split instead of relabelled: another labelling,
/// tried second), or with polycube_attempt::split_uncut also where a cut into rectangles finds no
/// path (polycube_uncut: boundary-spanning edges, or the edges of the faces a path would press onto
/// its line; up to max_cut_splits rounds; build_polycube_map tries it last, after every compactness
/// multiple failed, since it changes maps that are valid without it); `saw_uncut` is set when a
/// deformation met such a cut. The working mesh only grows; the map's face_origin names the input
/// face of each of its faces.
template <Executor E>
result<polycube_map> build_polycube_attempt(const tri_mesh& input, const face_adjacency_result& adj,
                                            const polycube_options& options, double t, E& exec,
                                            polycube_attempt kind = polycube_attempt::plain,
                                            bool* saw_uncut = nullptr) {
  const bool refine_first = kind == polycube_attempt::refine_first;
  const auto en = detail::make_polycube_energy(input, adj.neighbor, options, exec);
  auto lab = detail::alpha_expansion_labels(en, options.max_expansion_cycles);
  if (!lab) return lab.error();
  auto data = en.data;
  tri_mesh base = polycube_base_copy(input);
  auto nb = adj.neighbor;
  std::vector<index_t> origin;  // empty while nothing is split
  auto refine = [&] {
    if (options.refine) split_chart_chords(base, nb, *lab, data, origin);
  };
  std::size_t stall = 0, last_folded = std::numeric_limits<std::size_t>::max();
  int splits_for_cuts = 0;  // rounds that split edges for the cuts into rectangles
  status last;
  for (int round = 0;; ++round) {
    if (refine_first) refine();
    auto problem = detail::repair_polycube_labels(base, nb, data, *lab, options.max_repair_iterations);
    // a face pinned onto another chart that no relabelling frees: split the chords, then repair again
    // (a few times: the repair after a split may pin another face)
    for (int k = 0; k < 4 && problem.kind == detail::polycube_label_problem::pinned_face && options.refine; ++k) {
      if (split_chart_chords(base, nb, *lab, data, origin) == 0) break;
      problem = detail::repair_polycube_labels(base, nb, data, *lab, options.max_repair_iterations);
    }
    // a relabelling the repair cannot make valid ends the rounds with the previous round's failure
    if (problem.kind != detail::polycube_label_problem::none) return round == 0 ? problem.to_status() : last;
    refine();
    index_t bad = -1;
    std::vector<index_t> folded;
    polycube_uncut uncut;
    auto r = detail::deform_polycube(base, nb, *lab, t, options, exec, bad, folded, &uncut);
    if (r) r->face_origin = origin;
    if (!r && !uncut.empty() && saw_uncut) *saw_uncut = true;
    if (r || round >= options.max_relabel_rounds) return r;
    last = r.error();
    // a cut into rectangles that found no path: a chart meshed without interior vertices (CAD faces)
    // gets its boundary-spanning edges split, a path that would press faces onto the cut's line the
    // edges of those faces; then the same labelling is deformed again (a few times at most)
    if (kind == polycube_attempt::split_uncut && !uncut.empty() && options.refine && splits_for_cuts < max_cut_splits) {
      std::sort(uncut.edges.begin(), uncut.edges.end());
      const index_t n = split_boundary_spanning_edges(base, nb, *lab, data, origin, uncut.charts) +
                        split_listed_edges(base, nb, *lab, data, origin, uncut.edges);
      if (n > 0) {
        ++splits_for_cuts;
        continue;
      }
    }
    if (bad >= 0) {
      const auto cs = detail::find_polycube_charts(base, nb, *lab);
      for (std::size_t f = 0; f < data.size(); ++f)
        if (cs.face_chart[f] == bad) data[f][(*lab)[f]] += detail::relabel_tabu_cost;
      // a chart no other label fits (its neighbours take every other axis) gives up its border
      // faces to its neighbours instead, one ring more per round it does so
      // (relabel_folded_faces changes only the chart's faces that border another chart)
      if (!detail::relabel_chart(cs, bad, data, *lab, false, false)) {
        std::vector<index_t> faces;
        for (std::size_t f = 0; f < data.size(); ++f)
          if (cs.face_chart[f] == bad) faces.push_back(static_cast<index_t>(f));
        if (!detail::relabel_folded_faces(nb, faces, detail::relabel_tabu_cost, data, *lab)) return r;
      }
    } else if (folded.empty()) {
      return r;
    } else {
      // folded faces take a neighbouring chart's label; when that does not lower their count, the
      // region grows by a ring of faces per stalled round and the labels propagate into it
      stall = folded.size() < last_folded ? 0 : stall + 1;
      last_folded = folded.size();
      const auto region = detail::grow_face_region(nb, folded, stall);
      bool changed = false;
      for (std::size_t k = 0; k <= stall; ++k)
        changed = detail::relabel_folded_faces(nb, region, detail::relabel_tabu_cost, data, *lab) || changed;
      if (!changed) return r;
    }
  }
}
/// The attempts of build_polycube_attempt at one compactness, in turn until one is valid: plain, then
/// (with options.refine) refine_first; or, with `split`, split_uncut alone. `uncut` is set when an
/// attempt met a cut into rectangles that found no path. Returns the first valid map, else the last
/// attempt's failure (refine_first's: the refined labelling's, the most informative).
template <Executor E>
result<polycube_map> build_polycube_attempts(const tri_mesh& input, const face_adjacency_result& adj,
                                             const polycube_options& options, double t, E& exec, bool split,
                                             bool& uncut) {
  if (split) return build_polycube_attempt(input, adj, options, t, exec, polycube_attempt::split_uncut);
  auto r = build_polycube_attempt(input, adj, options, t, exec, polycube_attempt::plain, &uncut);
  if (r || !options.refine) return r;
  return build_polycube_attempt(input, adj, options, t, exec, polycube_attempt::refine_first, &uncut);
}

}  // namespace detail

/// Builds the polycube map of `mesh` automatically (see the file comment). The map keeps the input's
/// vertex and face order, unless options.refine split chords of the labelling (map.refined()): then
/// the input's vertices come first in the same order, face f < F_input is part of input face f, and
/// map.face_origin names the input face of every base face. Deterministic: the same output
/// for every executor and thread count. Errors: invalid_argument from validate_polycube_input and
/// polycube_tile_size; not_converged naming the chart, corner, face or edge when the repaired labelling
/// or the deformed polycube is not valid (never a half-valid map); internal_error for a failed solve.
/// Typical cost: O(F log F) plus six max-flows per α-expansion sweep and six sparse factorisations.
template <Mesh M, Executor E = serial_executor>
result<polycube_map> build_polycube_map(const M& mesh, const polycube_options& options = {}, E&& exec = E{}) {
  if (auto s = validate_polycube_input(mesh); !s) return s;
  auto t = polycube_tile_size(mesh, options);
  if (!t) return t.error();
  if (options.max_expansion_cycles < 0 || options.max_repair_iterations < 0 || options.untangle_iterations < 0 ||
      options.max_relabel_rounds < 0 || options.max_compactness_retries < 0 || options.distortion_retries < 0 ||
      !(options.compactness >= 0) || !(options.opposite_penalty >= 1 && options.opposite_penalty <= 2) ||
      !(options.min_area_ratio >= 0 && options.min_area_ratio < 1))
    return status::invalid_argument(detail::cat(
        "polycube_options: max_expansion_cycles, max_repair_iterations, untangle_iterations, "
        "max_relabel_rounds, max_compactness_retries and distortion_retries must be >= 0, compactness >= 0, "
        "opposite_penalty in [1, 2] and min_area_ratio in [0, 1); got ",
        options.max_expansion_cycles, ", ", options.max_repair_iterations, ", ", options.untangle_iterations, ", ",
        options.max_relabel_rounds, ", ", options.max_compactness_retries, ", ", options.distortion_retries, ", ",
        options.compactness, ", ", options.opposite_penalty, ", ", options.min_area_ratio));
  auto m = to_tri_mesh(mesh);
  if (!m) return m.error();
  tri_mesh base = detail::polycube_base_copy(*m);
  const auto adj = face_adjacency(base);
  // the labelling's compactness decides most failures on scanned meshes: retry with other multiples;
  // with distortion_retries, the valid maps of the next multiples compete: the least distorted is kept.
  // Only when no multiple gives a valid map and a cut into rectangles found no path, the multiples are
  // tried again with the edges split that block the cuts (it changes maps that are valid without)
  const int tries = options.compactness == 0
                        ? 0
                        : std::min<int>(options.max_compactness_retries,
                                        static_cast<int>(std::size(detail::compactness_schedule)) - 1);
  status first;  // the first attempt's failure
  std::optional<polycube_map> best;
  double best_score = 0;
  bool uncut = false;
  for (int pass = 0; pass < 2 && !best && (pass == 0 || (uncut && options.refine)); ++pass) {
    // more: attempts left after the first valid map (-1 until there is one)
    for (int k = 0, more = -1; k <= tries && more != 0; ++k) {
      polycube_options o = options;
      o.compactness = options.compactness * detail::compactness_schedule[detail::to_size(k)];
      auto r = detail::build_polycube_attempts(base, adj, o, *t, exec, pass == 1, uncut);
      more = more >= 0 ? more - 1 : r ? options.distortion_retries : -1;
      if (!r) {
        if (k == 0 && pass == 0) first = r.error();
        continue;
      }
      if (options.distortion_retries == 0) return r;  // nothing to compare: no distortion figures needed
      const auto d = polycube_distortion(*r);
      if (!best || d.area_distortion + d.angle_distortion < best_score) {
        best_score = d.area_distortion + d.angle_distortion;
        best = std::move(*r);
      }
    }
  }
  if (best) return std::move(*best);
  if (tries == 0) return first;
  return status::not_converged(detail::cat(first.message(), " (also tried compactness x",
                                           detail::compactness_schedule[1], " .. x",
                                           detail::compactness_schedule[detail::to_size(tries)], ": none valid)"));
}

/// Builds the polycube map of `mesh` from a user labelling: one label per face (input face order),
/// used as given (no graph cut, no repair). Errors: as build_polycube_map; invalid_argument when
/// `labels` has the wrong length or a value outside 0..5 (naming the face); not_converged naming the
/// chart when the labelling is not a valid polycube labelling.
template <Mesh M, Executor E = serial_executor>
result<polycube_map> build_polycube_map_from_labels(const M& mesh, std::span<const std::uint8_t> labels,
                                                    const polycube_options& options = {}, E&& exec = E{}) {
  if (auto s = validate_polycube_input(mesh); !s) return s;
  auto t = polycube_tile_size(mesh, options);
  if (!t) return t.error();
  if (!(options.min_area_ratio >= 0 && options.min_area_ratio < 1))
    return status::invalid_argument(
        detail::cat("polycube_options::min_area_ratio must be in [0, 1), got ", options.min_area_ratio));
  if (static_cast<index_t>(labels.size()) != num_faces(mesh))
    return status::invalid_argument(
        detail::cat("polycube labels: ", labels.size(), " labels for ", num_faces(mesh), " faces"));
  for (std::size_t f = 0; f < labels.size(); ++f)
    if (labels[f] > 5)
      return status::invalid_argument(
          detail::cat("polycube labels: face ", f, " has label ", int(labels[f]), ", outside 0..5"));
  auto m = to_tri_mesh(mesh);
  if (!m) return m.error();
  tri_mesh base = detail::polycube_base_copy(*m);
  const auto adj = face_adjacency(base);
  std::vector<std::uint8_t> lab(labels.begin(), labels.end());
  const auto cs = detail::find_polycube_charts(base, adj.neighbor, lab);
  if (auto p = detail::find_label_problem(base, adj.neighbor, cs); p.kind != detail::polycube_label_problem::none)
    return p.to_status();
  index_t bad = -1;
  std::vector<index_t> folded;
  return detail::deform_polycube(std::move(base), adj.neighbor, lab, *t, options, exec, bad, folded);
}

/// Builds the polycube map of `mesh` from `deformed`, a copy of it (same vertex count, same faces)
/// whose vertices already lie on a polycube with chart planes on the grid of `tile_size`. Each face's
/// label is read from its deformed normal. Errors: invalid_argument when the connectivity differs or a
/// deformed face is not axis-aligned (naming the face), or tile_size is not positive and finite;
/// not_converged when the deformed mesh is not a valid polycube (as build_polycube_map).
template <Mesh M, Mesh D, Executor E = serial_executor>
result<polycube_map> polycube_map_from_deformed(const M& mesh, const D& deformed, double tile_size, E&& exec = E{}) {
  if (auto s = validate_polycube_input(mesh); !s) return s;
  if (auto s = validate_mesh(deformed, "deformed mesh"); !s) return s;
  if (!(tile_size > 0) || !std::isfinite(tile_size))
    return status::invalid_argument(detail::cat("polycube: tile_size must be > 0 and finite, got ", tile_size));
  if (num_vertices(deformed) != num_vertices(mesh) || num_faces(deformed) != num_faces(mesh))
    return status::invalid_argument(detail::cat("deformed mesh: has ", num_vertices(deformed), " vertices and ",
                                                num_faces(deformed), " faces, the mesh ", num_vertices(mesh), " and ",
                                                num_faces(mesh)));
  const index_t nf = num_faces(mesh);
  std::vector<std::uint8_t> lab(detail::to_size(nf));
  for (index_t f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k)
      if (face_vertex(deformed, f, k) != face_vertex(mesh, f, k))
        return status::invalid_argument(detail::cat("deformed mesh: face ", f, " has other vertices than in the mesh"));
    const vec3 n = normalized(face_area_normal(deformed, f));
    int best = -1;
    for (int l = 0; l < 6; ++l)
      if (dot(n, label_direction(static_cast<polycube_label>(l))) > 1 - detail::axis_aligned_cos_slack) best = l;
    if (best < 0)
      return status::invalid_argument(detail::cat("deformed mesh: face ", f, " is not axis-aligned (normal ", n.x, ", ",
                                                  n.y, ", ", n.z, "): not a polycube"));
    lab[detail::to_size(f)] = static_cast<std::uint8_t>(best);
  }
  auto m = to_tri_mesh(mesh);
  if (!m) return m.error();
  auto d = to_tri_mesh(deformed);
  if (!d) return d.error();
  tri_mesh base = detail::polycube_base_copy(*m);
  const auto adj = face_adjacency(base);
  const auto cs = detail::find_polycube_charts(base, adj.neighbor, lab);
  if (auto p = detail::find_label_problem(base, adj.neighbor, cs); p.kind != detail::polycube_label_problem::none)
    return p.to_status();
  return detail::assemble_polycube_map(std::move(base), lab, std::move(d->positions), tile_size,
                                       polycube_options{}.min_area_ratio, exec);
}

TESSERA_NAMESPACE_END
