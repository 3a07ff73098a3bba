// tessera/core/explain.hpp: readable compile errors for types that do not model tessera's concepts.
// Call `tessera::explain_image<MyTexture>();` (or explain_writable_image, explain_mesh,
// explain_uv_mesh, explain_tile_coloring, explain_executor) anywhere; if the type does not fit, the
// first unmet requirement is reported as one static_assert sentence that says what to add. When the
// type fits, the call compiles to nothing.
//
// The diagnosis itself (`detail::image_problem_of<T>()` and friends) is a constexpr value, so the
// negative cases are testable without triggering the static_asserts.
#pragma once

#include <concepts>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "executor.hpp"
#include "image.hpp"
#include "mesh.hpp"
#include "tile_coloring.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
template <class>
inline constexpr bool dependent_false = false;

template <class I>
concept traits_has_width = requires(const I& i) {
  image_traits<I>::width(i);
};
template <class I>
concept traits_has_height = requires(const I& i) {
  image_traits<I>::height(i);
};
template <class I>
concept traits_has_read = requires(const I& i) {
  image_traits<I>::read(i, index_t{0}, index_t{0});
};
template <class P>
concept has_pixel_traits = requires {
  typename pixel_traits<P>::channel_type;
};

/// The first requirement of Image / WritableImage a type misses, in the order explain_image checks.
enum class image_problem {
  none,
  no_size,                  ///< no width()/height()
  no_read,                  ///< no read(x, y)
  unknown_pixel,            ///< read() returns a type pixel_traits does not know
  bad_channel_type,         ///< channel type is not uint8_t, uint16_t or float
  bad_channel_count,        ///< not 1 to 4 channels
  incomplete_pixel_traits,  ///< pixel_traits lacks get/set, or the pixel is not default-constructible
  not_writable              ///< (writable images only) no write(x, y, pixel)
};

// Member-level checks: image_traits' primary template offers nothing unless all members fit, so a
// member-style type missing only read() must be told about read(), not about width().
template <class I>
concept member_size_ok = requires(const I& i) {
  { i.width() } -> std::convertible_to<index_t>;
  { i.height() } -> std::convertible_to<index_t>;
};
template <class I>
concept member_has_read = requires(const I& i) {
  i.read(index_t{0}, index_t{0});
};

template <class T>
constexpr image_problem image_problem_of() {
  if constexpr (!(traits_has_width<T> && traits_has_height<T> && traits_has_read<T>)) {
    if constexpr (traits_has_width<T> && traits_has_height<T>)
      return image_problem::no_read;  // partial traits
    else if constexpr (!member_size_ok<T>)
      return image_problem::no_size;
    else if constexpr (!member_has_read<T>)
      return image_problem::no_read;
    else
      return image_problem::no_size;  // unreachable: the members would make image_traits complete
  } else if constexpr (!has_pixel_traits<pixel_t<T>>)
    return image_problem::unknown_pixel;
  else if constexpr (!Channel<typename pixel_traits<pixel_t<T>>::channel_type>)
    return image_problem::bad_channel_type;
  else if constexpr (pixel_traits<pixel_t<T>>::channels < 1 || pixel_traits<pixel_t<T>>::channels > max_channels)
    return image_problem::bad_channel_count;
  else if constexpr (!Image<T>)
    return image_problem::incomplete_pixel_traits;
  else
    return image_problem::none;
}

template <class T>
constexpr image_problem writable_image_problem_of() {
  if constexpr (image_problem_of<T>() != image_problem::none)
    return image_problem_of<T>();
  else if constexpr (!WritableImage<T>)
    return image_problem::not_writable;
  else
    return image_problem::none;
}

template <class M>
concept traits_has_counts = requires(const M& m) {
  mesh_traits<M>::num_vertices(m);
  mesh_traits<M>::num_faces(m);
};
template <class M>
concept traits_has_face_vertex = requires(const M& m) {
  mesh_traits<M>::face_vertex(m, index_t{0}, 0);
};
template <class M>
concept traits_has_position = requires(const M& m) {
  mesh_traits<M>::position(m, index_t{0});
};
template <class M>
concept traits_has_uvs = requires(const M& m) {
  mesh_traits<M>::has_uvs(m);
  mesh_traits<M>::corner_uv(m, index_t{0}, 0);
};

