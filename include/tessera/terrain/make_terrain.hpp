// tessera/terrain/make_terrain.hpp: procedural test scenes for terrain synthesis: a heightfield of
// seeded fractal gradient noise over a regular grid, as a triangle mesh (z up, two triangles per
// cell, counter-clockwise seen from above). height = 0 gives the wide flat plane of the paper's
// grass figures. Any resolution: cells_x * cells_y * 2 triangles.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of make_terrain: a seeded fractal heightfield over a grid.
struct terrain_options {
  index_t cells_x = 128;      ///< grid cells along x (>= 1)
  index_t cells_y = 128;      ///< grid cells along y (>= 1)
  double size_x = 100;        ///< extent along x, centred on 0, in (0, 1e15]
  double size_y = 100;        ///< extent along y, centred on 0, in (0, 1e15]
  double height = 14;         ///< relief: heights run from 0 to about this (0: a flat plane), in [0, 1e15]
  double feature_size = 0.4;  ///< wavelength of the largest hills, as a fraction of max(size_x, size_y), in [1e-6, 1e6]
  int octaves = 6;            ///< noise octaves (1 to 16), each half the wavelength and amplitude
  /// Seed of the noise.
  std::uint64_t seed = 1;
};

namespace detail {
/// 2D gradient noise (Perlin-style, quintic fade, hashed unit gradients), about [-0.7, 0.7].
inline double gradient_noise(const counter_rng& rng, std::uint64_t octave, double x, double y) noexcept {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const double tx = x - fx, ty = y - fy;
  auto grad = [&](std::int64_t i, std::int64_t j, double dx, double dy) {
    const double a = 6.283185307179586 * rng.uniform(octave, i, j);
    return std::cos(a) * dx + std::sin(a) * dy;
  };
  auto fade = [](double t) { return t * t * t * (t * (t * 6 - 15) + 10); };
  const double n00 = grad(ix, iy, tx, ty), n10 = grad(ix + 1, iy, tx - 1, ty);
  const double n01 = grad(ix, iy + 1, tx, ty - 1), n11 = grad(ix + 1, iy + 1, tx - 1, ty - 1);
  const double u = fade(tx), v = fade(ty);
  const double a = n00 + u * (n10 - n00), b = n01 + u * (n11 - n01);
  return a + v * (b - a);
}
}  // namespace detail

/// Builds the heightfield mesh: vertex (i, j) at x = -size_x / 2 + i * size_x / cells_x (likewise y)
/// and z = height * shape(fractal noise), with valleys flattened a little so low ground reads as
/// plains. Errors (invalid_argument / size_overflow, naming the option): cells < 1, more than 2^28
/// vertices, sizes outside (0, 1e15], height outside [0, 1e15], feature_size outside [1e-6, 1e6]
/// (a tinier wavelength would push noise coordinates past what floor() can turn into an integer),
/// octaves outside 1..16. O(vertices * octaves), parallel over rows through `exec`; the mesh is a
/// pure function of the options.
template <Executor E = serial_executor>
result<tri_mesh> make_terrain(const terrain_options& o = {}, E&& exec = {}) {
  if (o.cells_x < 1 || o.cells_y < 1)
    return status::invalid_argument(detail::cat("terrain cells must be >= 1, got ", o.cells_x, " x ", o.cells_y));
  if (o.cells_x > (index_t{1} << 14) || o.cells_y > (index_t{1} << 14) ||
      (o.cells_x + 1) * (o.cells_y + 1) > (index_t{1} << 28))
    return status::size_overflow(
        detail::cat("terrain of ", o.cells_x, " x ", o.cells_y, " cells exceeds 2^28 vertices"));
  // bounds that keep every noise coordinate x / wavelength * 2^15 far inside the int64 range of
  // floor() in gradient_noise (at most 0.5e6 * 2^15 + 300), and every position finite
  if (!(o.size_x > 0 && o.size_y > 0 && o.size_x <= 1e15 && o.size_y <= 1e15))
    return status::invalid_argument(detail::cat("terrain size must be in (0, 1e15], got ", o.size_x, " x ", o.size_y));
  if (!(o.height >= 0 && o.height <= 1e15))
    return status::invalid_argument(detail::cat("terrain height must be in [0, 1e15], got ", o.height));
  if (!(o.feature_size >= 1e-6 && o.feature_size <= 1e6))
    return status::invalid_argument(detail::cat("terrain feature_size must be in [1e-6, 1e6], got ", o.feature_size));
  if (o.octaves < 1 || o.octaves > 16)
    return status::invalid_argument(detail::cat("terrain octaves must be 1 to 16, got ", o.octaves));
  const index_t nx = o.cells_x + 1, ny = o.cells_y + 1;
  tri_mesh m;
  m.positions.resize(detail::to_size(nx * ny));
  const counter_rng rng(o.seed, stream_id("terrain.heightfield"));
  const double wavelength = o.feature_size * std::max(o.size_x, o.size_y);
  exec.parallel_for(0, ny, [&](index_t j) {
    for (index_t i = 0; i < nx; ++i) {
      const double x = -0.5 * o.size_x + o.size_x * static_cast<double>(i) / static_cast<double>(o.cells_x);
      const double y = -0.5 * o.size_y + o.size_y * static_cast<double>(j) / static_cast<double>(o.cells_y);
      double z = 0;
      if (o.height > 0) {
        double sum = 0, amp = 1, norm_ = 0, f = 1 / wavelength;
        for (int k = 0; k < o.octaves; ++k) {
          sum += amp * detail::gradient_noise(rng, static_cast<std::uint64_t>(k), x * f + 17.3 * k, y * f - 5.1 * k);
          norm_ += amp;
          amp *= 0.5;
          f *= 2;
        }
        const double t = std::clamp(0.5 + 0.9 * sum / norm_, 0.0, 1.0);  // about [0, 1]
        z = o.height * t * t * (1.6 - 0.6 * t);                          // flatter lowlands, steeper peaks
      }
      m.positions[detail::to_size(j * nx + i)] = {x, y, z};
    }
  });
  m.faces.reserve(detail::to_size(2 * o.cells_x * o.cells_y));
  for (index_t j = 0; j < o.cells_y; ++j)
    for (index_t i = 0; i < o.cells_x; ++i) {
      const index_t v00 = j * nx + i, v10 = v00 + 1, v01 = v00 + nx, v11 = v01 + 1;
      m.faces.push_back({v00, v10, v11});
      m.faces.push_back({v00, v11, v01});
    }
  return m;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_make_terrain.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
