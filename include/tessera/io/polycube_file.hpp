// tessera/io/polycube_file.hpp: polycube maps (surface/polycube_map.hpp) and per-face label lists as text
// files. A polycube file holds the tile size, the base mesh, the polycube position of every vertex and
// the label of every face:
//
//   tessera-polycube 1
//   tile <tile_size>
//   counts <V> <F>
//   v <x> <y> <z> <px> <py> <pz>      (V lines: base and polycube position)
//   f <a> <b> <c> <label> [<origin>]  (F lines: vertex indices, label 0..5, and for a refined base
//                                      the input face it is part of: polycube_map::face_origin)
//
// Loading re-derives charts, corners, edges and the quad layout and re-verifies the polycube
// (polycube_map_from_deformed), so a loaded map is as valid as a built one. A labels file holds one
// integer 0..5 per line ('#' comments allowed). No extra library needed.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../surface/build_polycube_map.hpp"
#include "../surface/polycube_map.hpp"
#include "detail/file.hpp"

TESSERA_NAMESPACE_BEGIN

/// Writes `map` to `path` (format above). Errors: io_error naming the path. Numbers round-trip exactly.
inline status save_polycube_map(const std::string& path, const polycube_map& map) {
  std::string s = "tessera-polycube 1\ntile ";
  detail::append_number(s, map.tile_size);
  s += "\ncounts ";
  detail::append_number(s, map.base.num_vertices());
  s += ' ';
  detail::append_number(s, map.base.num_faces());
  s += '\n';
  for (index_t v = 0; v < map.base.num_vertices(); ++v) {
    s += 'v';
    for (const vec3& p : {map.base.position(v), map.polycube[detail::to_size(v)]})
      for (int a = 0; a < 3; ++a) {
        s += ' ';
        detail::append_number(s, p[a]);
      }
    s += '\n';
  }
  for (index_t f = 0; f < map.base.num_faces(); ++f) {
    s += 'f';
    for (index_t v : map.base.faces[detail::to_size(f)]) {
      s += ' ';
      detail::append_number(s, v);
    }
    s += ' ';
    detail::append_number(s, static_cast<int>(map.labels[detail::to_size(f)]));
    if (map.refined()) {
      s += ' ';
      detail::append_number(s, map.face_origin[detail::to_size(f)]);
    }
    s += '\n';
  }
  return detail::write_file(path, s);
}

