// tessera/core/tri_mesh.hpp: tessera's owning triangle mesh (double positions, optional per-corner
// uvs), validation of any Mesh, conversion of any Mesh into a tri_mesh, and per-face / per-vertex
// geometry (normals, areas, bounding box). Connectivity (adjacency, boundary, components) is in
// core/mesh_topology.hpp. The geometry helpers expect a valid mesh (validate_mesh): the whole-mesh
// ones (face_normals, vertex_normals, bounding_box) ignore faces naming a vertex out of range rather
// than touch memory outside the mesh; the per-face ones take a face index in [0, F) as a precondition,
// like operator[]. All are O(V + F), allocate only their result, and are thread-safe on const input.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <string_view>
#include <type_traits>
#include <vector>

#include "config.hpp"
#include "mesh.hpp"
#include "status.hpp"
#include "vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// Smallest interior angle of triangle (a, b, c), in degrees (0 for a degenerate one).
inline double smallest_angle_degrees(vec3 a, vec3 b, vec3 c) noexcept {
  const vec3 p[3] = {a, b, c};
  double largest_cos = -1;  // the smallest angle has the largest cosine: one acos
  for (int k = 0; k < 3; ++k)
    largest_cos = std::max(largest_cos, dot(normalized(p[(k + 1) % 3] - p[k]), normalized(p[(k + 2) % 3] - p[k])));
  return std::acos(std::min(largest_cos, 1.0)) * (180 / 3.14159265358979323846);
}

/// Owning triangle mesh. Plain data: `positions`, `faces` (three vertex indices, counter-clockwise
/// seen from the front) and `uvs` (empty, or exactly one uv triple per face; validate_mesh checks
/// this). Models Mesh and UVMesh.
struct tri_mesh {
  /// Vertex positions.
  std::vector<vec3> positions;
  /// Triangles, three vertex indices each.
  std::vector<std::array<index_t, 3>> faces;
  /// Optional texture coordinates per face corner (empty, or one entry per face).
  std::vector<std::array<vec2, 3>> uvs;

  /// Vertex count.
  [[nodiscard]] index_t num_vertices() const noexcept { return static_cast<index_t>(positions.size()); }
  /// Face count.
  [[nodiscard]] index_t num_faces() const noexcept { return static_cast<index_t>(faces.size()); }
  /// Vertex index of corner k (0..2) of face f.
  [[nodiscard]] index_t face_vertex(index_t f, int k) const noexcept {
    return faces[detail::to_size(f)][detail::to_size(k)];
  }
  /// Position of vertex v.
  [[nodiscard]] const vec3& position(index_t v) const noexcept { return positions[detail::to_size(v)]; }
  /// True when uvs is not empty.
  [[nodiscard]] bool has_uvs() const noexcept { return !uvs.empty(); }
  /// Texture coordinate of corner k of face f.
  [[nodiscard]] const vec2& corner_uv(index_t f, int k) const noexcept {
    return uvs[detail::to_size(f)][detail::to_size(k)];
  }

  /// Appends a vertex; returns its index.
  index_t add_vertex(vec3 p) {
    positions.push_back(p);
    return num_vertices() - 1;
  }
  /// Appends a face without uvs (use on meshes without uvs).
  index_t add_face(index_t a, index_t b, index_t c) {
    faces.push_back({a, b, c});
    return num_faces() - 1;
  }
  /// Appends a face with its corner uvs (use on meshes whose every face has uvs).
  index_t add_face(index_t a, index_t b, index_t c, const std::array<vec2, 3>& corner_uvs) {
    faces.push_back({a, b, c});
    uvs.push_back(corner_uvs);
    return num_faces() - 1;
  }
  /// Appends another mesh (its vertices translated by `offset`), renumbering its indices. The result
  /// has uvs when every face of both meshes has them (a mesh without faces does not count); otherwise
  /// all uvs are dropped, since uvs must cover every face.
  void append(const tri_mesh& other, vec3 offset = {}) {
    const bool keep_uvs =
        (has_uvs() || faces.empty()) && (other.has_uvs() || other.faces.empty()) && (has_uvs() || other.has_uvs());
    if (!keep_uvs) uvs.clear();
    const index_t base = num_vertices();
    positions.reserve(positions.size() + other.positions.size());
    for (const vec3& p : other.positions) positions.push_back(p + offset);
    faces.reserve(faces.size() + other.faces.size());
    for (const auto& f : other.faces) faces.push_back({f[0] + base, f[1] + base, f[2] + base});
    if (keep_uvs) uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  }
  friend bool operator==(const tri_mesh&, const tri_mesh&) = default;
};

