// tessera/core/image.hpp: how tessera sees an image. `pixel_traits` describes a pixel type,
// `image_traits` reaches a user's image type (primary template: forward to members), and the concepts
// `Image` / `WritableImage` say what an algorithm needs. Pixels travel by value (`read` / `write`),
// never by reference, so packed, 16-bit, float and staging-buffer formats all fit.
//
// Adapting a type: give it members `width()`, `height()`, `read(x, y)` (and `write(x, y, p)` to be
// writable), or specialize `tessera::image_traits<YourType>` with the same four static functions.
// `explain_image<T>()` (core/explain.hpp) says in words what is missing.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>
#include <utility>

#include "config.hpp"

TESSERA_NAMESPACE_BEGIN

// ---------------------------------------------------------------------------------------------
// Channels

/// Channel types tessera's kernels are instantiated for.
template <class T>
concept Channel = std::same_as<T, std::uint8_t> || std::same_as<T, std::uint16_t> || std::same_as<T, float>;

/// Largest channel count tessera handles (RGBA).
inline constexpr int max_channels = 4;

/// Converts a channel value to a float in [0, 1] for integer types (0..255 or 0..65535 map to 0..1);
/// float channels pass through unchanged.
template <Channel T>
constexpr float channel_to_unit(T v) noexcept {
  if constexpr (std::is_floating_point_v<T>) {
    return v;
  } else {
    return static_cast<float>(v) * (1.0f / static_cast<float>(std::numeric_limits<T>::max()));
  }
}

/// Inverse of channel_to_unit: rounds to nearest and clamps for integer types; NaN becomes 0.
template <Channel T>
constexpr T unit_to_channel(float u) noexcept {
  if constexpr (std::is_floating_point_v<T>) {
    return u;
  } else {
    constexpr float max = static_cast<float>(std::numeric_limits<T>::max());
    if (!(u > 0.0f)) return T{0};  // also catches NaN
    if (u >= 1.0f) return std::numeric_limits<T>::max();
    return static_cast<T>(u * max + 0.5f);
  }
}

/// Converts between channel types through the unit range (uint8 200 -> uint16 51400 -> float 0.784).
/// Between the integer types the conversion is exact integer arithmetic: uint8 v -> uint16 v * 257,
/// uint16 v -> uint8 round(v / 257), so uint8 -> uint16 -> uint8 is the identity.
template <Channel To, Channel From>
constexpr To convert_channel(From v) noexcept {
  if constexpr (std::same_as<To, From>) {
    return v;
  } else if constexpr (std::same_as<From, std::uint8_t> && std::same_as<To, std::uint16_t>) {
    return static_cast<std::uint16_t>(v * 257u);
  } else if constexpr (std::same_as<From, std::uint16_t> && std::same_as<To, std::uint8_t>) {
    return static_cast<std::uint8_t>((static_cast<std::uint32_t>(v) * 255u + 32767u) / 65535u);
  } else {
    return unit_to_channel<To>(channel_to_unit(v));
  }
}

// ---------------------------------------------------------------------------------------------
// Pixels

/// Describes a pixel type: `channel_type`, `channels`, `get(p, c)`, `set(p, c, v)`.
/// Specialized here for arithmetic scalars and std::array<T, C>; adapters/eigen.hpp and
/// adapters/glm.hpp add Eigen::Matrix<T, C, 1> and glm::vec<C, T>. Specialize it for packed formats.
template <class P>
struct pixel_traits;

/// A scalar is a one-channel pixel.
template <class T>
requires std::is_arithmetic_v<T>
struct pixel_traits<T> {
  using channel_type = T;
  static constexpr int channels = 1;
  static constexpr T get(const T& p, int) noexcept { return p; }
  static constexpr void set(T& p, int, T v) noexcept { p = v; }
};

/// std::array<T, C> is a C-channel pixel.
template <class T, std::size_t C>
struct pixel_traits<std::array<T, C>> {
  /// The channel type T.
  using channel_type = T;
  /// The channel count C.
  static constexpr int channels = static_cast<int>(C);
  /// Channel c of p.
  static constexpr T get(const std::array<T, C>& p, int c) noexcept { return p[detail::to_size(c)]; }
  /// Sets channel c of p to v.
  static constexpr void set(std::array<T, C>& p, int c, T v) noexcept { p[detail::to_size(c)] = v; }
};

/// A pixel type tessera can read: known to pixel_traits, 1 to 4 channels of uint8, uint16 or float.
template <class P>
concept Pixel = requires(const P& p, P& q, typename pixel_traits<P>::channel_type v) {
  typename pixel_traits<P>::channel_type;
  { pixel_traits<P>::channels } -> std::convertible_to<int>;
  { pixel_traits<P>::get(p, 0) } -> std::convertible_to<typename pixel_traits<P>::channel_type>;
  pixel_traits<P>::set(q, 0, v);
}
&&Channel<typename pixel_traits<P>::channel_type> && (pixel_traits<P>::channels >= 1) &&
    (pixel_traits<P>::channels <= max_channels) && std::default_initializable<P>;

/// tessera's own pixel: C channels of T.
template <Channel T, int C>
using pixel = std::array<T, static_cast<std::size_t>(C)>;

