// tessera/terrain/synthesize_anchored_region.hpp: ground-anchored triangle synthesis of one
// world-anchored region (plan_anchored_regions.hpp): paper 003's face-to-neighbour growth (§2.3),
// moved from the screen to the ground so that the result is a pure function of (mesh, exemplar
// size, options, face).
//
//   congruent the paper copies each triangle congruently into the exemplar (on the screen a
//            translation). On the ground a face is UNFOLDED across the side it shares with a placed
//            neighbour: the shared corners keep the neighbour's coordinates (copied, bit for bit),
//            the third corner is put where the face, turned about the shared side into the texture
//            plane, puts it: a congruent copy of the face in its own plane, whatever its slope
//   placement the faces grown from one start; a vertex has ONE coordinate per placement (a small
//            table per region), so faces of a placement agree bit for bit on their shared corners.
//            On curved ground unfolding does not close up round a vertex (the angle defect, Gauss):
//            when the third corner already has a coordinate in the placement, the face takes it and
//            is then not quite congruent; it joins only if its stretch (texture_stretch.hpp) stays
//            at most max_stretch (default 1.55; with the relaxation relax_join_stretch, 2), else it
//            is a seam (another neighbour's placement,
//            or a new placement)
//   order    the paper's growth over face adjacency inside the region, from the region's seed
//            face: each face taken up is placed and adds its unplaced neighbours of the same region
//            in side order; when none are left (and the waiting list is empty), the smallest
//            unplaced face id of the region starts the next connected part. By default the faces
//            are taken up oldest first (a queue, breadth_first): the region grows in rings, and a
//            loop of faces closes next to where it opened, with a small unfolding mismatch; the
//            paper's stack (newest first) snakes away and closes loops far from where they opened,
//            where the mismatch has grown with the curvature in between (more faces fail
//            max_stretch: more seams). Nothing here depends on a camera
//   first    the seed face: its own plane (u along world axis_a projected into it, v = n x u) and
//            a random offset (keyed by the face id) that puts it inside the exemplar
//   next     the placement of a placed neighbour, if the face's coordinates there stay inside the
//            exemplar and within max_stretch; of several, the oldest placement
//   wait     as synthesize_triangles: when none fits, the face waits once (defer_restarts)
//   restart  otherwise a new placement: the face unfolded congruently from its oldest placed
//            neighbour, then shifted back into the exemplar (a random shift keyed by the face id;
//            an axis along which it fits is kept, keep_fitting_axis), so the seam is a translation
//            along one axis (none at all where the face only failed max_stretch); sides between
//            placements (and between regions) are seams the renderer blends
//   relax    after the growth (relax_iterations > 0, the default; the growth then joins faces up to
//            relax_join_stretch, so more loops close), the faces it left stretched beyond relax_above
//            are relaxed with the vertices round them (detail/relax_anchored_region.hpp: bounded
//            as-rigid-as-possible steps that spread a loop's mismatch over its neighbours, move
//            every placement's coordinate of a vertex alike and so change no edge's continuity,
//            keep the coordinates in the exemplar and every face within the growth's bound)
//   settle   then a face still stretched beyond min(max_stretch, relaxed_max_stretch) becomes a
//            placement of its own:
//            congruent, unfolded across its first side that continues its placement (exactly, as
//            a restart), shifted into the exemplar only if it leaves it. So every face ends within
//            min(max_stretch, relaxed_max_stretch), at the price of the seams round those faces
//
// Coordinates are exemplar pixels at level 0 measured from the exemplar's centre; a face at
// pyramid level l uses uv * scale(l), the same picture pre-filtered by the level.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "detail/anchored_vertex_table.hpp"
#include "detail/relax_anchored_region.hpp"
#include "detail/stack_growth.hpp"
#include "anchored_region_geometry.hpp"
#include "plan_anchored_regions.hpp"
#include "prepare_terrain_mesh.hpp"
#include "texture_stretch.hpp"

TESSERA_NAMESPACE_BEGIN

