// tessera/surface/polycube_projection.hpp: forward and inverse projection between the base mesh and its
// polycube (paper 000 §4: P maps M_base to T³, P⁻¹ takes a point of a tile back to the base surface;
// the paper uses a BSP tree over T³, this a BVH over the polycube-deformed mesh).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "../geometry/bvh.hpp"
#include "polycube_map.hpp"
#include "quad_layout.hpp"

TESSERA_NAMESPACE_BEGIN

/// A point of the polycube surface: its position (mesh units) and the quad it lies in, with local
/// coordinates (u, v) in [0, 1]² along the quad's sides 0 and 3 (reversed) from corner 0.
struct polycube_point {
  /// Position in mesh units.
  vec3 position;
  /// The quad it lies in.
  index_t quad = -1;
  /// Local coordinates in the quad, in [0, 1].
  double u = 0, v = 0;
};

/// A point of the base surface: face, barycentric weights of its corners, position.
struct base_surface_point {
  /// The base face.
  index_t face = -1;
  /// Barycentric weights of its corners.
  vec3 bary;
  /// Position in mesh units.
  vec3 position;
};

/// Projects between a polycube_map's base mesh and its polycube. Keeps a pointer to the map (which
/// must outlive it) and a BVH over the deformed mesh. Queries are const and thread-safe.
class polycube_projector {
 public:
  /// Builds the BVH; `map` must outlive the projector.
  explicit polycube_projector(const polycube_map& map) : map_(&map), bvh_(map.deformed_mesh()) {}

  /// P: the polycube point of the base point (face, bary). Errors: out_of_range for a face outside
  /// [0, F); invalid_argument for non-finite weights. O(1).
  [[nodiscard]] result<polycube_point> forward(index_t face, vec3 bary) const {
    if (face < 0 || face >= map_->base.num_faces())
      return status::out_of_range(
          detail::cat("polycube forward: face ", face, " outside [0, ", map_->base.num_faces(), ")"));
    if (!is_finite(bary)) return status::invalid_argument("polycube forward: non-finite barycentric weights");
    const auto& f = map_->base.faces[detail::to_size(face)];
    polycube_point out;
    for (int k = 0; k < 3; ++k) out.position += bary[k] * map_->polycube[detail::to_size(f[detail::to_size(k)])];
    const auto c = detail::to_size(map_->face_chart[detail::to_size(face)]);
    locate(c, out);
    return out;
  }

  /// P⁻¹ of a point of quad `quad` at local (u, v) in [0, 1]²: the base face and barycentric weights
  /// of the polycube point there (closest point on the deformed mesh). Errors: out_of_range for a quad
  /// outside the layout, invalid_argument for (u, v) outside [0, 1]² or not finite. O(log F).
  [[nodiscard]] result<base_surface_point> inverse(index_t quad, double u, double v) const {
    if (quad < 0 || quad >= static_cast<index_t>(map_->layout.quads.size()))
      return status::out_of_range(
          detail::cat("polycube inverse: quad ", quad, " outside [0, ", map_->layout.quads.size(), ")"));
    if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1))
      return status::invalid_argument(detail::cat("polycube inverse: (u, v) = (", u, ", ", v, ") outside [0, 1]²"));
    const auto& q = map_->layout.quads[detail::to_size(quad)];
    vec3 c0, c1, c3;
    for (int a = 0; a < 3; ++a) {
      c0[a] = static_cast<double>(q.corners[0][detail::to_size(a)]) * map_->tile_size;
      c1[a] = static_cast<double>(q.corners[1][detail::to_size(a)]) * map_->tile_size;
      c3[a] = static_cast<double>(q.corners[3][detail::to_size(a)]) * map_->tile_size;
    }
    return inverse(c0 + u * (c1 - c0) + v * (c3 - c0));
  }

  /// P⁻¹ of any point near the polycube surface (the closest point of the deformed mesh is used).
  /// `search_radius`: where the point is known to lie within this distance of the polycube surface
  /// (e.g. on it), the search prunes everything farther (much faster); when nothing lies that close,
  /// the whole mesh is searched.
  [[nodiscard]] base_surface_point inverse(vec3 polycube_position,
                                           double search_radius = std::numeric_limits<double>::infinity()) const {
    auto hit = bvh_.closest_point(polycube_position, search_radius * search_radius);
    if (hit.face < 0 && search_radius < std::numeric_limits<double>::infinity())
      hit = bvh_.closest_point(polycube_position);
    base_surface_point out;
    if (hit.face < 0) return out;
    out.face = hit.face;
    out.bary = hit.bary;
    const auto& f = map_->base.faces[detail::to_size(hit.face)];
    for (int k = 0; k < 3; ++k) out.position += hit.bary[k] * map_->base.position(f[detail::to_size(k)]);
    return out;
  }

 private:
  void locate(std::size_t chart, polycube_point& p) const {
    const auto& g = map_->layout.chart_grids[chart];
    const auto ax = detail::quad_plane_axes(map_->charts[chart].label);
    const double x = p.position[ax[0]] / map_->tile_size - static_cast<double>(g.origin[0]);
    const double y = p.position[ax[1]] / map_->tile_size - static_cast<double>(g.origin[1]);
    const auto i0 =
        std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(x)), 0, std::max<std::int64_t>(0, g.size[0] - 1));
    const auto j0 =
        std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(y)), 0, std::max<std::int64_t>(0, g.size[1] - 1));
    // on a square's border the square itself may be outside the chart: take the nearest one inside
    double best = 1e300;
    for (std::int64_t j = std::max<std::int64_t>(0, j0 - 1); j <= std::min(g.size[1] - 1, j0 + 1); ++j)
      for (std::int64_t i = std::max<std::int64_t>(0, i0 - 1); i <= std::min(g.size[0] - 1, i0 + 1); ++i) {
        const index_t q = g.quad[detail::to_size(j * g.size[0] + i)];
        if (q < 0) continue;
        const double dx = std::max({0.0, static_cast<double>(i) - x, x - static_cast<double>(i + 1)});
        const double dy = std::max({0.0, static_cast<double>(j) - y, y - static_cast<double>(j + 1)});
        if (dx * dx + dy * dy < best) {
          best = dx * dx + dy * dy;
          p.quad = q;
          p.u = std::clamp(x - static_cast<double>(i), 0.0, 1.0);
          p.v = std::clamp(y - static_cast<double>(j), 0.0, 1.0);
        }
      }
  }

  const polycube_map* map_;
  triangle_bvh bvh_;
};

TESSERA_NAMESPACE_END
