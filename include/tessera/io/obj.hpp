// tessera/io/obj.hpp: Wavefront OBJ triangle meshes.
//   read_obj(path) / parse_obj(text, name)   -> result<tri_mesh>
//   write_obj(path, mesh) / format_obj(mesh) <- any Mesh (per-corner uvs written when present)
//   write_textured_obj(path, mesh, texture)  <- OBJ + MTL (map_Kd naming the texture) beside it
// Reading understands `v x y z [w | r g b ...]` (extra values ignored), `vt u [v [w]]`,
// `f v`, `f v/vt`, `f v//vn`, `f v/vt/vn` with positive or negative (relative) indices, comments,
// blank lines, LF / CRLF / CR endings and `\` line continuations. Polygons with more than three
// corners are fan-triangulated (corner 0, i, i + 1). Other statements (vn, o, g, s, usemtl, mtllib,
// l, p, ...) are skipped. When some faces have texture coordinates, faces without them get uv (0, 0).
// A successful read returns a mesh that passes validate_mesh: an index out of range or 0, a face
// repeating a vertex, a non-finite or malformed number, fewer than three corners, corners that mix
// with and without `vt`, or binary bytes are parse_errors "PATH, line N: ...".
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "detail/file.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// Resolves an OBJ index token (1-based, or negative = relative to the `count` elements so far).
inline bool obj_index(std::string_view tok, index_t count, index_t& out) {
  long long i = 0;
  if (!parse_int(tok, i) || i == 0) return false;
  out = i > 0 ? static_cast<index_t>(i - 1) : count + static_cast<index_t>(i);
  return out >= 0 && out < count;
}
}  // namespace detail

/// Parses OBJ text into a tri_mesh (see the header comment for what is understood). `name` names
/// the text in error messages. Errors: parse_error "NAME, line N: ...". O(size of text).
inline result<tri_mesh> parse_obj(std::string_view text, std::string_view name = "obj") {
  tri_mesh m;
  std::vector<vec2> texcoords;
  std::vector<std::array<vec2, 3>> face_uvs;
  bool any_uv = false;
  std::vector<index_t> corner_v, corner_t;
  std::string joined;
  detail::line_scanner lines(text);
  std::string_view line;
  while (lines.next(line)) {
    const index_t line_no = lines.line_number();
    auto err = [&](std::string_view what) { return detail::parse_error_at_line(name, line_no, what); };
    if (!line.empty() && line.back() == '\\') {  // continuation: join with the following lines
      joined.assign(line.substr(0, line.size() - 1));
      std::string_view more;
      while (lines.next(more)) {
        const bool again = !more.empty() && more.back() == '\\';
        joined += ' ';
        joined.append(more.substr(0, more.size() - (again ? 1 : 0)));
        if (!again) break;
      }
      line = joined;
    }
    if (detail::has_binary_bytes(line)) return err("binary data: this is not a text OBJ file");
    std::string_view rest = detail::strip_comment(line);
    const std::string_view key = detail::next_token(rest);
    if (key == "v") {
      vec3 p;
      for (int k = 0; k < 3; ++k) {
        const auto tok = detail::next_token(rest);
        if (tok.empty()) return err("a vertex needs three coordinates");
        if (!detail::parse_double(tok, p[k]))
          return err(detail::cat("vertex coordinate '", tok, "' is not a finite number"));
      }
      m.positions.push_back(p);
    } else if (key == "vt") {
      vec2 t;
      const auto u = detail::next_token(rest), v = detail::next_token(rest);
      if (u.empty()) return err("a texture coordinate needs at least one value");
      if (!detail::parse_double(u, t.x) || (!v.empty() && !detail::parse_double(v, t.y)))
        return err(detail::cat("texture coordinate '", line, "' holds a value that is not a finite number"));
      texcoords.push_back(t);
    } else if (key == "f") {
      corner_v.clear();
      corner_t.clear();
      for (auto tok = detail::next_token(rest); !tok.empty(); tok = detail::next_token(rest)) {
        const std::size_t s1 = tok.find('/');
        const std::string_view vtok = tok.substr(0, s1);
        index_t v = 0;
        if (!detail::obj_index(vtok, m.num_vertices(), v))
          return err(detail::cat("face corner '", tok, "' refers to a vertex outside 1..", m.num_vertices(),
                                 " (or -1..-", m.num_vertices(), ")"));
        corner_v.push_back(v);
        if (s1 != std::string_view::npos) {
          const std::string_view after = tok.substr(s1 + 1);
          const std::string_view ttok = after.substr(0, after.find('/'));
          if (!ttok.empty()) {
            index_t t = 0;
            if (!detail::obj_index(ttok, static_cast<index_t>(texcoords.size()), t))
              return err(
                  detail::cat("face corner '", tok, "' refers to a texture coordinate outside 1..", texcoords.size()));
            corner_t.push_back(t);
          }
        }
      }
      if (corner_v.size() < 3) return err(detail::cat("a face needs at least three corners, got ", corner_v.size()));
      if (!corner_t.empty() && corner_t.size() != corner_v.size())
        return err("face mixes corners with and without texture coordinates");
      any_uv |= !corner_t.empty();
      for (std::size_t i = 1; i + 1 < corner_v.size(); ++i) {  // fan triangulation
        const index_t a = corner_v[0], b = corner_v[i], c = corner_v[i + 1];
        if (a == b || b == c || a == c)
          return err(detail::cat("degenerate face: it repeats vertex ", (a == b || a == c) ? a + 1 : b + 1));
        m.faces.push_back({a, b, c});
        if (corner_t.empty())
          face_uvs.push_back({});
        else
          face_uvs.push_back({texcoords[detail::to_size(corner_t[0])], texcoords[detail::to_size(corner_t[i])],
                              texcoords[detail::to_size(corner_t[i + 1])]});
      }
    }
    // everything else (vn, vp, o, g, s, usemtl, mtllib, l, p, curves...) is skipped
  }
  if (any_uv) m.uvs = std::move(face_uvs);
  return m;
}

