// tessera/terrain/synthesize_anchored_region.hpp: ground-anchored triangle synthesis of one
// world-anchored region (plan_anchored_regions.hpp): paper 003's stack-ordered growth (§2.3),
// moved from the screen to the ground so that the result is a pure function of (mesh, exemplar
// size, options, face).
//
//   placement a plane frame in the world (origin, unit axes u, v in the plane, normal n) plus a
//            texture offset: a vertex P of a face in the placement gets exemplar coordinates
//            ((P - origin).u, (P - origin).v) * texels_per_unit + offset. Within a plane region this
//            IS the unfolding of the faces across their neighbours, congruent; faces tilted
//            against the plane by an angle a are stretched by at most 1 / cos a across the tilt,
//            and a face joins a placement only while a <= max_tilt (default 40 degrees: 31 %).
//            Exact unfolding cannot stay continuous on a curved surface (the faces round a vertex
//            do not close up: Gauss), so the stretch is bounded instead; the coordinates of a
//            vertex are one formula per placement, so two faces of a placement agree bit for bit
//   order    a stack over face adjacency inside the region, from the region's seed face; each
//            popped face is placed and pushes its unplaced neighbours of the same region in side
//            order; when the stack and the waiting list are empty, the smallest unplaced face id of
//            the region starts the next connected part. Nothing here depends on a camera
//   first    the seed face: its own plane (u along world axis_a projected into it, v = n x u) and
//            a random offset (keyed by the face id) that puts it inside the exemplar
//   next     the placement of a placed neighbour, if the face is tilted at most max_tilt against
//            it and its coordinates stay inside the exemplar; of several, the oldest placement
//   wait     as synthesize_triangles: when none fits, the face waits once (defer_restarts)
//   restart  otherwise a new placement in the face's own plane, its offset chosen so that the
//            oldest placed neighbour's shared edge keeps its coordinates at its midpoint (a seam
//            that only shears), then shifted back into the exemplar (a random shift keyed by the
//            face id; an axis along which it fits is kept, keep_fitting_axis); sides between
//            placements are seams the renderer blends
//
// Coordinates are exemplar pixels at level 0 measured from the exemplar's centre; a face at
// pyramid level l uses uv * scale(l), the same picture pre-filtered by the level.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <cstdint>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "detail/stack_growth.hpp"
#include "plan_anchored_regions.hpp"
#include "prepare_terrain_mesh.hpp"

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

