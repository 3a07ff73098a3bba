// tessera/geometry/detail/hole_replace.hpp: the replacement rule of hole filling after mesh quilting
// (an extension of paper 000 §3.3; hole_fill.hpp finds the holes, hole_relax.hpp pushes neighbours
// apart). The patches drop large elements more often than small ones (a large one collides more
// often with what stands), so a quilt holds more, smaller elements than its exemplar, and filling
// the holes, which only adds, cannot bring the element count down to the exemplar's density while
// the covered area reaches the exemplar's. Here one large exemplar element takes the place of two or
// more small free ones: it is placed where the elements that may not go leave room for it, and it
// displaces the small ones that come nearer to it than the exemplar's clearance. This header decides
// which neighbours a placed element displaces and whether the exchange pays; the quilt engine
// (quilt_engine.hpp) finds the places, checks intersections and commits.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "hole_relax.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

/// A neighbour of an element being placed in an exchange: its mesh, its projected area (hole_fill's
/// projected_area) and whether it may be removed.
struct replace_neighbour {
  const tri_mesh* mesh = nullptr;
  double area = 0;
  bool removable = false;
};

/// The neighbours (indices into `neighbours`) an element with projection `placed` displaces: those
/// nearer to it than `clearance` (distances sampled on pixels of side `h`, as relax_pushes samples
/// them; the caller adds a pixel to `clearance`), when the exchange pays: at least `min_displaced`
/// of them (the element count drops), every one removable, and their projected areas adding up to
/// between `area_lo` and `area_hi` (the caller's bounds on how the covered area may change). Empty
/// when it does not pay.
inline std::vector<std::size_t> displaced_neighbours(const tri_mesh& placed,
                                                     std::span<const replace_neighbour> neighbours, double h,
                                                     double clearance, double area_lo, double area_hi,
                                                     std::size_t min_displaced = 2) {
  const footprint_distance dist(placed, h, clearance + 2 * h);
  std::vector<std::size_t> out;
  double area = 0;
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    if (dist.nearest(*neighbours[k].mesh, {}) >= clearance) continue;
    if (!neighbours[k].removable) return {};
    out.push_back(k);
    area += neighbours[k].area;
  }
  if (out.size() < min_displaced || area < area_lo || area > area_hi) return {};
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
