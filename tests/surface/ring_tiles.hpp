// Procedural closed elements in quad-local (u, v, h) coordinates for the shell-mapping tests: a ring
// (torus) inside one quad, and a ring centred on a quad side, cut along that side into two halves that
// are expressed in the two quads' own frames (the neighbour may lie across a polycube edge).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <tessera/core/tri_mesh.hpp>
#include <tessera/surface/polycube_map.hpp>

namespace ring_tiles {

/// Ring centred at (cu, cv) of the quad: in-plane radius R, tube radius r (tile units), tube centre at
/// height hc and tube half-height rh (mesh units). Outward oriented, closed.
inline tessera::tri_mesh ring(double cu, double cv, double R, double r, double hc, double rh, int nt = 24, int np = 8) {
  tessera::tri_mesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double t = 2 * pi * i / nt, p = 2 * pi * j / np;
      m.add_vertex(
          {cu + (R + r * std::cos(p)) * std::cos(t), cv + (R + r * std::cos(p)) * std::sin(t), hc + rh * std::sin(p)});
    }
  auto at = [&](int i, int j) { return static_cast<tessera::index_t>(((i + nt) % nt) * np + (j + np) % np); };
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

inline const std::array<std::array<double, 2>, 4> corner_uv{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

/// Quad-local (u, v) of the point at parameter p along side k (corner k to k + 1) and distance d
/// inwards from it.
inline std::array<double, 2> side_point(int k, double p, double d) {
  const auto& a = corner_uv[static_cast<std::size_t>(k)];
  const auto& b = corner_uv[static_cast<std::size_t>((k + 1) % 4)];
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  return {a[0] + p * dx - d * dy, a[1] + p * dy + d * dx};
}

/// A ring centred on side k of quad q (in-plane radius R, tube r, tile units; heights as ring()), as
/// two open halves: the one inside q (d >= 0) in q's frame and the other in the frame of the neighbour
/// across side k. Returns {mesh of q, mesh of the neighbour}.
inline std::array<tessera::tri_mesh, 2> ring_across_side(const tessera::polycube_quad& q, int k, double R, double r,
                                                         double hc, double rh, int nt = 24, int np = 8) {
  const double pi = 3.14159265358979323846;
  const int k2 = q.neighbor_side[static_cast<std::size_t>(k)];
  std::array<tessera::tri_mesh, 2> out;
  for (int half = 0; half < 2; ++half) {
    auto& m = out[static_cast<std::size_t>(half)];
    for (int i = 0; i <= nt / 2; ++i) {
      const int ii = i + half * nt / 2;
      const double t = 2 * pi * ii / nt;
      for (int j = 0; j < np; ++j) {
        const double ph = 2 * pi * j / np, rho = R + r * std::cos(ph);
        const double p = 0.5 + rho * std::cos(t);
        const double d = (ii % (nt / 2) == 0) ? 0.0 : rho * std::sin(t);
        const auto uv = half == 0 ? side_point(k, p, d) : side_point(k2, 1 - p, -d);
        m.add_vertex({uv[0], uv[1], hc + rh * std::sin(ph)});
      }
    }
    auto at = [&](int i, int j) { return static_cast<tessera::index_t>(i * np + (j + np) % np); };
    for (int i = 0; i < nt / 2; ++i)
      for (int j = 0; j < np; ++j) {
        m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
  }
  return out;
}

}  // namespace ring_tiles
