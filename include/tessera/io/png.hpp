// tessera/io/png.hpp: PNG files (link tessera::io; Debian libstb-dev).
//   read_png_info(path)            size, channels and bit depth without decoding pixels
//   read_png<T, C>(path, limits)   decode into an image_buffer<T, C> (channels and depth converted)
//   write_png(path, image)         encode any Image (uint8 -> 8-bit PNG; uint16 and float -> 16-bit)
//   decode_png<T, C>(bytes, name)  / encode_png(image): the same on memory, for engines with their
//                                  own file systems or packed archives
// Every file is checked chunk by chunk (lengths, CRCs, IHDR fields, declared size against the
// compressed data) before stb inflates and unfilters it, so a truncated or corrupt file is a
// parse_error naming the file and the byte offset, never a crash or an absurd allocation. Grey,
// grey + alpha, RGB, RGBA and palette images at every bit depth are read; channel and depth
// conversion follow convert_pixel / convert_channel (16 -> 8 bits rounds to nearest). A valid file
// of a few hundred kilobytes can inflate to gigabytes, so decoding also stops at an absolute size
// (png_read_options: 2^28 pixels and 1 GiB decoded by default; raise them for larger images).
// Thread-safe.
// (If the host itself calls stb's stbi_set_flip_vertically_on_load(1), decoded images come out
// flipped; tessera never calls it.)
#pragma once

#include <stb_image.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "../core/config.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/status.hpp"
#include "detail/file.hpp"
#include "detail/png_chunks.hpp"

// stb builds its zlib compressor into libstb but declares it only in its implementation section.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len, int quality);

TESSERA_NAMESPACE_BEGIN

/// What a PNG file holds.
struct png_info {
  /// Width in pixels.
  index_t width = 0;
  /// Height in pixels.
  index_t height = 0;
  int channels = 0;        ///< after decoding: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA (palettes expand)
  int bit_depth = 8;       ///< precision after decoding: 8 or 16
  int file_bit_depth = 8;  ///< as stored: 1, 2, 4, 8 or 16
  bool palette = false;    ///< stored as palette indices
  /// Stored interlaced (Adam7).
  bool interlaced = false;
};

/// Reads the header of an in-memory PNG after checking its whole chunk structure. `name` names the
/// data in messages. parse_error for anything that is not a well-formed PNG. O(size).
inline result<png_info> decode_png_info(const unsigned char* data, std::size_t size, std::string_view name = "png") {
  auto l = detail::check_png(data, size, name);
  if (!l) return l.error();
  return png_info{static_cast<index_t>(l->width),
                  static_cast<index_t>(l->height),
                  l->channels(),
                  l->bit_depth == 16 ? 16 : 8,
                  l->bit_depth,
                  l->color_type == 3,
                  l->interlaced};
}

/// Reads the header of a PNG file (the whole file is read and its structure checked).
/// io_error when the file cannot be read; parse_error naming the file and byte otherwise.
inline result<png_info> read_png_info(const std::string& path) {
  auto bytes = detail::read_file(path);
  if (!bytes) return bytes.error();
  return decode_png_info(reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size(), path);
}

/// Limits on what decode_png / read_png inflate. The chunk walk already refuses a header declaring
/// more pixels than the compressed data can hold, but deflate legitimately expands ~1000:1: a valid
/// 1 MB PNG can declare 32000 x 32000 pixels. These bound the absolute size; raise them to read
/// larger images (the `tessera` command: environment variable TESSERA_MAX_PIXELS).
struct png_read_options {
  std::uint64_t max_pixels = std::uint64_t{1} << 28;  ///< width x height at most (default 268 M pixels)
  std::uint64_t max_bytes = std::uint64_t{1} << 30;   ///< bytes of the decoded image at most (default 1 GiB),
                                                      ///< counting the decoder's buffer and the output image
};

