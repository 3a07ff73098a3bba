#include <tessera/io/ply.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/core/random.hpp>

#include "mesh_samples.hpp"

using tessera::index_t;
using tessera::status_code;
using tessera::tri_mesh;
using tessera::vec2;
using tessera::vec3;

namespace {
// Builds PLY bodies value by value in any of the three encodings.
struct body {
  bool binary = false, big = false;
  std::string out;
  template <class T>
  body& put(T v) {
    if (binary) {
      tessera::detail::put_binary(out, v, big);
    } else {
      if constexpr (sizeof(T) == 1 && std::is_integral_v<T>)
        tessera::detail::append_number(out, int(v));
      else
        tessera::detail::append_number(out, v);
      out += ' ';
    }
    return *this;
  }
  body& endl() {
    if (!binary) out += '\n';
    return *this;
  }
};
std::string format_line(bool binary, bool big) {
  return std::string("format ") + (!binary ? "ascii" : big ? "binary_big_endian" : "binary_little_endian") + " 1.0\n";
}
struct encoding {
  bool binary, big;
  const char* name;
};
constexpr encoding encodings[3] = {{false, false, "ascii"}, {true, false, "binary LE"}, {true, true, "binary BE"}};
}  // namespace

TEST_CASE("ply: round trips in every encoding, with and without uvs", "[ply]") {
  for (const encoding& e : encodings)
    for (bool uvs : {false, true}) {
      INFO(e.name << (uvs ? " with uvs" : ""));
      const tri_mesh m = samples::grid(3, 2, uvs);
      const std::string path = samples::out_path(std::string("grid_") + (e.binary ? (e.big ? "be" : "le") : "ascii") +
                                                 (uvs ? "_uv" : "") + ".ply");
      REQUIRE(tessera::write_ply(path, m, {.binary = e.binary, .big_endian = e.big}).ok());
      const auto back = tessera::read_ply(path);
      REQUIRE(back.ok());
      REQUIRE(*back == m);  // doubles exact; uvs are float-exact values
    }
  const std::string text = tessera::format_ply(samples::grid(1, 1, false), {.binary = true});
  REQUIRE(text.find("format binary_little_endian 1.0\n") != std::string::npos);
}

TEMPLATE_TEST_CASE("ply: every scalar type for positions, counts and indices", "[ply]", std::int8_t, std::uint8_t,
                   std::int16_t, std::uint16_t, std::int32_t, std::uint32_t) {
  const char* names[] = {"char", "uchar", "short", "ushort", "int", "uint"};
  const int which = std::is_same_v<TestType, std::int8_t>     ? 0
                    : std::is_same_v<TestType, std::uint8_t>  ? 1
                    : std::is_same_v<TestType, std::int16_t>  ? 2
                    : std::is_same_v<TestType, std::uint16_t> ? 3
                    : std::is_same_v<TestType, std::int32_t>  ? 4
                                                              : 5;
  const std::string t = names[which];
  for (const encoding& e : encodings)
    for (const char* pos_type : {"float", "double", "int8", "uint16", "int32"}) {
      INFO(e.name << " " << pos_type << " " << t);
      const std::string pt = pos_type;
      std::string header = "ply\n" + format_line(e.binary, e.big) + "comment typed\nelement vertex 5\n";
      header += "property " + pt + " x\nproperty " + pt + " y\nproperty " + pt + " z\n";
      header += "property uchar red\nelement face 2\nproperty list " + t + " " + t + " vertex_indices\nend_header\n";
      body b{e.binary, e.big, {}};
      const int coords[5][3] = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 1}, {9, 9, 9}};
      for (const auto& c : coords) {
        for (int k = 0; k < 3; ++k) {
          if (pt == "float")
            b.put(static_cast<float>(c[k]));
          else if (pt == "double")
            b.put(static_cast<double>(c[k]));
          else if (pt == "int8")
            b.put(static_cast<std::int8_t>(c[k]));
          else if (pt == "uint16")
            b.put(static_cast<std::uint16_t>(c[k]));
          else
            b.put(static_cast<std::int32_t>(c[k]));
        }
        b.put(std::uint8_t{200}).endl();
      }
      b.put(TestType{4}).put(TestType{0}).put(TestType{1}).put(TestType{2}).put(TestType{3}).endl();  // a quad
      b.put(TestType{3}).put(TestType{4}).put(TestType{0}).put(TestType{2}).endl();
      const auto r = tessera::parse_ply(header + b.out, "typed.ply");
      REQUIRE(r.ok());
      REQUIRE(r->positions[3] == vec3{0, 3, 1});
      REQUIRE(r->faces == std::vector<std::array<index_t, 3>>{{0, 1, 2}, {0, 2, 3}, {4, 0, 2}});
      REQUIRE_FALSE(r->has_uvs());
    }
}

