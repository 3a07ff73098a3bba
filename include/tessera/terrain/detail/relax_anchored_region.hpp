// tessera/terrain/detail/relax_anchored_region.hpp: a bounded as-rigid-as-possible relaxation of a
// grown region (synthesize_anchored_region.hpp) where its unfolding closed loops stretched.
//
// The greedy unfolding puts each loop's mismatch (the angle defect of the curved ground inside the
// loop) into the one face that closes it. Spreading it over the faces round it lowers the worst
// stretch; the as-rigid-as-possible parameterization (Liu, Zhang, Xu, Gotsman, Gortler 2008, "A
// local/global approach to mesh parameterization", energy (3) with the rotations of §3.2) does that
// by minimizing sum_t A_t |J_t - R_t|_F^2 over the texture coordinates, J_t the map from face t's
// plane to the texture (texture_stretch.hpp) and R_t a rotation. Here only where it is needed:
//
//   hot      the faces the growth placed stretched by more than `above` (relax_above)
//   free     the vertices of the faces within `rings` side-steps of a hot face whose fan of faces
//            in the region the walk finds whole (round the vertex across the sides through it, to a
//            border of the region or mesh or back round; a non-manifold or degenerate fan stays
//            fixed). A vertex has one table entry per placement it is in; ALL of them move by the
//            same step, so a seam keeps exactly the offset it had between its two placements (a
//            new placement that continues its neighbour along a side still does), and the faces
//            of a placement still agree bit for bit on every corner: no edge's continuity changes
//   local    per face round a free vertex, R_t the nearest rotation to J_t (the polar part of a 2 x 2
//            matrix: the angle of (j11 + j22, j21 - j12))
//   global   per free vertex in a fixed order (Gauss-Seidel, over-relaxed by anchored_relax_over),
//            with R_t and the other corners held, the step d of the vertex's entries to the
//            energy's minimum: with g_k the gradient of corner k's linear hat function in face t's
//            plane (texels), J_t = sum_k u_k g_k^T, so
//              d = sum_t A_t (R_t - J_t) g_v / sum_t A_t |g_v|^2
//            (one entry: u_v = sum_t A_t (R_t g_v - sum_{k != v} (g_k . g_v) u_k) / sum_t A_t |g_v|^2)
//   checked  a step is kept only if every entry stays inside the exemplar less the margin and every
//            face round the vertex within max_stretch and counter-clockwise (on J, and near the
//            bound on the float corners the atlas will hold: anchored_within); else half the step
//            is tried, else the vertex stays
//   passes   `iterations` local/global rounds per pass; the next pass starts from the faces still
//            stretched beyond `above`, with rings wider by `rings`
//
// Cost: proportional to the faces round the hot ones, not to the region; a region with no hot face
// (developable ground) is left exactly as grown. Serial and in a fixed order (the hot faces in
// growth order, rings and vertices in the order found), so the result is a pure function of the
// grown region.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/vec.hpp"
#include "../anchored_region_geometry.hpp"
#include "anchored_vertex_table.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Faces round one vertex beyond which it is left fixed (no terrain has such a fan).
inline constexpr std::size_t anchored_relax_max_fan = 64;
/// Moves whose faces come within this relative distance of max_stretch on J are tested again on
/// the float corners the atlas will hold.
inline constexpr double anchored_relax_recheck = 1e-3;
/// Over-relaxation of the global step (successive over-relaxation, 1 < w < 2): each vertex moves w
/// times the way to its energy minimum. Measured on the default relief and the 10^6-face grid
/// (docs/terrain.md, "Slope stretch"): 1.6 takes two thirds of the plain step's rounds for the same
/// stretch.
inline constexpr double anchored_relax_over = 1.6;

/// What relax_anchored_region reads of a grown region.
struct anchored_relax_region {
  const anchored_face_geometry* geo = nullptr;           ///< per region face
  const std::int32_t* patch = nullptr;                   ///< per region face: its placement
  const std::array<std::int32_t, 3>* corners = nullptr;  ///< per region face: table entries of its corners
  std::size_t faces = 0;                                 ///< region faces
  std::size_t vertices = 0;                              ///< region vertices
};

/// Settings of relax_anchored_region.
struct anchored_relax_settings {
  int iterations = 0;             ///< local/global rounds
  int rings = 0;                  ///< side-steps from a hot face whose vertices move (times the pass number)
  int passes = 1;                 ///< passes round the faces still hot
  double above = 1;               ///< a face stretched beyond this is hot
  double max_stretch = 1;         ///< no face may end beyond it
  double half_w = 0, half_h = 0;  ///< coordinates stay within [-half_w, half_w] x [-half_h, half_h]
  double texels_per_unit = 1;     ///< plan.texels_per_unit
};

