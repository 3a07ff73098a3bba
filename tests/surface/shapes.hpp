// Procedural closed meshes for the surface tests: voxel solids (cube, L-shape, ring torus, genus-2
// block) with every unit face cut into s x s squares, and smooth ones (sphere, torus).
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include <tessera/core/tri_mesh.hpp>

namespace shapes {

using voxel = std::array<int, 3>;

/// Boundary surface of a set of unit voxels, each unit face as s x s squares (two triangles each),
/// outward oriented, vertices welded, scaled by `scale`.
inline tessera::tri_mesh voxel_surface(const std::set<voxel>& vox, int s, double scale = 1.0) {
  tessera::tri_mesh m;
  std::map<std::array<int, 3>, tessera::index_t> id;
  auto vert = [&](std::array<int, 3> g) {
    auto [it, fresh] = id.emplace(g, m.num_vertices());
    if (fresh) m.add_vertex({g[0] * scale / s, g[1] * scale / s, g[2] * scale / s});
    return it->second;
  };
  for (const voxel& v : vox)
    for (int a = 0; a < 3; ++a)
      for (int sign = -1; sign <= 1; sign += 2) {
        voxel n = v;
        n[a] += sign;
        if (vox.count(n)) continue;
        const int u = sign > 0 ? (a + 1) % 3 : (a + 2) % 3, w = sign > 0 ? (a + 2) % 3 : (a + 1) % 3;
        for (int i = 0; i < s; ++i)
          for (int j = 0; j < s; ++j) {
            std::array<tessera::index_t, 4> q;
            const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
            for (int k = 0; k < 4; ++k) {
              std::array<int, 3> g{v[0] * s, v[1] * s, v[2] * s};
              if (sign > 0) g[a] += s;
              g[u] += i + du[k];
              g[w] += j + dw[k];
              q[k] = vert(g);
            }
            m.add_face(q[0], q[1], q[2]);
            m.add_face(q[0], q[2], q[3]);
          }
      }
  return m;
}

inline std::set<voxel> cube() { return {{0, 0, 0}}; }
inline std::set<voxel> l_shape() { return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}; }
inline std::set<voxel> ring() {  // 3 x 3 x 1 minus the centre: genus 1
  std::set<voxel> r;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      if (x != 1 || y != 1) r.insert({x, y, 0});
  return r;
}
inline std::set<voxel> genus2() {  // 5 x 3 x 1 minus two holes
  std::set<voxel> r;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 3; ++y)
      if (y != 1 || (x != 1 && x != 3)) r.insert({x, y, 0});
  return r;
}

/// Unit sphere from a cube whose faces are cut into n x n squares, projected outwards.
inline tessera::tri_mesh sphere(int n) {
  auto m = voxel_surface(cube(), n);
  for (auto& p : m.positions) p = tessera::normalized(p - tessera::vec3{0.5, 0.5, 0.5});
  return m;
}

/// Torus around Z with radii R > r, nu segments around Z and nv around the tube.
inline tessera::tri_mesh torus(double R, double r, int nu, int nv) {
  tessera::tri_mesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      m.add_vertex({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto at = [&](int i, int j) { return static_cast<tessera::index_t>(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

}  // namespace shapes
