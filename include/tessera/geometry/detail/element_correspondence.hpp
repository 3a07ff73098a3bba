// tessera/geometry/detail/element_correspondence.hpp: the first steps of merging a pair of
// corresponding elements (paper 000, after Zhou et al. 2006): §3.3.4 correspondences by closest
// points, §3.3.5 Laplacian deformation of both elements towards the midpoints (eq. 6 and 7) with
// their border vertices held, and what the cuts of §3.3.6 read from the deformed pair (the eq. 8
// distances, the correspondence frontier). element_merge.hpp runs the steps.
#pragma once

#include <cmath>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/mesh_topology.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../bvh.hpp"
#include "../laplacian.hpp"
#include "../mesh_elements.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// A vertex of C_T and its closest point on C_in (face, barycentric coordinates, point).
struct element_correspondence {
  index_t v, face;
  vec3 bary, point;
};

/// One element of a pair after the deformation of §3.3.5, with what its cut (§3.3.6) reads.
struct merge_side {
  tri_mesh mesh;                        ///< deformed
  std::vector<unsigned char> fixed;     ///< held vertices (held_vertices)
  std::vector<unsigned char> border;    ///< border triangles (§3.3.5)
  std::vector<double> dist;             ///< Dist(v, other element) of eq. 8, capped
  std::vector<index_t> corr_face;       ///< the other element's closest face within the radius, or -1
  std::vector<unsigned char> frontier;  ///< faces on the correspondence frontier (when computed)
};

/// §3.3.4 of paper 000: each vertex of `from` corresponds to its closest point on `to` when that
/// lies within the correspondence radius (`radius2` is its square).
/// With `to_mesh` (the mesh of `to`), a pair counts only when the vertex normal of `from` and the
/// face normal of `to` agree to at least `min_cos`: the flat caps of clipped thread pieces then
/// correspond to nothing, instead of pulling the other piece's walls into a neck (§3.3.5).
inline std::vector<element_correspondence> find_correspondences(const tri_mesh& from, const triangle_bvh& to,
                                                                double radius2, const tri_mesh* to_mesh = nullptr,
                                                                double min_cos = 0) {
  std::vector<element_correspondence> out;
  const std::vector<vec3> vn = to_mesh ? vertex_normals(from) : std::vector<vec3>{};
  for (index_t v = 0; v < from.num_vertices(); ++v) {
    const auto h = to.closest_point(from.positions[to_size(v)], radius2);
    if (h.face < 0) continue;
    if (to_mesh) {
      const auto& f = to_mesh->faces[to_size(h.face)];
      const vec3 a = to_mesh->positions[to_size(f[0])], b = to_mesh->positions[to_size(f[1])],
                 c = to_mesh->positions[to_size(f[2])];
      const vec3 n = cross(b - a, c - a);
      const double len = norm(n);
      if (!(len > 0) || dot(vn[to_size(v)], n) < min_cos * len) continue;
    }
    out.push_back({v, h.face, h.bary, h.point});
  }
  return out;
}

/// The vertices §3.3.5 holds while deforming `el`: its border vertices (corners of the triangles
/// that cross a tile side in B(el)) and the vertices an earlier merge fixed.
inline std::vector<unsigned char> held_vertices(const texture_element& el, const xy_rect& domain) {
  std::vector<unsigned char> held = border_vertices(el, domain);
  for (std::size_t v = 0; v < held.size(); ++v) held[v] = held[v] || (v < el.fixed.size() && el.fixed[v]);
  return held;
}

/// §3.3.5, eq. 6 and 7 of paper 000: C_T and C_in deformed towards the midpoints
/// c_i = (v_T^i + h_in^i) / 2 of their correspondences with weight mu, their held vertices fixed.
/// Writes the deformed meshes into t.mesh and in.mesh; false when a solve fails.
template <class Deferred = void>
bool deform_to_midpoints(const tri_mesh& ct, const tri_mesh& cin, const std::vector<element_correspondence>& corr,
                         double mu, merge_side& t, merge_side& in) {
  std::vector<laplacian_constraint> ks_t, ks_in;
  for (const element_correspondence& c : corr) {
    const vec3 mid = (ct.positions[to_size(c.v)] + c.point) * 0.5;
    ks_t.push_back({{c.v, -1, -1}, {1, 0, 0}, mid});  // eq. 6: the vertex itself
    const auto& f = cin.faces[to_size(c.face)];
    ks_in.push_back({{f[0], f[1], f[2]}, {c.bary.x, c.bary.y, c.bary.z}, mid});  // eq. 7: alpha, beta, gamma
  }
  const auto dt = laplacian_deform(ct, t.fixed, ks_t, {.soft_weight = mu});
  const auto din = laplacian_deform(cin, in.fixed, ks_in, {.soft_weight = mu});
  if (!dt || !din) return false;
  t.mesh = ct;
  in.mesh = cin;
  t.mesh.positions = *dt;
  in.mesh.positions = *din;
  return true;
}

/// What the cut of `side` reads from the other element (eq. 8): per vertex, Dist(v, other) searched
/// up to `cap` and capped there, and the other's closest face when within the correspondence radius.
inline void measure_distances(merge_side& side, const triangle_bvh& other, double radius2, double cap) {
  const std::size_t nv = side.mesh.positions.size();
  side.dist.assign(nv, 0.0);
  side.corr_face.assign(nv, -1);
  for (std::size_t v = 0; v < nv; ++v) {
    const auto h = other.closest_point(side.mesh.positions[v], cap * cap);
    side.dist[v] = h.face >= 0 ? std::sqrt(h.squared_distance) : cap;
    if (h.face >= 0 && h.squared_distance <= radius2) side.corr_face[v] = h.face;
  }
}

/// The "frontier" of §3.3.6 on an element: faces all of whose corners have the other element within
/// the correspondence distance, next to a face that has not (where the element goes on beyond the
/// other one). The paper asks for the faces whose neighbours no vertex of the other element is
/// closest to; closest-face sets are too sparse on meshes of similar density, so every face near the
/// other element counts as corresponded.
template <class Deferred = void>
std::vector<unsigned char> correspondence_frontier(const tri_mesh& m, const std::vector<index_t>& corr_face) {
  std::vector<unsigned char> corresponded(m.faces.size(), 0), out(m.faces.size(), 0);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    bool all = true;
    for (index_t v : m.faces[f]) all = all && corr_face[to_size(v)] >= 0;
    corresponded[f] = all ? 1 : 0;
  }
  const auto adj = face_adjacency(m);
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (corresponded[f])
      for (index_t g : adj.neighbor[f])
        if (g >= 0 && !corresponded[to_size(g)]) out[f] = 1;
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
