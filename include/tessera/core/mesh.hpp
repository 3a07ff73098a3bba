// tessera/core/mesh.hpp: how tessera sees a triangle mesh. The vocabulary is index based:
// `num_vertices()`, `num_faces()`, `face_vertex(f, k)` for k in 0..2, `position(v)`, and optionally
// per-corner texture coordinates `has_uvs()` and `corner_uv(f, k)`. `mesh_traits` reaches a user's
// mesh type (primary template: forward to members; specialize for foreign types such as OpenMesh,
// see adapters/openmesh.hpp). `point_traits` reads a position or uv of any vector type: anything
// with `p[i]` (std::array, Eigen, glm, OpenMesh vectors) or members `x, y, z`.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "vec.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
template <class P>
concept subscript_point = requires(const P& p, int i) {
  { p[i] } -> std::convertible_to<double>;
};
template <class P>
concept member_xy_point = requires(const P& p) {
  { p.x } -> std::convertible_to<double>;
  { p.y } -> std::convertible_to<double>;
};
/// Number of coordinates of a subscriptable point type when known at compile time (std::array,
/// Eigen fixed-size vectors, glm vectors); -1 when unknown.
template <class P>
constexpr int static_point_size() noexcept {
  if constexpr (requires { std::tuple_size<P>::value; })
    return static_cast<int>(std::tuple_size<P>::value);
  else if constexpr (requires {
                       { P::SizeAtCompileTime } -> std::convertible_to<int>;
                     })
    return P::SizeAtCompileTime > 0 ? static_cast<int>(P::SizeAtCompileTime) : -1;
  else if constexpr (requires {
                       { P::length() } -> std::convertible_to<int>;
                     })
    return static_cast<int>(P::length());
  else
    return -1;
}
}  // namespace detail

/// Reads coordinate i (0..2) of a point type as double. Coordinates a type does not have read as 0
/// (z of a 2D point), when its size is known at compile time. Specialize for vector types that have
/// neither `p[i]` nor `x, y, z` members.
template <class P>
struct point_traits {
  /// Coordinate i of p, from p[i] or p.x / p.y / p.z.
  static double get(const P& p, int i) requires detail::subscript_point<P> || detail::member_xy_point<P> {
    if constexpr (detail::subscript_point<P>) {
      constexpr int size = detail::static_point_size<P>();
      if (size >= 0 && i >= size) return 0.0;
      return static_cast<double>(p[i]);
    } else {
      if (i == 0) return static_cast<double>(p.x);
      if (i == 1) return static_cast<double>(p.y);
      if constexpr (requires { p.z; }) return static_cast<double>(p.z);
      return 0.0;
    }
  }
};

/// A type whose coordinates point_traits can read.
template <class P>
concept Point = requires(const P& p) {
  { point_traits<std::remove_cvref_t<P>>::get(p, 0) } -> std::convertible_to<double>;
};

/// The first three coordinates of any Point as a vec3.
template <Point P>
vec3 to_vec3(const P& p) {
  using T = point_traits<std::remove_cvref_t<P>>;
  return {T::get(p, 0), T::get(p, 1), T::get(p, 2)};
}
/// The first two coordinates of any Point as a vec2.
template <Point P>
vec2 to_vec2(const P& p) {
  using T = point_traits<std::remove_cvref_t<P>>;
  return {T::get(p, 0), T::get(p, 1)};
}

namespace detail {
template <class M>
concept member_mesh = requires(const M& m, index_t i, int k) {
  { m.num_vertices() } -> std::convertible_to<index_t>;
  { m.num_faces() } -> std::convertible_to<index_t>;
  { m.face_vertex(i, k) } -> std::convertible_to<index_t>;
  m.position(i);
};
template <class M>
concept member_uv_mesh = member_mesh<M> && requires(const M& m, index_t f, int k) {
  { m.has_uvs() } -> std::convertible_to<bool>;
  m.corner_uv(f, k);
};
}  // namespace detail

