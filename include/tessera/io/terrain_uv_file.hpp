// tessera/io/terrain_uv_file.hpp: the terrain texture-coordinate buffer (terrain_uv_buffer of
// terrain/export_corner_uvs.hpp) as a file, in the binary layout of encode_terrain_uvs: what
// `tessera terrain --uv-out` writes. No extra library needed.
#pragma once

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../terrain/export_corner_uvs.hpp"

TESSERA_NAMESPACE_BEGIN

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
