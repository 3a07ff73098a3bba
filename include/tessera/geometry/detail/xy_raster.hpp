// tessera/geometry/detail/xy_raster.hpp: square pixels over an XY window and the pixels whose centres
// lie in the XY projection of a mesh's triangles. Shared by the likeness figures (texture_quality.hpp:
// covered area, bands) and hole filling after mesh quilting (hole_fill.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../mesh_elements.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

/// Square pixels of side `px` over a window, nx x ny of them from its lower corner.
struct xy_raster {
  xy_rect window;
  double px = 0;
  std::size_t nx = 0, ny = 0;
  [[nodiscard]] vec3 centre(std::size_t x, std::size_t y) const {
    return {window.x0 + (double(x) + 0.5) * px, window.y0 + (double(y) + 0.5) * px, 0};
  }
};

/// A raster of pixels of side `px` over `w`, coarser when that would take more than max_pixels.
inline xy_raster make_xy_raster(const xy_rect& w, double px, index_t max_pixels) {
  xy_raster r;
  r.window = w;
  r.px = std::max(px, std::sqrt(w.width() * w.height() / double(std::max<index_t>(max_pixels, 1))));
  r.nx = static_cast<std::size_t>(std::max(1.0, std::ceil(w.width() / r.px)));
  r.ny = static_cast<std::size_t>(std::max(1.0, std::ceil(w.height() / r.px)));
  return r;
}

/// Calls mark(x, y) for every pixel whose centre lies in the XY projection of a triangle of `m`
/// (once per triangle covering it; triangles seen edge-on cover none).
template <class Mark>
void for_each_covered_pixel(const tri_mesh& m, const xy_raster& r, Mark&& mark) {
  for (const auto& f : m.faces) {
    const vec3 a = m.positions[to_size(f[0])], b = m.positions[to_size(f[1])], c = m.positions[to_size(f[2])];
    const double area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area2 == 0 || !std::isfinite(area2)) continue;  // seen edge-on: covers no pixel centre
    const double s = area2 > 0 ? 1.0 : -1.0;
    const double lo_x = std::min({a.x, b.x, c.x}), hi_x = std::max({a.x, b.x, c.x});
    const double lo_y = std::min({a.y, b.y, c.y}), hi_y = std::max({a.y, b.y, c.y});
    const double fx0 = std::floor((lo_x - r.window.x0) / r.px - 0.5),
                 fx1 = std::ceil((hi_x - r.window.x0) / r.px - 0.5);
    const double fy0 = std::floor((lo_y - r.window.y0) / r.px - 0.5),
                 fy1 = std::ceil((hi_y - r.window.y0) / r.px - 0.5);
    if (fx1 < 0 || fy1 < 0 || fx0 >= double(r.nx) || fy0 >= double(r.ny)) continue;
    const auto x0 = static_cast<std::size_t>(std::max(0.0, fx0)), y0 = static_cast<std::size_t>(std::max(0.0, fy0));
    const auto x1 = static_cast<std::size_t>(std::min(double(r.nx - 1), fx1)),
               y1 = static_cast<std::size_t>(std::min(double(r.ny - 1), fy1));
    for (std::size_t y = y0; y <= y1; ++y)
      for (std::size_t x = x0; x <= x1; ++x) {
        const vec3 p = r.centre(x, y);
        const double w0 = s * ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x));
        const double w1 = s * ((c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x));
        const double w2 = s * ((a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x));
        if (w0 >= 0 && w1 >= 0 && w2 >= 0) mark(x, y);
      }
  }
}

}  // namespace detail
TESSERA_NAMESPACE_END