namespace detail {
struct unit_rgba {
  float r, g, b, a;
};
template <Pixel P>
constexpr unit_rgba to_unit_rgba(const P& p) noexcept {
  using T = pixel_traits<P>;
  auto u = [&](int c) { return channel_to_unit(T::get(p, c)); };
  if constexpr (T::channels == 1)
    return {u(0), u(0), u(0), 1.0f};
  else if constexpr (T::channels == 2)
    return {u(0), u(0), u(0), u(1)};
  else if constexpr (T::channels == 3)
    return {u(0), u(1), u(2), 1.0f};
  else
    return {u(0), u(1), u(2), u(3)};
}
template <Pixel P>
constexpr P from_unit_rgba(const unit_rgba& q) noexcept {
  using T = pixel_traits<P>;
  using C = typename T::channel_type;
  P out{};
  auto set = [&](int c, float v) { T::set(out, c, unit_to_channel<C>(v)); };
  const float luma = 0.299f * q.r + 0.587f * q.g + 0.114f * q.b;  // Rec. 601
  if constexpr (T::channels <= 2) set(0, luma);
  if constexpr (T::channels == 2) set(1, q.a);
  if constexpr (T::channels >= 3) {
    set(0, q.r);
    set(1, q.g);
    set(2, q.b);
  }
  if constexpr (T::channels == 4) set(3, q.a);
  return out;
}
}  // namespace detail

/// Converts any Pixel to any other. With equal channel counts each channel converts through the unit
/// range (uint8 200 -> uint16 51400 -> float 0.784). Otherwise grey expands to RGB, colour reduces to
/// Rec. 601 luma, a missing alpha becomes opaque and a dropped alpha is discarded.
template <Pixel To, Pixel From>
constexpr To convert_pixel(const From& p) noexcept {
  using FT = pixel_traits<From>;
  using TT = pixel_traits<To>;
  if constexpr (FT::channels == TT::channels) {
    To out{};
    for (int c = 0; c < TT::channels; ++c) TT::set(out, c, convert_channel<typename TT::channel_type>(FT::get(p, c)));
    return out;
  } else {
    return detail::from_unit_rgba<To>(detail::to_unit_rgba(p));
  }
}

// ---------------------------------------------------------------------------------------------
// Images

namespace detail {
template <class I>
concept member_image = requires(const I& i, index_t x, index_t y) {
  { i.width() } -> std::convertible_to<index_t>;
  { i.height() } -> std::convertible_to<index_t>;
  i.read(x, y);
};
template <class I>
concept member_validating_image = requires(const I& i, const char* what) {
  i.validate(std::string_view(what));
};
template <class I>
concept member_writable_image = member_image<I> &&
    requires(I& i, index_t x, index_t y, const std::remove_cvref_t<decltype(std::declval<const I&>().read(0, 0))>& p) {
  i.write(x, y, p);
};
}  // namespace detail

/// Reaches an image type. The primary template forwards to members; specialize it for foreign types
/// (an engine texture class) with static width, height, read and, for outputs, write.
/// Optionally, like mesh_traits, a specialization (or a member `validate(what)`) may add
/// `static status validate(const I&, std::string_view what)` for checks only the type can make (null
/// storage, a size that claims more pixels than the storage holds); validate_image()
/// (core/image_checks.hpp), which every entry point runs on its images, calls it before its own checks.
template <class I>
struct image_traits {
  /// Forwards to the image's own validate(what) hook when it has one.
  static decltype(auto) validate(const I& i, std::string_view what) requires detail::member_validating_image<I> {
    return i.validate(what);
  }
  /// Width in pixels, from the image's width().
  static index_t width(const I& i) requires detail::member_image<I> { return static_cast<index_t>(i.width()); }
  /// Height in pixels, from the image's height().
  static index_t height(const I& i) requires detail::member_image<I> { return static_cast<index_t>(i.height()); }
  /// Pixel (x, y), from the image's read(x, y).
  static decltype(auto) read(const I& i, index_t x, index_t y) requires detail::member_image<I> { return i.read(x, y); }
  /// Writes pixel (x, y) through the image's write(x, y, p).
  template <class P>
  static void write(I& i, index_t x, index_t y, const P& p) requires detail::member_writable_image<I> {
    i.write(x, y, p);
  }
};

/// The pixel type an image reads (cv-ref removed).
template <class I>
using pixel_t = std::remove_cvref_t<decltype(image_traits<I>::read(std::declval<const I&>(), index_t{0}, index_t{0}))>;

/// An image tessera can read: width, height and pixels by value through image_traits.
template <class I>
concept Image = requires(const I& img, index_t x, index_t y) {
  { image_traits<I>::width(img) } -> std::convertible_to<index_t>;
  { image_traits<I>::height(img) } -> std::convertible_to<index_t>;
  image_traits<I>::read(img, x, y);
}
&&Pixel<pixel_t<I>>;

/// An image tessera can also write pixels of its own pixel type into.
template <class I>
concept WritableImage = Image<I> && requires(I& img, index_t x, index_t y, const pixel_t<I>& p) {
  image_traits<I>::write(img, x, y, p);
};

/// Channel type and count of an image's pixels.
template <Image I>
using channel_t = typename pixel_traits<pixel_t<I>>::channel_type;
/// Channel count (1 to 4) of an image's pixels.
template <Image I>
inline constexpr int channels_v = pixel_traits<pixel_t<I>>::channels;

/// Width and height of any Image.
template <Image I>
index_t width_of(const I& img) {
  return static_cast<index_t>(image_traits<I>::width(img));
}
/// Height of any Image.
template <Image I>
index_t height_of(const I& img) {
  return static_cast<index_t>(image_traits<I>::height(img));
}

TESSERA_NAMESPACE_END