/// Reads a polycube file and re-verifies it. Errors: io_error naming the path; parse_error naming the
/// line; the statuses of polycube_map_from_deformed (invalid_argument, not_converged) when the stored
/// polycube is not valid; invalid_argument when a stored label differs from the polycube's face normal.
inline result<polycube_map> load_polycube_map(const std::string& path) {
  auto text = detail::read_file(path);
  if (!text) return text.error();
  detail::line_scanner sc(*text);
  std::string_view line;
  auto next = [&](std::string_view& l) {
    while (sc.next(l)) {
      l = detail::strip_comment(l);
      std::string_view probe = l;
      if (!detail::next_token(probe).empty()) return true;
    }
    return false;
  };
  if (!next(line) || line.substr(0, 18) != "tessera-polycube 1")
    return status::parse_error(detail::cat(path, ": not a tessera-polycube 1 file"));
  double tile = 0;
  index_t nv = 0, nf = 0;
  if (!next(line) || detail::next_token(line) != "tile" || !detail::parse_double(detail::next_token(line), tile))
    return detail::parse_error_at_line(path, sc.line_number(), "expected 'tile <size>'");
  if (!next(line) || detail::next_token(line) != "counts" || !detail::parse_int(detail::next_token(line), nv) ||
      !detail::parse_int(detail::next_token(line), nf) || nv < 0 || nf < 0)
    return detail::parse_error_at_line(path, sc.line_number(), "expected 'counts <V> <F>'");
  // every v or f line takes at least 8 bytes: counts larger than the file allows are rejected before
  // anything is allocated
  if (static_cast<double>(nv) + static_cast<double>(nf) > static_cast<double>(sc.remaining()) / 8 + 1)
    return detail::parse_error_at_line(path, sc.line_number(), "counts exceed what the file holds");
  tri_mesh base, deformed;
  std::vector<std::uint8_t> labels;
  std::vector<index_t> origin;
  base.positions.reserve(detail::to_size(nv));
  deformed.positions.reserve(detail::to_size(nv));
  for (index_t v = 0; v < nv; ++v) {
    if (!next(line) || detail::next_token(line) != "v")
      return detail::parse_error_at_line(path, sc.line_number(), "expected a 'v' line");
    double x[6];
    for (double& c : x)
      if (!detail::parse_double(detail::next_token(line), c))
        return detail::parse_error_at_line(path, sc.line_number(), "expected six finite numbers");
    base.add_vertex({x[0], x[1], x[2]});
    deformed.add_vertex({x[3], x[4], x[5]});
  }
  for (index_t f = 0; f < nf; ++f) {
    if (!next(line) || detail::next_token(line) != "f")
      return detail::parse_error_at_line(path, sc.line_number(), "expected an 'f' line");
    index_t i[3];
    int l = 0;
    for (index_t& c : i)
      if (!detail::parse_int(detail::next_token(line), c))
        return detail::parse_error_at_line(path, sc.line_number(), "expected three vertex indices");
    if (!detail::parse_int(detail::next_token(line), l) || l < 0 || l > 5)
      return detail::parse_error_at_line(path, sc.line_number(), "expected a label 0..5");
    // the input face of a refined base: on every f line or on none, each within 0..f
    const auto o_tok = detail::next_token(line);
    index_t o = -1;
    if (!o_tok.empty() && (!detail::parse_int(o_tok, o) || o < 0 || o > f))
      return detail::parse_error_at_line(path, sc.line_number(), "expected the input face 0..f of a refined face");
    if ((o >= 0) != (f == 0 ? o >= 0 : !origin.empty()))
      return detail::parse_error_at_line(path, sc.line_number(), "an input face on some 'f' lines only");
    if (o >= 0) origin.push_back(o);
    base.add_face(i[0], i[1], i[2]);
    deformed.add_face(i[0], i[1], i[2]);
    labels.push_back(static_cast<std::uint8_t>(l));
  }
  auto map = polycube_map_from_deformed(base, deformed, tile);
  if (!map) return map.error();
  for (std::size_t f = 0; f < labels.size(); ++f)
    if (static_cast<int>(map->labels[f]) != labels[f])
      return status::invalid_argument(detail::cat(path, ": face ", f, " is stored with label ", int(labels[f]),
                                                  " but its polycube normal gives ", int(map->labels[f])));
  map->face_origin = std::move(origin);
  return map;
}

/// Writes one label (0..5) per line. Errors: io_error naming the path.
inline status write_polycube_labels(const std::string& path, const std::vector<polycube_label>& labels) {
  std::string s;
  s.reserve(labels.size() * 2);
  for (polycube_label l : labels) {
    s += static_cast<char>('0' + static_cast<int>(l));
    s += '\n';
  }
  return detail::write_file(path, s);
}

/// Reads a labels file: one integer per non-empty line. Values are checked (0..5) and their count
/// against the mesh by build_polycube_map_from_labels; here only that each line is an integer in 0..5.
/// Errors: io_error naming the path, parse_error naming the line.
inline result<std::vector<std::uint8_t>> read_polycube_labels(const std::string& path) {
  auto text = detail::read_file(path);
  if (!text) return text.error();
  detail::line_scanner sc(*text);
  std::string_view line;
  std::vector<std::uint8_t> out;
  while (sc.next(line)) {
    line = detail::strip_comment(line);
    const std::string_view tok = detail::next_token(line);
    if (tok.empty()) continue;
    int l = -1;
    if (!detail::parse_int(tok, l) || l < 0 || l > 5 || !detail::next_token(line).empty())
      return detail::parse_error_at_line(path, sc.line_number(),
                                         detail::cat("expected one label 0..5, got '", tok, "'"));
    out.push_back(static_cast<std::uint8_t>(l));
  }
  return out;
}

TESSERA_NAMESPACE_END
