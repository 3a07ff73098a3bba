// tessera/adapters/openmesh.hpp: OpenMesh meshes through tessera's concepts (link tessera::openmesh;
// Debian libopenmesh-dev).
//
//   mesh_traits<M>       any OpenMesh mesh (TriMesh_ArrayKernelT<>, PolyMesh_ArrayKernelT<>, or a
//                        class derived from them) models Mesh and UVMesh: vertex and face indices are
//                        OpenMesh's handle indices, face_vertex walks the face's halfedges in the
//                        order OpenMesh's fv_range() visits them, uvs come from halfedge texcoords
//                        (per corner) or else vertex texcoords
//   validate_openmesh    what a halfedge mesh needs beyond validate_mesh(): triangle faces only and
//                        no deleted elements (validate_mesh() and to_tri_mesh() call it)
//   to_openmesh          any Mesh (an algorithm's tri_mesh result) into an OpenMesh mesh
//
// Two things to do before handing an OpenMesh mesh to tessera:
//   * mesh.garbage_collection() after deleting elements: deleted faces and vertices keep their
//     indices until then, and tessera reports them rather than reading them;
//   * mesh.triangulate() on a PolyMesh with quads or n-gons: tessera's algorithms read triangles.
#pragma once

#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <OpenMesh/Core/Mesh/PolyConnectivity.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <concepts>
#include <string_view>
#include <type_traits>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// An OpenMesh halfedge mesh with vertex positions (a PolyConnectivity-derived mesh such as
/// TriMesh_ArrayKernelT or PolyMesh_ArrayKernelT): what the OpenMesh adapter accepts.
template <class M>
concept OpenMeshMesh = std::derived_from<M, OpenMesh::PolyConnectivity> &&
    requires(const M& m, typename M::VertexHandle v) {
  m.point(v);
};

namespace detail {
/// The halfedge of face f pointing to its corner k (corner 0 is the target of the face's halfedge).
template <OpenMeshMesh M>
typename M::HalfedgeHandle openmesh_corner(const M& m, index_t f, int k) {
  auto h = m.halfedge_handle(m.face_handle(static_cast<unsigned>(f)));
  for (int i = 0; i < k; ++i) h = m.next_halfedge_handle(h);
  return h;
}
}  // namespace detail

/// OpenMesh vectors as points; coordinates past the vector's size read 0.
template <class S, int N>
struct point_traits<OpenMesh::VectorT<S, N>> {
  /// Coordinate i, or 0 past the vector's size.
  static double get(const OpenMesh::VectorT<S, N>& p, int i) noexcept {
    return i >= 0 && i < N ? static_cast<double>(p[detail::to_size(i)]) : 0.0;
  }
};

/// Checks what tessera needs of an OpenMesh mesh beyond validate_mesh(): no deleted vertex or face
/// (call garbage_collection() first) and only triangle faces (call triangulate() first). Returns an
/// invalid_argument status naming the first offending element and the fix. O(V + F). Thread-safe for
/// concurrent readers.
template <OpenMeshMesh M>
status validate_openmesh(const M& m, std::string_view what = "mesh") {
  auto first_deleted = [&](const char* kind, bool has_status, const auto& range) -> status {
    if (has_status)
      for (auto h : range)
        if (m.status(h).deleted())
          return status::invalid_argument(detail::cat(what, ": ", kind, " ", h.idx(),
                                                      " is deleted; call garbage_collection() on the OpenMesh mesh "
                                                      "before handing it to tessera"));
    return {};
  };
  if (auto s = first_deleted("vertex", m.has_vertex_status(), m.all_vertices()); !s) return s;
  if (auto s = first_deleted("face", m.has_face_status(), m.all_faces()); !s) return s;
  for (auto f : m.all_faces()) {
    if (!m.halfedge_handle(f).is_valid())
      return status::invalid_argument(detail::cat(what, ": face ", f.idx(), " has no halfedge"));
    const auto n = m.valence(f);
    if (n != 3)
      return status::invalid_argument(detail::cat(what, ": face ", f.idx(), " has ", n,
                                                  " vertices; tessera reads triangle meshes (call triangulate() "
                                                  "on the OpenMesh mesh first)"));
  }
  return {};
}

