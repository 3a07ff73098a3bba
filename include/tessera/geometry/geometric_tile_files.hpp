// tessera/geometry/geometric_tile_files.hpp: saving and loading a geometric Wang tile set as a
// directory: one OBJ per tile (DIR/tile_<index>.obj, coordinates written shortest-round-trip, so
// borders stay bit-identical) and DIR/tiles.json, the manifest of io/tile_manifest.hpp (index,
// edges [north, east, south, west]) with the exact world tile size as "tile_size" (a number, 4.8 is
// written 4.8) and extra numbers "edge_height" and "height".
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../detail/json.hpp"
#include "../io/obj.hpp"
#include "../io/tile_manifest.hpp"
#include "geometric_wang_tiles.hpp"
#include "tile_geometric_plane.hpp"

TESSERA_NAMESPACE_BEGIN

/// Writes `set` into `dir` (created when missing): DIR/tile_<i>.obj and DIR/tiles.json, whose
/// "tile_size" is the exact world size (not rounded). Errors: an inconsistent set, io_error naming
/// the file that could not be written.
inline status save_geometric_tile_set(const std::string& dir, const geometric_tile_set& set) {
  if (set.tiles.empty() || set.tiles.size() != set.edges.size())
    return status::invalid_argument("save_geometric_tile_set: the set has no tiles or tiles and edges differ in count");
  if (!(set.tile_size > 0) || !std::isfinite(set.tile_size))
    return status::invalid_argument(detail::cat("save_geometric_tile_set: tile_size must be > 0, got ", set.tile_size));
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  tile_manifest m;
  m.tile_size = 1;  // the integer field is replaced by the exact size below
  m.horizontal_colors = set.horizontal_colors;
  m.vertical_colors = set.vertical_colors;
  double height = 0;
  for (std::size_t i = 0; i < set.tiles.size(); ++i) {
    const std::string file = detail::cat("tile_", i, ".obj");
    if (auto s = write_obj((std::filesystem::path(dir) / file).string(), set.tiles[i]); !s) return s;
    m.tiles.push_back({static_cast<index_t>(i), file, set.edges[i], {}});
    for (const vec3& p : set.tiles[i].positions) height = std::max(height, p.z);
  }
  m.extra = {{"edge_height", set.edge_height}, {"height", height}};
  const std::string path = tile_manifest_path(dir);
  if (auto s = validate_tile_manifest(m, path); !s) return s;
  std::string text = format_tile_manifest(m);
  const std::string integer_field = "\"tile_size\": 1,";
  const std::size_t at = text.find(integer_field);
  if (at == std::string::npos) return status::internal_error("save_geometric_tile_set: unexpected manifest layout");
  text.replace(at, integer_field.size(), detail::cat("\"tile_size\": ", detail::json_number(set.tile_size), ","));
  return detail::write_tile_manifest_text(dir, text);
}

