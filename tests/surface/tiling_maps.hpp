// The polycube maps the tiling tests run on (tests/surface): a sphere (convex polycube edges only), a
// torus and an L-shaped voxel solid (concave ones too), built once per test executable.
#pragma once

#include <tessera/surface/build_polycube_map.hpp>

#include <vector>

#include "shapes.hpp"

namespace tiling_maps {
struct named_map {
  const char* name;
  tessera::polycube_map map;
};
inline const std::vector<named_map>& maps() {
  static const std::vector<named_map> all = [] {
    std::vector<named_map> out;
    tessera::polycube_options o;
    o.tiles_across = 6;
    out.push_back({"sphere", *tessera::build_polycube_map(shapes::sphere(8), o)});
    out.push_back({"torus", *tessera::build_polycube_map(shapes::torus(2, 0.7, 48, 16), o)});
    tessera::polycube_options v;
    v.tile_size = 0.5;
    out.push_back({"L-shape", *tessera::build_polycube_map(shapes::voxel_surface(shapes::l_shape(), 2), v)});
    return out;
  }();
  return all;
}
}  // namespace tiling_maps
