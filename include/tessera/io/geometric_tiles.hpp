// tessera/io/geometric_tiles.hpp: geometric Wang tile directories, saved and loaded: one OBJ per
// tile (DIR/tile_<index>.obj, coordinates written shortest round-trip, so borders stay
// bit-identical) and DIR/tiles.json, the manifest of io/tile_manifest.hpp (kind geometric: the exact
// world tile size as "tile_size", 4.8 is written 4.8) with extra numbers "edge_height" and "height".
// Planar and three-axis sets alike (a three-axis set's manifest is version 2: "axis_colors" and a
// "face" per tile).
// The image counterpart is io/wang_tiles.hpp. No extra library needed.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../geometry/geometric_wang_tiles.hpp"
#include "../geometry/tile_geometric_plane.hpp"
#include "obj.hpp"
#include "tile_manifest.hpp"

TESSERA_NAMESPACE_BEGIN

/// Writes `set` into `dir` (created when missing): DIR/tile_<i>.obj and DIR/tiles.json, whose
/// "tile_size" is the exact world size (not rounded). Errors: an inconsistent set, io_error naming
/// the file that could not be written.
inline status save_geometric_tile_set(const std::string& dir, const geometric_tile_set& set) {
  if (set.tiles.empty() || set.tiles.size() != set.edges.size() ||
      (set.three_axis() && set.faces.size() != set.tiles.size()))
    return status::invalid_argument(
        "save_geometric_tile_set: the set has no tiles or its tiles, edges (and faces) differ in count");
  if (!(set.tile_size > 0) || !std::isfinite(set.tile_size))
    return status::invalid_argument(cat("save_geometric_tile_set: tile_size must be > 0, got ", set.tile_size));
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  tile_manifest m;
  m.kind = tile_set_kind::geometric;
  m.tile_size = set.tile_size;
  m.horizontal_colors = set.horizontal_colors;
  m.vertical_colors = set.vertical_colors;
  m.axis_colors = set.axis_colors;
  double height = 0;
  for (std::size_t i = 0; i < set.tiles.size(); ++i) {
    const std::string file = cat("tile_", i, ".obj");
    if (auto s = write_obj((std::filesystem::path(dir) / file).string(), set.tiles[i]); !s) return s;
    m.tiles.push_back({static_cast<index_t>(i), file, set.edges[i], {}, set.three_axis() ? set.faces[i] : -1});
    for (const vec3& p : set.tiles[i].positions) height = std::max(height, p.z);
  }
  m.extra = {{"edge_height", set.edge_height}, {"height", height}};
  return write_tile_manifest(dir, m);
}

/// Reads a tile set written by save_geometric_tile_set, planar or three-axis (also the older layout
/// with an integer "tile_size" and the exact "tile_world_size"), and checks it: every tile inside
/// [0, tile_size]^2 with nothing on a corner, and for every colour (of every axis, three-axis) the
/// same border geometry on every tile carrying it (within `tolerance`, tile_set_border_mismatch), so
/// that welding a plane or a polycube surface from it is sound.
/// Errors: io_error naming a missing tiles.json or tile file, parse errors of the manifest or an
/// OBJ (a manifest of a newer version is refused, naming it), invalid_argument for a tile with
/// vertices outside its square or on a corner, and for borders that differ (naming how many tile
/// sides).
inline result<geometric_tile_set> load_geometric_tile_set(const std::string& dir, double tolerance = 1e-6) {
  auto m = read_tile_manifest(dir, tile_set_kind::geometric);
  if (!m) return m.error();
  geometric_tile_set set;
  set.tile_size = m->tile_size;
  set.edge_height = m->extra_value("edge_height", 0);
  set.horizontal_colors = m->horizontal_colors;
  set.vertical_colors = m->vertical_colors;
  set.axis_colors = m->axis_colors;
  for (const auto& t : m->tiles) {
    const std::string file = (std::filesystem::path(dir) / t.file).string();
    auto tile = read_obj(file);
    if (!tile) return tile.error();
    for (const vec3& p : tile->positions)
      if (!(p.x >= 0 && p.x <= set.tile_size && p.y >= 0 && p.y <= set.tile_size))
        return status::invalid_argument(
            cat(file, ": vertex (", p.x, ", ", p.y, ") lies outside the tile [0, ", set.tile_size, "]^2"));
    set.tiles.push_back(std::move(*tile));
    set.edges.push_back(t.edges);
    if (set.three_axis()) set.faces.push_back(t.face);
  }
  auto mismatch = tile_set_border_mismatch(set, tolerance);
  if (!mismatch) return status::invalid_argument(cat(dir, ": ", mismatch.error().message()));
  if (*mismatch > 0)
    return status::invalid_argument(cat(dir, ": border_mismatch ", *mismatch,
                                        ": tile sides differ from the first side of their colour by more than ",
                                        tolerance, "; the set would not tile continuously"));
  return set;
}

TESSERA_NAMESPACE_END
