// tessera/io/png.hpp: PNG files through stb (link tessera::io; Debian libstb-dev).
//   read_png_info(path)          size, channel count and bit depth without decoding
//   read_png<T, C>(path)         decode into an image_buffer<T, C> (channels and depth converted)
//   write_png(path, image)       encode any Image (uint8 -> 8-bit PNG; uint16 and float -> 16-bit)
// Errors name the file and what went wrong; nothing throws.
#pragma once

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"

// stb builds its zlib compressor into libstb but declares it only in its implementation section.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len, int quality);

TESSERA_NAMESPACE_BEGIN

/// What a PNG file holds.
struct png_info {
  index_t width = 0;
  index_t height = 0;
  int channels = 0;   ///< 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
  int bit_depth = 8;  ///< 8 or 16
};

/// Reads the header of an image file (PNG, and anything else stb decodes).
inline result<png_info> read_png_info(const std::string& path) {
  int w = 0, h = 0, c = 0;
  if (!stbi_info(path.c_str(), &w, &h, &c)) {
    if (FILE* f = std::fopen(path.c_str(), "rb")) {
      std::fclose(f);
      return status::parse_error(detail::cat(path, ": not a readable image (", stbi_failure_reason(), ")"));
    }
    return status::io_error(detail::cat(path, ": cannot open file"));
  }
  return png_info{w, h, c, stbi_is_16_bit(path.c_str()) ? 16 : 8};
}

/// Decodes an image file into C channels of T (grey/colour/alpha converted like convert_pixel;
/// 16-bit files keep their precision when T is uint16_t or float).
template <Channel T, int C>
result<image_buffer<T, C>> read_png(const std::string& path) {
  auto info = read_png_info(path);
  if (!info) return info.error();
  if (auto s = validate_image_extent(info->width, info->height, C, path); !s) return s;
  int w = 0, h = 0, file_channels = 0;
  const bool wide = info->bit_depth == 16 && !std::is_same_v<T, std::uint8_t>;
  void* raw = wide ? static_cast<void*>(stbi_load_16(path.c_str(), &w, &h, &file_channels, C))
                   : static_cast<void*>(stbi_load(path.c_str(), &w, &h, &file_channels, C));
  if (raw == nullptr) return status::parse_error(detail::cat(path, ": cannot decode (", stbi_failure_reason(), ")"));
  image_buffer<T, C> out(w, h);
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * C;
  for (std::size_t i = 0; i < n; ++i) {
    if (wide) out.data()[i] = convert_channel<T>(static_cast<const std::uint16_t*>(raw)[i]);
    else out.data()[i] = convert_channel<T>(static_cast<const std::uint8_t*>(raw)[i]);
  }
  stbi_image_free(raw);
  return out;
}

namespace detail {
inline std::uint32_t png_crc(const unsigned char* data, std::size_t n, std::uint32_t crc = 0xffffffffu) {
  for (std::size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc;
}
inline void put_be32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}
inline void put_chunk(std::vector<unsigned char>& out, const char* type, const unsigned char* data, std::size_t n) {
  put_be32(out, static_cast<std::uint32_t>(n));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + n);
  put_be32(out, png_crc(out.data() + start, n + 4) ^ 0xffffffffu);
}
/// A 16-bit PNG (stb_image_write only writes 8-bit): unfiltered rows, zlib from libstb.
inline status write_png16(const std::string& path, index_t w, index_t h, int channels, const std::uint16_t* samples) {
  const std::size_t row = static_cast<std::size_t>(w) * static_cast<std::size_t>(channels) * 2 + 1;
  std::vector<unsigned char> raw(row * static_cast<std::size_t>(h));
  for (index_t y = 0; y < h; ++y) {
    unsigned char* r = raw.data() + static_cast<std::size_t>(y) * row;
    r[0] = 0;  // filter: none
    for (index_t i = 0; i < w * channels; ++i) {
      const std::uint16_t v = samples[y * w * channels + i];
      r[1 + 2 * i] = static_cast<unsigned char>(v >> 8);
      r[2 + 2 * i] = static_cast<unsigned char>(v & 0xff);
    }
  }
  if (raw.size() > 0x7fffffff) return status::size_overflow(detail::cat(path, ": image too large for one PNG stream"));
  int zlen = 0;
  unsigned char* z = stbi_zlib_compress(raw.data(), static_cast<int>(raw.size()), &zlen, 8);
  if (z == nullptr) return status::internal_error(detail::cat(path, ": compression failed"));
  static constexpr unsigned char color_type[5] = {0, 0, 4, 2, 6};
  std::vector<unsigned char> file = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> ihdr;
  put_be32(ihdr, static_cast<std::uint32_t>(w));
  put_be32(ihdr, static_cast<std::uint32_t>(h));
  ihdr.insert(ihdr.end(), {16, color_type[channels], 0, 0, 0});
  put_chunk(file, "IHDR", ihdr.data(), ihdr.size());
  put_chunk(file, "IDAT", z, static_cast<std::size_t>(zlen));
  std::free(z);
  put_chunk(file, "IEND", nullptr, 0);
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return status::io_error(detail::cat(path, ": cannot open for writing"));
  const bool ok = std::fwrite(file.data(), 1, file.size(), f) == file.size();
  if (std::fclose(f) != 0 || !ok) return status::io_error(detail::cat(path, ": write failed"));
  return {};
}
}  // namespace detail

/// Writes any Image as PNG: uint8 channels as an 8-bit PNG, uint16 and float as 16-bit (floats
/// clamped to [0, 1]). The channel count of the image is kept (1 to 4).
template <Image I>
status write_png(const std::string& path, const I& img) {
  if (auto s = validate_image(img, path); !s) return s;
  constexpr int C = channels_v<I>;
  const index_t w = width_of(img), h = height_of(img);
  if (w > 0x7fffffff / (C * 2) || h > 0x7fffffff)
    return status::size_overflow(detail::cat(path, ": ", w, " x ", h, " is too large for a PNG"));
  if constexpr (std::is_same_v<channel_t<I>, std::uint8_t>) {
    auto buf = to_buffer<std::uint8_t, C>(img, path);
    if (!buf) return buf.error();
    if (!stbi_write_png(path.c_str(), static_cast<int>(w), static_cast<int>(h), C, buf->data(), static_cast<int>(w * C)))
      return status::io_error(detail::cat(path, ": cannot write PNG"));
    return {};
  } else {
    auto buf = to_buffer<std::uint16_t, C>(img, path);
    if (!buf) return buf.error();
    return detail::write_png16(path, w, h, C, buf->data());
  }
}

TESSERA_NAMESPACE_END