TEST_CASE("ply: texture coordinates per face corner or per vertex, other elements skipped", "[ply]") {
  for (const encoding& e : encodings) {
    INFO(e.name);
    std::string header = "ply\n" + format_line(e.binary, e.big) +
                         "obj_info made by hand\n"
                         "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                         "property float s\nproperty float t\n"
                         "element material 1\nproperty list int uchar name\nproperty double shininess\n"
                         "element face 1\nproperty list uchar uint vertex_index\nproperty uchar flags\n"
                         "element edge 2\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    body b{e.binary, e.big, {}};
    for (int v = 0; v < 3; ++v) b.put(float(v)).put(float(v == 2)).put(0.0f).put(0.5f * v).put(0.25f).endl();
    b.put(std::int32_t{3}).put(std::uint8_t{'a'}).put(std::uint8_t{'b'}).put(std::uint8_t{'c'}).put(0.5).endl();
    b.put(std::uint8_t{3})
        .put(std::uint32_t{0})
        .put(std::uint32_t{1})
        .put(std::uint32_t{2})
        .put(std::uint8_t{7})
        .endl();
    b.put(std::int32_t{0}).put(std::int32_t{1}).endl().put(std::int32_t{1}).put(std::int32_t{2}).endl();
    const auto r = tessera::parse_ply(header + b.out, "uv.ply");
    REQUIRE(r.ok());
    REQUIRE(r->faces.size() == 1);
    REQUIRE(r->uvs[0] == std::array<vec2, 3>{vec2{0, 0.25}, vec2{0.5, 0.25}, vec2{1, 0.25}});

    // a face texcoord list wins over vertex uvs
    std::string h2 = "ply\n" + format_line(e.binary, e.big) +
                     "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nproperty float u\n"
                     "property float v\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "property list uchar float texcoord\nend_header\n";
    body c{e.binary, e.big, {}};
    for (int v = 0; v < 3; ++v) c.put(double(v)).put(double(v == 2)).put(0.0).put(9.0f).put(9.0f).endl();
    c.put(std::uint8_t{3}).put(0).put(1).put(2).put(std::uint8_t{6});
    for (float f : {0.f, 0.f, 1.f, 0.f, 0.f, 1.f}) c.put(f);
    c.endl();
    const auto r2 = tessera::parse_ply(h2 + c.out, "uv2.ply");
    REQUIRE(r2.ok());
    REQUIRE(r2->uvs[0] == std::array<vec2, 3>{vec2{0, 0}, vec2{1, 0}, vec2{0, 1}});
  }
  // an ASCII file without a final newline, and CRLF header lines
  const auto crlf = tessera::parse_ply(
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2");
  REQUIRE(crlf.ok());
  REQUIRE(crlf->num_faces() == 1);
}

TEST_CASE("ply: malformed headers name the line", "[ply]") {
  using samples::require_error_at_line;
  const std::string f = "format ascii 1.0\n";
  require_error_at_line(tessera::parse_ply("", "h.ply"), "h.ply", 1, "not a PLY file");
  require_error_at_line(tessera::parse_ply("OFF\n", "h.ply"), "h.ply", 1, "not a PLY file");
  require_error_at_line(tessera::parse_ply("ply\nelement vertex 0\n", "h.ply"), "h.ply", 2, "no end_header");
  require_error_at_line(tessera::parse_ply("ply\nend_header\n", "h.ply"), "h.ply", 2, "no format line");
  require_error_at_line(tessera::parse_ply("ply\nformat binary 1.0\nend_header\n", "h.ply"), "h.ply", 2,
                        "unknown format");
  require_error_at_line(tessera::parse_ply("ply\nformat ascii 2.0\nend_header\n", "h.ply"), "h.ply", 2, "version");
  require_error_at_line(tessera::parse_ply("ply\n" + f + f + "end_header\n", "h.ply"), "h.ply", 3, "second format");
  // a second face element, the second with per-corner uvs (a fuzz finding: the uvs covered only the
  // second element's faces), and a second vertex element
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  require_error_at_line(
      tessera::parse_ply("ply\n" + f + "element vertex 3\nproperty float x\nproperty float y\n" + "property float z\n" +
                             face + face + "property list uchar float texcoord\nend_header\n",
                         "h.ply"),
      "h.ply", 9, "a second 'face' element (the first is on line 7)");
  require_error_at_line(tessera::parse_ply("ply\n" + f + "element vertex 0\nelement vertex 0\nend_header\n", "h.ply"),
                        "h.ply", 4, "a second 'vertex' element");
  require_error_at_line(tessera::parse_ply("ply\n" + f + "property float x\nend_header\n", "h.ply"), "h.ply", 3,
                        "before any element");
  require_error_at_line(tessera::parse_ply("ply\n" + f + "element vertex -1\nend_header\n", "h.ply"), "h.ply", 3,
                        "non-negative");
  require_error_at_line(
      tessera::parse_ply("ply\n" + f + "element vertex 1\nproperty float128 x\nend_header\n", "h.ply"), "h.ply", 4,
      "unknown type 'float128'");
  require_error_at_line(
      tessera::parse_ply("ply\n" + f + "element face 1\nproperty list float int vertex_indices\nend_header\n", "h.ply"),
      "h.ply", 4, "count type");
  require_error_at_line(tessera::parse_ply("ply\n" + f + "elephant 1\nend_header\n", "h.ply"), "h.ply", 3,
                        "unknown header keyword");
  require_error_at_line(
      tessera::parse_ply("ply\n" + f + "element vertex 1\nproperty float x\nend_header\n0\n", "h.ply"), "h.ply", 3,
      "x, y and z");
  require_error_at_line(
      tessera::parse_ply("ply\n" + f +
                             "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 0\nproperty int vertex_indices\nend_header\n",
                         "h.ply"),
      "h.ply", 7, "list property vertex_indices");
  require_error_at_line(tessera::parse_ply("ply\n" + f +
                                               "element face 1\nproperty list uchar int vertex_indices\n"
                                               "end_header\n3 0 1 2\n",
                                           "h.ply"),
                        "h.ply", 3, "without a vertex element");
  // counts the data cannot hold: refused before any allocation
  require_error_at_line(tessera::parse_ply("ply\n" + f +
                                               "element vertex 4000000000\nproperty float x\nproperty float y\n"
                                               "property float z\nend_header\n0 0 0\n",
                                           "h.ply"),
                        "h.ply", 3, "declares 4000000000 'vertex' elements");
}

TEST_CASE("ply: malformed data names the line (ASCII) or byte (binary)", "[ply]") {
  const std::string head =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list int int vertex_indices\nend_header\n";
  auto ascii = [&](const std::string& data) {
    return tessera::parse_ply("ply\nformat ascii 1.0\n" + head + data, "d.ply");
  };
  using samples::require_error_at_line;
  const std::string v = "0 0 0\n1 0 0\n0 1 0\n";
  require_error_at_line(ascii(v + "3 0 1 3\n"), "d.ply", 13, "vertex index 3 outside 0..2");
  require_error_at_line(ascii(v + "3 0 1 -1\n"), "d.ply", 13, "vertex index -1");
  require_error_at_line(ascii(v + "2 0 1\n"), "d.ply", 13, "at least 3 corners");
  require_error_at_line(ascii(v + "3 0 1 1\n"), "d.ply", 13, "degenerate");
  require_error_at_line(ascii(v + "-3 0 1 2\n"), "d.ply", 13, "negative list length");
  require_error_at_line(ascii(v + "99999 0 1 2\n"), "d.ply", 13, "does not fit");
  require_error_at_line(ascii("0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"), "d.ply", 11, "'nan'");
  require_error_at_line(ascii("0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n"), "d.ply", 13, "'1.5' is not an integer");
  require_error_at_line(ascii(v + "3 0 1\n\n\n\n\n\n\n\n"), "d.ply", 20, "truncated");  // 7 empty lines after 13

  // binary: byte offsets
  const std::string bin_head = "ply\nformat binary_little_endian 1.0\n" + head;
  body b{true, false, {}};
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b.put(c);
  b.put(3).put(0).put(1).put(7);
  auto r = tessera::parse_ply(bin_head + b.out, "d.ply");
  REQUIRE(r.error().code() == status_code::parse_error);
  REQUIRE(r.error().message().rfind("d.ply, byte " + std::to_string(bin_head.size() + 36 + 12) + ":", 0) == 0);
  REQUIRE(r.error().message().find("vertex index 7") != std::string::npos);
  // a list length that the remaining bytes cannot hold: no allocation, an error at the count
  body big{true, false, {}};
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) big.put(c);
  big.put(2147483647).put(0).put(1).put(2);
  r = tessera::parse_ply(bin_head + big.out, "d.ply");
  REQUIRE(r.error().message().rfind("d.ply, byte " + std::to_string(bin_head.size() + 36) + ":", 0) == 0);
  REQUIRE(r.error().message().find("does not fit") != std::string::npos);
  // a NaN coordinate
  body nan{true, false, {}};
  for (float c : {0.f, 0.f, 0.f, 1.f, std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f, 1.f, 0.f}) nan.put(c);
  nan.put(3).put(0).put(1).put(2);
  r = tessera::parse_ply(bin_head + nan.out, "d.ply");
  REQUIRE(r.error().message().rfind("d.ply, byte " + std::to_string(bin_head.size() + 16) + ":", 0) == 0);
  REQUIRE(r.error().message().find("not a finite number") != std::string::npos);
  // texcoord lists that do not match the corners
  const std::string tex_head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property list uchar float texcoord\nend_header\n" +
      v;
  require_error_at_line(tessera::parse_ply(tex_head + "3 0 1 2 4 0 0 1 0\n", "t.ply"), "t.ply", 14,
                        "2 uv pairs for 3 corners");
  require_error_at_line(tessera::parse_ply(tex_head + "3 0 1 2 5 0 0 1 0 1\n", "t.ply"), "t.ply", 14, "odd number");
  REQUIRE(tessera::read_ply(samples::out_path("missing.ply")).error().code() == status_code::io_error);
}