namespace detail {
/// Removes zero-length IDAT chunks (valid PNG, but stb then copies from a null pointer). The data
/// has passed check_png, so every chunk lies inside it. Returns an empty vector when there is none.
inline std::vector<unsigned char> without_empty_idat(const unsigned char* data, std::size_t size) {
  std::vector<unsigned char> out;
  bool any = false;
  for (std::size_t pos = 8; size - pos >= 12;) {
    const std::size_t len = get_be32(data + pos);
    if (size - pos - 12 < len) break;  // not reached after check_png; kept for safety
    const bool iend = std::memcmp(data + pos + 4, "IEND", 4) == 0;
    if (len == 0 && std::memcmp(data + pos + 4, "IDAT", 4) == 0) {
      if (!any) out.assign(data, data + pos);
      any = true;
    } else if (any) {
      out.insert(out.end(), data + pos, data + pos + 12 + len);
    }
    pos += 12 + len;
    if (iend) break;
  }
  if (!any) out.clear();
  return out;
}

struct stbi_deleter {
  void operator()(void* p) const noexcept { stbi_image_free(p); }
};
template <Channel T, int C, class S, int FC>
void convert_decoded(const S* src, image_buffer<T, C>& out) {
  const index_t n = out.width() * out.height();
  T* dst = out.data();
  for (index_t i = 0; i < n; ++i) {
    pixel<S, FC> p;
    for (int c = 0; c < FC; ++c) p[to_size(c)] = src[i * FC + c];
    const auto q = convert_pixel<pixel<T, C>>(p);
    for (int c = 0; c < C; ++c) dst[i * C + c] = q[to_size(c)];
  }
}
}  // namespace detail

/// Decodes an in-memory PNG into C channels of T: the file's channels convert like convert_pixel
/// (grey expands, colour reduces to Rec. 601 luma, alpha added opaque or dropped) and its samples
/// like convert_channel (16-bit files keep their precision in uint16_t and float). Errors:
/// parse_error (structure, CRC, truncation, corrupt compressed data; message names `name` and the
/// byte), size_overflow for an image beyond `limits` (message names the size and the limit),
/// unsupported for one too large for the decoder (2 GB). O(pixels).
template <Channel T, int C>
result<image_buffer<T, C>> decode_png(const unsigned char* data, std::size_t size, std::string_view name = "png",
                                      const png_read_options& limits = {}) {
  auto info = decode_png_info(data, size, name);
  if (!info) return info.error();
  const int fc = info->channels;
  const bool wide = info->bit_depth == 16;
  const std::uint64_t pixels = static_cast<std::uint64_t>(info->width) * static_cast<std::uint64_t>(info->height);
  const std::uint64_t per_pixel =
      std::max<std::uint64_t>(std::uint64_t(fc) * (wide ? 2u : 1u), std::uint64_t(C) * sizeof(T));
  // pixels < 2^62: compared by division, so that a raised limit cannot make the product wrap
  if (pixels > limits.max_pixels || pixels > limits.max_bytes / per_pixel) {
    const std::uint64_t bytes = pixels <= UINT64_MAX / per_pixel ? pixels * per_pixel : UINT64_MAX;
    return status::size_overflow(detail::cat(name, ": ", info->width, " x ", info->height, " = ", pixels, " pixels (",
                                             bytes, " bytes decoded) exceeds the decoding limit of ", limits.max_pixels,
                                             " pixels and ", limits.max_bytes,
                                             " bytes; raise png_read_options to read it"));
  }
  if (auto s = validate_image_extent(info->width, info->height, C, name); !s) return s;
  if (size > INT_MAX ||
      static_cast<double>(info->width) * static_cast<double>(info->height) * fc * (wide ? 2 : 1) > INT_MAX)
    return status::unsupported(
        detail::cat(name, ": ", info->width, " x ", info->height, " is too large for the PNG decoder (2 GB limit)"));
  const std::vector<unsigned char> cleaned = detail::without_empty_idat(data, size);
  if (!cleaned.empty()) {
    data = cleaned.data();
    size = cleaned.size();
  }
  int w = 0, h = 0, got = 0;
  const int len = static_cast<int>(size);
  std::unique_ptr<void, detail::stbi_deleter> raw(
      wide ? static_cast<void*>(stbi_load_16_from_memory(data, len, &w, &h, &got, 0))
           : static_cast<void*>(stbi_load_from_memory(data, len, &w, &h, &got, 0)));
  if (!raw) return status::parse_error(detail::cat(name, ": corrupt image data (", stbi_failure_reason(), ")"));
  if (w != info->width || h != info->height || got != fc)
    return status::internal_error(detail::cat(name, ": the decoder disagrees with the header"));
  auto out = image_buffer<T, C>::create(w, h);
  if (!out) return out.error();
  auto run = [&]<class S, int FC>() { detail::convert_decoded<T, C, S, FC>(static_cast<const S*>(raw.get()), *out); };
  auto by_channels = [&]<class S>() {
    switch (fc) {
      case 1: run.template operator()<S, 1>(); break;
      case 2: run.template operator()<S, 2>(); break;
      case 3: run.template operator()<S, 3>(); break;
      default: run.template operator()<S, 4>(); break;
    }
  };
  if (wide)
    by_channels.template operator()<std::uint16_t>();
  else
    by_channels.template operator()<std::uint8_t>();
  return out;
}