/// Per-face ground-anchored coordinates of the regions grown so far (indexed like the mesh).
struct anchored_atlas {
  std::vector<std::array<float, 6>> uv;   ///< u0 v0 u1 v1 u2 v2, exemplar pixels from its centre (level 0)
  std::vector<std::int32_t> patch;        ///< placement within the face's region (-1: region not grown)
  std::vector<std::uint8_t> seam;         ///< bit k: side k borders another placement, region or nothing
  std::vector<std::uint8_t> region_done;  ///< per region: grown
  /// Bytes held.
  [[nodiscard]] std::size_t memory_bytes() const noexcept { return 29 * uv.size() + region_done.size(); }
};

/// What growing a region did.
struct anchored_region_stats {
  /// Faces placed, placements made, restarts, deferred faces, faces larger than their level image.
  index_t faces = 0, patches = 0, restarts = 0, deferred = 0, oversized = 0;
  /// Faces the growth left stretched beyond relax_above (or the final bound if smaller), free
  /// vertices of the relaxation (summed over its passes), faces made placements of their own after it.
  index_t hot = 0, relaxed = 0, settled = 0;
};

/// Empties `atlas` for `plan` over a mesh of `faces` faces (no region grown).
inline void reset_anchored_atlas(const anchored_regions& plan, index_t faces, anchored_atlas& atlas) {
  atlas.uv.assign(detail::to_size(faces), {});
  atlas.patch.assign(detail::to_size(faces), -1);
  atlas.seam.assign(detail::to_size(faces), 7);
  atlas.region_done.assign(detail::to_size(plan.num_regions()), 0);
}

namespace detail {
using tri_uv = std::array<float, 6>;

/// A face whose normal is within this (the norm of the axis' projection) of world axis_a takes u
/// along axis_b instead: the projection of axis_a into its plane is too short to give a direction.
inline constexpr double anchored_axis_min_projection = 1e-6;
/// Plane axes shorter than this mean a degenerate face (no normal): the plain world axes are used.
inline constexpr double anchored_degenerate_axis = 1e-12;

/// A placement: world plane frame and texture offset (see the file comment).
struct anchored_frame {
  vec3 origin, u, v, n;
  double du = 0, dv = 0;
};

/// The frame of the plane through `origin` with unit normal n: u along world axis_a projected into
/// it, v = n x u (a plane containing neither axis direction: the plain axes).
inline anchored_frame anchored_plane_frame(const anchored_regions& plan, const vec3& n, const vec3& origin) {
  anchored_frame fr;
  fr.n = n;
  const vec3 ea = plan.axis_a == 0 ? vec3{1, 0, 0} : plan.axis_a == 1 ? vec3{0, 1, 0} : vec3{0, 0, 1};
  const vec3 eb = plan.axis_b == 0 ? vec3{1, 0, 0} : plan.axis_b == 1 ? vec3{0, 1, 0} : vec3{0, 0, 1};
  vec3 u = ea - fr.n * dot(ea, fr.n);
  if (norm(u) < anchored_axis_min_projection) u = eb - fr.n * dot(eb, fr.n);
  vec3 v = cross(fr.n, u);
  if (!(norm(u) > anchored_degenerate_axis) || !(norm(v) > anchored_degenerate_axis)) {  // degenerate face
    u = ea;
    v = eb;
    fr.n = cross(ea, eb);
  }
  fr.u = normalized(u);
  fr.v = normalized(v);
  fr.origin = origin;
  return fr;
}

/// The plane frame of face f (through its centroid).
inline anchored_frame anchored_face_frame(const terrain_mesh& mesh, const anchored_regions& plan, std::int32_t f) {
  const auto& fv = mesh.faces[to_size(f)];
  const vec3 a = mesh.position(fv[0]), b = mesh.position(fv[1]), c = mesh.position(fv[2]);
  return anchored_plane_frame(plan, normalized(cross(b - a, c - a)), mesh.centroids[to_size(f)]);
}

/// Exemplar coordinates of world point p in placement fr.
inline vec2 anchored_coord(const anchored_frame& fr, const vec3& p, double tpu) {
  const vec3 d = p - fr.origin;
  return {dot(d, fr.u) * tpu + fr.du, dot(d, fr.v) * tpu + fr.dv};
}

/// The corners of face f in placement fr (each vertex by the same formula: bit-identical between faces).
inline tri_uv anchored_face_coords(const terrain_mesh& mesh, const anchored_frame& fr, std::int32_t f, double tpu) {
  tri_uv t;
  for (std::size_t k = 0; k < 3; ++k) {
    const vec2 c = anchored_coord(fr, mesh.position(mesh.faces[to_size(f)][k]), tpu);
    t[2 * k] = static_cast<float>(c.x);
    t[2 * k + 1] = static_cast<float>(c.y);
  }
  return t;
}

/// What growing a region needs besides the atlas, kept per thread between calls (regions grow in
/// parallel; allocating it per region would cost more than growing a small one): the order's
/// queue (or stack) and waiting list, the vertex table, the region's geometry when the caller has
/// none gathered, and per face of the region its placement and the table entries of its corners
/// (their coordinates in its placement).
struct anchored_scratch {
  std::vector<std::int32_t> order, deferred, patch, hot;
  std::vector<std::array<std::int32_t, 3>> corners;
  std::vector<anchored_face_geometry> geometry;
  anchored_vertex_table table;
  anchored_relax_scratch relax;
  unsigned char touched = 0;  ///< keeps the reading of the geometry before the growth
};
inline anchored_scratch& anchored_thread_scratch() {
  thread_local anchored_scratch s;
  return s;
}

inline bool anchored_fits_axis(const tri_uv& t, int axis, double half) noexcept {
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(static_cast<double>(t[to_size(2 * k + axis)])) <= half)) return false;
  return true;
}
}  // namespace detail