/// Checks any Mesh: non-negative counts, face indices in range, no face repeating a vertex
/// (degenerate), finite positions and uvs (and, for tri_mesh, one uv triple per face when it has
/// uvs). `what` names the mesh in the message. Zero-area faces with three distinct vertices are
/// accepted. When mesh_traits<M> has `static status validate(const M&, std::string_view what)`
/// (checks only the adapter can make, e.g. OpenMesh's non-triangle faces and deleted elements), that
/// runs first. Returns invalid_argument, or out_of_range for a bad index. O(V + F).
template <Mesh M>
status validate_mesh(const M& m, std::string_view what = "mesh") {
  if constexpr (requires {
                  { mesh_traits<M>::validate(m, what) } -> std::same_as<status>;
                }) {
    if (auto s = mesh_traits<M>::validate(m, what); !s) return s;
  }
  const index_t nv = tessera::num_vertices(m), nf = tessera::num_faces(m);
  if (nv < 0 || nf < 0)
    return status::invalid_argument(detail::cat(what, ": negative vertex or face count (", nv, ", ", nf, ")"));
  if constexpr (std::is_same_v<M, tri_mesh>) {
    if (!m.uvs.empty() && m.uvs.size() != m.faces.size())
      return status::invalid_argument(detail::cat(what, ": has ", m.uvs.size(), " uv triples for ", m.faces.size(),
                                                  " faces; uvs must be empty or hold one triple per face"));
  }
  for (index_t v = 0; v < nv; ++v) {
    const vec3 p = tessera::vertex_position(m, v);
    if (!is_finite(p))
      return status::invalid_argument(
          detail::cat(what, ": vertex ", v, " has a non-finite position (", p.x, ", ", p.y, ", ", p.z, ")"));
  }
  for (index_t f = 0; f < nf; ++f) {
    index_t idx[3];
    for (int k = 0; k < 3; ++k) {
      const index_t v = tessera::face_vertex(m, f, k);  // a local, not idx[k]: GCC's -Warray-bounds misfires
      if (v < 0 || v >= nv)
        return status::out_of_range(detail::cat(what, ": face ", f, " corner ", k, " refers to vertex ", v,
                                                " but the mesh has ", nv, " vertices"));
      idx[k] = v;
    }
    if (idx[0] == idx[1] || idx[1] == idx[2] || idx[0] == idx[2])
      return status::invalid_argument(
          detail::cat(what, ": face ", f, " is degenerate (vertices ", idx[0], ", ", idx[1], ", ", idx[2], ")"));
  }
  if constexpr (UVMesh<M>) {
    if (mesh_traits<M>::has_uvs(m))
      for (index_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k)
          if (!is_finite(to_vec2(mesh_traits<M>::corner_uv(m, f, k))))
            return status::invalid_argument(detail::cat(what, ": face ", f, " corner ", k, " has a non-finite uv"));
  }
  return {};
}

/// Validates any Mesh and copies it into a tri_mesh (uvs too, when it has them).
template <Mesh M>
result<tri_mesh> to_tri_mesh(const M& m, std::string_view what = "mesh") {
  if (auto s = validate_mesh(m, what); !s) return s;
  tri_mesh out;
  const index_t nv = tessera::num_vertices(m), nf = tessera::num_faces(m);
  out.positions.resize(detail::to_size(nv));
  for (index_t v = 0; v < nv; ++v) out.positions[detail::to_size(v)] = tessera::vertex_position(m, v);
  out.faces.resize(detail::to_size(nf));
  for (index_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) out.faces[detail::to_size(f)][detail::to_size(k)] = tessera::face_vertex(m, f, k);
  if constexpr (UVMesh<M>) {
    if (mesh_traits<M>::has_uvs(m)) {
      out.uvs.resize(detail::to_size(nf));
      for (index_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k)
          out.uvs[detail::to_size(f)][detail::to_size(k)] = to_vec2(mesh_traits<M>::corner_uv(m, f, k));
    }
  }
  return out;
}

/// The three corner positions of face f. Precondition: f in [0, F) and the face's vertices in range.
template <Mesh M>
std::array<vec3, 3> face_corners(const M& m, index_t f) {
  return {tessera::vertex_position(m, tessera::face_vertex(m, f, 0)),
          tessera::vertex_position(m, tessera::face_vertex(m, f, 1)),
          tessera::vertex_position(m, tessera::face_vertex(m, f, 2))};
}

/// Un-normalized normal of face f: (b - a) x (c - a), length twice the area.
template <Mesh M>
vec3 face_area_normal(const M& m, index_t f) {
  const auto c = face_corners(m, f);
  return cross(c[1] - c[0], c[2] - c[0]);
}

/// Unit normal per face (zero for zero-area faces and for faces naming a vertex out of range).
template <Mesh M>
std::vector<vec3> face_normals(const M& m) {
  const index_t nv = tessera::num_vertices(m), nf = std::max<index_t>(0, tessera::num_faces(m));
  std::vector<vec3> n(detail::to_size(nf));
  for (index_t f = 0; f < nf; ++f)
    if (detail::face_in_range(m, f, nv)) n[detail::to_size(f)] = normalized(face_area_normal(m, f));
  return n;
}

/// Unit normal per vertex: area-weighted average of incident face normals (zero where a vertex has
/// no face of non-zero area).
template <Mesh M>
std::vector<vec3> vertex_normals(const M& m) {
  const index_t nv = std::max<index_t>(0, tessera::num_vertices(m)), nf = std::max<index_t>(0, tessera::num_faces(m));
  std::vector<vec3> n(detail::to_size(nv));
  for (index_t f = 0; f < nf; ++f) {
    if (!detail::face_in_range(m, f, nv)) continue;
    const vec3 an = face_area_normal(m, f);
    for (int k = 0; k < 3; ++k) n[detail::to_size(tessera::face_vertex(m, f, k))] += an;
  }
  for (vec3& v : n) v = normalized(v);
  return n;
}

/// Area of face f.
template <Mesh M>
double face_area(const M& m, index_t f) {
  return 0.5 * norm(face_area_normal(m, f));
}

/// Bounding box of all vertices (empty box for a mesh without vertices).
template <Mesh M>
aabb bounding_box(const M& m) {
  aabb b;
  for (index_t v = 0; v < tessera::num_vertices(m); ++v) b.extend(tessera::vertex_position(m, v));
  return b;
}

TESSERA_NAMESPACE_END
