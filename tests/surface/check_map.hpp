// Shared checks of a polycube_map for the surface tests.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include <tessera/surface/polycube_map.hpp>
#include <tessera/surface/quad_layout.hpp>

/// Flat, positively oriented, quantized faces; a closed quad layout whose grid edges agree; returns
/// the Euler characteristic of the quad surface (2 - 2 genus).
inline long long check_polycube(const tessera::polycube_map& m) {
  using namespace tessera;
  const double t = m.tile_size;
  REQUIRE(m.polycube.size() == m.base.positions.size());
  REQUIRE(m.labels.size() == m.base.faces.size());
  double area = 0;
  for (std::size_t f = 0; f < m.base.faces.size(); ++f) {
    const auto& ch = m.charts[static_cast<std::size_t>(m.face_chart[f])];
    REQUIRE(ch.label == m.labels[f]);
    const int a = label_axis(ch.label);
    const auto& fv = m.base.faces[f];
    for (index_t v : fv)
      REQUIRE(std::abs(m.polycube[static_cast<std::size_t>(v)][a] - double(ch.plane) * t) <=
              1e-9 * (1 + std::abs(double(ch.plane) * t)));
    const vec3 n = cross(m.polycube[static_cast<std::size_t>(fv[1])] - m.polycube[static_cast<std::size_t>(fv[0])],
                         m.polycube[static_cast<std::size_t>(fv[2])] - m.polycube[static_cast<std::size_t>(fv[0])]);
    REQUIRE(dot(n, label_direction(ch.label)) > 0);  // not flipped
    area += 0.5 * norm(n);
  }
  const auto& L = m.layout;
  REQUIRE(std::abs(double(L.quads.size()) * t * t - area) <= 1e-6 * area);
  std::set<grid_point> verts;
  for (std::size_t q = 0; q < L.quads.size(); ++q) {
    const auto& Q = L.quads[q];
    for (int k = 0; k < 4; ++k) {
      verts.insert(Q.corners[static_cast<std::size_t>(k)]);
      const index_t n = Q.neighbors[static_cast<std::size_t>(k)];
      REQUIRE(n >= 0);
      const auto& N = L.quads[static_cast<std::size_t>(n)];
      const int s = Q.neighbor_side[static_cast<std::size_t>(k)];
      REQUIRE(N.neighbors[static_cast<std::size_t>(s)] == static_cast<index_t>(q));
      REQUIRE(N.edges[static_cast<std::size_t>(s)] == Q.edges[static_cast<std::size_t>(k)]);
      REQUIRE(N.edge_forward[static_cast<std::size_t>(s)] != Q.edge_forward[static_cast<std::size_t>(k)]);
      const auto& e = L.edges[static_cast<std::size_t>(Q.edges[static_cast<std::size_t>(k)])];
      const grid_point& a = Q.corners[static_cast<std::size_t>(k)];
      const grid_point& b = Q.corners[static_cast<std::size_t>((k + 1) % 4)];
      REQUIRE(e.origin == (Q.edge_forward[static_cast<std::size_t>(k)] ? a : b));
      REQUIRE(std::abs(a[static_cast<std::size_t>(e.axis)] - b[static_cast<std::size_t>(e.axis)]) == 1);
    }
  }
  return static_cast<long long>(verts.size()) - static_cast<long long>(L.edges.size()) +
         static_cast<long long>(L.quads.size());
}