/// Reaches a mesh type. The primary template forwards to members; specialize it for foreign types.
/// A specialization may add `static status validate(const M&, std::string_view what)` for checks only
/// it can make (a polygon mesh's non-triangle faces); validate_mesh() calls it before its own checks.
template <class M>
struct mesh_traits {
  /// Vertex count, from the mesh's num_vertices().
  static index_t num_vertices(const M& m) requires detail::member_mesh<M> {
    return static_cast<index_t>(m.num_vertices());
  }
  /// Face count, from the mesh's num_faces().
  static index_t num_faces(const M& m) requires detail::member_mesh<M> { return static_cast<index_t>(m.num_faces()); }
  /// Vertex index of corner k (0..2) of face f, from the mesh's face_vertex(f, k).
  static index_t face_vertex(const M& m, index_t f, int k) requires detail::member_mesh<M> {
    return static_cast<index_t>(m.face_vertex(f, k));
  }
  /// Position of vertex v, from the mesh's position(v).
  static decltype(auto) position(const M& m, index_t v) requires detail::member_mesh<M> { return m.position(v); }
  /// Whether the mesh has per-corner texture coordinates, from its has_uvs().
  static bool has_uvs(const M& m) requires detail::member_uv_mesh<M> { return static_cast<bool>(m.has_uvs()); }
  /// Texture coordinate of corner k of face f, from the mesh's corner_uv(f, k).
  static decltype(auto) corner_uv(const M& m, index_t f, int k) requires detail::member_uv_mesh<M> {
    return m.corner_uv(f, k);
  }
};

/// A triangle mesh tessera can read.
template <class M>
concept Mesh = requires(const M& m, index_t i, int k) {
  { mesh_traits<M>::num_vertices(m) } -> std::convertible_to<index_t>;
  { mesh_traits<M>::num_faces(m) } -> std::convertible_to<index_t>;
  { mesh_traits<M>::face_vertex(m, i, k) } -> std::convertible_to<index_t>;
  { mesh_traits<M>::position(m, i) } -> Point;
};

/// A Mesh that may carry per-corner texture coordinates (check has_uvs at run time).
template <class M>
concept UVMesh = Mesh<M> && requires(const M& m, index_t f, int k) {
  { mesh_traits<M>::has_uvs(m) } -> std::convertible_to<bool>;
  { mesh_traits<M>::corner_uv(m, f, k) } -> Point;
};

/// Number of vertices of any Mesh (through mesh_traits).
template <Mesh M>
index_t num_vertices(const M& m) {
  return mesh_traits<M>::num_vertices(m);
}
/// Number of triangle faces of any Mesh.
template <Mesh M>
index_t num_faces(const M& m) {
  return mesh_traits<M>::num_faces(m);
}
/// Vertex index of corner k (0..2) of face f. Not range-checked: validate_mesh checks every index once.
template <Mesh M>
index_t face_vertex(const M& m, index_t f, int k) {
  return mesh_traits<M>::face_vertex(m, f, k);
}
/// Position of vertex v as a vec3 (double), whatever the mesh stores.
template <Mesh M>
vec3 vertex_position(const M& m, index_t v) {
  return to_vec3(mesh_traits<M>::position(m, v));
}

namespace detail {
/// True when all three corners of face f name a vertex in [0, nv): the guard of the whole-mesh
/// helpers (topology, normals), which skip such faces instead of indexing out of bounds.
template <Mesh M>
bool face_in_range(const M& m, index_t f, index_t nv) {
  for (int k = 0; k < 3; ++k) {
    const index_t v = tessera::face_vertex(m, f, k);
    if (v < 0 || v >= nv) return false;
  }
  return true;
}
}  // namespace detail
/// True when the mesh carries per-corner uvs (always false for a Mesh that is not a UVMesh).
template <Mesh M>
bool has_uvs(const M& m) {
  if constexpr (UVMesh<M>)
    return mesh_traits<M>::has_uvs(m);
  else
    return false;
}
/// Texture coordinate of corner k of face f. Precondition: has_uvs(m).
template <UVMesh M>
vec2 corner_uv(const M& m, index_t f, int k) {
  return to_vec2(mesh_traits<M>::corner_uv(m, f, k));
}

TESSERA_NAMESPACE_END
