// tessera/terrain/anchored_region_geometry.hpp: what the ground-anchored growth of a region
// (synthesize_anchored_region.hpp) reads of each of its faces, gathered once per mesh: the face's
// corners and neighbours numbered inside the region, and its shape in its own plane for unfolding
// (paper 003 §2.3 places congruent triangles; on the ground a face is unfolded across a side it
// shares with a placed neighbour) and for the stretch test (texture_stretch.hpp).
//
//   side k    runs from corner k (A) to corner k + 1 (B); C is the third corner, e = B - A,
//             w = C - A. In the face's plane C = A + a e + b perp(e) with a = w.e / |e|^2 and
//             b = |e x w| / |e|^2 = area2 / |e|^2 (twice the area, the same for every side)
//   unfold    texture corners ta, tb of A and B, d = tb - ta: the third corner goes to
//             mid + (a - 1/2) f d + b f perp(d) with f = |e| tpu / |d| (the face turned about the
//             side into the texture plane), computed as g = tpu / sqrt(|e|^2 |d|^2), f = |e|^2 g
//             and b f = area2 g: one square root and one division
//   stretch   with T the texture edges (t1 - t0, t2 - t0) and G = tpu^2 [[e1.e1, e1.e2],
//             [e1.e2, e2.e2]] the Gram matrix of the face's edges e1 = p1 - p0, e2 = p2 - p0, the
//             squared singular values of the map J from the face to the texture are the
//             eigenvalues of T^T T G^-1: |J|_F^2 = tr(T^T T G^-1), det J^2 = det T^2 / det G with
//             det G = tpu^4 area2^2. With e1.e1 = |side 0|^2, e2.e2 = |side 2|^2 and e1.e2 =
//             a_0 |side 0|^2, the test "stretch <= m" needs no square root (see within)
//
// A session gathers every region once (make_anchored_geometry, O(F), in make_terrain_session) so
// that growing a region at the first frame reads one dense array in the region's order instead of
// the mesh's arrays; synthesize_anchored_region without it gathers the region itself (the same
// numbers: the result does not depend on which).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "plan_anchored_regions.hpp"
#include "prepare_terrain_mesh.hpp"

TESSERA_NAMESPACE_BEGIN

/// One face of a region as its growth reads it (see the file comment); 88 bytes.
struct anchored_face_geometry {
  std::array<std::int32_t, 3> vertices{};  ///< its corners, numbered in the region (0 .. region vertices - 1)
  std::array<std::int32_t, 3>
      neighbors{};               ///< index in the region of the face across side k (-1: none or another region)
  std::array<double, 3> a{};     ///< side k: w.e / |e|^2
  std::array<double, 3> len2{};  ///< side k: |e|^2 (0 for every side of a degenerate face)
  double area2 = 0;              ///< |e1 x e2|
  double inv_metric = 0;         ///< 1 / (texels_per_unit^2 area2^2) (0: degenerate)
};

/// The geometry of every region of a plan: faces in the plan's order (plan.faces), so region r's
/// are faces[plan.first[r] .. plan.first[r + 1]).
struct anchored_geometry {
  std::vector<anchored_face_geometry> faces;  ///< per face, in the plan's order
  std::vector<std::int32_t> vertex_count;     ///< per region: its vertices
  /// Bytes held.
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    return sizeof(anchored_face_geometry) * faces.capacity() + 4 * vertex_count.capacity();
  }
};

