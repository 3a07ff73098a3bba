// tessera/io/ply.hpp: PLY (Stanford polygon file) triangle meshes, ASCII and binary.
//   read_ply(path) / parse_ply(bytes, name)        -> result<tri_mesh>
//   write_ply(path, mesh, {.binary = true}) / format_ply(mesh, options) <- any Mesh
// Reading: ascii, binary_little_endian and binary_big_endian; vertex x, y, z of any scalar type
// (char .. double); faces as a list `vertex_indices` (or `vertex_index`) with any integer count and
// index types; polygons are fan-triangulated. Texture coordinates come from a face list `texcoord`
// (2 values per corner, MeshLab's convention) or else per-vertex u/v, s/t, texture_u/texture_v.
// Other elements and properties are skipped. Element counts and list lengths are checked against
// the bytes that remain before anything is allocated. A successful read passes validate_mesh;
// errors are parse_errors naming the file and the line (ASCII) or byte offset (binary).
// Writing: double x, y, z; `list uchar int vertex_indices`; `list uchar float texcoord` when the
// mesh has uvs (`double` when a uv lies beyond float range, so every written file reads back).
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "detail/file.hpp"
#include "detail/ply_format.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
template <class Source>
status read_ply_elements(const ply_header& h, Source& src, std::string_view name, tri_mesh& m) {
  const ply_element* vertex = nullptr;
  for (const ply_element& e : h.elements)
    if (e.name == "vertex") vertex = &e;
  const index_t nv = vertex != nullptr ? vertex->count : 0;
  std::vector<vec2> vertex_uv;
  std::vector<std::array<vec2, 3>> face_uv;
  bool have_face_uv = false, have_vertex_uv = false;
  std::vector<double> list;
  std::vector<index_t> corners;
  for (const ply_element& e : h.elements) {
    std::size_t least = 0;  // bytes one element occupies at the very least
    for (const ply_property& p : e.properties)
      least += Source::min_value_bytes(p.is_list ? p.count_type : p.value_type);
    if (least > 0 && to_size(e.count) > (src.remaining() + 1) / least) {  // +1: no final newline
      const std::string msg = cat("truncated or corrupt: the header (line ", e.header_line, ") declares ", e.count,
                                  " '", e.name, "' elements but only ", src.remaining(), " bytes of data follow");
      if constexpr (std::is_same_v<Source, ply_binary_source>)
        return src.error_ahead(msg);
      else
        return parse_error_at_line(name, e.header_line, msg);
    }
    const bool is_vertex = &e == vertex, is_face = e.name == "face";
    int xyz[3] = {-1, -1, -1}, uv[2] = {-1, -1}, indices = -1, texcoord = -1;
    if (is_vertex) {
      static constexpr std::string_view axes[3] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) xyz[k] = e.find(axes[k]);
      static constexpr std::string_view uv_names[4][2] = {
          {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
      for (const auto& n : uv_names)
        if (uv[0] < 0 && e.find(n[0]) >= 0 && e.find(n[1]) >= 0) {
          uv[0] = e.find(n[0]);
          uv[1] = e.find(n[1]);
        }
      for (int k = 0; k < 3; ++k)
        if (xyz[k] < 0 || e.properties[to_size(xyz[k])].is_list)
          return parse_error_at_line(name, e.header_line, "the vertex element needs scalar properties x, y and z");
      have_vertex_uv = uv[0] >= 0 && !e.properties[to_size(uv[0])].is_list && !e.properties[to_size(uv[1])].is_list;
      const std::size_t n = bounded_reserve(e.count, src.remaining(), least);
      m.positions.reserve(n);
      if (have_vertex_uv) vertex_uv.reserve(n);
    } else if (is_face) {
      indices = e.find("vertex_indices") >= 0 ? e.find("vertex_indices") : e.find("vertex_index");
      texcoord = e.find("texcoord");
      if (indices < 0 || !e.properties[to_size(indices)].is_list)
        return parse_error_at_line(name, e.header_line, "the face element needs a list property vertex_indices");
      if (e.count > 0 && vertex == nullptr)
        return parse_error_at_line(name, e.header_line, "faces without a vertex element");
      if (texcoord >= 0 && !e.properties[to_size(texcoord)].is_list) texcoord = -1;
      have_face_uv = texcoord >= 0;
      // a triangle holds its count and three indices at the very least
      const ply_property& ip = e.properties[to_size(indices)];
      m.faces.reserve(bounded_reserve(e.count, src.remaining(), least + 3 * Source::min_value_bytes(ip.value_type)));
    }
    if (e.properties.empty()) continue;  // holds no data, however many it declares (no 2^63-step loop)
    std::vector<vec2> corner_uv;
    for (index_t i = 0; i < e.count; ++i) {
      auto where = [&] { return cat("element '", e.name, "' ", i); };  // built only for messages
      vec3 p;
      vec2 t;
      corners.clear();
      corner_uv.clear();
      for (int j = 0; j < static_cast<int>(e.properties.size()); ++j) {
        const ply_property& prop = e.properties[to_size(j)];
        double value = 0;
        if (!prop.is_list) {
          if (!src.read(prop.value_type, value)) return src.error_status(where());
          for (int k = 0; k < 3; ++k)
            if (j == xyz[k]) p[k] = value;
          if (j == uv[0]) t.x = value;
          if (j == uv[1]) t.y = value;
          continue;
        }
        if (!src.read(prop.count_type, value)) return src.error_status(where());
        if (value < 0) return src.error_here(cat(where(), ": negative list length ", value));
        const auto count = to_size(value);
        if (count > (src.remaining() + 1) / Source::min_value_bytes(prop.value_type))
          return src.error_here(cat(where(), ": a list of ", count, " values does not fit in the ", src.remaining(),
                                    " bytes that follow"));
        list.clear();
        for (std::size_t k = 0; k < count; ++k) {
          if (!src.read(prop.value_type, value)) return src.error_status(where());
          list.push_back(value);
        }
        if (j == indices) {
          for (double d : list) {
            if (!(d >= 0 && d < static_cast<double>(nv)) || d != static_cast<double>(static_cast<index_t>(d)))
              return src.error_here(cat(where(), ": vertex index ", d, " outside 0..", nv - 1));
            corners.push_back(static_cast<index_t>(d));
          }
          if (corners.size() < 3)
            return src.error_here(cat(where(), ": a face needs at least 3 corners, got ", corners.size()));
        } else if (j == texcoord) {
          for (std::size_t k = 0; k + 1 < list.size(); k += 2) corner_uv.push_back({list[k], list[k + 1]});
          if (list.size() % 2 != 0) return src.error_here(cat(where(), ": texcoord holds an odd number of values"));
        }
      }
      if (is_vertex) {
        m.positions.push_back(p);
        if (have_vertex_uv) vertex_uv.push_back(t);
      } else if (is_face) {
        if (texcoord >= 0 && corner_uv.size() != corners.size())
          return src.error_here(
              cat(where(), ": texcoord has ", corner_uv.size(), " uv pairs for ", corners.size(), " corners"));
        for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
          const index_t a = corners[0], b = corners[k], c = corners[k + 1];
          if (a == b || b == c || a == c)
            return src.error_here(cat(where(), ": degenerate face repeating vertex ", (a == b || a == c) ? a : b));
          m.faces.push_back({a, b, c});
          if (texcoord >= 0) face_uv.push_back({corner_uv[0], corner_uv[k], corner_uv[k + 1]});
        }
      }
    }
  }
  if (have_face_uv) {
    m.uvs = std::move(face_uv);
  } else if (have_vertex_uv) {
    m.uvs.resize(m.faces.size());
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      for (int k = 0; k < 3; ++k) m.uvs[f][to_size(k)] = vertex_uv[to_size(m.faces[f][to_size(k)])];
  }
  return {};
}