/// Reads an OBJ file (see parse_obj). io_error when it cannot be read; parse_error "PATH, line N:
/// ..." when it is malformed.
inline result<tri_mesh> read_obj(const std::string& path) {
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_obj(*text, path);
}

namespace detail {
/// format_obj, with `mtllib LIB` before the vertices and `usemtl MAT` before the faces when given.
template <Mesh M>
std::string format_obj_with(const M& m, std::string_view mtllib, std::string_view material) {
  const index_t nv = tessera::num_vertices(m), nf = tessera::num_faces(m);
  std::string out;
  out.reserve(detail::to_size(40 * nv + 30 * nf + 64));
  out += "# written by tessera: ";
  detail::append_number(out, nv);
  out += " vertices, ";
  detail::append_number(out, nf);
  out += " triangles\n";
  if (!mtllib.empty()) out += detail::cat("mtllib ", mtllib, "\n");
  for (index_t v = 0; v < nv; ++v) {
    const vec3 p = tessera::vertex_position(m, v);
    out += "v ";
    detail::append_number(out, p.x);
    out += ' ';
    detail::append_number(out, p.y);
    out += ' ';
    detail::append_number(out, p.z);
    out += '\n';
  }
  std::vector<index_t> uv_id;  // per corner
  if (tessera::has_uvs(m)) {
    if constexpr (UVMesh<M>) {
      struct key_hash {
        std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const noexcept {
          return detail::to_size(k.first * 0x9e3779b97f4a7c15ULL ^ (k.second + 0x632be59bd9b4e019ULL));
        }
      };
      std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, index_t, key_hash> ids;
      uv_id.resize(detail::to_size(3 * nf));
      for (index_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) {
          const vec2 t = tessera::corner_uv(m, f, k);
          std::pair<std::uint64_t, std::uint64_t> key;
          std::memcpy(&key.first, &t.x, 8);
          std::memcpy(&key.second, &t.y, 8);
          auto [it, fresh] = ids.emplace(key, static_cast<index_t>(ids.size()));
          if (fresh) {
            out += "vt ";
            detail::append_number(out, t.x);
            out += ' ';
            detail::append_number(out, t.y);
            out += '\n';
          }
          uv_id[detail::to_size(3 * f + k)] = it->second;
        }
    }
  }
  if (!material.empty()) out += detail::cat("usemtl ", material, "\n");
  for (index_t f = 0; f < nf; ++f) {
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      detail::append_number(out, tessera::face_vertex(m, f, k) + 1);
      if (!uv_id.empty()) {
        out += '/';
        detail::append_number(out, uv_id[detail::to_size(3 * f + k)] + 1);
      }
    }
    out += '\n';
  }
  return out;
}
}  // namespace detail

/// Formats any valid Mesh as OBJ text: `v` lines with the shortest exact decimal of each
/// coordinate, `vt` lines (identical uvs shared) when the mesh has uvs, and 1-based `f` lines.
/// Precondition: validate_mesh(m) passed (write_obj checks it). O(V + F).
template <Mesh M>
std::string format_obj(const M& m) {
  return detail::format_obj_with(m, {}, {});
}

/// Validates any Mesh and writes it as an OBJ file (see format_obj). Errors: the validate_mesh
/// status (naming the path) for an invalid mesh, io_error when the file cannot be written.
template <Mesh M>
status write_obj(const std::string& path, const M& m) {
  if (auto s = validate_mesh(m, path); !s) return s;
  return detail::write_file(path, format_obj(m));
}

/// Writes a textured OBJ: `path` (a mesh with per-corner uvs, see format_obj, plus `mtllib` and
/// `usemtl tessera`) and its material library beside it (`path` with the extension .mtl) whose one
/// material "tessera" shows the image `texture` through `map_Kd` (a file name relative to the OBJ,
/// e.g. an atlas PNG written beside it). Errors: the validate_mesh status (naming the path), a mesh
/// without uvs, an empty texture name or one with a line break, io_error when a file cannot be written.
template <Mesh M>
status write_textured_obj(const std::string& path, const M& m, const std::string& texture) {
  if (auto s = validate_mesh(m, path); !s) return s;
  if (!tessera::has_uvs(m))
    return status::invalid_argument(detail::cat(path, ": a textured OBJ needs a mesh with per-corner uvs"));
  if (texture.empty() || texture.find_first_of("\r\n") != std::string::npos)
    return status::invalid_argument(detail::cat(path, ": the texture name must be one non-empty line"));
  const std::filesystem::path obj(path);
  std::filesystem::path mtl = obj;
  mtl.replace_extension(".mtl");
  const std::string lib = mtl.filename().string();
  if (auto s = detail::write_file(mtl.string(), detail::cat("# written by tessera\nnewmtl tessera\nKa 1 1 1\nKd 1 1 "
                                                            "1\nKs 0 0 0\nillum 1\nmap_Kd ",
                                                            texture, "\n"));
      !s)
    return s;
  return detail::write_file(path, detail::format_obj_with(m, lib, "tessera"));
}

TESSERA_NAMESPACE_END