/// Grows region `region` of `plan` (see the file comment) into `atlas` (reset with
/// reset_anchored_atlas for this plan and mesh); does nothing if it is grown already. Only the
/// region's own faces are read and written, so distinct regions may be grown in parallel.
/// `geometry`: the plan's make_anchored_geometry, or null to gather the region's (the same result).
/// Errors: region out of range, an atlas or geometry of another plan or mesh (invalid_argument).
/// O(faces of the region). The result is a pure function of (mesh, plan, exemplar size, opts, region).
inline status synthesize_anchored_region(const terrain_mesh& mesh, const anchored_regions& plan, index_t region,
                                         index_t exemplar_width, index_t exemplar_height,
                                         const anchored_synthesis_options& opts, anchored_atlas& atlas,
                                         anchored_region_stats* stats = nullptr,
                                         const anchored_geometry* geometry = nullptr) {
  const index_t nf = mesh.num_faces();
  if (region < 0 || region >= plan.num_regions())
    return status::invalid_argument(detail::cat("region ", region, " is not one of the plan's ", plan.num_regions()));
  if (static_cast<index_t>(atlas.uv.size()) != nf || static_cast<index_t>(atlas.patch.size()) != nf ||
      static_cast<index_t>(atlas.seam.size()) != nf || static_cast<index_t>(plan.region.size()) != nf ||
      atlas.region_done.size() != detail::to_size(plan.num_regions()))
    return status::invalid_argument(detail::cat("synthesize_anchored_region: the atlas (", atlas.uv.size(),
                                                " faces) and plan (", plan.region.size(),
                                                " faces) must belong to the mesh (", nf, " faces)"));
  if (geometry && (geometry->faces.size() != plan.faces.size() ||
                   geometry->vertex_count.size() != detail::to_size(plan.num_regions())))
    return status::invalid_argument(detail::cat(
        "synthesize_anchored_region: the geometry (", geometry->faces.size(), " faces, ", geometry->vertex_count.size(),
        " regions) must belong to the plan (", plan.faces.size(), " faces, ", plan.num_regions(), " regions)"));
  anchored_region_stats st;
  if (atlas.region_done[detail::to_size(region)]) {
    if (stats) *stats = st;
    return {};
  }
  const counter_rng rng(opts.seed, stream_id("terrain.synthesize_anchored_region"));
  const double hw = 0.5 * static_cast<double>(exemplar_width) - opts.margin,
               hh = 0.5 * static_cast<double>(exemplar_height) - opts.margin;
  const std::int32_t* begin = plan.faces.data() + plan.first[detail::to_size(region)];
  const std::int32_t* end = plan.faces.data() + plan.first[detail::to_size(region) + 1];
  const auto nfaces = detail::to_size(end - begin);
  detail::anchored_scratch& scr = detail::anchored_thread_scratch();
  // the region's faces as dense arrays by their index i in the region (faces ascend): the growth
  // reads a few hundred kilobytes in cache instead of the mesh's arrays at random
  const anchored_face_geometry* geo = nullptr;
  std::size_t nvertices = 0;
  if (geometry) {
    geo = geometry->faces.data() + plan.first[detail::to_size(region)];
    nvertices = detail::to_size(geometry->vertex_count[detail::to_size(region)]);
    // read in order once: the growth below visits the faces in breadth-first order, at random
    // within the region, which would otherwise wait for memory face by face
    const auto* words = reinterpret_cast<const unsigned char*>(geo);
    unsigned char touch = 0;
    for (std::size_t b = 0; b < nfaces * sizeof(anchored_face_geometry); b += 64) touch |= words[b];
    scr.touched = touch;
  } else {
    detail::anchored_gather_scratch& gs = detail::anchored_thread_gather_scratch();
    gs.fit(nf, mesh.num_vertices());
    scr.geometry.resize(nfaces);
    detail::gather_anchored_region(mesh, plan, region, scr.geometry.data(), gs.local, gs.vlocal, gs.vertices);
    geo = scr.geometry.data();
    nvertices = gs.vertices.size();
  }
  // the same for the faces' coordinates, written in that order (the region's faces ascend)
  for (std::size_t i = 0; i < nfaces; i += 2) __builtin_prefetch(atlas.uv.data() + begin[i], 1);
  auto& queue = scr.order;
  auto& deferred = scr.deferred;
  auto& table = scr.table;
  auto& corners = scr.corners;  // per i: table entries of its corners
  auto& lpatch = scr.patch;     // per i: placement (-1 unplaced, -2 waiting)
  const bool relax = opts.relax_iterations > 0;
  // with the relaxation, the growth joins faces up to relax_join_stretch (loops close: continuity),
  // and the faces left beyond the final bound are settled after it
  const double tpu = plan.texels_per_unit,
               max_stretch = relax ? std::max(opts.max_stretch, opts.relax_join_stretch) : opts.max_stretch;
  const double final_stretch = std::min(opts.max_stretch, opts.relaxed_max_stretch);
  queue.clear();
  table.reset(nvertices);
  corners.resize(nfaces);
  lpatch.assign(nfaces, -1);
  std::int32_t patches = 0;
  const double hot_above = std::min(opts.relax_above, final_stretch);
  auto& hot = scr.hot;
  hot.clear();
  const std::int32_t seed_face = plan.seed[detail::to_size(region)];
  std::size_t next_start = 0;
  auto fits = [&](const detail::tri_uv& t) {
    return detail::anchored_fits_axis(t, 0, hw) && detail::anchored_fits_axis(t, 1, hh);
  };
  // the placement's coordinates are kept in double; a face's corners are their rounding to float
  // (so faces sharing a corner in a placement agree bit for bit)
  auto to_uv = [](const std::array<vec2, 3>& c3) {
    detail::tri_uv t;
    for (std::size_t c = 0; c < 3; ++c)
      t[2 * c] = static_cast<float>(c3[c].x), t[2 * c + 1] = static_cast<float>(c3[c].y);
    return t;
  };
  // the corner of neighbour n (a region index) holding vertex v (n shares a side with the face)
  auto corner_of = [&](std::int32_t n, std::int32_t v) {
    const auto& nv = geo[detail::to_size(n)].vertices;
    return nv[0] == v ? std::size_t{0} : nv[1] == v ? std::size_t{1} : std::size_t{2};
  };
  // a new placement for face i of the region: the face congruent, unfolded across its side `side`
  // from the placed neighbour there (or, with side -1, in its own plane's world-anchored frame),
  // then shifted into the exemplar; true if it is larger than the exemplar
  auto new_placement = [&](std::int32_t i, int side) {
    const auto li = detail::to_size(i);
    const auto f = begin[li];
    const anchored_face_geometry& shape = geo[li];
    const auto& fv = shape.vertices;
    const double half[2] = {hw, hh};
    bool keep[2] = {false, false};
    std::array<vec2, 3> c3;
    bool have = false;
    if (side >= 0) {
      const std::int32_t n = shape.neighbors[detail::to_size(side)];
      const auto& cn = corners[detail::to_size(n)];
      have = detail::anchored_unfold(shape, side, table.coord(cn[corner_of(n, fv[detail::to_size(side)])]),
                                     table.coord(cn[corner_of(n, fv[detail::to_size((side + 1) % 3)])]), tpu, true, c3);
      if (have)
        for (int axis = 0; axis < 2; ++axis)
          keep[axis] = opts.keep_fitting_axis && detail::anchored_fits_axis(to_uv(c3), axis, half[axis]);
    }
    if (!have) {
      const detail::anchored_frame own = detail::anchored_face_frame(mesh, plan, f);
      for (std::size_t c = 0; c < 3; ++c)
        c3[c] = detail::anchored_coord(own, mesh.position(mesh.faces[detail::to_size(f)][c]), tpu);
    }
    bool big = false;
    for (int axis = 0; axis < 2; ++axis) {
      if (keep[axis]) continue;
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (std::size_t c = 0; c < 3; ++c) lo = std::min(lo, c3[c][axis]), hi = std::max(hi, c3[c][axis]);
      const double a = -half[axis] - lo, b = half[axis] - hi;  // feasible shifts [a, b]
      if (b < a) big = true;
      const double shift = b < a ? 0.5 * (a + b) : a + rng.uniform(f, axis) * (b - a);
      for (std::size_t c = 0; c < 3; ++c) c3[c][axis] += shift;
    }
    auto& ce = corners[li];
    for (std::size_t c = 0; c < 3; ++c) table.use(ce[c] = table.insert(fv[c], patches, c3[c]));
    atlas.uv[detail::to_size(f)] = to_uv(c3);
    lpatch[li] = patches++;
    return big;
  };
  // §2.3 step (2) on the ground for face i of the region taken up: continue a placed neighbour's
  // placement, wait, or place anew
  auto place_face = [&](std::int32_t i, bool forced) {
    const auto li = detail::to_size(i);
    if (lpatch[li] >= 0) return true;
    const auto f = begin[li];
    const anchored_face_geometry& shape = geo[li];
    const auto& nb = shape.neighbors;
    const auto& fv = shape.vertices;
    int placed = 0, oldest = -1;
    std::int32_t best_patch = -1, oldest_patch = std::numeric_limits<std::int32_t>::max();
    detail::tri_uv best_uv{};
    std::array<vec2, 3> best_c3;
    std::array<std::int32_t, 3> best_entries{};  // of the corners k, k + 1, k + 2 of side best_side
    int best_side = 0;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = nb[detail::to_size(k)];
      if (n < 0 || lpatch[detail::to_size(n)] < 0) continue;
      ++placed;
      const std::int32_t p = lpatch[detail::to_size(n)];
      if (p < oldest_patch) {
        oldest_patch = p;
        oldest = k;
      }
      if (best_patch >= 0 && p >= best_patch) continue;
      // unfolded across side k from n (n's corners are the placement's coordinates of the shared
      // vertices); the third corner takes the placement's coordinate if it has one
      const auto& cn = corners[detail::to_size(n)];
      const std::int32_t va = fv[detail::to_size(k)], vb = fv[detail::to_size((k + 1) % 3)],
                         vc = fv[detail::to_size((k + 2) % 3)];
      const std::int32_t ea = cn[corner_of(n, va)], eb = cn[corner_of(n, vb)];
      std::array<vec2, 3> c3;
      if (!detail::anchored_unfold(shape, k, table.coord(ea), table.coord(eb), tpu, false, c3)) continue;
      const std::size_t kc = detail::to_size((k + 2) % 3);
      const std::int32_t known = table.find(vc, p);
      if (known >= 0) c3[kc] = table.coord(known);
      const detail::tri_uv t = to_uv(c3);
      if (!fits(t)) continue;
      if (!detail::anchored_within(shape, t, max_stretch)) continue;
      best_patch = p;
      best_uv = t;
      best_c3 = c3;
      best_entries = {ea, eb, known};
      best_side = k;
    }
    if (best_patch >= 0) {
      atlas.uv[detail::to_size(f)] = best_uv;
      lpatch[li] = best_patch;
      // the one corner the placement did not hold yet (the other two came from the neighbour)
      const std::size_t kc = detail::to_size((best_side + 2) % 3);
      if (best_entries[2] < 0) best_entries[2] = table.insert(fv[kc], best_patch, best_c3[kc]);
      auto& ce = corners[li];
      for (std::size_t j = 0; j < 3; ++j) ce[(detail::to_size(best_side) + j) % 3] = best_entries[j];
      for (const std::int32_t e : best_entries) table.use(e);
      if (relax && !detail::anchored_within(shape, best_uv, hot_above)) hot.push_back(i);
    } else if (opts.defer_restarts && placed > 0 && !forced) {
      if (lpatch[li] == -1) {
        lpatch[li] = -2;
        deferred.push_back(i);
        ++st.deferred;
      }
      return true;
    } else {
      st.oversized += new_placement(i, oldest) ? 1 : 0;
      st.restarts += oldest >= 0 ? 1 : 0;
    }
    ++st.faces;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = nb[detail::to_size(k)];
      if (n >= 0 && lpatch[detail::to_size(n)] < 0) queue.push_back(n);
    }
    return true;
  };
  while (true) {
    std::int32_t start = -1;
    if (patches == 0 && seed_face >= 0) {
      start = static_cast<std::int32_t>(std::lower_bound(begin, end, seed_face) - begin);
    } else {
      while (next_start < nfaces && lpatch[next_start] >= 0) ++next_start;
      if (next_start == nfaces) break;
      start = static_cast<std::int32_t>(next_start);
    }
    queue.push_back(start);
    if (opts.breadth_first)
      detail::grow_by_queue(queue, deferred, place_face);
    else
      detail::grow_by_stack(queue, deferred, place_face);
  }
  // the relaxation round the faces left stretched (detail/relax_anchored_region.hpp); the faces
  // round the moved vertices take their corners from the table again. Then a face still stretched
  // beyond relaxed_max_stretch becomes a placement of its own, a congruent copy unfolded across
  // its first side that continues its placement (a seam round it, nearly continuous there)
  st.hot = static_cast<index_t>(hot.size());
  if (relax && !hot.empty()) {
    const detail::anchored_relax_region reg{geo, lpatch.data(), corners.data(), nfaces, nvertices};
    const detail::anchored_relax_settings set{.iterations = opts.relax_iterations,
                                              .rings = opts.relax_rings,
                                              .passes = opts.relax_passes,
                                              .above = opts.relax_above,
                                              .max_stretch = max_stretch,
                                              .half_w = hw,
                                              .half_h = hh,
                                              .texels_per_unit = tpu};
    scr.relax.hot.assign(hot.begin(), hot.end());
    st.relaxed = static_cast<index_t>(detail::relax_anchored_region(reg, table, set, scr.relax));
    for (const std::int32_t i : scr.relax.changed) {
      const auto& ce = corners[detail::to_size(i)];
      atlas.uv[detail::to_size(begin[detail::to_size(i)])] = table.face_uv(ce);
    }
    if (final_stretch < max_stretch) {
      const std::int32_t first_own = patches;
      auto settle = [&](std::int32_t i) {
        const auto li = detail::to_size(i);
        if (lpatch[li] >= first_own ||
            detail::anchored_within(geo[li], atlas.uv[detail::to_size(begin[li])], final_stretch))
          return;
        int side = -1;
        for (int k = 0; k < 3 && side < 0; ++k) {
          const std::int32_t n = geo[li].neighbors[detail::to_size(k)];
          if (n >= 0 && lpatch[detail::to_size(n)] == lpatch[li]) side = k;
        }
        st.oversized += new_placement(i, side) ? 1 : 0;
        ++st.settled;
      };
      for (const std::int32_t i : hot) settle(i);
      for (const std::int32_t i : scr.relax.changed) settle(i);
    }
  }
  st.patches = patches;
  // placements and seams: a side is continuous when the neighbour is of this region and of the
  // same placement (every corner of a face in placement p is the table's entry (vertex, p), so both
  // shared corners have the same coordinates, bit for bit)
  for (std::size_t i = 0; i < nfaces; ++i) {
    const auto fi = detail::to_size(begin[i]);
    atlas.patch[fi] = lpatch[i];
    std::uint8_t bits = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t n = geo[i].neighbors[k];
      if (n < 0 || lpatch[detail::to_size(n)] != lpatch[i]) bits = static_cast<std::uint8_t>(bits | 1u << k);
    }
    atlas.seam[fi] = bits;
  }
  atlas.region_done[detail::to_size(region)] = 1;
  if (stats) *stats = st;
  return {};
}

TESSERA_NAMESPACE_END