template <class T>
void put_binary(std::string& out, T v, bool big) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof v);
  if (big != (std::endian::native == std::endian::big))
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(b), sizeof b);
}
}  // namespace detail

/// Parses PLY file contents into a tri_mesh (see the header comment). `name` names the data in
/// error messages. Errors: parse_error "NAME, line N: ..." (header, ASCII data) or "NAME, byte N:
/// ..." (binary data). O(size of data).
inline result<tri_mesh> parse_ply(std::string_view data, std::string_view name = "ply") {
  auto h = detail::parse_ply_header(data, name);
  if (!h) return h.error();
  tri_mesh m;
  status s;
  if (h->encoding == detail::ply_encoding::ascii) {
    detail::ply_ascii_source src(data.substr(h->data_offset), h->data_line, name);
    s = detail::read_ply_elements(*h, src, name, m);
  } else {
    detail::ply_binary_source src(data, h->data_offset, h->encoding == detail::ply_encoding::binary_big_endian, name);
    s = detail::read_ply_elements(*h, src, name, m);
  }
  if (!s) return s;
  if (auto v = validate_mesh(m, name); !v) return v;  // the promise of the header comment, checked once
  return m;
}

/// Reads a PLY file (see parse_ply). io_error when it cannot be read.
inline result<tri_mesh> read_ply(const std::string& path) {
  auto data = detail::read_file(path);
  if (!data) return data.error();
  return parse_ply(*data, path);
}

