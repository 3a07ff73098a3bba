// tessera/io/off.hpp: OFF (Object File Format, as written by Geomview, CGAL, Meshlab) triangle
// meshes.
//   read_off(path) / parse_off(text, name)   -> result<tri_mesh>
//   write_off(path, mesh) / format_off(mesh) <- any Mesh (OFF has no per-corner uvs: not written)
// Reading accepts the header keywords OFF, COFF, NOFF, CNOFF, STOFF, STCOFF, ... (extra per-vertex
// values such as colours, normals and texture coordinates are ignored), the counts on the header
// line or the next one (`nv nf [ne]`), `#` comments, blank lines and any line endings. Each face is
// `n i0 .. i(n-1) [colour]` with 0-based indices; polygons are fan-triangulated. 4OFF / nOFF
// (other dimensions) and binary OFF are unsupported. Counts are checked against the file size
// before anything is allocated, and memory is reserved only for what the remaining bytes can hold. Errors: parse_error "PATH, line N: ...".
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "detail/file.hpp"

TESSERA_NAMESPACE_BEGIN

/// Parses OFF text into a tri_mesh (see the header comment). `name` names the text in error
/// messages. Errors: parse_error "NAME, line N: ..." (unsupported for 4OFF, nOFF, binary OFF).
/// O(size of text).
inline result<tri_mesh> parse_off(std::string_view text, std::string_view name = "off") {
  detail::line_scanner lines(text);
  std::string_view line, rest;
  // next_content: the next line holding something other than blanks and comments
  auto next_content = [&]() -> int {  // 1 found, 0 end of text, -1 binary bytes
    while (lines.next(line)) {
      if (detail::has_binary_bytes(line)) return -1;
      rest = detail::strip_comment(line);
      std::string_view probe = rest;
      if (!detail::next_token(probe).empty()) return 1;
    }
    return 0;
  };
  auto err = [&](std::string_view what) { return detail::parse_error_at_line(name, lines.line_number(), what); };
  int got = next_content();
  if (got < 0) return err("binary data: this is not a text OFF file");
  if (got == 0)
    return detail::parse_error_at_line(name, std::max<index_t>(1, lines.line_number()),
                                       "empty file: expected the OFF keyword");
  const std::string_view keyword = detail::next_token(rest);
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF")
    return err(detail::cat("expected the OFF keyword, got '", keyword, "'"));
  const std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  for (char c : prefix) {
    if (c == '4' || c == 'n')
      return status::unsupported(detail::cat(name, ": ", keyword, " (not 3D) is not supported"));
    if (c != 'S' && c != 'T' && c != 'C' && c != 'N')
      return err(detail::cat("expected the OFF keyword, got '", keyword, "'"));
  }
  std::string_view counts = rest;
  std::string_view probe = counts;
  const std::string_view first = detail::next_token(probe);
  if (first == "BINARY") return status::unsupported(detail::cat(name, ": binary OFF is not supported"));
  if (first.empty()) {  // counts on the next line
    got = next_content();
    if (got <= 0) return err(got < 0 ? "binary data in the header" : "truncated: missing the vertex and face counts");
    counts = rest;
  }
  long long nv = -1, nf = -1, ne = 0;
  const auto t0 = detail::next_token(counts), t1 = detail::next_token(counts), t2 = detail::next_token(counts);
  if (!detail::parse_int(t0, nv) || !detail::parse_int(t1, nf) || (!t2.empty() && !detail::parse_int(t2, ne)) ||
      nv < 0 || nf < 0)
    return err("expected the counts 'vertices faces [edges]' as non-negative integers");
  // every vertex line holds at least "0 0 0\n", every face line "3 0 1 2\n"
  const double least = 6.0 * double(nv) + 8.0 * double(nf) - 1.0;
  if (least > double(lines.remaining()))
    return err(detail::cat("truncated or corrupt: the header declares ", nv, " vertices and ", nf, " faces but only ",
                           lines.remaining(), " bytes follow"));
  tri_mesh m;
  m.positions.reserve(detail::bounded_reserve(nv, lines.remaining(), 6));
  m.faces.reserve(detail::bounded_reserve(nf, lines.remaining(), 8));
  for (long long v = 0; v < nv; ++v) {
    got = next_content();
    if (got <= 0)
      return err(got < 0 ? "binary data: this is not a text OFF file"
                         : detail::cat("truncated: expected ", nv, " vertices, the file ends after ", v));
    vec3 p;
    for (int k = 0; k < 3; ++k) {
      const auto tok = detail::next_token(rest);
      if (tok.empty()) return err(detail::cat("vertex ", v, " needs three coordinates"));
      if (!detail::parse_double(tok, p[k]))
        return err(detail::cat("vertex ", v, " coordinate '", tok, "' is not a finite number"));
    }
    m.positions.push_back(p);
  }
  std::vector<index_t> corners;
  for (long long f = 0; f < nf; ++f) {
    got = next_content();
    if (got <= 0)
      return err(got < 0 ? "binary data: this is not a text OFF file"
                         : detail::cat("truncated: expected ", nf, " faces, the file ends after ", f));
    long long n = 0;
    const auto ntok = detail::next_token(rest);
    if (!detail::parse_int(ntok, n) || n < 3)
      return err(detail::cat("face ", f, " must start with its corner count (at least 3), got '", ntok, "'"));
    corners.clear();
    for (long long k = 0; k < n; ++k) {
      const auto tok = detail::next_token(rest);
      long long i = -1;
      if (tok.empty()) return err(detail::cat("face ", f, " declares ", n, " corners but lists ", k));
      if (!detail::parse_int(tok, i) || i < 0 || i >= nv)
        return err(detail::cat("face ", f, " refers to vertex '", tok, "', outside 0..", nv - 1));
      corners.push_back(static_cast<index_t>(i));
    }
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
      const index_t a = corners[0], b = corners[i], c = corners[i + 1];
      if (a == b || b == c || a == c)
        return err(detail::cat("face ", f, " is degenerate: it repeats vertex ", (a == b || a == c) ? a : b));
      m.faces.push_back({a, b, c});
    }
  }
  return m;
}

/// Reads an OFF file (see parse_off). io_error when it cannot be read.
inline result<tri_mesh> read_off(const std::string& path) {
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_off(*text, path);
}

/// Formats any valid Mesh as OFF text (shortest exact decimals; uvs are not representable and are
/// dropped). Precondition: validate_mesh(m) passed (write_off checks it). O(V + F).
template <Mesh M>
std::string format_off(const M& m) {
  const index_t nv = tessera::num_vertices(m), nf = tessera::num_faces(m);
  std::string out = "OFF\n";
  out.reserve(detail::to_size(40 * nv + 24 * nf + 32));
  detail::append_number(out, nv);
  out += ' ';
  detail::append_number(out, nf);
  out += " 0\n";
  for (index_t v = 0; v < nv; ++v) {
    const vec3 p = tessera::vertex_position(m, v);
    detail::append_number(out, p.x);
    out += ' ';
    detail::append_number(out, p.y);
    out += ' ';
    detail::append_number(out, p.z);
    out += '\n';
  }
  for (index_t f = 0; f < nf; ++f) {
    out += '3';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      detail::append_number(out, tessera::face_vertex(m, f, k));
    }
    out += '\n';
  }
  return out;
}

/// Validates any Mesh and writes it as an OFF file. Errors: the validate_mesh status (naming the
/// path), io_error when the file cannot be written.
template <Mesh M>
status write_off(const std::string& path, const M& m) {
  if (auto s = validate_mesh(m, path); !s) return s;
  return detail::write_file(path, format_off(m));
}

TESSERA_NAMESPACE_END
