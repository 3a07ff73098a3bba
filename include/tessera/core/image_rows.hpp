// tessera/core/image_rows.hpp: the contiguous-memory fast path of adapted images. An image reached
// through image_traits is written pixel by pixel (one call per pixel, a pixel conversion each): the
// generic path every WritableImage supports. When the type's pixels live in ordinary rows of memory
// (an engine texture of packed RGBA8, a staging buffer), its image_traits specialization can say so
// by adding
//
//   static tessera::image_view<std::uint8_t, 4> view(MyTexture& t);   // rows over t's own memory
//
// and the hot loops (compose_tiles, synthesize, synthesize_aligned, copy_image) then write whole
// rows through that view, as fast as into an image_view. The view must show exactly the pixels that
// read() and write() show: pixel (x, y) of the view holds the channels pixel_traits gives for
// read(x, y), in the same order (for RGBA8 packed in a uint32 on a little-endian machine, R in the
// low byte). docs/adapting.md shows the specialization.
#pragma once

#include <string_view>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "image.hpp"
#include "image_view.hpp"
#include "status.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
template <class V>
inline constexpr bool is_writable_image_view_v = false;
template <class T, int C>
inline constexpr bool is_writable_image_view_v<image_view<T, C>> = !std::is_const_v<T>;
}  // namespace detail

/// A WritableImage whose image_traits also has `static image_view<T, C> view(I&)` (T not const):
/// its pixels are rows of memory that tessera may write directly (see the file comment).
template <class I>
concept ContiguousImage = WritableImage<I> && requires(I& img) {
  image_traits<I>::view(img);
} && detail::is_writable_image_view_v<std::remove_cvref_t<decltype(image_traits<I>::view(std::declval<I&>()))>>;

/// The image_view a ContiguousImage exposes over its own memory.
template <ContiguousImage I>
auto contiguous_view(I& img) {
  return image_traits<I>::view(img);
}

namespace detail {
/// The view of a ContiguousImage, refused when its size differs from the image's own (a
/// specialization that views the wrong memory would otherwise be written past).
template <ContiguousImage I>
auto checked_contiguous_view(I& img, std::string_view what) -> result<decltype(image_traits<I>::view(img))> {
  auto v = image_traits<I>::view(img);
  if (v.width() != width_of(img) || v.height() != height_of(img))
    return status::invalid_argument(cat(what, ": image_traits::view gives a ", v.width(), " x ", v.height(),
                                        " view of a ", width_of(img), " x ", height_of(img), " image"));
  if (auto s = v.validate(what); !s) return s;
  return v;
}
}  // namespace detail

TESSERA_NAMESPACE_END