namespace detail {
/// tiles.json of a geometric set: like parse_tile_manifest, but "tile_size" may be any positive
/// number. Files of older versions (an integer "tile_size" rounded from "tile_world_size") read too:
/// "tile_world_size", when present, wins.
inline result<std::pair<tile_manifest, double>> parse_geometric_manifest(std::string_view text,
                                                                         const std::string& path) {
  auto json = parse_json(text, path);
  if (!json) return json.error();
  auto bad = [&](auto... what) { return status::parse_error(cat(path, ": ", what...)); };
  if (!json->is_object()) return bad("the manifest must be a JSON object");
  auto integer = [&](const json_value& obj, std::string_view key, double lo, double hi, index_t& out,
                     std::string_view where) -> status {
    const json_value* v = obj.find(key);
    if (v == nullptr) return bad(where, "missing \"", key, "\"");
    if (!v->is_number() || v->number != std::floor(v->number) || !(v->number >= lo && v->number <= hi))
      return bad(where, "\"", key, "\" must be an integer in [", lo, ", ", hi, "]");
    out = static_cast<index_t>(v->number);
    return {};
  };
  const json_value* size = json->find("tile_size");
  if (size == nullptr || !size->is_number()) return bad("missing \"tile_size\" number");
  double tile_size = size->number;
  if (const json_value* world = json->find("tile_world_size"); world != nullptr && world->is_number())
    tile_size = world->number;
  if (!(tile_size > 0) || !std::isfinite(tile_size))
    return status::invalid_argument(cat(path, ": tile_size must be > 0, got ", tile_size));
  tile_manifest m;
  m.tile_size = 1;
  index_t nh = 0, nv = 0;
  if (auto s = integer(*json, "horizontal_colors", 1, max_wang_colors, nh, ""); !s) return s;
  if (auto s = integer(*json, "vertical_colors", 1, max_wang_colors, nv, ""); !s) return s;
  m.horizontal_colors = static_cast<int>(nh);
  m.vertical_colors = static_cast<int>(nv);
  for (const auto& [k, v] : json->object)
    if (v.is_number() && k != "tile_size" && k != "horizontal_colors" && k != "vertical_colors")
      m.extra.push_back({k, v.number});
  const json_value* tiles = json->find("tiles");
  if (tiles == nullptr || !tiles->is_array()) return bad("missing \"tiles\" array");
  for (std::size_t i = 0; i < tiles->array.size(); ++i) {
    const json_value& t = tiles->array[i];
    const std::string where = cat("tiles[", i, "]: ");
    if (!t.is_object()) return bad(where, "must be an object");
    tile_manifest_entry e;
    if (auto s = integer(t, "index", 0, 9.0e15, e.index, where); !s) return s;
    const json_value* file = t.find("file");
    if (file == nullptr || !file->is_string()) return bad(where, "missing \"file\" string");
    e.file = file->string;
    const json_value* edges = t.find("edges");
    if (edges == nullptr || !edges->is_array() || edges->array.size() != 4)
      return bad(where, "\"edges\" must be an array of four colours [north, east, south, west]");
    int c[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < 4; ++k) {
      const json_value& x = edges->array[k];
      if (!x.is_number() || x.number != std::floor(x.number) || std::fabs(x.number) > 1e9)
        return bad(where, "edge colours must be integers");
      c[k] = static_cast<int>(x.number);
    }
    e.edges = {c[0], c[1], c[2], c[3]};
    m.tiles.push_back(std::move(e));
  }
  if (auto s = validate_tile_manifest(m, path); !s) return s;
  std::sort(m.tiles.begin(), m.tiles.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  return std::pair{std::move(m), tile_size};
}
}  // namespace detail

/// Reads a tile set written by save_geometric_tile_set (also the older layout with an integer
/// "tile_size" and the exact "tile_world_size"), and checks it: every tile inside [0, tile_size]^2
/// with nothing on a corner, and for every colour the same border geometry on every tile carrying
/// it (within `tolerance`, tile_set_border_mismatch), so that welding a plane from it is sound.
/// Errors: io_error naming a missing tiles.json or tile file, parse errors of the manifest or an
/// OBJ, invalid_argument for a tile with vertices outside its square or on a corner, and for
/// borders that differ (naming how many tile sides).
inline result<geometric_tile_set> load_geometric_tile_set(const std::string& dir, double tolerance = 1e-6) {
  const std::string path = tile_manifest_path(dir);
  auto text = detail::read_tile_manifest_text(dir);
  if (!text) return text.error();
  auto parsed = detail::parse_geometric_manifest(*text, path);
  if (!parsed) return parsed.error();
  const tile_manifest& m = parsed->first;
  geometric_tile_set set;
  set.tile_size = parsed->second;
  set.edge_height = m.extra_value("edge_height", 0);
  set.horizontal_colors = m.horizontal_colors;
  set.vertical_colors = m.vertical_colors;
  for (const auto& t : m.tiles) {
    const auto found = detail::existing_tile_file(dir, t, path);
    if (!found) return found.error();
    const std::string& file = *found;
    auto tile = read_obj(file);
    if (!tile) return tile.error();
    for (const vec3& p : tile->positions)
      if (!(p.x >= 0 && p.x <= set.tile_size && p.y >= 0 && p.y <= set.tile_size))
        return status::invalid_argument(
            detail::cat(file, ": vertex (", p.x, ", ", p.y, ") lies outside the tile [0, ", set.tile_size, "]^2"));
    set.tiles.push_back(std::move(*tile));
    set.edges.push_back(t.edges);
  }
  auto mismatch = tile_set_border_mismatch(set, tolerance);
  if (!mismatch) return status::invalid_argument(detail::cat(dir, ": ", mismatch.error().message()));
  if (*mismatch > 0)
    return status::invalid_argument(detail::cat(dir, ": border_mismatch ", *mismatch,
                                                ": tile sides differ from the first side of their colour by more than ",
                                                tolerance, "; the set would not tile continuously"));
  return set;
}

TESSERA_NAMESPACE_END