namespace detail {

/// The shape part of a face's geometry from its corners p (see the file comment); a degenerate or
/// non-finite face gets zeros (every side refused by anchored_unfold, every placement by within).
inline void anchored_face_shape(const std::array<vec3, 3>& p, double tpu, anchored_face_geometry& g) noexcept {
  g.a = {};
  g.len2 = {};
  g.area2 = g.inv_metric = 0;
  const double area2 = norm(cross(p[1] - p[0], p[2] - p[0]));
  const double metric = tpu * tpu * area2 * area2;
  if (!(area2 > 0) || !(metric > 0) || !std::isfinite(metric)) return;
  g.area2 = area2;
  g.inv_metric = 1 / metric;
  for (std::size_t k = 0; k < 3; ++k) {
    const vec3 e = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
    g.len2[k] = dot(e, e);
    g.a[k] = dot(w, e) / g.len2[k];
  }
}

/// Per-thread scratch of gather_anchored_region: `local` (per mesh face) and `vlocal` (per mesh
/// vertex), all -1 between calls (grown to the mesh on demand), and the region's mesh vertices.
struct anchored_gather_scratch {
  std::vector<std::int32_t> local, vlocal, vertices;
  /// Makes local and vlocal cover a mesh of nf faces and nv vertices.
  void fit(index_t nf, index_t nv) {
    if (local.size() < to_size(nf)) local.assign(to_size(nf), -1);
    if (vlocal.size() < to_size(nv)) vlocal.assign(to_size(nv), -1);
  }
};
inline anchored_gather_scratch& anchored_thread_gather_scratch() {
  thread_local anchored_gather_scratch s;
  return s;
}

/// Writes the geometry of region `r`'s faces to out[0 .. faces of r) and its mesh vertices to
/// `vertices` (indexed by region vertex number). `local` (per mesh face) and `vlocal` (per mesh
/// vertex) are sized to the mesh and all -1; they are all -1 again on return. The mesh's vertex
/// indices must be valid.
inline void gather_anchored_region(const terrain_mesh& mesh, const anchored_regions& plan, index_t r,
                                   anchored_face_geometry* out, std::vector<std::int32_t>& local,
                                   std::vector<std::int32_t>& vlocal, std::vector<std::int32_t>& vertices) {
  const std::int32_t* begin = plan.faces.data() + plan.first[to_size(r)];
  const auto nfaces = to_size(plan.first[to_size(r) + 1] - plan.first[to_size(r)]);
  const index_t nf = mesh.num_faces();
  vertices.clear();
  for (std::size_t i = 0; i < nfaces; ++i) local[to_size(begin[i])] = static_cast<std::int32_t>(i);
  for (std::size_t i = 0; i < nfaces; ++i) {
    const auto f = to_size(begin[i]);
    const auto& fv = mesh.faces[f];
    anchored_face_geometry& g = out[i];
    std::array<vec3, 3> p;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t n = mesh.neighbors[f][k];
      g.neighbors[k] = n >= 0 && n < nf ? local[to_size(n)] : -1;
      const auto v = to_size(fv[k]);
      p[k] = mesh.positions[v];
      if (vlocal[v] < 0) {
        vlocal[v] = static_cast<std::int32_t>(vertices.size());
        vertices.push_back(fv[k]);
      }
      g.vertices[k] = vlocal[v];
    }
    anchored_face_shape(p, plan.texels_per_unit, g);
  }
  for (std::size_t i = 0; i < nfaces; ++i) local[to_size(begin[i])] = -1;
  for (const std::int32_t v : vertices) vlocal[to_size(v)] = -1;
}

/// Unfolds face g across its side k from texture coordinates ta, tb of the side's corners (see the
/// file comment): out[k] = ta, out[k + 1] = tb, out[k + 2] the third corner. With `exact` the two
/// side corners are instead rebuilt from the side's midpoint and direction so that the whole face is
/// congruent (a new placement next to a neighbour whose side is slightly stretched). False for a
/// degenerate side or texture side.
inline bool anchored_unfold(const anchored_face_geometry& g, int k, vec2 ta, vec2 tb, double tpu, bool exact,
                            std::array<vec2, 3>& out) noexcept {
  const auto ks = to_size(k);
  const vec2 d = tb - ta;
  const double len2 = g.len2[ks], tlen2 = d.x * d.x + d.y * d.y;
  if (!(len2 > 0) || !(tlen2 > 0)) return false;
  const double s = tpu / std::sqrt(len2 * tlen2);
  const double f = len2 * s, bf = g.area2 * s;  // |e| tpu / |d|, and b times it
  const vec2 n{-d.y, d.x}, mid = (ta + tb) * 0.5;
  const vec2 c = mid + d * ((g.a[ks] - 0.5) * f) + n * bf;
  if (exact) {
    ta = mid - d * (0.5 * f);
    tb = mid + d * (0.5 * f);
  }
  out[ks] = ta;
  out[to_size((k + 1) % 3)] = tb;
  out[to_size((k + 2) % 3)] = c;
  return true;
}

