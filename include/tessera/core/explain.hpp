// tessera/core/explain.hpp: readable compile errors for types that do not model tessera's concepts.
// Call `tessera::explain_image<MyTexture>();` (or explain_writable_image, explain_mesh) anywhere; if
// the type does not fit, the first unmet requirement is reported as one static_assert sentence that
// says what to add. When the type fits, the call compiles to nothing.
#pragma once

#include <type_traits>

#include "config.hpp"
#include "image.hpp"
#include "mesh.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
template <class>
inline constexpr bool dependent_false = false;

template <class I>
concept traits_has_width = requires(const I& i) { image_traits<I>::width(i); };
template <class I>
concept traits_has_height = requires(const I& i) { image_traits<I>::height(i); };
template <class I>
concept traits_has_read = requires(const I& i) { image_traits<I>::read(i, index_t{0}, index_t{0}); };
template <class P>
concept has_pixel_traits = requires { typename pixel_traits<P>::channel_type; };

template <class M>
concept traits_has_counts = requires(const M& m) {
  mesh_traits<M>::num_vertices(m);
  mesh_traits<M>::num_faces(m);
};
template <class M>
concept traits_has_face_vertex = requires(const M& m) { mesh_traits<M>::face_vertex(m, index_t{0}, 0); };
template <class M>
concept traits_has_position = requires(const M& m) { mesh_traits<M>::position(m, index_t{0}); };
}  // namespace detail

/// Reports the first reason T is not a tessera::Image.
template <class T>
constexpr void explain_image() {
  if constexpr (!detail::traits_has_width<T> || !detail::traits_has_height<T>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Image: the type has no width()/height(). Add members `index_t width() const` and "
                  "`index_t height() const`, or specialize tessera::image_traits<T> with static width(const T&) "
                  "and height(const T&) (see docs/adapting.md).");
  } else if constexpr (!detail::traits_has_read<T>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Image: the type has no read(x, y). Add a member `Pixel read(index_t x, index_t y) const` "
                  "returning the pixel by value, or specialize tessera::image_traits<T>::read.");
  } else if constexpr (!detail::has_pixel_traits<pixel_t<T>>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Image: read() returns a pixel type tessera does not know. Return a scalar or "
                  "std::array<channel, C>, include tessera/adapters/eigen.hpp or glm.hpp for those vectors, or "
                  "specialize tessera::pixel_traits<YourPixel> (channel_type, channels, get, set).");
  } else if constexpr (!Channel<typename pixel_traits<pixel_t<T>>::channel_type>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Image: the pixel's channel type must be std::uint8_t, std::uint16_t or float.");
  } else if constexpr (pixel_traits<pixel_t<T>>::channels < 1 || pixel_traits<pixel_t<T>>::channels > max_channels) {
    static_assert(detail::dependent_false<T>, "tessera::Image: pixels must have 1 to 4 channels.");
  } else if constexpr (!Pixel<pixel_t<T>>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Image: pixel_traits<Pixel> is incomplete: it needs channel_type, channels, get(p, c), "
                  "set(p, c, v), and the pixel must be default-constructible.");
  }
}

/// Reports the first reason T is not a tessera::WritableImage.
template <class T>
constexpr void explain_writable_image() {
  explain_image<T>();
  if constexpr (Image<T> && !WritableImage<T>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::WritableImage: the type cannot be written. Add a member `void write(index_t x, "
                  "index_t y, const Pixel& p)` taking the pixel type read() returns, or specialize "
                  "tessera::image_traits<T>::write.");
  }
}

/// Reports the first reason T is not a tessera::Mesh.
template <class T>
constexpr void explain_mesh() {
  if constexpr (!detail::traits_has_counts<T>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Mesh: the type has no num_vertices()/num_faces(). Add those members, or specialize "
                  "tessera::mesh_traits<T> (see docs/adapting.md; OpenMesh: include tessera/adapters/openmesh.hpp).");
  } else if constexpr (!detail::traits_has_face_vertex<T>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Mesh: the type has no face_vertex(f, k). Add `index_t face_vertex(index_t f, int k) "
                  "const` returning corner k (0..2) of triangle f, or specialize tessera::mesh_traits<T>.");
  } else if constexpr (!detail::traits_has_position<T>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Mesh: the type has no position(v). Add `position(index_t v) const` returning a 3D "
                  "point, or specialize tessera::mesh_traits<T>::position.");
  } else if constexpr (!Point<decltype(mesh_traits<T>::position(std::declval<const T&>(), index_t{0}))>) {
    static_assert(detail::dependent_false<T>,
                  "tessera::Mesh: position(v) returns a type tessera cannot read. Return something with p[i] or "
                  "members x, y, z, or specialize tessera::point_traits<YourPoint>.");
  }
}

TESSERA_NAMESPACE_END
