// tessera/io/tile_manifest.hpp: the `tiles.json` manifest of a Wang tile directory, shared by
// image tiles (io/wang_tiles.hpp, `tessera wang build`) and geometric tiles (io/geometric_tiles.hpp):
// the format, its one parser, and reading and writing DIR/tiles.json. No extra library needed.
//
//   {
//     "tile_size": 64, "horizontal_colors": 2, "vertical_colors": 2,
//     "tiles": [
//       {"index": 0, "file": "tile_0.png", "edges": [0, 0, 0, 0]},     // [north, east, south, west]
//       ...
//     ]
//   }
//
// Three-axis sets, geometric or image (paper 000 §3.1, polycube surfaces), write "version": 2, "axis_colors":
// [nX, nY, nZ] instead of the two colour counts, and a "face" (0..5: +X, -X, +Y, -Y, +Z, -Z) per tile,
// whose edges are then in that face's frame (tiling/axis_tile_set.hpp). A file without "version" is
// version 1 (planar); a version above 2 is refused, naming it.
//
// "tile_size" is the side of a tile: a whole number of pixels for image tiles, any positive number
// (world units, written shortest round-trip) for geometric tiles. Geometric manifests of older
// versions wrote a rounded integer "tile_size" and the exact size as "tile_world_size", which then
// wins. Any other numeric member, at the top level or inside a tile, is kept as an extra field (the
// geometry side adds e.g. "height"). Reading is tolerant (comments, trailing commas, members in any
// order); every error names the file and what is wrong.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "detail/json.hpp"
#include "../tiling/axis_tile_set.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "../tiling/tile_set_edges.hpp"
#include "detail/file.hpp"

TESSERA_NAMESPACE_BEGIN

/// A named number beyond the required fields ("height": 0.25).
struct manifest_field {
  /// The field's name.
  std::string name;
  /// Its value.
  double value = 0;
  friend bool operator==(const manifest_field&, const manifest_field&) = default;
};

/// One tile of a manifest.
struct tile_manifest_entry {
  index_t index = 0;      ///< tile number; the entries hold each of 0..n-1 once
  std::string file;       ///< file name relative to the directory ("tile_3.png")
  wang_edges edges = {};  ///< [north, east, south, west]
  /// Further numbers of the tile.
  std::vector<manifest_field> extra = {};
  /// Three-axis sets: the cube face (0..5); -1 in planar sets.
  int face = -1;
  friend bool operator==(const tile_manifest_entry&, const tile_manifest_entry&) = default;
};

/// What the tiles of a directory are: the kind decides what "tile_size" may be (it is not written).
enum class tile_set_kind {
  image,     ///< PNG tiles: tile_size is a whole number of pixels
  geometric  ///< OBJ tiles: tile_size is any positive, finite world size
};

/// The contents of `tiles.json`.
struct tile_manifest {
  /// image or geometric.
  tile_set_kind kind = tile_set_kind::image;
  double tile_size = 0;  ///< pixels (a whole number) for image tiles, world units for geometric ones
  /// nh, colours of north/south edges.
  int horizontal_colors = 0;
  /// nv, colours of east/west edges.
  int vertical_colors = 0;
  /// Three-axis geometric sets: {nX, nY, nZ} (and nh = nv = 0); {0, 0, 0} for planar sets.
  axis_color_counts axis_colors = {0, 0, 0};
  std::vector<tile_manifest_entry> tiles;  ///< sorted by index after reading
  /// Further numbers of the set.
  std::vector<manifest_field> extra = {};

  /// The value of a top-level extra field, or `fallback`.
  [[nodiscard]] double extra_value(std::string_view name, double fallback = 0) const {
    for (const auto& f : extra)
      if (f.name == name) return f.value;
    return fallback;
  }
  friend bool operator==(const tile_manifest&, const tile_manifest&) = default;
};

namespace detail {
/// Why `file` cannot name a tile inside its directory, or nullptr when it can: a manifest must never
/// make a reader or writer leave its directory. A tile file is a relative path of plain components
/// separated by '/': no absolute path ("/x", "C:x"), no ".." or "." component, no backslash, no
/// control character (NUL included, which would cut the name short), at most 255 bytes.
inline const char* tile_file_problem(std::string_view file) noexcept {
  if (file.empty()) return "is empty";
  if (file.size() > 255) return "is longer than 255 bytes";
  for (char c : file) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) return "holds a control character";
    if (c == '\\') return "holds a backslash";
    if (c == ':') return "holds a colon (a drive or stream name)";
  }
  if (file.front() == '/') return "is an absolute path";
  std::size_t start = 0;
  while (start <= file.size()) {
    const std::size_t end = std::min(file.find('/', start), file.size());
    const std::string_view part = file.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") return "has an empty, '.' or '..' component";
    start = end + 1;
  }
  return nullptr;
}
/// Extra fields: names unique, not one of `reserved`, values finite (they are written as numbers).
inline const char* manifest_fields_problem(const std::vector<manifest_field>& fields,
                                           std::initializer_list<std::string_view> reserved, std::string& which) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    which = fields[i].name;
    for (std::string_view r : reserved)
      if (fields[i].name == r) return "uses a reserved name";
    for (std::size_t j = 0; j < i; ++j)
      if (fields[j].name == fields[i].name) return "appears twice";
    if (!std::isfinite(fields[i].value)) return "is not a finite number";
  }
  return nullptr;
}
}  // namespace detail