/// A face round a free vertex: its area weight, the gradients of its corners' hat functions (x, y
/// per corner, texels) and its current rotation.
struct anchored_relax_face {
  std::int32_t i = 0;
  double weight = 0;
  std::array<double, 6> g{};
  std::array<double, 4> j{};  ///< J: j11 j12 j21 j22
  double c = 1, s = 0;
};

/// Per-thread scratch of relax_anchored_region; the per-face and per-entry marks are all zero
/// between calls (grown on demand).
struct anchored_relax_scratch {
  std::vector<std::int32_t> hot;                  ///< hot faces (region indices), filled by the growth
  std::vector<std::int32_t> ring;                 ///< faces within the rings, in the order found
  std::vector<std::int32_t> changed;              ///< faces whose corners may have moved
  std::vector<std::int32_t> slot;                 ///< per region face: 1 + its index in `faces`, 0 none
  std::vector<std::uint8_t> in_ring;              ///< per region face
  std::vector<std::uint8_t> seen;                 ///< per region vertex
  std::vector<std::int32_t> seen_list;            ///< the vertices marked in `seen`
  std::vector<anchored_relax_face> faces;         ///< faces round the free vertices
  std::vector<std::array<std::int32_t, 3>> free;  ///< per free vertex: region vertex, first fan item, fan size
  std::vector<std::array<std::int32_t, 2>> fan;   ///< (index in faces, corner), by free vertex
  std::vector<std::array<std::int32_t, 2>> walk;  ///< one fan walk: (region face, corner)
};

inline int anchored_corner(const anchored_face_geometry& g, std::int32_t v) noexcept {
  return g.vertices[0] == v ? 0 : g.vertices[1] == v ? 1 : g.vertices[2] == v ? 2 : -1;
}

/// Walks the faces round region vertex v from face i (corner ci) across the sides through v, both
/// ways until a border of the region or mesh (or round to i), into `walk` as (region face, corner).
/// True if it found every face of the region with corner v: no face repeats and the count matches
/// the table's uses of v's entries (false on a non-manifold vertex or a longer fan than
/// anchored_relax_max_fan).
inline bool anchored_vertex_fan(const anchored_relax_region& reg, const anchored_vertex_table& table, std::int32_t i,
                                int ci, std::vector<std::array<std::int32_t, 2>>& walk) {
  walk.clear();
  walk.push_back({i, ci});
  const std::int32_t v = reg.geo[to_size(i)].vertices[to_size(ci)];
  bool closed = false;
  for (int dir = 0; dir < 2 && !closed; ++dir) {
    std::int32_t f = i;
    int side = dir == 0 ? ci : (ci + 2) % 3;  // side c runs from corner c to c + 1: c and c + 2 pass corner c
    while (true) {
      const auto& gf = reg.geo[to_size(f)];
      const std::int32_t n = gf.neighbors[to_size(side)];
      if (n < 0) break;
      if (n == i) {
        closed = true;
        break;
      }
      if (walk.size() >= anchored_relax_max_fan) return false;
      for (const auto& w : walk)
        if (w[0] == n) return false;
      const int cf = anchored_corner(gf, v);
      const std::int32_t other = gf.vertices[to_size(side == cf ? (cf + 1) % 3 : side)];  // the side's far end
      const auto& gn = reg.geo[to_size(n)];
      const int cn = anchored_corner(gn, v);
      if (cn < 0) return false;
      // n's other side through v
      if (gn.vertices[to_size((cn + 1) % 3)] == other)
        side = (cn + 2) % 3;
      else if (gn.vertices[to_size((cn + 2) % 3)] == other)
        side = cn;
      else
        return false;
      walk.push_back({n, cn});
      f = n;
    }
  }
  std::int32_t uses = 0;
  for (std::int32_t e = table.head(v); e >= 0; e = table.next(e)) uses += table.uses(e);
  return static_cast<std::int32_t>(walk.size()) == uses;
}