/// Options of write_ply.
struct ply_write_options {
  bool binary = false;      ///< binary instead of ASCII
  bool big_endian = false;  ///< binary_big_endian instead of binary_little_endian (binary only)
};

/// Formats any valid Mesh as PLY file contents. Precondition: validate_mesh(m) passed and fewer
/// than 2^31 vertices (write_ply checks both). O(V + F).
template <Mesh M>
std::string format_ply(const M& m, const ply_write_options& opts = {}) {
  const index_t nv = tessera::num_vertices(m), nf = tessera::num_faces(m);
  const bool uvs = tessera::has_uvs(m), big = opts.big_endian;
  std::string out = "ply\nformat ";
  out += !opts.binary ? "ascii" : big ? "binary_big_endian" : "binary_little_endian";
  out += " 1.0\ncomment written by tessera\nelement vertex ";
  detail::append_number(out, nv);
  out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  detail::append_number(out, nf);
  out += "\nproperty list uchar int vertex_indices\n";
  // uvs as float, or as double when one lies beyond float range (a float would store inf, which no
  // reader accepts: whatever is written must read back)
  bool double_uvs = false;
  if constexpr (UVMesh<M>) {
    for (index_t f = 0; uvs && f < nf && !double_uvs; ++f)
      for (int k = 0; k < 3; ++k) {
        const vec2 t = tessera::corner_uv(m, f, k);
        if (!(std::fabs(t.x) <= std::numeric_limits<float>::max() &&
              std::fabs(t.y) <= std::numeric_limits<float>::max()))
          double_uvs = true;
      }
  }
  if (uvs) out += double_uvs ? "property list uchar double texcoord\n" : "property list uchar float texcoord\n";
  out += "end_header\n";
  out.reserve(out.size() + detail::to_size(opts.binary ? 24 * nv + 13 * nf + (uvs ? 25 * nf : 0)
                                                       : 40 * nv + 24 * nf + (uvs ? 60 * nf : 0)));
  for (index_t v = 0; v < nv; ++v) {
    const vec3 p = tessera::vertex_position(m, v);
    for (int k = 0; k < 3; ++k) {
      if (opts.binary) {
        detail::put_binary(out, p[k], big);
      } else {
        detail::append_number(out, p[k]);
        out += k < 2 ? ' ' : '\n';
      }
    }
  }
  for (index_t f = 0; f < nf; ++f) {
    if (opts.binary) {
      out += '\3';
      for (int k = 0; k < 3; ++k)
        detail::put_binary(out, static_cast<std::int32_t>(tessera::face_vertex(m, f, k)), big);
    } else {
      out += '3';
      for (int k = 0; k < 3; ++k) {
        out += ' ';
        detail::append_number(out, tessera::face_vertex(m, f, k));
      }
    }
    if constexpr (UVMesh<M>) {
      if (uvs) {
        if (opts.binary)
          out += '\6';
        else
          out += " 6";
        for (int k = 0; k < 3; ++k) {
          const vec2 t = tessera::corner_uv(m, f, k);
          for (double c : {t.x, t.y}) {
            if (opts.binary) {
              if (double_uvs)
                detail::put_binary(out, c, big);
              else
                detail::put_binary(out, static_cast<float>(c), big);
            } else {
              out += ' ';
              if (double_uvs)
                detail::append_number(out, c);
              else
                detail::append_number(out, static_cast<float>(c));
            }
          }
        }
      }
    }
    if (!opts.binary) out += '\n';
  }
  return out;
}

/// Validates any Mesh and writes it as a PLY file (ASCII by default; `.binary = true` for binary
/// little-endian). Errors: the validate_mesh status (naming the path), size_overflow for 2^31 or more
/// vertices (32-bit PLY indices), io_error when the file cannot be written.
template <Mesh M>
status write_ply(const std::string& path, const M& m, const ply_write_options& opts = {}) {
  if (auto s = validate_mesh(m, path); !s) return s;
  if (tessera::num_vertices(m) > std::numeric_limits<std::int32_t>::max())
    return status::size_overflow(
        detail::cat(path, ": ", tessera::num_vertices(m), " vertices exceed PLY's 32-bit indices"));
  return detail::write_file(path, format_ply(m, opts));
}

TESSERA_NAMESPACE_END