/// Checks a manifest's consistency: positive, finite tile size (a whole number for image tiles),
/// valid colour counts, at least one tile,
/// indices forming 0..n-1, edge colours in range, tile files that stay inside the directory
/// (relative, no "..", no backslash, no NUL or other control character), extra fields with unique,
/// non-reserved names and finite values. `name` (the file) starts every message. O(n log n).
inline status validate_tile_manifest(const tile_manifest& m, std::string_view name = "tiles.json") {
  auto bad = [&](auto... what) { return status::invalid_argument(detail::cat(name, ": ", what...)); };
  if (!(m.tile_size > 0) || !std::isfinite(m.tile_size)) return bad("tile_size must be positive, got ", m.tile_size);
  if (m.kind == tile_set_kind::image && (m.tile_size != std::floor(m.tile_size) || m.tile_size > 9.0e15))
    return bad("tile_size of image tiles must be a whole number of pixels, got ", m.tile_size);
  const bool three = m.axis_colors != axis_color_counts{0, 0, 0};
  if (three) {
    if (auto s = validate_axis_color_counts(m.axis_colors); !s) return bad(s.message());
  } else if (auto s = validate_color_counts(m.horizontal_colors, m.vertical_colors); !s) {
    return bad(s.message());
  }
  if (m.tiles.empty()) return bad("\"tiles\" is empty");
  std::string field;
  if (const char* p = detail::manifest_fields_problem(
          m.extra, {"tile_size", "horizontal_colors", "vertical_colors", "tiles", "version", "axis_colors"}, field))
    return bad("extra field \"", field, "\" ", p);
  std::vector<char> seen(m.tiles.size(), 0);
  for (const auto& t : m.tiles) {
    if (t.index < 0 || t.index >= static_cast<index_t>(m.tiles.size()))
      return bad("tile index ", t.index, " is outside [0, ", m.tiles.size(), ") (indices must be 0..n-1)");
    if (seen[detail::to_size(t.index)]++) return bad("tile index ", t.index, " appears twice");
    if (three) {
      if (auto s = validate_axis_tile({t.face, t.edges}, m.axis_colors); !s)
        return bad("tile ", t.index, ": ", s.message());
    } else if (t.face != -1) {
      return bad("tile ", t.index, ": a planar set's tiles have no face");
    } else if (auto s = validate_wang_edges(t.edges, m.horizontal_colors, m.vertical_colors); !s) {
      return bad("tile ", t.index, ": ", s.message());
    }
    if (const char* p = detail::tile_file_problem(t.file))
      return bad("tile ", t.index, ": file ", detail::json_quote(t.file), " ", p,
                 " (it must be a relative name inside the tile directory)");
    if (const char* p = detail::manifest_fields_problem(t.extra, {"index", "file", "edges", "face"}, field))
      return bad("tile ", t.index, ": extra field \"", field, "\" ", p);
  }
  return {};
}

