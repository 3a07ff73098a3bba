// tessera/terrain/texture_stretch.hpp: how far a face's texture is from a congruent copy of the face
// (paper 003 §2.3 textures every triangle by a congruent triangle of the exemplar: no stretching on
// slopes). The measure of a face with corners a, b, c (world) and texture corners t0, t1, t2 (texels)
// at a density of `texels_per_unit` texels per world unit:
//
//   J        the affine map from the face's own plane (an orthonormal frame of the plane, world units
//            times texels_per_unit) to the texture plane, J [p1 - p0, p2 - p0] = [t1 - t0, t2 - t0]
//   s1 >= s2 its singular values: the largest and smallest factor by which J scales a direction
//   stretch  max(s1, 1 / s2): 1 if and only if the texture is a congruent copy of the face (a
//            rotation plus a translation); 1.05 means some direction is stretched or compressed by
//            5 %. +infinity for a degenerate face or texture and for a mirrored texture (det J <= 0).
//
// Unlike the anisotropy s1 / s2 it also counts a uniform scaling as stretch (a similar but not
// congruent copy). terrain_session_stretch summarizes it over the faces a session shows (texture
// coordinates divided by their level's scale, so the measure is in level-0 texels).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/vec.hpp"
#include "prepare_terrain_mesh.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// A triangle in its own plane: corner 0 at the origin, corner 1 at (l1, 0), corner 2 at (x2, y2)
/// with y2 > 0 (counter-clockwise about the normal its corner order gives); l1 = 0 or y2 = 0 for a
/// degenerate triangle.
struct plane_triangle {
  double l1 = 0, x2 = 0, y2 = 0;
};
inline plane_triangle to_plane_triangle(const vec3& a, const vec3& b, const vec3& c) noexcept {
  const vec3 e1 = b - a, e2 = c - a;
  const double l1 = norm(e1), cr = norm(cross(e1, e2));
  if (!(l1 > 0) || !(cr > 0)) return {};
  return {l1, dot(e2, e1) / l1, cr / l1};
}
/// The stretch of texture corners `uv` on triangle `p` at `texels_per_unit` (see the file comment).
inline double plane_triangle_stretch(const plane_triangle& p, const std::array<float, 6>& uv,
                                     double texels_per_unit) noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!(p.l1 > 0) || !(p.y2 > 0) || !(texels_per_unit > 0)) return inf;
  const double s = texels_per_unit;
  const double u1 = static_cast<double>(uv[2]) - uv[0], v1 = static_cast<double>(uv[3]) - uv[1];
  const double u2 = static_cast<double>(uv[4]) - uv[0], v2 = static_cast<double>(uv[5]) - uv[1];
  // J = T P^-1 with P = s [[l1, x2], [0, y2]], T = [[u1, u2], [v1, v2]]
  const double i11 = 1 / (s * p.l1), i12 = -p.x2 / (s * p.l1 * p.y2), i22 = 1 / (s * p.y2);
  const double j11 = u1 * i11, j12 = u1 * i12 + u2 * i22, j21 = v1 * i11, j22 = v1 * i12 + v2 * i22;
  const double det = j11 * j22 - j12 * j21;
  if (!(det > 0)) return inf;
  // singular values of a 2 x 2 matrix: s1 +- s2 = sqrt(|J|_F^2 +- 2 det)
  const double q = j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22;
  const double hi = std::sqrt(q + 2 * det), lo = std::sqrt(std::max(0.0, q - 2 * det));
  const double s1 = 0.5 * (hi + lo), s2 = 0.5 * (hi - lo);
  return s2 > 0 ? std::max(s1, 1 / s2) : inf;
}
}  // namespace detail

/// The stretch (see the file comment) of texture corners `uv` (u0 v0 u1 v1 u2 v2, texels) on the
/// triangle a, b, c at `texels_per_unit` (> 0).
inline double triangle_stretch(const vec3& a, const vec3& b, const vec3& c, const std::array<float, 6>& uv,
                               double texels_per_unit) noexcept {
  return detail::plane_triangle_stretch(detail::to_plane_triangle(a, b, c), uv, texels_per_unit);
}

/// The stretch of face f of `mesh` textured by `uv` at `texels_per_unit`.
inline double face_stretch(const terrain_mesh& mesh, index_t f, const std::array<float, 6>& uv,
                           double texels_per_unit) noexcept {
  const auto& fv = mesh.faces[detail::to_size(f)];
  return triangle_stretch(mesh.position(fv[0]), mesh.position(fv[1]), mesh.position(fv[2]), uv, texels_per_unit);
}

/// Distribution of the stretch over a set of faces.
struct stretch_summary {
  index_t faces = 0;  ///< faces measured
  /// Quantiles of the stretch (1 when no face was measured).
  double median = 1, p95 = 1, p99 = 1, max = 1;
  double over_1_percent = 0;  ///< fraction of the faces stretched by more than 1 %
};

/// Summarizes the stretch values in `s` (reordered).
inline stretch_summary summarize_stretch(std::vector<double>& s) {
  stretch_summary out;
  out.faces = static_cast<index_t>(s.size());
  if (s.empty()) return out;
  std::sort(s.begin(), s.end());
  auto q = [&](double p) {
    return s[std::min(s.size() - 1, static_cast<std::size_t>(p * static_cast<double>(s.size() - 1) + 0.5))];
  };
  out.median = q(0.5);
  out.p95 = q(0.95);
  out.p99 = q(0.99);
  out.max = s.back();
  out.over_1_percent =
      static_cast<double>(s.end() - std::upper_bound(s.begin(), s.end(), 1.01)) / static_cast<double>(s.size());
  return out;
}

TESSERA_NAMESPACE_END
