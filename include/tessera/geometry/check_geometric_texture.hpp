// tessera/geometry/check_geometric_texture.hpp: the quality figures of a geometric texture (a quilt,
// a tile, a tiled plane): open edges away from the texture's outer border, non-manifold edges, pairs
// of triangles of two distinct elements that intersect (triangle-triangle test, BVH accelerated),
// and the element count. These are the figures the tests assert and `--stats` reports.
#pragma once

#include <cmath>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "bvh.hpp"
#include "mesh_elements.hpp"

TESSERA_NAMESPACE_BEGIN

/// What check_geometric_texture found.
struct geometric_texture_report {
  index_t open_edges_inside = 0;   ///< open edges not lying on the outer border
  index_t nonmanifold_edges = 0;   ///< edges of more than two faces
  index_t intersecting_pairs = 0;  ///< intersecting triangle pairs from two distinct elements
  index_t elements = 0;            ///< connected components
};

/// Checks any valid Mesh. An open edge is allowed when both its vertices lie on the boundary of
/// `outer` (within `tolerance`; pass an empty rectangle to allow none). Errors: invalid mesh.
/// O(F log F) plus the intersecting candidate pairs.
template <Mesh M>
result<geometric_texture_report> check_geometric_texture(const M& mesh, const xy_rect& outer = {},
                                                         double tolerance = 1e-9) {
  auto tm = to_tri_mesh(mesh, "check_geometric_texture: mesh");
  if (!tm) return tm.error();
  const tri_mesh& m = *tm;
  geometric_texture_report r;
  auto on_border = [&](vec3 p) {
    if (!(outer.x1 > outer.x0)) return false;
    const bool in = p.x >= outer.x0 - tolerance && p.x <= outer.x1 + tolerance && p.y >= outer.y0 - tolerance &&
                    p.y <= outer.y1 + tolerance;
    return in && (std::abs(p.x - outer.x0) <= tolerance || std::abs(p.x - outer.x1) <= tolerance ||
                  std::abs(p.y - outer.y0) <= tolerance || std::abs(p.y - outer.y1) <= tolerance);
  };
  for (const mesh_edge& e : mesh_edges(m)) {
    if (e.faces.size() > 2) ++r.nonmanifold_edges;
    if (e.faces.size() == 1 &&
        !(on_border(m.positions[detail::to_size(e.v0)]) && on_border(m.positions[detail::to_size(e.v1)])))
      ++r.open_edges_inside;
  }
  const mesh_components comp = connected_components(m);
  r.elements = comp.count;
  const triangle_bvh bvh(m);
  bvh.for_each_self_intersection(
      [&](index_t f, index_t g) {
        return comp.face_component[detail::to_size(f)] == comp.face_component[detail::to_size(g)];
      },
      [&](index_t, index_t) { ++r.intersecting_pairs; });
  return r;
}

TESSERA_NAMESPACE_END
