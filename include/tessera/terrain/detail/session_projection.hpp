// tessera/terrain/detail/session_projection.hpp: the per-frame visibility of a terrain_session,
// by blocks (small square pieces of the regions, see session_blocks). A session needs per frame
// only which faces are visible (and whether they cross the near plane); ground-anchored
// coordinates need no screen positions or bounds, and the renderer projects the vertices it draws.
// So a frame classifies each region, and each block of a region that is only partly in view, by
// the box of its faces' vertices against the view frustum: every corner of the box beyond one clip
// plane (with a relative margin for rounding): culled whole; every corner comfortably inside every
// plane: all its faces are inside (the clip volume is convex in homogeneous coordinates, so it
// holds every convex combination of the corners); otherwise its faces are tested one by one with
// project_mesh's rule (all corners beyond one frustum plane: culled; back faces when asked),
// except that a face crossing the near plane whose clipped polygon misses the viewport stays
// visible (it draws nothing).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "../../core/config.hpp"
#include "../../core/vec.hpp"
#include "../plan_anchored_regions.hpp"
#include "../prepare_terrain_mesh.hpp"
#include "../project_mesh.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Relative margin of the box tests: a box corner counts as inside (or beyond) a clip plane only
/// by more than this times its largest clip coordinate, far above the rounding of a matrix product.
inline constexpr double region_clip_margin = 1e-9;
/// Relative margin of the distance test that lets a block keep the levels of all its faces.
inline constexpr double block_slack_margin = 1e-9;

/// An axis-aligned box lo x y z, hi x y z.
using box6 = std::array<double, 6>;

/// Empty box (lo = +inf, hi = -inf).
inline box6 empty_box() noexcept {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {inf, inf, inf, -inf, -inf, -inf};
}
inline void grow_box(box6& b, const vec3& p) noexcept {
  b[0] = std::min(b[0], p.x), b[1] = std::min(b[1], p.y), b[2] = std::min(b[2], p.z);
  b[3] = std::max(b[3], p.x), b[4] = std::max(b[4], p.y), b[5] = std::max(b[5], p.z);
}

/// How a region lies against the frustum.
enum class region_view : std::uint8_t { outside = 0, inside = 1, partial = 2 };

/// Classifies box `b` (the box of a region's vertices) for clip matrix `m` (see the file comment).
inline region_view classify_region_box(const box6& b, const glm::dmat4& m, bool zero_to_one) noexcept {
  if (!(b[0] <= b[3])) return region_view::outside;  // no faces
  unsigned beyond_all = 63, not_inside_any = 0;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 c = m * glm::dvec4(b[(k & 1) ? 3 : 0], b[(k & 2) ? 4 : 1], b[(k & 4) ? 5 : 2], 1.0);
    const double e = region_clip_margin * std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z), std::abs(c.w)});
    const double zlo = zero_to_one ? 0.0 : -c.w;
    // beyond: by more than the margin; inside: by more than the margin
    const unsigned beyond = (c.x < -c.w - e ? 1u : 0u) | (c.x > c.w + e ? 2u : 0u) | (c.y < -c.w - e ? 4u : 0u) |
                            (c.y > c.w + e ? 8u : 0u) | (c.z < zlo - e ? 16u : 0u) | (c.z > c.w + e ? 32u : 0u);
    const unsigned inside = (c.x > -c.w + e ? 1u : 0u) | (c.x < c.w - e ? 2u : 0u) | (c.y > -c.w + e ? 4u : 0u) |
                            (c.y < c.w - e ? 8u : 0u) | (c.z > zlo + e ? 16u : 0u) | (c.z < c.w - e ? 32u : 0u);
    beyond_all &= beyond;
    not_inside_any |= ~inside & 63u;
  }
  if (beyond_all != 0) return region_view::outside;
  return not_inside_any == 0 ? region_view::inside : region_view::partial;
}

/// The visibility state (a face_visibility) of face f for clip matrix `m`: project_mesh's rule
/// (see the file comment). The face's vertex indices must be valid.
inline std::uint8_t face_view_state(const terrain_mesh& mesh, std::int32_t f, const glm::dmat4& m, bool zero_to_one,
                                    bool cull_back_faces, const vec3& eye) noexcept {
  const auto& face = mesh.faces[to_size(f)];
  std::uint8_t all = 63, any = 0;
  for (const std::int32_t v : face) {
    const vec3& p = mesh.positions[to_size(v)];
    const glm::dvec4 c = m * glm::dvec4(p.x, p.y, p.z, 1.0);
    const std::uint8_t code = clip_outcode({c.x, c.y, c.z, c.w}, zero_to_one);
    all &= code;
    any |= code;
  }
  if (all != 0) return 0;
  if (cull_back_faces) {
    const vec3 a = mesh.position(face[0]), n3 = cross(mesh.position(face[1]) - a, mesh.position(face[2]) - a);
    if (dot(n3, a - eye) >= 0) return 0;
  }
  return static_cast<std::uint8_t>((any & 16) ? face_visibility::near_clipped : face_visibility::inside);
}

