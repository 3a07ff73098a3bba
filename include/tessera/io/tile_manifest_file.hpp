// tessera/io/tile_manifest_file.hpp: reading and writing DIR/tiles.json, the manifest of a Wang
// tile directory (tiling/tile_manifest.hpp holds the format itself). No extra library needed.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../tiling/tile_manifest.hpp"

TESSERA_NAMESPACE_BEGIN

/// The path of the manifest inside a tile directory: DIR/tiles.json.
inline std::string tile_manifest_path(const std::string& dir) { return (std::filesystem::path(dir) / "tiles.json").string(); }

/// Reads and validates DIR/tiles.json and checks that every listed tile file exists. Errors:
/// io_error naming DIR/tiles.json or the first missing tile file; parse_error / invalid_argument
/// from parse_tile_manifest. Thread-safe (reads only).
inline result<tile_manifest> read_tile_manifest(const std::string& dir) {
  const std::string path = tile_manifest_path(dir);
  std::ifstream in(path, std::ios::binary);
  if (!in) return status::io_error(detail::cat(path, ": cannot open the tile manifest"));
  std::ostringstream text;
  text << in.rdbuf();
  auto m = parse_tile_manifest(text.str(), path);
  if (!m) return m.error();
  for (const auto& t : m->tiles) {
    const auto file = std::filesystem::path(dir) / t.file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      return status::io_error(detail::cat(file.string(), ": tile ", t.index, " listed in ", path, " is missing"));
  }
  return m;
}

/// Validates `m` and writes it to DIR/tiles.json (creating DIR if needed). Errors: invalid manifest,
/// io_error naming the path.
inline status write_tile_manifest(const std::string& dir, const tile_manifest& m) {
  const std::string path = tile_manifest_path(dir);
  if (auto s = validate_tile_manifest(m, path); !s) return s;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return status::io_error(detail::cat(path, ": cannot write the tile manifest"));
  out << format_tile_manifest(m);
  out.flush();
  if (!out) return status::io_error(detail::cat(path, ": write failed"));
  return {};
}

TESSERA_NAMESPACE_END