/// anchored_face_coords for face f next to face n (across f's side k) already in placement fr with
/// corners `uv_n`: the two shared corners are copied from n (the same formula gave them), the
/// third is computed.
inline tri_uv anchored_face_coords_across(const terrain_mesh& mesh, const anchored_frame& fr, std::int32_t f, int k,
                                          std::int32_t n, const tri_uv& uv_n, double tpu) {
  const auto& fv = mesh.faces[to_size(f)];
  const auto& nv = mesh.faces[to_size(n)];
  tri_uv t;
  for (std::size_t c = 0; c < 3; ++c) {
    const std::int32_t v = fv[c];
    std::size_t j = 3;
    if (c != (to_size(k) + 2) % 3) j = nv[0] == v ? 0 : nv[1] == v ? 1 : nv[2] == v ? 2 : 3;
    if (j < 3) {
      t[2 * c] = uv_n[2 * j];
      t[2 * c + 1] = uv_n[2 * j + 1];
    } else {
      const vec2 q = anchored_coord(fr, mesh.position(v), tpu);
      t[2 * c] = static_cast<float>(q.x);
      t[2 * c + 1] = static_cast<float>(q.y);
    }
  }
  return t;
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
/// Errors: region out of range, an atlas of another plan or mesh (invalid_argument). O(faces of
/// the region). The result is a pure function of (mesh, plan, exemplar size, opts, region).
inline status synthesize_anchored_region(const terrain_mesh& mesh, const anchored_regions& plan, index_t region,
                                         index_t exemplar_width, index_t exemplar_height,
                                         const anchored_synthesis_options& opts, anchored_atlas& atlas,
                                         anchored_region_stats* stats = nullptr) {
  const index_t nf = mesh.num_faces();
  if (region < 0 || region >= plan.num_regions())
    return status::invalid_argument(detail::cat("region ", region, " is not one of the plan's ", plan.num_regions()));
  if (static_cast<index_t>(atlas.uv.size()) != nf || static_cast<index_t>(atlas.patch.size()) != nf ||
      static_cast<index_t>(atlas.seam.size()) != nf || static_cast<index_t>(plan.region.size()) != nf ||
      atlas.region_done.size() != detail::to_size(plan.num_regions()))
    return status::invalid_argument(detail::cat("synthesize_anchored_region: the atlas (", atlas.uv.size(),
                                                " faces) and plan (", plan.region.size(),
                                                " faces) must belong to the mesh (", nf, " faces)"));
  anchored_region_stats st;
  if (atlas.region_done[detail::to_size(region)]) {
    if (stats) *stats = st;
    return {};
  }
  const counter_rng rng(opts.seed, stream_id("terrain.synthesize_anchored_region"));
  const double hw = 0.5 * static_cast<double>(exemplar_width) - opts.margin,
               hh = 0.5 * static_cast<double>(exemplar_height) - opts.margin;
  const auto r32 = static_cast<std::int32_t>(region);
  const std::int32_t* begin = plan.faces.data() + plan.first[detail::to_size(region)];
  const std::int32_t* end = plan.faces.data() + plan.first[detail::to_size(region) + 1];
  auto& patch = atlas.patch;
  auto mine = [&](std::int32_t n) { return n >= 0 && n < nf && plan.region[detail::to_size(n)] == r32; };
  std::vector<std::int32_t> stack, deferred;
  std::int32_t patches = 0;
  std::vector<detail::anchored_frame> frames;  // placements of this region
  const double tpu = plan.texels_per_unit, cos_tilt = std::cos(opts.max_tilt_degrees * std::numbers::pi / 180);
  const double cos2_tilt = cos_tilt * cos_tilt;
  // the region's mean plane (area-weighted normal): new placements lie in it unless the face is
  // tilted against it by more than max_tilt (then in the face's own plane)
  vec3 mean{};
  for (const std::int32_t* f = begin; f != end; ++f) {
    const auto& fv = mesh.faces[detail::to_size(*f)];
    mean += cross(mesh.position(fv[1]) - mesh.position(fv[0]), mesh.position(fv[2]) - mesh.position(fv[0]));
  }
  mean = normalized(mean);
  auto new_frame = [&](std::int32_t f) {
    detail::anchored_frame fr = detail::anchored_face_frame(mesh, plan, f);
    if (norm(mean) > 0.5 && dot(fr.n, mean) >= cos_tilt) fr = detail::anchored_plane_frame(plan, mean, fr.origin);
    return fr;
  };
  const std::int32_t seed_face = plan.seed[detail::to_size(region)];
  const std::int32_t* next_start = begin;
  // §2.3 step (2) on the ground for the popped face f: continue a placed neighbour's placement, wait,
  // or place anew
  auto place_face = [&](std::int32_t f, bool forced) {
    const auto fi = detail::to_size(f);
    if (patch[fi] >= 0) return true;
    const auto& nb = mesh.neighbors[fi];
    int placed = 0, oldest = -1;
    std::int32_t best_patch = -1, oldest_patch = std::numeric_limits<std::int32_t>::max();
    const auto& fv3 = mesh.faces[fi];
    // tilt test without a square root: n . m >= cos |n| for the face's (unnormalized) normal n
    const vec3 normal =
        cross(mesh.position(fv3[1]) - mesh.position(fv3[0]), mesh.position(fv3[2]) - mesh.position(fv3[0]));
    const double len2 = dot(normal, normal);
    auto tilted_within = [&](const vec3& m) {
      const double d = dot(normal, m);
      return len2 > 0 && d >= 0 && d * d >= cos2_tilt * len2;
    };
    detail::tri_uv best_uv{};
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = nb[detail::to_size(k)];
      if (!mine(n) || patch[detail::to_size(n)] < 0) continue;
      ++placed;
      const std::int32_t p = patch[detail::to_size(n)];
      if (p < oldest_patch) {
        oldest_patch = p;
        oldest = k;
      }
      if (best_patch >= 0 && p >= best_patch) continue;
      const auto& fr = frames[detail::to_size(p)];
      if (!tilted_within(fr.n)) continue;
      const detail::tri_uv t =
          detail::anchored_face_coords_across(mesh, fr, f, k, n, atlas.uv[detail::to_size(n)], tpu);
      if (detail::anchored_fits_axis(t, 0, hw) && detail::anchored_fits_axis(t, 1, hh)) {
        best_patch = p;
        best_uv = t;
      }
    }
    if (best_patch >= 0) {
      atlas.uv[fi] = best_uv;
      patch[fi] = best_patch;
    } else if (opts.defer_restarts && placed > 0 && !forced) {
      if (patch[fi] == -1) {
        patch[fi] = -2;
        deferred.push_back(f);
        ++st.deferred;
      }
      return true;
    } else {
      // a new placement in the face's own plane; next to a placed neighbour, the midpoint of the
      // shared edge keeps its coordinates (the seam only shears), then shifted into the exemplar
      detail::anchored_frame fr = new_frame(f);
      const double half[2] = {hw, hh};
      bool keep[2] = {false, false};
      if (oldest >= 0) {
        const auto& fv = mesh.faces[fi];
        const vec3 mid =
            (mesh.position(fv[detail::to_size(oldest)]) + mesh.position(fv[detail::to_size((oldest + 1) % 3)])) * 0.5;
        const vec2 want = detail::anchored_coord(frames[detail::to_size(oldest_patch)], mid, tpu);
        const vec2 got = detail::anchored_coord(fr, mid, tpu);
        fr.du = want.x - got.x;
        fr.dv = want.y - got.y;
        const detail::tri_uv t = detail::anchored_face_coords(mesh, fr, f, tpu);
        for (int axis = 0; axis < 2; ++axis)
          keep[axis] = opts.keep_fitting_axis && detail::anchored_fits_axis(t, axis, half[axis]);
      }
      bool big = false;
      for (int axis = 0; axis < 2; ++axis) {
        if (keep[axis]) continue;
        const detail::tri_uv t = detail::anchored_face_coords(mesh, fr, f, tpu);
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (std::size_t k = 0; k < 3; ++k) {
          lo = std::min(lo, static_cast<double>(t[2 * k + detail::to_size(axis)]));
          hi = std::max(hi, static_cast<double>(t[2 * k + detail::to_size(axis)]));
        }
        const double a = -half[axis] - lo, b = half[axis] - hi;  // feasible shifts [a, b]
        if (b < a) big = true;
        const double shift = b < a ? 0.5 * (a + b) : a + rng.uniform(f, axis) * (b - a);
        (axis == 0 ? fr.du : fr.dv) += shift;
      }
      frames.push_back(fr);
      atlas.uv[fi] = detail::anchored_face_coords(mesh, fr, f, tpu);
      patch[fi] = patches++;
      st.restarts += oldest >= 0 ? 1 : 0;
      st.oversized += big ? 1 : 0;
    }
    ++st.faces;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t n = nb[detail::to_size(k)];
      if (mine(n) && patch[detail::to_size(n)] < 0) stack.push_back(n);
    }
    return true;
  };
  while (true) {
    std::int32_t start = -1;
    if (patches == 0 && seed_face >= 0) {
      start = seed_face;
    } else {
      while (next_start != end && patch[detail::to_size(*next_start)] >= 0) ++next_start;
      if (next_start == end) break;
      start = *next_start;
    }
    stack.push_back(start);
    detail::grow_by_stack(stack, deferred, place_face);
  }
  // seams: a side is continuous when the neighbour is of this region and placement (then both
  // corners of the side have the same coordinates, one formula per placement)
  for (const std::int32_t* f = begin; f != end; ++f) {
    const auto fi = detail::to_size(*f);
    std::uint8_t bits = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t n = mesh.neighbors[fi][k];
      if (!mine(n) || patch[detail::to_size(n)] != patch[fi]) bits = static_cast<std::uint8_t>(bits | 1u << k);
    }
    atlas.seam[fi] = bits;
  }
  atlas.region_done[detail::to_size(region)] = 1;
  st.patches = patches;
  if (stats) *stats = st;
  return {};
}

TESSERA_NAMESPACE_END