/// Parses manifest text of a tile set of the given kind (the one parser of tiles.json). `name`
/// (usually the file path) starts every message. For geometric tiles, "tile_size" may be any
/// number and an older file's "tile_world_size" wins over it. Errors: malformed JSON (with line and
/// column), missing or mistyped required members, non-integer counts (and a non-integer tile_size
/// of image tiles), and everything validate_tile_manifest checks. Tiles come back sorted by index.
/// O(text size).
inline result<tile_manifest> parse_tile_manifest(std::string_view text, std::string_view name = "tiles.json",
                                                 tile_set_kind kind = tile_set_kind::image) {
  auto json = detail::parse_json(text, name);
  if (!json) return json.error();
  auto bad = [&](auto... what) { return status::parse_error(detail::cat(name, ": ", what...)); };
  if (!json->is_object()) return bad("the manifest must be a JSON object");
  auto integer = [&](const detail::json_value& obj, std::string_view key, index_t& out,
                     std::string_view where) -> status {
    const detail::json_value* v = obj.find(key);
    if (v == nullptr) return bad(where, "missing \"", key, "\"");
    if (!v->is_number() || v->number != std::floor(v->number) || std::fabs(v->number) > 9.0e15)
      return bad(where, "\"", key, "\" must be an integer");
    out = static_cast<index_t>(v->number);
    return {};
  };
  auto extras = [](const detail::json_value& obj, std::initializer_list<std::string_view> known) {
    std::vector<manifest_field> out;
    for (const auto& [k, v] : obj.object) {
      bool is_known = false;
      for (std::string_view kn : known) is_known = is_known || k == kn;
      if (!is_known && v.is_number()) out.push_back({k, v.number});
    }
    return out;
  };
  tile_manifest m;
  m.kind = kind;
  if (kind == tile_set_kind::image) {
    index_t pixels = 0;
    if (auto s = integer(*json, "tile_size", pixels, ""); !s) return s;
    m.tile_size = static_cast<double>(pixels);
  } else {
    const detail::json_value* size = json->find("tile_size");
    if (size == nullptr || !size->is_number()) return bad("missing \"tile_size\" number");
    m.tile_size = size->number;
    const detail::json_value* world = json->find("tile_world_size");  // older versions' exact size
    if (world != nullptr && world->is_number()) m.tile_size = world->number;
  }
  index_t version = 1;
  if (json->find("version") != nullptr) {
    if (auto s = integer(*json, "version", version, ""); !s) return s;
    if (version < 1 || version > 2)
      return bad("version ", version, " is not one this tessera reads (1 or 2; a newer tessera wrote it?)");
  }
  const detail::json_value* axes = json->find("axis_colors");
  if (axes != nullptr) {  // a three-axis set
    if (version < 2) return bad("\"axis_colors\" needs \"version\": 2");
    if (!axes->is_array() || axes->array.size() != 3)
      return bad("\"axis_colors\" must be an array of three colour counts [nX, nY, nZ]");
    for (std::size_t a = 0; a < 3; ++a) {
      const detail::json_value& v = axes->array[a];
      if (!v.is_number() || v.number != std::floor(v.number) || v.number < 1 || v.number > max_wang_colors)
        return bad("\"axis_colors\" must hold three integers in [1, ", max_wang_colors, "]");
      m.axis_colors[a] = static_cast<int>(v.number);
    }
  } else {
    index_t nh = 0, nv = 0;
    if (auto s = integer(*json, "horizontal_colors", nh, ""); !s) return s;
    if (auto s = integer(*json, "vertical_colors", nv, ""); !s) return s;
    if (nh < 1 || nh > max_wang_colors || nv < 1 || nv > max_wang_colors)
      return bad("colour counts must be in [1, ", max_wang_colors, "], got ", nh, " x ", nv);
    m.horizontal_colors = static_cast<int>(nh);
    m.vertical_colors = static_cast<int>(nv);
  }
  m.extra = kind == tile_set_kind::image
                ? extras(*json, {"tile_size", "horizontal_colors", "vertical_colors", "version"})
                : extras(*json, {"tile_size", "horizontal_colors", "vertical_colors", "tile_world_size", "version"});
  const detail::json_value* tiles = json->find("tiles");
  if (tiles == nullptr || !tiles->is_array()) return bad("missing \"tiles\" array");
  for (std::size_t i = 0; i < tiles->array.size(); ++i) {
    const detail::json_value& t = tiles->array[i];
    const std::string where = detail::cat("tiles[", i, "]: ");
    if (!t.is_object()) return bad(where, "must be an object");
    tile_manifest_entry e;
    if (auto s = integer(t, "index", e.index, where); !s) return s;
    const detail::json_value* file = t.find("file");
    if (file == nullptr || !file->is_string()) return bad(where, "missing \"file\" string");
    e.file = file->string;
    const detail::json_value* edges = t.find("edges");
    if (edges == nullptr || !edges->is_array() || edges->array.size() != 4)
      return bad(where, "\"edges\" must be an array of four colours [north, east, south, west]");
    int c[4] = {0, 0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      const detail::json_value& v = edges->array[detail::to_size(k)];
      if (!v.is_number() || v.number != std::floor(v.number) || std::fabs(v.number) > 1e9)
        return bad(where, "edge colours must be integers");
      c[k] = static_cast<int>(v.number);
    }
    e.edges = {c[0], c[1], c[2], c[3]};
    if (axes != nullptr) {
      index_t face = -1;
      if (auto s = integer(t, "face", face, where); !s) return s;
      if (face < 0 || face >= cube_faces) return bad(where, "\"face\" must be in [0, 6), got ", face);
      e.face = static_cast<int>(face);
    }
    e.extra = extras(t, {"index", "edges", "face"});
    m.tiles.push_back(std::move(e));
  }
  if (auto s = validate_tile_manifest(m, name); !s) return s;
  std::sort(m.tiles.begin(), m.tiles.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  return m;
}

/// The manifest as JSON text, one tile per line (what write_tile_manifest stores).
inline std::string format_tile_manifest(const tile_manifest& m) {
  std::string out = "{\n";
  const bool three = m.axis_colors != axis_color_counts{0, 0, 0};
  if (three)
    out +=
        detail::cat("  \"version\": 2,\n  \"tile_size\": ", detail::json_number(m.tile_size), ",\n  \"axis_colors\": [",
                    m.axis_colors[0], ", ", m.axis_colors[1], ", ", m.axis_colors[2], "],\n");
  else
    out += detail::cat("  \"tile_size\": ", detail::json_number(m.tile_size),
                       ",\n  \"horizontal_colors\": ", m.horizontal_colors,
                       ",\n  \"vertical_colors\": ", m.vertical_colors, ",\n");
  for (const auto& f : m.extra)
    out += detail::cat("  ", detail::json_quote(f.name), ": ", detail::json_number(f.value), ",\n");
  out += "  \"tiles\": [\n";
  for (std::size_t i = 0; i < m.tiles.size(); ++i) {
    const auto& t = m.tiles[i];
    out += detail::cat("    {\"index\": ", t.index, ", \"file\": ", detail::json_quote(t.file), ", \"edges\": [",
                       t.edges.north, ", ", t.edges.east, ", ", t.edges.south, ", ", t.edges.west, "]");
    if (three) out += detail::cat(", \"face\": ", t.face);
    for (const auto& f : t.extra)
      out += detail::cat(", ", detail::json_quote(f.name), ": ", detail::json_number(f.value));
    out += i + 1 < m.tiles.size() ? "},\n" : "}\n";
  }
  out += "  ]\n}\n";
  return out;
}

/// The tile set described by a manifest (tile i has the edges of the entry with index i).
inline result<tile_set_edges> manifest_tile_set(const tile_manifest& m) {
  if (auto s = validate_tile_manifest(m); !s) return s;
  if (m.axis_colors != axis_color_counts{0, 0, 0})
    return status::invalid_argument("tiles.json: a three-axis set has no single horizontal x vertical tile set");
  std::vector<wang_edges> edges(m.tiles.size());
  for (const auto& t : m.tiles) edges[detail::to_size(t.index)] = t.edges;
  return tile_set_edges::create(m.horizontal_colors, m.vertical_colors, std::move(edges));
}

/// The path of the manifest inside a tile directory: DIR/tiles.json.
inline std::string tile_manifest_path(const std::string& dir) {
  return (std::filesystem::path(dir) / "tiles.json").string();
}

namespace detail {
/// The text of DIR/tiles.json; io_error "DIR/tiles.json: cannot open the tile manifest".
inline result<std::string> read_tile_manifest_text(const std::string& dir) {
  const std::string path = tile_manifest_path(dir);
  auto text = read_file(path);
  if (!text) return status::io_error(cat(path, ": cannot open the tile manifest"));
  return text;
}
/// The path of tile `t`'s file in DIR, or an io_error naming it when it is missing (`manifest`: the
/// manifest's path, for the message).
inline result<std::string> existing_tile_file(const std::string& dir, const tile_manifest_entry& t,
                                              const std::string& manifest) {
  const auto file = std::filesystem::path(dir) / t.file;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    return status::io_error(cat(file.string(), ": tile ", t.index, " listed in ", manifest, " is missing"));
  return file.string();
}
/// Writes manifest text to DIR/tiles.json, creating DIR if needed.
inline status write_tile_manifest_text(const std::string& dir, std::string_view text) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return write_file(tile_manifest_path(dir), text);
}
}  // namespace detail

/// Reads and validates DIR/tiles.json of a tile set of the given kind and checks that every listed
/// tile file exists. Errors: io_error naming DIR/tiles.json or the first missing tile file;
/// parse_error / invalid_argument from parse_tile_manifest. Thread-safe (reads only).
inline result<tile_manifest> read_tile_manifest(const std::string& dir, tile_set_kind kind = tile_set_kind::image) {
  auto text = detail::read_tile_manifest_text(dir);
  if (!text) return text.error();
  const std::string path = tile_manifest_path(dir);
  auto m = parse_tile_manifest(*text, path, kind);
  if (!m) return m.error();
  for (const auto& t : m->tiles)
    if (auto file = detail::existing_tile_file(dir, t, path); !file) return file.error();
  return m;
}

/// Validates `m` and writes it to DIR/tiles.json (creating DIR if needed). Errors: invalid manifest,
/// io_error naming the path.
inline status write_tile_manifest(const std::string& dir, const tile_manifest& m) {
  if (auto s = validate_tile_manifest(m, tile_manifest_path(dir)); !s) return s;
  return detail::write_tile_manifest_text(dir, format_tile_manifest(m));
}

TESSERA_NAMESPACE_END