/// The BLOCKS of a session: each region (plan_anchored_regions) cut into split x split square
/// sub-cells of its cell (a face goes to the sub-cell of its centroid); the non-empty ones, region
/// by region, are the blocks. Per block the box of its faces' vertices and
/// the blocks holding a neighbour of one of its faces. Blocks are the unit of the per-frame tests;
/// regions stay the unit of growth. A pure function of the mesh and the plan; O(F), serial.
struct session_blocks {
  int split = 1;                           ///< sub-cells per cell side
  std::vector<box6> vertex_box;            ///< per block
  std::vector<std::int32_t> first, faces;  ///< per block b: faces[first[b] .. first[b + 1]), ascending
  std::vector<std::int32_t> region;        ///< per block: its region
  std::vector<std::int32_t> region_first;  ///< per region r: blocks region_first[r] .. region_first[r + 1]
  std::vector<std::int32_t> block_of;      ///< per face: its block
  std::vector<std::int32_t> nb_first, nb;  ///< per block: neighbouring blocks (CSR, ascending, itself excluded)
  [[nodiscard]] index_t num_blocks() const noexcept { return static_cast<index_t>(region.size()); }
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    return 48 * vertex_box.size() + 4 * (first.size() + faces.size() + region.size() + region_first.size() +
                                         block_of.size() + nb_first.size() + nb.size());
  }
};

/// Faces a block aims at (the split is chosen so that an average region's blocks hold about this many).
inline constexpr double session_block_faces = 192;

inline session_blocks make_session_blocks(const terrain_mesh& mesh, const anchored_regions& plan) {
  session_blocks g;
  const auto nr = to_size(plan.num_regions());
  const auto nf = plan.region.size();
  index_t nonempty = 0;
  for (std::size_t r = 0; r < nr; ++r) nonempty += plan.first[r + 1] > plan.first[r] ? 1 : 0;
  const double avg = nonempty > 0 ? static_cast<double>(nf) / static_cast<double>(nonempty) : 1.0;
  g.split = static_cast<int>(std::clamp(std::lround(std::sqrt(avg / session_block_faces)), 1L, 16L));
  const int split = g.split;
  const auto cells = to_size(split * split);
  g.block_of.assign(nf, -1);
  g.first.push_back(0);
  g.region_first.assign(nr + 1, 0);
  std::vector<std::int32_t> sub, count(cells);
  for (std::size_t r = 0; r < nr; ++r) {
    const std::int32_t b0 = plan.first[r], b1 = plan.first[r + 1];
    const double ia = static_cast<double>(static_cast<index_t>(r) % plan.cells_a),
                 ib = static_cast<double>(static_cast<index_t>(r) / plan.cells_a);
    sub.resize(to_size(b1 - b0));
    std::fill(count.begin(), count.end(), 0);
    for (std::int32_t i = b0; i < b1; ++i) {
      const vec3& c = mesh.centroids[to_size(plan.faces[to_size(i)])];
      const double a = (axis_value(c, plan.axis_a) - plan.origin_a) / plan.cell - ia,
                   b = (axis_value(c, plan.axis_b) - plan.origin_b) / plan.cell - ib;
      const auto sa = std::clamp<index_t>(static_cast<index_t>(std::floor(a * split)), 0, split - 1),
                 sb = std::clamp<index_t>(static_cast<index_t>(std::floor(b * split)), 0, split - 1);
      const auto k = static_cast<std::int32_t>(sb * split + sa);
      sub[to_size(i - b0)] = k;
      ++count[to_size(k)];
    }
    // blocks of this region in sub-cell order; faces ascending within a block (stable counting)
    std::vector<std::int32_t> id(cells, -1);
    for (std::size_t k = 0; k < cells; ++k) {
      if (count[k] == 0) continue;
      id[k] = static_cast<std::int32_t>(g.region.size());
      g.region.push_back(static_cast<std::int32_t>(r));
      g.first.push_back(g.first.back() + count[k]);
    }
    g.region_first[r + 1] = static_cast<std::int32_t>(g.region.size());
    for (std::int32_t i = b0; i < b1; ++i)
      g.block_of[to_size(plan.faces[to_size(i)])] = id[to_size(sub[to_size(i - b0)])];
  }
  const auto nb = g.region.size();
  g.faces.resize(nf);
  std::vector<std::int32_t> fill(g.first.begin(), g.first.end() - 1);
  for (std::size_t f = 0; f < nf; ++f) g.faces[to_size(fill[to_size(g.block_of[f])]++)] = static_cast<std::int32_t>(f);
  g.vertex_box.assign(nb, empty_box());
  g.nb_first.assign(nb + 1, 0);
  std::vector<std::int32_t> list;
  for (std::size_t b = 0; b < nb; ++b) {
    list.clear();
    for (std::int32_t i = g.first[b]; i < g.first[b + 1]; ++i) {
      const auto f = to_size(g.faces[to_size(i)]);
      for (const std::int32_t v : mesh.faces[f]) grow_box(g.vertex_box[b], mesh.positions[to_size(v)]);
      for (const std::int32_t n : mesh.neighbors[f]) {
        if (n < 0) continue;
        const std::int32_t q = g.block_of[to_size(n)];
        if (q != static_cast<std::int32_t>(b)) list.push_back(q);
      }
    }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    g.nb.insert(g.nb.end(), list.begin(), list.end());
    g.nb_first[b + 1] = static_cast<std::int32_t>(g.nb.size());
  }
  return g;
}

/// What a session knows of a block between frames (terrain_session.hpp).
struct block_frame {
  std::int32_t visible = 0;   ///< faces visible
  std::int32_t near = 0;      ///< of which crossing the near plane
  std::int32_t blending = 0;  ///< visible faces still blending a level change
  int jump = 0;               ///< largest level difference across the edges below
  /// Shared edges between visible faces whose smaller face is in this block; continuous ones.
  std::int64_t shared = 0, same = 0;
  /// The eye when the block was last visited, and the least distance any visible face of it was
  /// from leaving its level's hysteresis band then: while the eye stays closer than that to where
  /// it was, no face of the block changes level (|D' - D| <= |eye' - eye|).
  vec3 eye;
  double slack = -1;
};

}  // namespace detail
TESSERA_NAMESPACE_END
