// tessera/terrain/terrain_uv_file.hpp: the per-face texture coordinates of a synthesized terrain
// frame (paper 003, §2.3; export_corner_uvs) as a small binary file an engine or a script can read
// (`tessera terrain --uv-out`). All numbers little-endian, no padding:
//
//   offset  size  header
//        0     4  magic "TSUV"
//        4     4  u32 version = 2
//        8     4  u32 F: faces (the mesh's, culled ones included)
//       12     8  u32 viewport width, u32 viewport height (pixels)
//       20     8  u32 exemplar width, u32 exemplar height (level 0 of the pyramid)
//       28     4  u32 levels of the scale field
//       32     4  f32 min_scale of the scale field
//
//   then F records of 44 bytes, face f at 36 + 44 f:
//        0    24  f32 u0 v0 u1 v1 u2 v2: corner uv (NaN where a corner is behind the eye, or culled)
//       24     8  f32 offset x, y: uv = pixel position (y down, centres at +0.5) + offset
//       32     4  i32 level (-1: culled)
//       36     4  f32 scale (0: culled)
//       40     4  u32 state: 0 culled, 1 visible, 2 visible and crossing the near plane
//
// uv is in pixels of the exemplar shrunk by `scale`, from its centre: sample it at normalized
// coordinates 0.5 + uv / (exemplar width * scale, exemplar height * scale). Version 1 (written
// before) had 32-byte records without offset and state and a 12-byte header.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "synthesize_triangles.hpp"

TESSERA_NAMESPACE_BEGIN

inline constexpr std::uint32_t terrain_uv_file_version = 2;
inline constexpr std::size_t terrain_uv_header_bytes = 36, terrain_uv_record_bytes = 44;

namespace detail {
inline void put_u32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}
inline void put_f32(std::vector<unsigned char>& out, float f) {
  std::uint32_t v;
  std::memcpy(&v, &f, 4);
  put_u32(out, v);
}
inline std::uint32_t get_u32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 | static_cast<std::uint32_t>(p[2]) << 16 |
         static_cast<std::uint32_t>(p[3]) << 24;
}
inline float get_f32(const unsigned char* p) {
  const std::uint32_t v = get_u32(p);
  float f;
  std::memcpy(&f, &v, 4);
  return f;
}
}  // namespace detail

/// Encodes a terrain_uv_buffer in the layout above. Errors (invalid_argument): arrays of different
/// lengths, more than 2^32 - 1 faces or sizes that do not fit a u32. O(F).
inline result<std::vector<unsigned char>> encode_terrain_uvs(const terrain_uv_buffer& uv) {
  const std::size_t n = uv.level.size();
  if (uv.corner_uv.size() != n || uv.offset.size() != n || uv.scale.size() != n || uv.state.size() != n)
    return status::invalid_argument(detail::cat("terrain uv buffer: arrays of different lengths (", uv.corner_uv.size(), ", ",
                                                uv.offset.size(), ", ", n, ", ", uv.scale.size(), ", ", uv.state.size(), ")"));
  constexpr index_t u32max = 0xffffffff;
  for (const index_t v : {static_cast<index_t>(n), uv.viewport_width, uv.viewport_height, uv.exemplar_width, uv.exemplar_height, uv.levels})
    if (v < 0 || v > u32max) return status::invalid_argument(detail::cat("terrain uv buffer: ", v, " does not fit the file's u32 fields"));
  std::vector<unsigned char> out;
  out.reserve(terrain_uv_header_bytes + terrain_uv_record_bytes * n);
  for (const char c : {'T', 'S', 'U', 'V'}) out.push_back(static_cast<unsigned char>(c));
  detail::put_u32(out, terrain_uv_file_version);
  for (const index_t v : {static_cast<index_t>(n), uv.viewport_width, uv.viewport_height, uv.exemplar_width, uv.exemplar_height, uv.levels})
    detail::put_u32(out, static_cast<std::uint32_t>(v));
  detail::put_f32(out, static_cast<float>(uv.min_scale));
  for (std::size_t f = 0; f < n; ++f) {
    for (const float c : uv.corner_uv[f]) detail::put_f32(out, c);
    for (const float c : uv.offset[f]) detail::put_f32(out, c);
    detail::put_u32(out, static_cast<std::uint32_t>(uv.level[f]));
    detail::put_f32(out, uv.scale[f]);
    detail::put_u32(out, uv.state[f]);
  }
  return out;
}

/// Decodes the layout above (version 2). Errors (invalid_argument): wrong magic or version, a size
/// that does not match the face count. O(F).
inline result<terrain_uv_buffer> decode_terrain_uvs(const unsigned char* data, std::size_t size) {
  if (size < terrain_uv_header_bytes || std::memcmp(data, "TSUV", 4) != 0)
    return status::invalid_argument(detail::cat("terrain uv file: no 'TSUV' header (", size, " bytes)"));
  if (const std::uint32_t v = detail::get_u32(data + 4); v != terrain_uv_file_version)
    return status::invalid_argument(detail::cat("terrain uv file: version ", v, ", expected ", terrain_uv_file_version));
  const std::size_t n = detail::get_u32(data + 8);
  if ((size - terrain_uv_header_bytes) / terrain_uv_record_bytes != n || (size - terrain_uv_header_bytes) % terrain_uv_record_bytes != 0)
    return status::invalid_argument(detail::cat("terrain uv file: ", size, " bytes do not hold ", n, " faces"));
  terrain_uv_buffer uv;
  uv.viewport_width = detail::get_u32(data + 12);
  uv.viewport_height = detail::get_u32(data + 16);
  uv.exemplar_width = detail::get_u32(data + 20);
  uv.exemplar_height = detail::get_u32(data + 24);
  uv.levels = detail::get_u32(data + 28);
  uv.min_scale = detail::get_f32(data + 32);
  uv.corner_uv.resize(n);
  uv.offset.resize(n);
  uv.level.resize(n);
  uv.scale.resize(n);
  uv.state.resize(n);
  for (std::size_t f = 0; f < n; ++f) {
    const unsigned char* r = data + terrain_uv_header_bytes + terrain_uv_record_bytes * f;
    for (std::size_t k = 0; k < 6; ++k) uv.corner_uv[f][k] = detail::get_f32(r + 4 * k);
    uv.offset[f] = {detail::get_f32(r + 24), detail::get_f32(r + 28)};
    uv.level[f] = static_cast<std::int32_t>(detail::get_u32(r + 32));
    uv.scale[f] = detail::get_f32(r + 36);
    uv.state[f] = static_cast<std::uint8_t>(detail::get_u32(r + 40));
  }
  return uv;
}

/// Writes `uv` to `path` in the layout above. Errors: as encode_terrain_uvs, io_error naming the
/// path. Thread-safe for distinct paths.
inline status write_terrain_uv_file(const std::string& path, const terrain_uv_buffer& uv) {
  auto bytes = encode_terrain_uvs(uv);
  if (!bytes) return bytes.error();
  std::ofstream out(path, std::ios::binary);
  if (!out) return status::io_error(path + ": cannot open for writing");
  out.write(reinterpret_cast<const char*>(bytes->data()), static_cast<std::streamsize>(bytes->size()));
  return out ? status{} : status::io_error(path + ": write failed");
}

/// Reads a file written by write_terrain_uv_file. Errors: io_error naming the path, or as
/// decode_terrain_uvs.
inline result<terrain_uv_buffer> read_terrain_uv_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return status::io_error(path + ": cannot open for reading");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return status::io_error(path + ": read failed");
  return decode_terrain_uvs(bytes.data(), bytes.size());
}

TESSERA_NAMESPACE_END
