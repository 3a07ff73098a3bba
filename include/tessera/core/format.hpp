// tessera/core/format.hpp: runtime pixel formats and dispatch to compile-time kernels.
// Engines often know their texture format only at run time (a channel count and a component type
// read from a file or a GPU format enum). `dispatch_format` turns that pair into the (T, C) that
// tessera's kernels are instantiated for:
//
//   tessera::dispatch_format(fmt, [&]<class T, int C>(tessera::format_tag<T, C>) {
//     tessera::image_view<T, C> view(static_cast<T*>(ptr), w, h);
//     return run_my_algorithm(view);   // returns status (or nothing)
//   });
#pragma once

#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "image.hpp"
#include "status.hpp"

TESSERA_NAMESPACE_BEGIN

/// Component type of a runtime pixel format.
enum class channel_type { uint8, uint16, float32 };

/// "uint8", "uint16" or "float32".
constexpr std::string_view to_string(channel_type t) noexcept {
  switch (t) {
    case channel_type::uint8: return "uint8";
    case channel_type::uint16: return "uint16";
    case channel_type::float32: return "float32";
  }
  return "unknown";
}

/// Bytes per component.
constexpr int channel_size(channel_type t) noexcept {
  return t == channel_type::uint8 ? 1 : t == channel_type::uint16 ? 2 : 4;
}

/// The channel_type of a compile-time channel type.
template <Channel T>
inline constexpr channel_type channel_type_of = std::is_same_v<T, std::uint8_t>    ? channel_type::uint8
                                                : std::is_same_v<T, std::uint16_t> ? channel_type::uint16
                                                                                   : channel_type::float32;

/// A pixel format known at run time.
struct pixel_format {
  /// The channel type (uint8, uint16 or float).
  channel_type type = channel_type::uint8;
  /// Channels per pixel, 1 to 4.
  int channels = 4;
  friend bool operator==(const pixel_format&, const pixel_format&) = default;
};

/// Empty tag carrying a compile-time (channel type, channel count) pair.
template <class T, int C>
struct format_tag {
  /// The channel type T.
  using channel = T;
  /// The channel count C.
  static constexpr int channels = C;
};

/// Bytes per pixel of a runtime format.
constexpr int pixel_size(pixel_format fmt) noexcept { return channel_size(fmt.type) * fmt.channels; }

/// The runtime format of a compile-time pixel type.
template <Pixel P>
inline constexpr pixel_format pixel_format_of =
    pixel_format{channel_type_of<typename pixel_traits<P>::channel_type>, pixel_traits<P>::channels};

namespace detail {
template <class T, class F>
status dispatch_count(int channels, F&& f) {
  auto call = [&]<int C>() -> status {
    using R = decltype(f(format_tag<T, C>{}));
    static_assert(std::is_void_v<R> || std::is_same_v<std::remove_cvref_t<R>, status>,
                  "dispatch_format: the callback must return void or tessera::status (a result<T> or other value "
                  "would be silently dropped; capture outputs by reference instead)");
    if constexpr (std::is_void_v<R>) {
      f(format_tag<T, C>{});
      return {};
    } else {
      return f(format_tag<T, C>{});
    }
  };
  switch (channels) {
    case 1: return call.template operator()<1>();
    case 2: return call.template operator()<2>();
    case 3: return call.template operator()<3>();
    case 4: return call.template operator()<4>();
    default: return status::invalid_argument(detail::cat("pixel format: channel count must be 1 to 4, got ", channels));
  }
}
}  // namespace detail

/// Calls `f(format_tag<T, C>{})` with the compile-time pair matching `fmt`. `f` must return void or
/// status (checked at compile time); its status is returned, or an invalid_argument status for a
/// channel count outside 1..4 or an unknown channel type (f is then not called). All 12
/// instantiations of f are compiled.
template <class F>
status dispatch_format(pixel_format fmt, F&& f) {
  switch (fmt.type) {
    case channel_type::uint8: return detail::dispatch_count<std::uint8_t>(fmt.channels, f);
    case channel_type::uint16: return detail::dispatch_count<std::uint16_t>(fmt.channels, f);
    case channel_type::float32: return detail::dispatch_count<float>(fmt.channels, f);
  }
  return status::invalid_argument(detail::cat("pixel format: unknown channel type ", static_cast<int>(fmt.type)));
}

/// Calls `f(format_tag<T, C>{})` for a fixed channel type T and a runtime channel count.
template <Channel T, class F>
status dispatch_channels(int channels, F&& f) {
  return detail::dispatch_count<T>(channels, f);
}

TESSERA_NAMESPACE_END