/// The first requirement of Mesh / UVMesh a type misses.
enum class mesh_problem {
  none,
  no_counts,       ///< no num_vertices()/num_faces()
  no_face_vertex,  ///< no face_vertex(f, k)
  no_position,     ///< no position(v)
  bad_point,       ///< position(v) returns a type point_traits cannot read
  incomplete,      ///< the members exist but return unusable types (e.g. a count not convertible to index_t)
  no_uvs,          ///< (UV meshes only) no has_uvs()/corner_uv(f, k)
  bad_uv_point     ///< (UV meshes only) corner_uv returns a type point_traits cannot read
};

template <class M>
concept member_has_counts = requires(const M& m) {
  m.num_vertices();
  m.num_faces();
};
template <class M>
concept member_has_face_vertex = requires(const M& m) {
  m.face_vertex(index_t{0}, 0);
};
template <class M>
concept member_has_position = requires(const M& m) {
  m.position(index_t{0});
};

template <class T>
constexpr mesh_problem mesh_problem_of() {
  if constexpr (!traits_has_counts<T>) {
    // mesh_traits' primary template offers nothing unless every member fits: look at the members
    if constexpr (!member_has_counts<T>)
      return mesh_problem::no_counts;
    else if constexpr (!member_has_face_vertex<T>)
      return mesh_problem::no_face_vertex;
    else if constexpr (!member_has_position<T>)
      return mesh_problem::no_position;
    else
      return mesh_problem::incomplete;  // all present, but counts or indices are not integers
  } else if constexpr (!traits_has_face_vertex<T>)
    return mesh_problem::no_face_vertex;
  else if constexpr (!traits_has_position<T>)
    return mesh_problem::no_position;
  else if constexpr (!Point<decltype(mesh_traits<T>::position(std::declval<const T&>(), index_t{0}))>)
    return mesh_problem::bad_point;
  else if constexpr (!Mesh<T>)
    return mesh_problem::incomplete;
  else
    return mesh_problem::none;
}

template <class T>
constexpr mesh_problem uv_mesh_problem_of() {
  if constexpr (mesh_problem_of<T>() != mesh_problem::none)
    return mesh_problem_of<T>();
  else if constexpr (!traits_has_uvs<T>)
    return mesh_problem::no_uvs;
  else if constexpr (!UVMesh<T>)
    return mesh_problem::bad_uv_point;
  else
    return mesh_problem::none;
}
}  // namespace detail

/// Reports the first reason T is not a tessera::Image. Beyond these compile-time requirements, a type
/// may add the optional run-time hook `image_traits<T>::validate(img, what)` (or a member
/// `validate(what)` returning a status) for inconsistencies only it can see (null storage, a size
/// larger than its storage); validate_image() runs it at every entry point (see core/image.hpp).
template <class T>
constexpr void explain_image() {
  using detail::image_problem;
  constexpr image_problem p = detail::image_problem_of<T>();
  static_assert(p != image_problem::no_size,
                "tessera::Image: the type has no width()/height() returning integers. Add members "
                "`index_t width() const` and "
                "`index_t height() const`, or specialize tessera::image_traits<T> with static width(const T&) "
                "and height(const T&) (see docs/adapting.md).");
  static_assert(p != image_problem::no_read,
                "tessera::Image: the type has no read(x, y) callable with index_t coordinates. Add a member "
                "`Pixel read(index_t x, index_t y) const` "
                "returning the pixel by value, or specialize tessera::image_traits<T>::read.");
  static_assert(p != image_problem::unknown_pixel,
                "tessera::Image: read() returns a pixel type tessera does not know. Return a scalar or "
                "std::array<channel, C>, include tessera/adapters/eigen.hpp or glm.hpp for those vectors, or "
                "specialize tessera::pixel_traits<YourPixel> (channel_type, channels, get, set).");
  static_assert(p != image_problem::bad_channel_type,
                "tessera::Image: the pixel's channel type must be std::uint8_t, std::uint16_t or float.");
  static_assert(p != image_problem::bad_channel_count, "tessera::Image: pixels must have 1 to 4 channels.");
  static_assert(p != image_problem::incomplete_pixel_traits,
                "tessera::Image: pixel_traits<Pixel> is incomplete: it needs channel_type, channels, get(p, c), "
                "set(p, c, v), and the pixel must be default-constructible.");
}