/// Whether the squared singular values of a 2 x 2 map J, the roots of x^2 - q x + d2 with q =
/// |J|_F^2 and d2 = det J^2, both lie in [1 / m^2, m^2] (stretch at most m, texture_stretch.hpp).
inline bool anchored_singular_within(double q, double d2, double max_stretch) noexcept {
  const double hi = max_stretch * max_stretch, lo = 1 / hi;
  // a monic quadratic with real roots has both in [lo, hi] iff its vertex q / 2 lies in [lo, hi]
  // and it is >= 0 at both ends
  return q <= 2 * hi && q >= 2 * lo && hi * hi - q * hi + d2 >= 0 && lo * lo - q * lo + d2 >= 0;
}

/// Whether texture corners `uv` (u0 v0 u1 v1 u2 v2, level-0 texels) on face g are stretched by at
/// most max_stretch (>= 1; texture_stretch.hpp's measure), without a square root: both squared
/// singular values of J, the roots of x^2 - |J|_F^2 x + det J^2, in [1 / m^2, m^2] (see the file
/// comment). A mirrored or degenerate placement (det T <= 0) or face never is.
inline bool anchored_within(const anchored_face_geometry& g, const std::array<float, 6>& uv,
                            double max_stretch) noexcept {
  if (!(g.inv_metric > 0)) return false;
  const double u1 = static_cast<double>(uv[2]) - uv[0], v1 = static_cast<double>(uv[3]) - uv[1];
  const double u2 = static_cast<double>(uv[4]) - uv[0], v2 = static_cast<double>(uv[5]) - uv[1];
  const double det_t = u1 * v2 - u2 * v1;
  if (!(det_t > 0)) return false;
  const double r = g.inv_metric;
  // tr(T^T T G^-1) with G^-1 = r [[e2.e2, -e1.e2], [-e1.e2, e1.e1]], r = 1 / (tpu^2 area2^2)
  const double q = ((u1 * u1 + v1 * v1) * g.len2[2] - 2 * (u1 * u2 + v1 * v2) * g.a[0] * g.len2[0] +
                    (u2 * u2 + v2 * v2) * g.len2[0]) *
                   r;
  const double d2 = det_t * det_t * (r * g.area2) * (r * g.area2);  // det T^2 / det G, det G = tpu^4 area2^2
  return anchored_singular_within(q, d2, max_stretch);
}

}  // namespace detail

/// Gathers the geometry of every region of `plan` (see the file comment), in parallel over
/// regions through `exec` (the same result for any executor). Errors (invalid_argument): a plan of
/// another mesh, a mesh failing validate_terrain_mesh. O(F).
template <Executor E = serial_executor>
result<anchored_geometry> make_anchored_geometry(const terrain_mesh& mesh, const anchored_regions& plan,
                                                 E&& exec = {}) {
  if (static_cast<index_t>(plan.region.size()) != mesh.num_faces() ||
      plan.first.size() != detail::to_size(plan.num_regions()) + 1)
    return status::invalid_argument(detail::cat("make_anchored_geometry: the plan (", plan.region.size(),
                                                " faces) must belong to the mesh (", mesh.num_faces(), " faces)"));
  if (auto s = validate_terrain_mesh(mesh); !s) return s;
  anchored_geometry g;
  g.faces.resize(plan.faces.size());
  g.vertex_count.assign(detail::to_size(plan.num_regions()), 0);
  const index_t nr = plan.num_regions();
  constexpr index_t chunk = 16;  // regions per task
  exec.parallel_for(0, (nr + chunk - 1) / chunk, [&](index_t c) {
    detail::anchored_gather_scratch& scr = detail::anchored_thread_gather_scratch();
    scr.fit(mesh.num_faces(), mesh.num_vertices());
    for (index_t r = c * chunk; r < std::min(nr, (c + 1) * chunk); ++r) {
      detail::gather_anchored_region(mesh, plan, r, g.faces.data() + plan.first[detail::to_size(r)], scr.local,
                                     scr.vlocal, scr.vertices);
      g.vertex_count[detail::to_size(r)] = static_cast<std::int32_t>(scr.vertices.size());
    }
  });
  return g;
}

TESSERA_NAMESPACE_END
