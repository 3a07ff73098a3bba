// tessera/geometry/detail/hole_relax.hpp: a local relaxation for hole filling after mesh quilting (an
// extension of paper 000 §3.3; hole_fill.hpp finds the holes). The holes left between the patches are
// mostly smaller than the exemplar's larger elements, so only small elements fit them, and the output
// ends up with more elements than the exemplar for the same covered area. Here the free neighbours of
// a hole move a little apart, each straight away from the hole's centre, so that an element drawn
// from the exemplar's size distribution keeps the exemplar's clearance from all of them. This header
// computes those bounded XY translations on a raster around the new element; the quilt engine checks
// the moved elements (no intersection, room around them, inside their tile) and commits them.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "hole_fill.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

/// A neighbour of an element being placed: its mesh, the centre it moves away from the hole along,
/// and whether the relaxation may move it at all.
struct relax_neighbour {
  const tri_mesh* mesh = nullptr;
  vec3 centre{};
  bool movable = false;
};

/// The distance from the XY projection of one mesh, sampled on pixels of side `h` around it (up to
/// `reach` beyond its bounds; farther counts as infinitely far).
class footprint_distance {
 public:
  footprint_distance(const tri_mesh& m, double h, double reach) : h_(h) {
    aabb b;
    for (const vec3& p : m.positions) b.extend(p);
    x0_ = b.min.x - reach - h;
    y0_ = b.min.y - reach - h;
    w_ = static_cast<index_t>(std::ceil((b.max.x + reach + h - x0_) / h)) + 1;
    rows_ = static_cast<index_t>(std::ceil((b.max.y + reach + h - y0_) / h)) + 1;
    coverage_raster r(x0_, y0_, h, w_, rows_);
    r.add_mesh(m);
    d_ = distance_to_covered(r, false);
  }
  /// Distance from `p` (XY) to the nearest covered pixel centre; infinity off the raster.
  [[nodiscard]] double at(vec3 p) const noexcept {
    const double fx = std::floor((p.x - x0_) / h_), fy = std::floor((p.y - y0_) / h_);
    if (!(fx >= 0 && fy >= 0 && fx < double(w_) && fy < double(rows_))) return std::numeric_limits<double>::infinity();
    return h_ * static_cast<double>(d_[to_size(static_cast<index_t>(fy) * w_ + static_cast<index_t>(fx))]);
  }
  /// The least distance over the vertices of `m` moved by `shift`.
  [[nodiscard]] double nearest(const tri_mesh& m, vec3 shift) const noexcept {
    double best = std::numeric_limits<double>::infinity();
    for (const vec3& p : m.positions) best = std::min(best, at(p + shift));
    return best;
  }

 private:
  double h_, x0_ = 0, y0_ = 0;
  index_t w_ = 0, rows_ = 0;
  std::vector<float> d_;
};

/// The XY translations (one per neighbour, zero for those that stay) that keep every neighbour at
/// least `clearance` from the projection of `placed`: a neighbour nearer than that moves straight
/// away from `from` (along its centre's direction from it), by the deficit, repeated until it is
/// clear (at most relax_iterations steps). nullopt when a neighbour that must move is not movable or
/// would move farther than `max_push`. Distances are sampled on pixels of side `h` (the caller adds a
/// pixel to `clearance`).
inline std::optional<std::vector<vec3>> relax_pushes(const tri_mesh& placed, vec3 from,
                                                     std::span<const relax_neighbour> neighbours, double h,
                                                     double clearance, double max_push) {
  constexpr int relax_iterations = 8;
  const footprint_distance dist(placed, h, clearance + max_push + 2 * h);
  std::vector<vec3> shifts(neighbours.size(), vec3{});
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    const relax_neighbour& n = neighbours[k];
    double gap = dist.nearest(*n.mesh, {});
    if (gap >= clearance) continue;
    if (!n.movable) return std::nullopt;
    const double dx = n.centre.x - from.x, dy = n.centre.y - from.y, len = std::hypot(dx, dy);
    if (!(len > 0)) return std::nullopt;
    const vec3 u{dx / len, dy / len, 0};
    double s = 0;
    for (int it = 0; it < relax_iterations && gap < clearance; ++it) {
      s += clearance - gap + 0.5 * h;
      if (s > max_push) return std::nullopt;
      gap = dist.nearest(*n.mesh, u * s);
    }
    if (gap < clearance) return std::nullopt;
    shifts[k] = u * s;
  }
  return shifts;
}

}  // namespace detail
TESSERA_NAMESPACE_END
