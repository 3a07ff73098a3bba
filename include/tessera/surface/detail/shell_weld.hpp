// tessera/surface/detail/shell_weld.hpp: gathers the per-quad tile meshes of map_tiles_to_shell into one
// texture-space mesh over the polycube surface. Each tile vertex (u, v, h) becomes a polycube point P (mesh
// units) and a height h. A vertex on a quad side is re-expressed in its grid edge's own parameter s
// (from the edge's origin along +axis), and one at a quad corner as that grid point; vertices of the
// quads around one grid edge or corner whose (s, h) agree within the weld tolerance become one vertex
// whose P is computed once from the canonical record (the one of the lowest quad, then the lowest
// local index). Shared-edge points are therefore one vertex with one position, in the plane and around
// polycube edges, and elements cut by quad borders close up again.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// A point of texture space: a polycube point (mesh units) and a height above it (mesh units).
struct shell_texture_point {
  vec3 p;
  double h = 0;
};

/// The tiles of all quads as one mesh over texture space.
struct shell_texture_mesh {
  std::vector<shell_texture_point> points;
  std::vector<std::array<index_t, 3>> faces;
  std::vector<index_t> face_quad;  ///< the quad of every face
  index_t input_vertices = 0;      ///< tile vertices over all quads
  index_t welded = 0;              ///< tile vertices merged into a vertex of another record
  index_t dropped_faces = 0;       ///< faces that lost a corner to the weld (two corners merged)
  index_t quads = 0;               ///< quads with a non-empty tile mesh
};

inline index_t weld_find(std::vector<index_t>& parent, index_t i) {
  while (parent[to_size(i)] != i) {
    parent[to_size(i)] = parent[to_size(parent[to_size(i)])];
    i = parent[to_size(i)];
  }
  return i;
}
/// Union keeping the smaller record as the root (the canonical one).
inline void weld_union(std::vector<index_t>& parent, index_t a, index_t b) {
  a = weld_find(parent, a);
  b = weld_find(parent, b);
  if (a == b) return;
  if (a < b)
    parent[to_size(b)] = a;
  else
    parent[to_size(a)] = b;
}

