// tessera/terrain/detail/triangle_placement.hpp: the per-triangle steps of paper 003, §2.3 step (2),
// for synthesize_triangles.hpp: continuing a synthesized neighbour's coordinates (the identity map
// between adjacent levels, step 2.2) and choosing a new congruent placement inside the level image
// (step 2.1, and the restart "out of bounds: choose a congruent triangle at random"). A placement is
// an offset: uv = screen position + offset, in level-image pixels from the image's centre.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/random.hpp"
#include "../../core/vec.hpp"
#include "../prepare_terrain_mesh.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

using screen_bounds = std::array<float, 4>;  ///< x0 y0 x1 y1 of a face on the screen

/// Whether a face with screen bounds b, moved by offset o, lies inside the level image
/// [-hw, hw] x [-hh, hh] along x, along y, and along both.
inline bool fits_level_x(const screen_bounds& b, double hw, vec2 o) { return b[0] + o.x >= -hw && b[2] + o.x <= hw; }
inline bool fits_level_y(const screen_bounds& b, double hh, vec2 o) { return b[1] + o.y >= -hh && b[3] + o.y <= hh; }
inline bool fits_level(const screen_bounds& b, double hw, double hh, vec2 o) {
  return fits_level_x(b, hw, o) && fits_level_y(b, hh, o);
}

/// §2.3 step (2.2) of paper 003: the placement of a synthesized neighbour of f (neighbours `nb`,
/// placements `region`, offsets `placements`) whose offset keeps f (bounds b) inside its level
/// image. Of several, the oldest placement (`oldest_first`, continuation_rule::oldest_placement) or
/// the first in side order (the paper read literally). Returns the placement or -1; counts f's
/// synthesized neighbours into `synthesized`.
inline std::int32_t continue_neighbour_placement(const std::array<std::int32_t, 3>& nb, index_t nf,
                                                 const std::vector<std::int32_t>& region,
                                                 const std::vector<vec2>& placements, const screen_bounds& b, double hw,
                                                 double hh, bool oldest_first, int& synthesized) {
  int best = -1;
  std::int32_t best_region = 0;
  for (int k = 0; k < 3; ++k) {
    const std::int32_t n = nb[to_size(k)];
    if (!is_face_index(n, nf)) continue;
    const std::int32_t r = region[to_size(n)];
    if (r < 0) continue;
    ++synthesized;
    const bool older = best < 0 || (oldest_first && r < best_region);
    if (older && fits_level(b, hw, hh, placements[to_size(r)])) {
      best = k;
      best_region = r;
    }
  }
  return best >= 0 ? best_region : -1;
}

/// Where in [0, 1]^2 of its feasible offsets a new placement of f prefers to sit
/// (placement_strategy::away_from_neighbors): on the side of the level image facing its
/// `synthesized` synthesized neighbours, leaving the rest for the unsynthesized side; the centre
/// without any.
inline vec2 placement_preference(const std::array<std::int32_t, 3>& nb, index_t nf,
                                 const std::vector<std::int32_t>& region, const std::vector<screen_bounds>& bounds,
                                 const screen_bounds& b, int synthesized) {
  vec2 toward{0.5, 0.5};
  if (synthesized == 0) return toward;
  vec2 away{};
  for (int k = 0; k < 3; ++k) {
    const std::int32_t n = nb[to_size(k)];
    if (!is_face_index(n, nf) || region[to_size(n)] < 0) continue;
    const auto& bn = bounds[to_size(n)];
    away += vec2{static_cast<double>(bn[0] + bn[2]), static_cast<double>(bn[1] + bn[3])} * 0.5;
  }
  const vec2 d = vec2{static_cast<double>(b[0] + b[2]), static_cast<double>(b[1] + b[3])} * 0.5 - away / synthesized;
  const double len = norm(d);
  if (len > 0) toward = vec2{0.5 - 0.5 * d.x / len, 0.5 - 0.5 * d.y / len};
  return toward;
}

/// keep_fitting_axis: the axis (0: x, 1: y) along which the oldest neighbouring placement of f
/// still fits it, with that placement's offset in `kept`; -1 when none does. The seam is then a
/// shift along the other axis only (blades of grass run on across it).
inline int fitting_axis(const std::array<std::int32_t, 3>& nb, index_t nf, const std::vector<std::int32_t>& region,
                        const std::vector<vec2>& placements, const screen_bounds& b, double hw, double hh, vec2& kept) {
  int keep = -1;
  std::int32_t oldest = std::numeric_limits<std::int32_t>::max();
  for (int k = 0; k < 3; ++k) {
    const std::int32_t n = nb[to_size(k)];
    if (!is_face_index(n, nf)) continue;
    const std::int32_t r = region[to_size(n)];
    if (r < 0 || r >= oldest) continue;
    const vec2 p = placements[to_size(r)];
    const bool fx = fits_level_x(b, hw, p), fy = fits_level_y(b, hh, p);
    if (fx || fy) {
      oldest = r;
      keep = fx ? 0 : 1;
      kept = p;
    }
  }
  return keep;
}

/// One axis of a new placement: [lo, hi] are the feasible offsets, `toward` in [0, 1] the preferred
/// position inside them (0: lo), jittered by the uniform number u (`uniform`: the paper's uniform
/// choice, u itself). An empty range (the face is larger than its level image) centres it and sets
/// `oversized`.
inline double place_axis(double lo, double hi, double u, double toward, bool uniform, bool& oversized) {
  if (hi < lo) {
    oversized = true;
    return 0.5 * (lo + hi);
  }
  const double t = uniform ? u : std::clamp(toward + (u - 0.5) * 1.0, 0.0, 1.0);
  return lo + t * (hi - lo);
}

}  // namespace detail
TESSERA_NAMESPACE_END