/// Reports the first reason T is not a tessera::WritableImage.
template <class T>
constexpr void explain_writable_image() {
  explain_image<T>();
  static_assert(detail::writable_image_problem_of<T>() != detail::image_problem::not_writable,
                "tessera::WritableImage: the type cannot be written. Add a member `void write(index_t x, "
                "index_t y, const Pixel& p)` taking the pixel type read() returns, or specialize "
                "tessera::image_traits<T>::write.");
}

/// Reports the first reason T is not a tessera::Mesh.
template <class T>
constexpr void explain_mesh() {
  using detail::mesh_problem;
  constexpr mesh_problem p = detail::mesh_problem_of<T>();
  static_assert(p != mesh_problem::no_counts,
                "tessera::Mesh: the type has no num_vertices()/num_faces(). Add those members, or specialize "
                "tessera::mesh_traits<T> (see docs/adapting.md; OpenMesh: include tessera/adapters/openmesh.hpp).");
  static_assert(p != mesh_problem::no_face_vertex,
                "tessera::Mesh: the type has no face_vertex(f, k). Add `index_t face_vertex(index_t f, int k) "
                "const` returning corner k (0..2) of triangle f, or specialize tessera::mesh_traits<T>.");
  static_assert(p != mesh_problem::no_position,
                "tessera::Mesh: the type has no position(v). Add `position(index_t v) const` returning a 3D "
                "point, or specialize tessera::mesh_traits<T>::position.");
  static_assert(p != mesh_problem::bad_point,
                "tessera::Mesh: position(v) returns a type tessera cannot read. Return something with p[i] or "
                "members x, y, z, or specialize tessera::point_traits<YourPoint>.");
  static_assert(p != mesh_problem::incomplete,
                "tessera::Mesh: num_vertices()/num_faces() and face_vertex(f, k) must return integers "
                "convertible to tessera::index_t.");
}

/// Reports the first reason T is not a tessera::UVMesh.
template <class T>
constexpr void explain_uv_mesh() {
  explain_mesh<T>();
  constexpr detail::mesh_problem p = detail::uv_mesh_problem_of<T>();
  static_assert(p != detail::mesh_problem::no_uvs,
                "tessera::UVMesh: the type has no per-corner uvs. Add `bool has_uvs() const` and "
                "`corner_uv(index_t f, int k) const` returning a 2D point, or specialize tessera::mesh_traits<T>.");
  static_assert(p != detail::mesh_problem::bad_uv_point,
                "tessera::UVMesh: corner_uv(f, k) returns a type tessera cannot read. Return something with p[i] "
                "or members x, y, or specialize tessera::point_traits<YourPoint>.");
}

/// Reports why T is not a tessera::TileColoring.
template <class T>
constexpr void explain_tile_coloring() {
  static_assert(TileColoring<T>,
                "tessera::TileColoring: the type needs members `index_t num_faces() const`, `int num_colors(int "
                "side) const` and `int edge_color(index_t face, int side) const` (sides 0 north, 1 east, 2 south, "
                "3 west); or copy it into a tessera::stored_tile_coloring.");
}

/// Reports why T is not a tessera::Executor.
template <class T>
constexpr void explain_executor() {
  static_assert(Executor<T>,
                "tessera::Executor: the type needs a member `template <class F> void parallel_for(index_t begin, "
                "index_t end, F&& fn)` calling fn(i) once for every i in [begin, end), on any thread and in any "
                "order; callable on a non-const object.");
}

TESSERA_NAMESPACE_END