/// One pass of relax_anchored_region round the faces in scr.hot with `rings` rings: moves table
/// entries and returns the number of free vertices; scr.faces then lists the faces round them.
inline std::size_t relax_anchored_pass(const anchored_relax_region& reg, anchored_vertex_table& table,
                                       const anchored_relax_settings& set, int rings, anchored_relax_scratch& scr) {
  scr.ring.clear();
  scr.faces.clear();
  scr.free.clear();
  scr.fan.clear();
  scr.seen_list.clear();
  if (scr.hot.empty() || set.iterations <= 0) return 0;
  if (scr.in_ring.size() < reg.faces) scr.in_ring.resize(reg.faces, 0);
  if (scr.slot.size() < reg.faces) scr.slot.resize(reg.faces, 0);
  if (scr.seen.size() < reg.vertices) scr.seen.resize(reg.vertices, 0);
  // the rings: side-steps within the region
  for (const std::int32_t h : scr.hot)
    if (!scr.in_ring[to_size(h)]) scr.in_ring[to_size(h)] = 1, scr.ring.push_back(h);
  std::size_t from = 0;
  for (int r = 0; r < rings; ++r) {
    const std::size_t to = scr.ring.size();
    for (std::size_t j = from; j < to; ++j)
      for (const std::int32_t n : reg.geo[to_size(scr.ring[j])].neighbors)
        if (n >= 0 && !scr.in_ring[to_size(n)]) scr.in_ring[to_size(n)] = 1, scr.ring.push_back(n);
    from = to;
  }
  // the free vertices and their fans
  const double tpu = set.texels_per_unit;
  for (const std::int32_t f : scr.ring) {
    const auto& gf = reg.geo[to_size(f)];
    for (int c = 0; c < 3; ++c) {
      const std::int32_t v = gf.vertices[to_size(c)];
      if (scr.seen[to_size(v)]) continue;
      scr.seen[to_size(v)] = 1;
      scr.seen_list.push_back(v);
      if (!anchored_vertex_fan(reg, table, f, c, scr.walk)) continue;
      bool ok = true;
      for (const auto& w : scr.walk) ok = ok && reg.geo[to_size(w[0])].inv_metric > 0;
      if (!ok) continue;
      scr.free.push_back({v, static_cast<std::int32_t>(scr.fan.size()), static_cast<std::int32_t>(scr.walk.size())});
      for (const auto& w : scr.walk) {
        std::int32_t& slot = scr.slot[to_size(w[0])];
        if (slot == 0) {
          // the face's plane triangle (texture_stretch.hpp: corner 0 at the origin, 1 at (l1, 0),
          // 2 at (x2, y2)) in texels, and the gradients of the hat functions: the rows of its
          // inverse edge matrix for corners 1 and 2, minus their sum for corner 0
          const auto& g = reg.geo[to_size(w[0])];
          const double l1 = std::sqrt(g.len2[0]), x2 = g.a[0] * l1, y2 = g.area2 / l1;
          anchored_relax_face rf;
          rf.i = w[0];
          rf.weight = g.area2;
          const double g1x = 1 / (tpu * l1), g1y = -x2 / (tpu * l1 * y2), g2y = 1 / (tpu * y2);
          rf.g = {-g1x, -g1y - g2y, g1x, g1y, 0, g2y};
          scr.faces.push_back(rf);
          slot = static_cast<std::int32_t>(scr.faces.size());
        }
        scr.fan.push_back({slot - 1, w[1]});
      }
    }
  }
  for (const std::int32_t v : scr.seen_list) scr.seen[to_size(v)] = 0;
  for (const std::int32_t f : scr.ring) scr.in_ring[to_size(f)] = 0;
  for (const auto& rf : scr.faces) scr.slot[to_size(rf.i)] = 0;
  // J of each face from the table (J = sum_k u_k g_k^T); kept up to date as its corners move
  for (auto& rf : scr.faces) {
    rf.j = {};
    for (std::size_t k = 0; k < 3; ++k) {
      const vec2 u = table.coord(reg.corners[to_size(rf.i)][k]);
      rf.j[0] += u.x * rf.g[2 * k], rf.j[1] += u.x * rf.g[2 * k + 1];
      rf.j[2] += u.y * rf.g[2 * k], rf.j[3] += u.y * rf.g[2 * k + 1];
    }
  }
  // J of face rf once corner cv has moved by d
  auto moved = [](const anchored_relax_face& rf, std::size_t cv, vec2 d) {
    const double gx = rf.g[2 * cv], gy = rf.g[2 * cv + 1];
    return std::array<double, 4>{rf.j[0] + d.x * gx, rf.j[1] + d.x * gy, rf.j[2] + d.y * gx, rf.j[3] + d.y * gy};
  };
  // whether moving every entry of the free vertex by d keeps it inside the exemplar and its faces
  // within max_stretch: tested on J (a little inside the bound), and where that is close, on the
  // float corners the atlas will hold
  const double strict = set.max_stretch * (1 - anchored_relax_recheck);
  auto acceptable = [&](const std::array<std::int32_t, 3>& fv, vec2 d) {
    for (std::int32_t e = table.head(fv[0]); e >= 0; e = table.next(e)) {
      const vec2 p = table.coord(e) + d;
      if (!(std::abs(static_cast<double>(static_cast<float>(p.x))) <= set.half_w) ||
          !(std::abs(static_cast<double>(static_cast<float>(p.y))) <= set.half_h))
        return false;
    }
    for (std::int32_t j = fv[1]; j < fv[1] + fv[2]; ++j) {
      const auto& item = scr.fan[to_size(j)];
      const anchored_relax_face& rf = scr.faces[to_size(item[0])];
      const auto m = moved(rf, to_size(item[1]), d);
      const double det = m[0] * m[3] - m[1] * m[2];
      if (!(det > 0)) return false;
      const double q = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] + m[3] * m[3];
      if (anchored_singular_within(q, det * det, strict)) continue;
      if (!anchored_singular_within(q, det * det, set.max_stretch * (1 + anchored_relax_recheck))) return false;
      if (!anchored_within(reg.geo[to_size(rf.i)], table.face_uv(reg.corners[to_size(rf.i)], item[1], d),
                           set.max_stretch))
        return false;
    }
    return true;
  };
  for (int it = 0; it < set.iterations; ++it) {
    // local step: the nearest rotation to each face's map
    for (auto& rf : scr.faces) {
      const double a = rf.j[0] + rf.j[3], b = rf.j[2] - rf.j[1], len = std::sqrt(a * a + b * b);
      if (len > 0) rf.c = a / len, rf.s = b / len;
    }
    // global step, vertex by vertex: d = sum_t A_t (R_t - J_t) g_v / sum_t A_t |g_v|^2 moves the
    // vertex's entries to the energy's minimum (one entry: the file comment's u_v)
    for (const auto& fv : scr.free) {
      vec2 num{0, 0};
      double den = 0;
      for (std::int32_t j = fv[1]; j < fv[1] + fv[2]; ++j) {
        const auto& item = scr.fan[to_size(j)];
        const anchored_relax_face& rf = scr.faces[to_size(item[0])];
        const auto cv = to_size(item[1]);
        const double gx = rf.g[2 * cv], gy = rf.g[2 * cv + 1];
        num += vec2{(rf.c - rf.j[0]) * gx + (-rf.s - rf.j[1]) * gy, (rf.s - rf.j[2]) * gx + (rf.c - rf.j[3]) * gy} *
               rf.weight;
        den += rf.weight * (gx * gx + gy * gy);
      }
      if (!(den > 0)) continue;
      vec2 d = num * (anchored_relax_over / den);
      if (!std::isfinite(d.x) || !std::isfinite(d.y)) continue;
      if (!acceptable(fv, d)) {
        d = d * 0.5;
        if (!acceptable(fv, d)) continue;
      }
      for (std::int32_t e = table.head(fv[0]); e >= 0; e = table.next(e)) table.move(e, table.coord(e) + d);
      for (std::int32_t j = fv[1]; j < fv[1] + fv[2]; ++j) {
        const auto& item = scr.fan[to_size(j)];
        anchored_relax_face& rf = scr.faces[to_size(item[0])];
        rf.j = moved(rf, to_size(item[1]), d);
      }
    }
  }
  return scr.free.size();
}

/// Relaxes the region's coordinates round the hot faces in `scr.hot` (see the file comment), in
/// `passes` passes: pass p relaxes round the faces still stretched beyond `above` with (p + 1) *
/// rings rings. Moves table entries and returns the number of vertex moves allowed (free vertices
/// summed over the passes); scr.changed then lists the faces whose corners may have moved (their
/// atlas coordinates are to be rewritten from the table; a face may be listed more than once).
inline std::size_t relax_anchored_region(const anchored_relax_region& reg, anchored_vertex_table& table,
                                         const anchored_relax_settings& set, anchored_relax_scratch& scr) {
  scr.changed.clear();
  std::size_t freed = 0;
  for (int pass = 0; pass < set.passes && !scr.hot.empty(); ++pass) {
    freed += relax_anchored_pass(reg, table, set, set.rings * (pass + 1), scr);
    scr.hot.clear();
    for (const auto& rf : scr.faces) {
      scr.changed.push_back(rf.i);
      if (!anchored_within(reg.geo[to_size(rf.i)], table.face_uv(reg.corners[to_size(rf.i)]), set.above))
        scr.hot.push_back(rf.i);
    }
  }
  return freed;
}

}  // namespace detail
TESSERA_NAMESPACE_END
