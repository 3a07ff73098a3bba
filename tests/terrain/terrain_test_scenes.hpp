// Shared small scenes for the terrain tests.
#pragma once

#include <array>
#include <cmath>

#include <tessera/core/random.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/prepare_terrain_mesh.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/terrain_camera.hpp>

namespace terrain_test {

inline tessera::terrain_mesh prepared_terrain(tessera::index_t cells, std::uint64_t seed = 1, double height = 14) {
  auto m = tessera::make_terrain({.cells_x = cells, .cells_y = cells, .height = height, .seed = seed});
  return tessera::prepare_terrain_mesh(m.value()).value();
}

/// Developable ground, prepared: a flat 40 x 40 relief, the same tilted by 50 degrees, and bent round
/// a cylinder of radius 30 (developable, though its triangulation is not quite: a cell's two
/// triangles are not coplanar).
inline std::array<tessera::terrain_mesh, 3> developable_reliefs() {
  auto flat = tessera::make_terrain({.cells_x = 40, .cells_y = 40, .height = 0}).value();
  auto tilted = flat, bent = flat;
  const double c = std::cos(50 * 3.14159265358979 / 180), s = std::sin(50 * 3.14159265358979 / 180);
  for (auto& p : tilted.positions) p = {p.x, p.y * c, p.y * s};
  for (auto& p : bent.positions) p = {p.x, 30 * std::sin(p.y / 30), 30 * (1 - std::cos(p.y / 30))};
  return {tessera::prepare_terrain_mesh(flat).value(), tessera::prepare_terrain_mesh(tilted).value(),
          tessera::prepare_terrain_mesh(bent).value()};
}

inline tessera::terrain_camera preset_camera(const tessera::terrain_mesh& m, tessera::camera_preset p,
                                             tessera::index_t w = 160, tessera::index_t h = 90) {
  return tessera::make_camera_preset(p, tessera::bounding_box(m), w, h).value();
}

/// A low eye over the 100 x 100 ground of a coarse terrain (make it with a few cells), looking
/// ahead and slightly down: the large faces under the eye reach behind it and cross the near plane.
inline tessera::terrain_camera low_camera(tessera::index_t w, tessera::index_t h) {
  return tessera::make_camera({.eye = {3, -10, 9}, .target = {0, 40, 0}, .fov_y_degrees = 70, .near = 0.05, .far = 400},
                              w, h)
      .value();
}

/// A random camera somewhere above the terrain looking at a random point of it.
inline tessera::terrain_camera random_camera(const tessera::terrain_mesh& m, std::uint64_t seed,
                                             tessera::index_t w = 120, tessera::index_t h = 80) {
  const tessera::counter_rng rng(seed);
  const tessera::aabb b = tessera::bounding_box(m);
  const tessera::vec3 e = b.extent();
  tessera::look_at_camera l;
  l.eye = {b.min.x + e.x * rng.uniform(0), b.min.y + e.y * rng.uniform(1),
           b.max.z + (0.02 + 0.5 * rng.uniform(2)) * e.x};
  l.target = {b.min.x + e.x * rng.uniform(3), b.min.y + e.y * rng.uniform(4), b.min.z};
  l.fov_y_degrees = 30 + 60 * rng.uniform(5);
  l.near = 0.01;
  l.far = 10 * e.x;
  return tessera::make_camera(l, w, h).value();
}

}  // namespace terrain_test