TEST_CASE("ply: truncation at every byte and byte flips never crash", "[ply]") {
  for (const encoding& e : encodings) {
    INFO(e.name);
    const std::string data = tessera::format_ply(samples::grid(2, 1, true), {.binary = e.binary, .big_endian = e.big});
    const std::size_t header_end = data.find("end_header\n") + 11;
    for (std::size_t n = 0; n < data.size(); ++n) {
      const auto r = tessera::parse_ply(data.substr(0, n), "cut.ply");
      samples::require_valid_or_parse_error(r, "cut.ply");
      if (e.binary) {
        REQUIRE_FALSE(r.ok());  // every cut of a binary file is detected
        if (n > header_end) REQUIRE(r.error().message().find(", byte ") != std::string::npos);
      }
    }
    const tessera::counter_rng rng(6);
    for (std::size_t i = 0; i < data.size(); ++i) {
      std::string bad = data;
      bad[i] = static_cast<char>(rng.below(256, i));
      samples::require_valid_or_parse_error(tessera::parse_ply(bad, "flip.ply"), "flip.ply");
    }
  }
}

TEST_CASE("ply: write errors", "[ply]") {
  tri_mesh bad = samples::grid(1, 1, false);
  bad.faces[0] = {0, 0, 1};
  REQUIRE(tessera::write_ply(samples::out_path("bad.ply"), bad).code() == status_code::invalid_argument);
  REQUIRE(tessera::write_ply(samples::out_path("no/dir.ply"), samples::grid(1, 1, false)).code() ==
          status_code::io_error);
}

