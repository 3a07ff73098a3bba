// tessera/geometry/geometric_tile_files.hpp: saving and loading a geometric Wang tile set as a
// directory: one OBJ per tile (DIR/tile_<index>.obj, coordinates written shortest-round-trip, so
// borders stay bit-identical) and DIR/tiles.json (tiling/tile_manifest.hpp: index, edges
// [north, east, south, west], tile size; extra numbers "tile_world_size", "edge_height" and "height").
#pragma once

#include <cmath>
#include <filesystem>
#include <string>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../io/obj.hpp"
#include "../tiling/tile_manifest.hpp"
#include "geometric_wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN

/// Writes `set` into `dir` (created when missing). The manifest's integer tile_size is the rounded
/// world size (at least 1); the exact size is the extra field "tile_world_size". Errors: an
/// inconsistent set, io_error naming the file that could not be written.
inline status save_geometric_tile_set(const std::string& dir, const geometric_tile_set& set) {
  if (set.tiles.empty() || set.tiles.size() != set.edges.size())
    return status::invalid_argument("save_geometric_tile_set: the set has no tiles or tiles and edges differ in count");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  tile_manifest m;
  m.tile_size = std::max<index_t>(1, static_cast<index_t>(std::llround(set.tile_size)));
  m.horizontal_colors = set.horizontal_colors;
  m.vertical_colors = set.vertical_colors;
  double height = 0;
  for (std::size_t i = 0; i < set.tiles.size(); ++i) {
    const std::string file = detail::cat("tile_", i, ".obj");
    if (auto s = write_obj((std::filesystem::path(dir) / file).string(), set.tiles[i]); !s) return s;
    m.tiles.push_back({static_cast<index_t>(i), file, set.edges[i], {}});
    for (const vec3& p : set.tiles[i].positions) height = std::max(height, p.z);
  }
  m.extra = {{"tile_world_size", set.tile_size}, {"edge_height", set.edge_height}, {"height", height}};
  return write_tile_manifest(dir, m);
}

/// Reads a tile set written by save_geometric_tile_set (or any tiles.json listing OBJ tiles; without
/// "tile_world_size" the integer tile_size is used). Errors: io_error naming a missing tiles.json or
/// tile file, parse errors of the manifest or an OBJ, invalid_argument for a tile with vertices
/// outside [0, tile_size]^2.
inline result<geometric_tile_set> load_geometric_tile_set(const std::string& dir) {
  auto m = read_tile_manifest(dir);
  if (!m) return m.error();
  geometric_tile_set set;
  set.tile_size = m->extra_value("tile_world_size", static_cast<double>(m->tile_size));
  set.edge_height = m->extra_value("edge_height", 0);
  set.horizontal_colors = m->horizontal_colors;
  set.vertical_colors = m->vertical_colors;
  if (!(set.tile_size > 0) || !std::isfinite(set.tile_size))
    return status::invalid_argument(detail::cat(tile_manifest_path(dir), ": tile_world_size must be > 0, got ", set.tile_size));
  for (const auto& t : m->tiles) {
    const std::string path = (std::filesystem::path(dir) / t.file).string();
    auto tile = read_obj(path);
    if (!tile) return tile.error();
    for (const vec3& p : tile->positions)
      if (!(p.x >= 0 && p.x <= set.tile_size && p.y >= 0 && p.y <= set.tile_size))
        return status::invalid_argument(detail::cat(path, ": vertex (", p.x, ", ", p.y, ") lies outside the tile [0, ", set.tile_size, "]^2"));
    set.tiles.push_back(std::move(*tile));
    set.edges.push_back(t.edges);
  }
  return set;
}

TESSERA_NAMESPACE_END
