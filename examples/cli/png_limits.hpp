// PNG decoding limits of the `tessera` command: the library's defaults (png_read_options: 2^28
// pixels, 1 GiB decoded), raised by the environment variable TESSERA_MAX_PIXELS; and the pixel
// formats a PNG holds (8 or 16 bits, 1 to 4 channels), the only ones the commands dispatch over.
#pragma once

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <tessera/core/format.hpp>
#include <tessera/io/png.hpp>

namespace cli {

/// The PNG decoding limits: the library's defaults, or TESSERA_MAX_PIXELS=N from the environment, which allows N pixels in any format (N pixels and
/// 16 N bytes: float RGBA). invalid_argument for a malformed value.
inline tessera::result<tessera::png_read_options> png_limits() {
  tessera::png_read_options o;
  const char* env = std::getenv("TESSERA_MAX_PIXELS");
  if (env == nullptr) return o;
  const std::string s = env;
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(s.c_str(), &end, 10);
  if (s.empty() || s[0] == '-' || *end != '\0' || errno == ERANGE || n < 1 || n > (1ULL << 40))
    return tessera::status::invalid_argument("TESSERA_MAX_PIXELS expects an integer in [1, 2^40], got '" + s + "'");
  o.max_pixels = n;
  o.max_bytes = std::max<std::uint64_t>(o.max_bytes, 16 * n);
  return o;
}

/// The pixel format of a PNG: 8 or 16 bits, 1 to 4 channels.
inline tessera::pixel_format png_format(const tessera::png_info& info) {
  return {info.bit_depth == 16 ? tessera::channel_type::uint16 : tessera::channel_type::uint8, info.channels};
}

/// Calls `f(format_tag<T, C>{})` for a format a PNG can hold: T is std::uint8_t or std::uint16_t.
/// Unlike tessera::dispatch_format it never instantiates `f` for float pixels, which no PNG holds
/// (8 instantiations instead of 12: a third less code for each command's kernels to compile).
/// unsupported for float32, invalid_argument for a channel count outside 1..4.
template <class F>
tessera::status dispatch_png_format(tessera::pixel_format fmt, F&& f) {
  if (fmt.type == tessera::channel_type::uint8) return tessera::dispatch_channels<std::uint8_t>(fmt.channels, f);
  if (fmt.type == tessera::channel_type::uint16) return tessera::dispatch_channels<std::uint16_t>(fmt.channels, f);
  return tessera::status::unsupported("PNG images hold 8 or 16 bits per channel, not " +
                                      std::string(tessera::to_string(fmt.type)));
}

/// read_png with the command's limits (png_limits); a size_overflow says how to raise them.
template <tessera::Channel T, int C>
tessera::result<tessera::image_buffer<T, C>> read_png_file(const std::string& path) {
  auto limits = png_limits();
  if (!limits) return limits.error();
  auto img = tessera::read_png<T, C>(path, *limits);
  if (!img && img.error().code() == tessera::status_code::size_overflow)
    return tessera::status::size_overflow(img.error().message() +
                                          " (set the environment variable TESSERA_MAX_PIXELS to allow more)");
  return img;
}

}  // namespace cli