TEST_CASE("ply: an element without properties holds no data, whatever count it declares", "[ply][bad_input]") {
  // A 2^63 - 1 count of property-less elements must not loop: they occupy no bytes.
  for (const encoding& e : encodings) {
    INFO(e.name);
    const std::string header = "ply\n" + format_line(e.binary, e.big) +
                               "element marker 9223372036854775807\n"
                               "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    body b{e.binary, e.big, {}};
    for (int v = 0; v < 3; ++v) b.put(float(v)).put(float(v == 2)).put(0.0f).endl();
    b.put(std::uint8_t{3}).put(0).put(1).put(2).endl();
    const auto r = tessera::parse_ply(header + b.out, "marker.ply");
    REQUIRE(r.ok());
    CHECK(r->num_vertices() == 3);
    CHECK(r->num_faces() == 1);
  }
}

TEST_CASE("ply: uvs and positions beyond float range are written so that they read back", "[ply][bad_input]") {
  // a float texcoord would store 1e300 as inf, which no reader accepts: such uvs are written as double
  tri_mesh m = samples::grid(2, 1, true);
  m.uvs[0][1] = vec2{1e300, -3.5e38};
  m.uvs[1][2] = vec2{0.25, 1e-320};  // tiny values are fine either way
  m.positions[2] = vec3{1e300, -1e-300, 2.5e38};
  for (const encoding& e : encodings) {
    INFO(e.name);
    const std::string text = tessera::format_ply(m, {.binary = e.binary, .big_endian = e.big});
    REQUIRE(text.find("property list uchar double texcoord") != std::string::npos);
    const auto back = tessera::parse_ply(text, "wide.ply");
    REQUIRE(back.ok());
    REQUIRE(back->positions == m.positions);
    REQUIRE(back->uvs == m.uvs);
  }
  // ordinary uvs stay float
  const tri_mesh plain = samples::grid(2, 1, true);
  REQUIRE(tessera::format_ply(plain).find("property list uchar float texcoord") != std::string::npos);
  const std::string path = samples::out_path("wide_uv.ply");
  REQUIRE(tessera::write_ply(path, m, {.binary = true}).ok());
  REQUIRE(tessera::read_ply(path).ok());
}

