// tessera/io/detail/png_chunks.hpp: PNG container checks and encoding pieces: CRC-32, a walk over
// the chunk structure that verifies every length, type, checksum and the IHDR fields before any
// pixel is decoded, and the row filters of the encoder. Internal: no stability promise.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "file.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

inline constexpr unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

inline constexpr std::array<std::uint32_t, 256> png_crc_table = [] {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
    t[n] = c;
  }
  return t;
}();

/// CRC-32 as PNG uses it (ISO 3309), over `n` bytes.
inline std::uint32_t png_crc(const unsigned char* data, std::size_t n) noexcept {
  std::uint32_t c = 0xffffffffu;
  for (std::size_t i = 0; i < n; ++i) c = png_crc_table[(c ^ data[i]) & 0xffu] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

inline std::uint32_t get_be32(const unsigned char* p) noexcept {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}
inline void put_be32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}

/// What the chunk walk learned about a PNG.
struct png_layout {
  std::uint32_t width = 0, height = 0;
  int bit_depth = 0;   ///< as stored: 1, 2, 4, 8 or 16
  int color_type = 0;  ///< 0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA
  bool interlaced = false;
  bool transparency = false;  ///< a tRNS chunk (adds an alpha channel when decoded)
  std::size_t idat_bytes = 0;
  /// Channels after decoding (palette expands to RGB or RGBA, tRNS adds alpha).
  [[nodiscard]] int channels() const noexcept {
    static constexpr int base[7] = {1, 0, 3, 3, 2, 0, 4};
    const int c = base[color_type];
    return (color_type == 0 || color_type == 2 || color_type == 3) && transparency ? c + 1 : c;
  }
};

