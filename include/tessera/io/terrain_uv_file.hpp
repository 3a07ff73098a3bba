// tessera/io/terrain_uv_file.hpp: the terrain texture-coordinate buffer (terrain_uv_buffer of
// terrain/export_corner_uvs.hpp) as a file, in the binary layout of encode_terrain_uvs: what
// `tessera terrain --uv-out` writes. No extra library needed.
#pragma once

#include <string>
#include <string_view>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../terrain/export_corner_uvs.hpp"
#include "detail/file.hpp"

TESSERA_NAMESPACE_BEGIN

/// Writes `uv` to `path` in the layout of encode_terrain_uvs. Errors: as encode_terrain_uvs, io_error naming the
/// path. Thread-safe for distinct paths.
inline status write_terrain_uv_file(const std::string& path, const terrain_uv_buffer& uv) {
  auto bytes = encode_terrain_uvs(uv);
  if (!bytes) return bytes.error();
  return detail::write_file(path, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

/// Reads a file written by write_terrain_uv_file. Errors: io_error naming the path, or as
/// decode_terrain_uvs.
inline result<terrain_uv_buffer> read_terrain_uv_file(const std::string& path) {
  auto bytes = detail::read_file(path);
  if (!bytes) return bytes.error();
  return decode_terrain_uvs(reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size());
}

TESSERA_NAMESPACE_END