TEST_CASE("ply: element counts do not reserve memory the file cannot hold", "[ply][bad_input]") {
  using tessera::detail::bounded_reserve;
  REQUIRE(bounded_reserve(-5, 100, 2) == 0);
  REQUIRE(bounded_reserve(10, 1000, 2) == 10);
  REQUIRE(bounded_reserve(1000, 100, 8) == 13);                              // 100 bytes hold 12.5 triangles
  REQUIRE(bounded_reserve(100000000, std::size_t{1} << 30, 2) == 1u << 20);  // at most 2^20 up front
  // a header claiming 10^8 faces over a few bytes of garbage: a parse error, no 2.4 GB reservation
  for (const encoding& e : encodings) {
    INFO(e.name);
    std::string text = "ply\n" + format_line(e.binary, e.big) +
                       "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 100000000\nproperty list uchar int vertex_indices\nend_header\n";
    body b{e.binary, e.big, {}};
    for (int v = 0; v < 3; ++v) b.put(float(v)).put(float(v == 2)).put(0.0f).endl();
    b.put(std::uint8_t{3}).put(0).put(1).put(2).endl();
    text += b.out + std::string(1000, e.binary ? '\0' : '9');
    const auto r = tessera::parse_ply(text, "claims.ply");
    REQUIRE(r.error().code() == status_code::parse_error);
  }
}