/// Walks the chunks of an in-memory PNG: signature, IHDR first with valid fields, every chunk
/// inside the data with a correct CRC, PLTE for palette images, at least one IDAT, IEND. Also
/// rejects a header promising far more pixels than the compressed data can hold (deflate expands
/// at most ~1032:1), so a hostile header cannot make the decoder allocate gigabytes.
/// Errors are parse_errors "NAME, byte OFFSET: ...".
inline result<png_layout> check_png(const unsigned char* data, std::size_t size, std::string_view name) {
  if (size == 0) return parse_error_at_byte(name, 0, "empty file");
  if (size < 8 || std::memcmp(data, png_signature, 8) != 0)
    return parse_error_at_byte(name, 0,
                               size < 8 && std::memcmp(data, png_signature, size) == 0
                                   ? "truncated inside the PNG signature"
                                   : "not a PNG file (wrong signature)");
  png_layout l;
  bool have_ihdr = false, have_plte = false, have_iend = false, idat_ended = false;
  std::size_t pos = 8;
  while (pos < size && !have_iend) {
    if (size - pos < 12)
      return parse_error_at_byte(name, pos, cat("truncated: a chunk header needs 12 bytes, ", size - pos, " left"));
    const std::uint32_t len = get_be32(data + pos);
    const unsigned char* type = data + pos + 4;
    const std::string tname(reinterpret_cast<const char*>(type), 4);
    for (unsigned char ch : tname)
      if (!((ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z')))
        return parse_error_at_byte(name, pos + 4, "corrupt chunk type (not four letters)");
    if (len > 0x7fffffffu) return parse_error_at_byte(name, pos, cat("corrupt chunk length ", len));
    if (size - pos - 12 < len)
      return parse_error_at_byte(name, pos,
                                 cat("truncated: chunk ", tname, " needs ", len, " bytes, ", size - pos - 12, " left"));
    const unsigned char* body = data + pos + 8;
    if (png_crc(type, std::size_t{len} + 4) != get_be32(body + len))
      return parse_error_at_byte(name, pos + 8 + len, cat("corrupt: CRC mismatch in chunk ", tname));
    if (!have_ihdr && tname != "IHDR") return parse_error_at_byte(name, pos, "the first chunk is not IHDR");
    if (tname == "IHDR") {
      if (have_ihdr) return parse_error_at_byte(name, pos, "second IHDR chunk");
      if (len != 13) return parse_error_at_byte(name, pos, cat("IHDR has length ", len, ", expected 13"));
      have_ihdr = true;
      l.width = get_be32(body);
      l.height = get_be32(body + 4);
      l.bit_depth = body[8];
      l.color_type = body[9];
      l.interlaced = body[12] == 1;
      if (l.width == 0 || l.height == 0 || l.width > 0x7fffffffu || l.height > 0x7fffffffu)
        return parse_error_at_byte(name, pos + 8, cat("invalid image size ", l.width, " x ", l.height));
      const int d = l.bit_depth, t = l.color_type;
      const bool depth_ok = (t == 0 && (d == 1 || d == 2 || d == 4 || d == 8 || d == 16)) ||
                            (t == 3 && (d == 1 || d == 2 || d == 4 || d == 8)) ||
                            ((t == 2 || t == 4 || t == 6) && (d == 8 || d == 16));
      if (!depth_ok) return parse_error_at_byte(name, pos + 16, cat("invalid colour type ", t, " / bit depth ", d));
      if (body[10] != 0 || body[11] != 0 || body[12] > 1)
        return parse_error_at_byte(name, pos + 18, "unknown compression, filter or interlace method");
    } else if (tname == "PLTE") {
      if (len == 0 || len % 3 != 0 || len > 768)
        return parse_error_at_byte(name, pos, cat("invalid PLTE length ", len));
      have_plte = true;
    } else if (tname == "tRNS") {
      l.transparency = true;
    } else if (tname == "IDAT") {
      if (idat_ended) return parse_error_at_byte(name, pos, "IDAT chunks are not consecutive");
      l.idat_bytes += len;
    } else if (tname == "IEND") {
      have_iend = true;
    } else if ((type[0] & 0x20) == 0) {
      return parse_error_at_byte(name, pos, cat("unknown critical chunk ", tname));
    }
    if (tname != "IDAT" && l.idat_bytes > 0) idat_ended = true;
    pos += 12 + std::size_t{len};
  }
  if (!have_iend) return parse_error_at_byte(name, size, "truncated: no IEND chunk");
  if (l.idat_bytes == 0) return parse_error_at_byte(name, pos, "no image data (IDAT)");
  if (l.color_type == 3 && !have_plte) return parse_error_at_byte(name, pos, "palette image without PLTE");
  // filtered bytes of a non-interlaced image: a lower bound for any interlacing
  const double bits_per_pixel = double(l.bit_depth) * double(l.color_type == 3 ? 1 : l.channels() - l.transparency);
  const double raw = double(l.height) * (1.0 + std::ceil(double(l.width) * bits_per_pixel / 8.0));
  if (raw > 1100.0 * double(l.idat_bytes) + 1024.0)
    return parse_error_at_byte(name, 8,
                               cat("corrupt or truncated: the header declares ", l.width, " x ", l.height,
                                   " pixels but the file holds only ", l.idat_bytes, " bytes of compressed data"));
  return l;
}

/// Applies the PNG filter that minimizes the sum of absolute filtered bytes (libpng's heuristic) to
/// each row of `raw` (rows of `row_bytes`, `bpp` bytes per pixel), producing the filtered stream.
inline std::vector<unsigned char> png_filter_rows(const unsigned char* raw, std::size_t row_bytes, std::size_t rows,
                                                  std::size_t bpp) {
  std::vector<unsigned char> out((row_bytes + 1) * rows);
  std::vector<unsigned char> trial(row_bytes);
  for (std::size_t y = 0; y < rows; ++y) {
    const unsigned char* cur = raw + y * row_bytes;
    const unsigned char* up = y > 0 ? cur - row_bytes : nullptr;
    unsigned char* dst = out.data() + y * (row_bytes + 1);
    long best_cost = -1;
    for (int f = 0; f < 5; ++f) {
      long cost = 0;
      for (std::size_t i = 0; i < row_bytes; ++i) {
        const int a = i >= bpp ? cur[i - bpp] : 0, b = up ? up[i] : 0, c = (up && i >= bpp) ? up[i - bpp] : 0;
        int pred = 0;
        if (f == 1)
          pred = a;
        else if (f == 2)
          pred = b;
        else if (f == 3)
          pred = (a + b) / 2;
        else if (f == 4) {
          const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
          pred = (pa <= pb && pa <= pc) ? a : pb <= pc ? b : c;
        }
        const auto v = static_cast<unsigned char>(cur[i] - pred);
        trial[i] = v;
        cost += v < 128 ? v : 256 - v;
      }
      if (best_cost < 0 || cost < best_cost) {
        best_cost = cost;
        dst[0] = static_cast<unsigned char>(f);
        std::copy(trial.begin(), trial.end(), dst + 1);
      }
    }
  }
  return out;
}

inline void put_png_chunk(std::vector<unsigned char>& out, const char* type, const unsigned char* data, std::size_t n) {
  put_be32(out, static_cast<std::uint32_t>(n));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  if (n > 0) out.insert(out.end(), data, data + n);
  put_be32(out, png_crc(out.data() + start, n + 4));
}

}  // namespace detail
TESSERA_NAMESPACE_END