/// Reads a PNG file into C channels of T (see decode_png; `limits` bounds the decoded size).
/// io_error when the file cannot be read.
template <Channel T, int C>
result<image_buffer<T, C>> read_png(const std::string& path, const png_read_options& limits = {}) {
  auto bytes = detail::read_file(path);
  if (!bytes) return bytes.error();
  return decode_png<T, C>(reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size(), path, limits);
}

/// Encodes any Image as PNG bytes: uint8 channels as an 8-bit PNG, uint16 and float as 16-bit
/// (floats clamped to [0, 1], NaN to 0), keeping the channel count (1 grey, 2 grey + alpha, 3 RGB,
/// 4 RGBA). Rows use the adaptive filter heuristic, zlib level 8. Errors: invalid_argument for an
/// empty image, size_overflow for one too large for PNG. O(pixels).
template <Image I>
result<std::vector<unsigned char>> encode_png(const I& img, std::string_view name = "png") {
  if (auto s = validate_image(img, name); !s) return s;
  constexpr int C = channels_v<I>;
  constexpr bool eight = std::is_same_v<channel_t<I>, std::uint8_t>;
  constexpr std::size_t bytes_per_sample = eight ? 1 : 2;
  const index_t w = width_of(img), h = height_of(img);
  const std::size_t row_bytes = detail::to_size(w) * C * bytes_per_sample;
  if (w > 0x7fffffff || h > 0x7fffffff || static_cast<double>(row_bytes + 1) * static_cast<double>(h) > INT_MAX)
    return status::size_overflow(detail::cat(name, ": ", w, " x ", h, " is too large for one PNG stream (2 GB)"));
  std::vector<unsigned char> raw(row_bytes * detail::to_size(h));
  for (index_t y = 0; y < h; ++y) {
    unsigned char* r = raw.data() + detail::to_size(y) * row_bytes;
    for (index_t x = 0; x < w; ++x) {
      if constexpr (eight) {
        const auto p = convert_pixel<pixel<std::uint8_t, C>>(image_traits<I>::read(img, x, y));
        for (int c = 0; c < C; ++c) r[x * C + c] = p[detail::to_size(c)];
      } else {
        const auto p = convert_pixel<pixel<std::uint16_t, C>>(image_traits<I>::read(img, x, y));
        for (int c = 0; c < C; ++c) {
          r[2 * (x * C + c)] = static_cast<unsigned char>(p[detail::to_size(c)] >> 8);
          r[2 * (x * C + c) + 1] = static_cast<unsigned char>(p[detail::to_size(c)] & 0xff);
        }
      }
    }
  }
  const auto filtered = detail::png_filter_rows(raw.data(), row_bytes, detail::to_size(h), C * bytes_per_sample);
  int zlen = 0;
  std::unique_ptr<unsigned char, decltype(&std::free)> z(
      stbi_zlib_compress(const_cast<unsigned char*>(filtered.data()), static_cast<int>(filtered.size()), &zlen, 8),
      &std::free);
  if (!z) return status::internal_error(detail::cat(name, ": PNG compression failed (out of memory?)"));
  static constexpr unsigned char color_type[5] = {0, 0, 4, 2, 6};
  std::vector<unsigned char> file(detail::png_signature, detail::png_signature + 8);
  std::vector<unsigned char> ihdr;
  detail::put_be32(ihdr, static_cast<std::uint32_t>(w));
  detail::put_be32(ihdr, static_cast<std::uint32_t>(h));
  ihdr.insert(ihdr.end(), {static_cast<unsigned char>(eight ? 8 : 16), color_type[C], 0, 0, 0});
  file.reserve(detail::to_size(zlen) + 64);
  detail::put_png_chunk(file, "IHDR", ihdr.data(), ihdr.size());
  detail::put_png_chunk(file, "IDAT", z.get(), detail::to_size(zlen));
  detail::put_png_chunk(file, "IEND", nullptr, 0);
  return file;
}

/// Writes any Image as a PNG file (see encode_png). io_error naming the file when it cannot be
/// written.
template <Image I>
status write_png(const std::string& path, const I& img) {
  auto bytes = encode_png(img, path);
  if (!bytes) return bytes.error();
  return detail::write_file(path, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

TESSERA_NAMESPACE_END
