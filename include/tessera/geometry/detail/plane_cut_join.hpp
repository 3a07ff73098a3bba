// tessera/geometry/detail/plane_cut_join.hpp: the retry of a failed merge of two pieces of one long
// element (a thread), paper 000 §3.3.6 ("cut both elements along the overlap, join the loops") with
// the cut placed across the thread instead of by the eq. 8 graph cut. On thread pairs the graph cut
// (after the deformation of §3.3.5, which pulls the walls of one piece towards the flat cap of the
// other) often left cut paths that do not pair up (two loops on one side, one on the other), kept
// parts that overlap (the joined element intersects itself), or no cut at all when the pieces only
// abut (cap against cap, after an earlier merge failed). Here both pieces, undeformed (two copies of
// one thread agree where they overlap), are cut across their common long axis: C_T keeps the faces
// wholly before a plane, C_in the faces wholly past a second plane a small gap further on, and the
// two cut loops are joined by join_cut_paths (element_seam.hpp). Several plane positions along the
// overlap are tried, middle first; the first whose join passes the caller's check wins.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../mesh_elements.hpp"
#include "element_seam.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Plane positions tried, as fractions of the overlap of the two pieces along their long axis
/// (middle first).
inline constexpr std::array<double, 5> plane_cut_fractions{0.5, 0.3, 0.7, 0.15, 0.85};

/// The keep flags of a cut of `m` across `axis`: faces whose every vertex has s * coordinate below
/// `limit` (s = +1 or -1) are kept. Nothing when a held vertex (`held`) would lose a face or the cut
/// keeps all or nothing.
inline std::optional<std::vector<unsigned char>> keep_before_plane(const tri_mesh& m,
                                                                   const std::vector<unsigned char>& held, int axis,
                                                                   double s, double limit) {
  std::vector<unsigned char> keep(m.faces.size(), 0);
  std::size_t kept = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    bool before = true;
    for (index_t v : m.faces[f]) before = before && s * m.positions[to_size(v)][axis] < limit;
    if (!before)
      for (index_t v : m.faces[f])
        if (to_size(v) < held.size() && held[to_size(v)]) return std::nullopt;
    keep[f] = before ? 1 : 0;
    kept += keep[f];
  }
  if (kept == 0 || kept == m.faces.size()) return std::nullopt;
  return keep;
}

/// Settings of join_across_plane.
struct plane_cut_params {
  xy_rect domain;         ///< the quilted domain (tile) of the merge
  double gap = 0;         ///< distance between the two cut planes
  double max_offset = 0;  ///< largest sideways offset of the two pieces' boxes
  int smooth_rings = -1;  ///< seam smoothing (smooth_seam; < 0: none, the ladder joins matching loops)
};

/// Joins C_T (`ct`, held vertices `held_t`) and C_in (`cin`, `held_in`), two pieces of one thread,
/// across their common long axis (the longer XY side of the pieces' joint box): C_T keeps what lies
/// wholly before a plane at u - gap / 2, C_in what lies wholly past u + gap / 2, where u runs over
/// plane_cut_fractions of the overlap of their extents along the axis (the meeting point when they
/// only abut), and join_cut_paths stitches the two cut loops. Nothing when the pieces are not one
/// thread (their boxes sideways more than max_offset apart), when C_in does not continue C_T (it
/// must reach further along the axis at both ends), or when no position gives a joined element that
/// `accept` (the caller's merged_element_valid) takes.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::optional<texture_element> join_across_plane(const texture_element& ct, const std::vector<unsigned char>& held_t,
                                                 const texture_element& cin, const std::vector<unsigned char>& held_in,
                                                 const plane_cut_params& p,
                                                 const std::function<bool(const texture_element&)>& accept) {
  const aabb& bt = ct.box;
  const aabb& bi = cin.box;
  aabb joint = bt;
  joint.extend(bi);
  const int axis = joint.extent().x >= joint.extent().y ? 0 : 1, side = 1 - axis;
  if (std::abs(bt.min[side] - bi.min[side]) > p.max_offset || std::abs(bt.max[side] - bi.max[side]) > p.max_offset)
    return std::nullopt;
  const double ct_mid = bt.center()[axis], in_mid = bi.center()[axis];
  if (ct_mid == in_mid) return std::nullopt;
  const double s = in_mid > ct_mid ? 1.0 : -1.0;  // u = s * coordinate grows from C_T towards C_in
  auto lo = [&](const aabb& b) { return s > 0 ? b.min[axis] : -b.max[axis]; };
  auto hi = [&](const aabb& b) { return s > 0 ? b.max[axis] : -b.min[axis]; };
  if (!(lo(bt) < lo(bi) && hi(bt) < hi(bi))) return std::nullopt;
  const double from = lo(bi), to = hi(bt);  // the overlap along u (empty when they only abut)
  for (const double fr : plane_cut_fractions) {
    const double u = to > from ? from + fr * (to - from) : 0.5 * (from + to);
    if (u - 0.5 * p.gap > lo(bt) && u + 0.5 * p.gap < hi(bi)) {
      const auto keep_t = keep_before_plane(ct.mesh, held_t, axis, s, u - 0.5 * p.gap);
      const auto keep_in = keep_before_plane(cin.mesh, held_in, axis, -s, -(u + 0.5 * p.gap));  // past the plane
      if (keep_t && keep_in) {
        std::optional<texture_element> out =
            join_cut_paths(ct, ct.mesh, *keep_t, cin, cin.mesh, *keep_in, p.domain, p.smooth_rings, nullptr);
        if (out && accept(*out)) return out;
      }
    }
    if (!(to > from)) break;  // abutting pieces: one place only
  }
  return std::nullopt;
}

}  // namespace detail
TESSERA_NAMESPACE_END
