// tessera/geometry/mesh_elements.hpp: a geometric texture as a set of elements (connected components:
// rings, pebbles, threads), with the per-element bookkeeping mesh quilting needs (paper 000, §3.3):
// fixed vertices, the border set B(C) of §3.3.5 (which tile sides the element was placed on), the
// border triangles and border vertices derived from it, and open / non-manifold edge counts.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// An axis-aligned rectangle of the XY plane: a tile [0, w]^2, a quilted texture's extent, a patch.
struct xy_rect {
  /// Corners: [x0, x1] x [y0, y1].
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  /// x1 - x0.
  [[nodiscard]] constexpr double width() const noexcept { return x1 - x0; }
  /// y1 - y0.
  [[nodiscard]] constexpr double height() const noexcept { return y1 - y0; }
  /// True when p's XY lies in the rectangle (borders included).
  [[nodiscard]] constexpr bool contains(vec3 p) const noexcept {
    return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
  }
  /// True when b's XY extent meets the rectangle.
  [[nodiscard]] constexpr bool overlaps(const aabb& b) const noexcept {
    return b.min.x <= x1 && b.max.x >= x0 && b.min.y <= y1 && b.max.y >= y0;
  }
  friend constexpr bool operator==(const xy_rect&, const xy_rect&) = default;
};

/// Bit of tile side s (0 north = y1, 1 east = x1, 2 south = y0, 3 west = x0) in a border set.
constexpr unsigned border_bit(int side) noexcept { return 1u << side; }

/// One element of a geometric texture, as its own small mesh.
struct texture_element {
  /// The element's mesh.
  tri_mesh mesh;
  std::vector<unsigned char> fixed;  ///< one flag per vertex: 1 = held fixed (tile border constraint)
  unsigned border = 0;               ///< B(C) of §3.3.5: border_bit(s) for each tile side s it lies on
  aabb box;                          ///< bounds of mesh.positions (call update_box after edits)

  /// Recomputes `box` from the mesh.
  void update_box() {
    box = aabb{};
    for (const vec3& p : mesh.positions) box.extend(p);
  }
  /// True when a vertex is held fixed.
  [[nodiscard]] bool has_fixed() const noexcept {
    return std::any_of(fixed.begin(), fixed.end(), [](unsigned char f) { return f != 0; });
  }
};

/// Open (boundary) and non-manifold edge counts of a mesh.
struct edge_defects {
  /// Edges of one face.
  index_t open_edges = 0;
  /// Edges of more than two faces.
  index_t nonmanifold_edges = 0;
};

/// Counts the open and non-manifold edges of m.
template <Mesh M>
edge_defects count_edge_defects(const M& m) {
  edge_defects d;
  for (const mesh_edge& e : mesh_edges(m)) {
    if (e.faces.size() == 1)
      ++d.open_edges;
    else if (e.faces.size() > 2)
      ++d.nonmanifold_edges;
  }
  return d;
}

/// Options of extract_elements.
struct extract_elements_options {
  bool require_closed = true;    ///< reject elements with open edges (a closed-element exemplar)
  bool require_manifold = true;  ///< reject edges shared by more than two faces
};

/// Splits a geometric texture into its elements (connected components, numbered in order of their
/// first face), each a compact tri_mesh with no fixed vertices and an empty border set.
/// Errors: invalid mesh (NaN positions, indices out of range, degenerate faces), a mesh without
/// faces, and, as the options ask, elements with open or non-manifold edges (the message names the
/// element and the edge count). O(F log F).
template <Mesh M>
result<std::vector<texture_element>> extract_elements(const M& mesh, const extract_elements_options& options = {},
                                                      std::string_view what = "mesh") {
  auto tm = to_tri_mesh(mesh, what);
  if (!tm) return tm.error();
  const tri_mesh& m = *tm;
  if (m.faces.empty()) return status::invalid_argument(detail::cat(what, ": has no faces"));
  const mesh_components comp = connected_components(m);
  std::vector<texture_element> out(detail::to_size(comp.count));
  std::vector<index_t> local(m.positions.size(), -1);
  for (index_t f = 0; f < m.num_faces(); ++f) {
    auto& e = out[detail::to_size(comp.face_component[detail::to_size(f)])];
    std::array<index_t, 3> lf{};
    for (int k = 0; k < 3; ++k) {
      const index_t v = m.faces[detail::to_size(f)][detail::to_size(k)];
      auto& id = local[detail::to_size(v)];
      if (id < 0) id = e.mesh.add_vertex(m.positions[detail::to_size(v)]);
      lf[detail::to_size(k)] = id;
    }
    e.mesh.add_face(lf[0], lf[1], lf[2]);
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    auto& e = out[i];
    e.fixed.assign(e.mesh.positions.size(), 0);
    e.update_box();
    if (options.require_closed || options.require_manifold) {
      const edge_defects d = count_edge_defects(e.mesh);
      if (options.require_manifold && d.nonmanifold_edges > 0)
        return status::invalid_argument(detail::cat(what, ": element ", i, " has ", d.nonmanifold_edges,
                                                    " non-manifold edges (shared by more than two faces)"));
      if (options.require_closed && d.open_edges > 0)
        return status::invalid_argument(
            detail::cat(what, ": element ", i, " has ", d.open_edges, " open edges; elements must be closed surfaces"));
    }
  }
  return out;
}

/// Concatenates elements into one mesh (element order, vertices renumbered).
inline tri_mesh combine_elements(std::span<const texture_element> elements) {
  tri_mesh out;
  std::size_t nv = 0, nf = 0;
  for (const auto& e : elements) {
    nv += e.mesh.positions.size();
    nf += e.mesh.faces.size();
  }
  out.positions.reserve(nv);
  out.faces.reserve(nf);
  for (const auto& e : elements) out.append(e.mesh);
  return out;
}

/// Border triangles of §3.3.5: faces of `e` that meet one of the tile sides in its border set B(C),
/// taking each side as the vertical plane through that side of `domain` (within `tolerance`).
inline std::vector<unsigned char> border_triangles(const texture_element& e, const xy_rect& domain,
                                                   double tolerance = 0) {
  std::vector<unsigned char> out(e.mesh.faces.size(), 0);
  if (e.border == 0) return out;
  for (std::size_t f = 0; f < e.mesh.faces.size(); ++f) {
    aabb b;
    for (index_t v : e.mesh.faces[f]) b.extend(e.mesh.positions[detail::to_size(v)]);
    bool hit = false;
    for (int side = 0; side < 4 && !hit; ++side) {
      if (!(e.border & border_bit(side))) continue;
      const int axis = is_horizontal_side(side) ? 1 : 0;
      const double line = side == side_north   ? domain.y1
                          : side == side_east  ? domain.x1
                          : side == side_south ? domain.y0
                                               : domain.x0;
      hit = b.min[axis] <= line + tolerance && b.max[axis] >= line - tolerance;
    }
    out[f] = hit ? 1 : 0;
  }
  return out;
}

/// Border vertices of §3.3.5: the corners of the border triangles (held fixed during deformation).
inline std::vector<unsigned char> border_vertices(const texture_element& e, const xy_rect& domain,
                                                  double tolerance = 0) {
  std::vector<unsigned char> out(e.mesh.positions.size(), 0);
  const auto tri = border_triangles(e, domain, tolerance);
  for (std::size_t f = 0; f < tri.size(); ++f)
    if (tri[f])
      for (index_t v : e.mesh.faces[f]) out[detail::to_size(v)] = 1;
  return out;
}

TESSERA_NAMESPACE_END