/// Gathers and welds the tiles (see the file comment). `tiles(q)` returns the tile mesh of quad q or
/// nullptr. Tolerances in tile units (for h: times tile_size). Errors: an invalid tile mesh, a vertex
/// outside [0, 1]² x [0, H] beyond the tolerance, more than 2^31 vertices.
template <class Tiles>
result<shell_texture_mesh> gather_shell_tiles(const polycube_map& map, const Tiles& tiles, double height,
                                              double weld_tolerance) {
  shell_texture_mesh out;
  const double T = map.tile_size, tol = weld_tolerance, tol_h = weld_tolerance * T;
  const auto nq = static_cast<index_t>(map.layout.quads.size());
  struct record {
    index_t quad;
    int kind;     // 0 interior, 1 on a side, 2 at a corner
    index_t key;  // grid edge id (side) or the quad corner slot (corner)
    double s, h;  // edge parameter, height
    vec3 p;       // own polycube position (interior) or canonical one (side, corner)
  };
  std::vector<record> rec;
  std::vector<index_t> first(to_size(nq) + 1, 0);
  std::vector<const tri_mesh*> mesh(to_size(nq), nullptr);
  for (index_t q = 0; q < nq; ++q) {
    first[to_size(q)] = static_cast<index_t>(rec.size());
    const tri_mesh* m = tiles(q);
    if (m == nullptr || m->faces.empty()) continue;
    if (auto s = validate_mesh(*m, cat("tile mesh of quad ", q)); !s) return s;
    if (rec.size() + m->positions.size() >= (std::size_t{1} << 31))
      return status::size_overflow("map_tiles_to_shell: more than 2^31 tile vertices");
    mesh[to_size(q)] = m;
    ++out.quads;
    const auto& Q = map.layout.quads[to_size(q)];
    std::array<vec3, 4> c;
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) c[to_size(k)][a] = static_cast<double>(Q.corners[to_size(k)][to_size(a)]);
    for (index_t v = 0; v < m->num_vertices(); ++v) {
      const vec3 t = m->position(v);
      if (!(t.x >= -tol && t.x <= 1 + tol && t.y >= -tol && t.y <= 1 + tol && t.z >= -tol_h && t.z <= height + tol_h))
        return status::invalid_argument(cat("map_tiles_to_shell: vertex ", v, " of the tile of quad ", q,
                                            " at (u, v, h) = (", t.x, ", ", t.y, ", ", t.z,
                                            ") lies outside [0, 1]² x [0, H = ", height, "]"));
      record r{q, 0, -1, 0, std::clamp(t.z, 0.0, height), {}};
      const double u = std::clamp(t.x, 0.0, 1.0), w = std::clamp(t.y, 0.0, 1.0);
      const bool u0 = u <= tol, u1 = u >= 1 - tol, w0 = w <= tol, w1 = w >= 1 - tol;
      if ((u0 || u1) && (w0 || w1)) {
        r.kind = 2;
        r.key = u0 ? (w0 ? 0 : 3) : (w0 ? 1 : 2);
        r.p = c[to_size(r.key)] * T;
      } else if (u0 || u1 || w0 || w1) {
        const int side = w0 ? 0 : u1 ? 1 : w1 ? 2 : 3;
        const double along = side == 0 ? u : side == 1 ? w : side == 2 ? 1 - u : 1 - w;
        r.kind = 1;
        r.key = Q.edges[to_size(side)];
        r.s = Q.edge_forward[to_size(side)] ? along : 1 - along;
        const auto& e = map.layout.edges[to_size(r.key)];
        vec3 o{static_cast<double>(e.origin[0]), static_cast<double>(e.origin[1]), static_cast<double>(e.origin[2])};
        o[e.axis] += r.s;
        r.p = o * T;
      } else {
        r.p = (c[0] + u * (c[1] - c[0]) + w * (c[3] - c[0])) * T;
      }
      rec.push_back(r);
    }
  }
  first[to_size(nq)] = static_cast<index_t>(rec.size());
  const auto n = static_cast<index_t>(rec.size());
  out.input_vertices = n;
  // cluster records on one grid edge (by s, h) and at one grid corner (by h)
  std::vector<index_t> parent(to_size(n));
  std::iota(parent.begin(), parent.end(), index_t{0});
  std::vector<index_t> sides, corners;
  std::vector<grid_point> corner_grid(to_size(n));
  for (index_t i = 0; i < n; ++i) {
    const auto& r = rec[to_size(i)];
    if (r.kind == 1) sides.push_back(i);
    if (r.kind == 2) {
      corners.push_back(i);
      corner_grid[to_size(i)] = map.layout.quads[to_size(r.quad)].corners[to_size(r.key)];
    }
  }
  std::sort(sides.begin(), sides.end(), [&](index_t a, index_t b) {
    const auto &x = rec[to_size(a)], &y = rec[to_size(b)];
    return x.key != y.key ? x.key < y.key : x.s != y.s ? x.s < y.s : a < b;
  });
  for (std::size_t i = 0; i < sides.size(); ++i)
    for (std::size_t j = i + 1; j < sides.size(); ++j) {
      const auto &x = rec[to_size(sides[i])], &y = rec[to_size(sides[j])];
      if (y.key != x.key || y.s - x.s > tol) break;
      if (std::abs(y.h - x.h) <= tol_h && y.quad != x.quad) weld_union(parent, sides[i], sides[j]);
    }
  std::sort(corners.begin(), corners.end(), [&](index_t a, index_t b) {
    const auto &x = corner_grid[to_size(a)], &y = corner_grid[to_size(b)];
    return x != y ? x < y : rec[to_size(a)].h != rec[to_size(b)].h ? rec[to_size(a)].h < rec[to_size(b)].h : a < b;
  });
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = i + 1; j < corners.size(); ++j) {
      const auto &x = rec[to_size(corners[i])], &y = rec[to_size(corners[j])];
      if (corner_grid[to_size(corners[i])] != corner_grid[to_size(corners[j])] || y.h - x.h > tol_h) break;
      if (y.quad != x.quad) weld_union(parent, corners[i], corners[j]);
    }
  // one vertex per cluster, positioned from its canonical (lowest) record
  std::vector<index_t> id(to_size(n), -1);
  out.points.reserve(to_size(n));
  for (index_t i = 0; i < n; ++i) {
    const index_t root = weld_find(parent, i);
    if (root != i) {
      id[to_size(i)] = id[to_size(root)];
      ++out.welded;
      continue;
    }
    id[to_size(i)] = static_cast<index_t>(out.points.size());
    out.points.push_back({rec[to_size(i)].p, rec[to_size(i)].h});
  }
  for (index_t q = 0; q < nq; ++q) {
    const tri_mesh* m = mesh[to_size(q)];
    if (m == nullptr) continue;
    const index_t b = first[to_size(q)];
    for (const auto& f : m->faces) {
      const std::array<index_t, 3> g{id[to_size(b + f[0])], id[to_size(b + f[1])], id[to_size(b + f[2])]};
      if (g[0] == g[1] || g[1] == g[2] || g[0] == g[2]) {
        ++out.dropped_faces;
        continue;
      }
      out.faces.push_back(g);
      out.face_quad.push_back(q);
    }
  }
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
