// tessera/fabric/detail/square_regions.hpp: raw access to tessera's own image types and the square
// regions a cat map works on (the whole square image, the largest centred square, or square tiles).
// Internal: no stability promise.
#pragma once

#include <algorithm>
#include <cstring>
#include <numeric>
#include <type_traits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/image.hpp"
#include "../../core/image_buffer.hpp"
#include "../../core/image_view.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Whether I is one of tessera's own packed types (image_view or image_buffer), whose memory the
/// kernels can use directly instead of converting through a buffer.
template <class I>
struct raw_image : std::false_type {};
template <class T, int C>
struct raw_image<image_view<T, C>> : std::true_type {};
template <class T, int C>
struct raw_image<image_buffer<T, C>> : std::true_type {};

template <class I>
inline constexpr bool raw_image_v = raw_image<std::remove_cvref_t<I>>::value;

/// Read-only view of one of tessera's own image types.
template <class I>
auto const_view_of(const I& img) {
  using V = std::remove_cvref_t<I>;
  using T = std::remove_const_t<typename V::value_type>;
  return image_view<const T, V::channels>(img.data(), img.width(), img.height(), img.stride());
}

/// Writable view of one of tessera's own writable image types.
template <class I>
auto mutable_view_of(I& img) {
  using V = std::remove_cvref_t<I>;
  return image_view<typename V::value_type, V::channels>(img.data(), img.width(), img.height(), img.stride());
}

/// Whether two views share memory (their byte ranges overlap).
template <class A, class B>
bool views_overlap(const A& a, const B& b) {
  if (a.empty() || b.empty()) return false;
  const auto* a0 = reinterpret_cast<const unsigned char*>(a.data());
  const auto* b0 = reinterpret_cast<const unsigned char*>(b.data());
  const auto* a1 = reinterpret_cast<const unsigned char*>(a.row(a.height() - 1) + a.width() * A::channels);
  const auto* b1 = reinterpret_cast<const unsigned char*>(b.row(b.height() - 1) + b.width() * B::channels);
  return std::less<>{}(a0, b1) && std::less<>{}(b0, a1);
}

/// Copies src into dst (same size and format), row by row.
template <class T, int C>
void copy_view(image_view<const T, C> src, image_view<T, C> dst) {
  for (index_t y = 0; y < src.height(); ++y) std::memcpy(dst.row(y), src.row(y), sizeof(T) * to_size(src.width() * C));
}

/// A square sub-region: top-left corner and side.
struct square_region {
  index_t x = 0, y = 0, side = 0;
};

}  // namespace detail
TESSERA_NAMESPACE_END