/// OpenMesh meshes as tessera meshes (see the top of this file).
template <class M>
requires OpenMeshMesh<M>
struct mesh_traits<M> {
  static index_t num_vertices(const M& m) noexcept { return static_cast<index_t>(m.n_vertices()); }
  static index_t num_faces(const M& m) noexcept { return static_cast<index_t>(m.n_faces()); }
  static index_t face_vertex(const M& m, index_t f, int k) {
    return static_cast<index_t>(m.to_vertex_handle(detail::openmesh_corner(m, f, k)).idx());
  }
  static decltype(auto) position(const M& m, index_t v) { return m.point(m.vertex_handle(static_cast<unsigned>(v))); }
  static bool has_uvs(const M& m) noexcept { return m.has_halfedge_texcoords2D() || m.has_vertex_texcoords2D(); }
  static auto corner_uv(const M& m, index_t f, int k) {
    const auto h = detail::openmesh_corner(m, f, k);
    return m.has_halfedge_texcoords2D() ? m.texcoord2D(h) : m.texcoord2D(m.to_vertex_handle(h));
  }
  static status validate(const M& m, std::string_view what) { return validate_openmesh(m, what); }
};

/// Copies any Mesh (typically an algorithm's tri_mesh result) into an OpenMesh mesh of type OM
/// (default OpenMesh::TriMesh_ArrayKernelT<>), keeping vertex and face order; per-corner uvs become
/// halfedge texcoords. OpenMesh's halfedge structure needs an oriented manifold, so besides
/// validate_mesh()'s checks this reports edges shared by more than two faces and neighbouring faces
/// with opposite orientation; a face OpenMesh still refuses (two fans meeting at one vertex) is
/// reported by index (OpenMesh also prints its own message to omerr()). O(F log F).
template <class OM = OpenMesh::TriMesh_ArrayKernelT<>, Mesh M>
requires OpenMeshMesh<OM> result<OM> to_openmesh(const M& m, std::string_view what = "mesh") {
  if (auto s = validate_mesh(m, what); !s) return s;
  for (const mesh_edge& e : mesh_edges(m)) {
    if (!e.is_manifold())
      return status::invalid_argument(detail::cat(what, ": edge (", e.v0, ", ", e.v1, ") is shared by ", e.faces.size(),
                                                  " faces; OpenMesh needs a manifold mesh"));
    if (e.faces.size() == 2) {
      const auto [f0, k0] = e.faces[0];
      const auto [f1, k1] = e.faces[1];
      const index_t from = face_vertex(m, f0, static_cast<int>(k0));
      if (from == face_vertex(m, f1, static_cast<int>(k1)))
        return status::invalid_argument(
            detail::cat(what, ": faces ", f0, " and ", f1, " are inconsistently oriented (both run ", "edge (", e.v0,
                        ", ", e.v1, ") from vertex ", from, "); OpenMesh needs a consistently oriented mesh"));
    }
  }
  using scalar = typename OM::Point::value_type;
  OM out;
  const index_t nv = num_vertices(m), nf = num_faces(m);
  out.reserve(detail::to_size(nv), detail::to_size(3 * nf / 2 + 1), detail::to_size(nf));
  for (index_t v = 0; v < nv; ++v) {
    const vec3 p = vertex_position(m, v);
    out.add_vertex(typename OM::Point(static_cast<scalar>(p.x), static_cast<scalar>(p.y), static_cast<scalar>(p.z)));
  }
  for (index_t f = 0; f < nf; ++f) {
    const auto fh = out.add_face(out.vertex_handle(static_cast<unsigned>(face_vertex(m, f, 0))),
                                 out.vertex_handle(static_cast<unsigned>(face_vertex(m, f, 1))),
                                 out.vertex_handle(static_cast<unsigned>(face_vertex(m, f, 2))));
    if (!fh.is_valid())
      return status::invalid_argument(detail::cat(what, ": OpenMesh cannot add face ", f,
                                                  " (a non-manifold vertex: two fans of faces meet at one vertex)"));
  }
  if constexpr (UVMesh<M>) {
    if (mesh_traits<M>::has_uvs(m)) {
      using tex = typename OM::TexCoord2D;
      using tscalar = typename tex::value_type;
      out.request_halfedge_texcoords2D();
      for (index_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) {
          const vec2 uv = to_vec2(mesh_traits<M>::corner_uv(m, f, k));
          out.set_texcoord2D(detail::openmesh_corner(out, f, k),
                             tex(static_cast<tscalar>(uv.x), static_cast<tscalar>(uv.y)));
        }
    }
  }
  return out;
}

TESSERA_NAMESPACE_END
