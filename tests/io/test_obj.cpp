#include <tessera/io/obj.hpp>

#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/core/mesh_view.hpp>
#include <tessera/core/random.hpp>

#include "mesh_samples.hpp"

using tessera::index_t;
using tessera::status_code;
using tessera::tri_mesh;
using tessera::vec2;
using tessera::vec3;

TEST_CASE("obj: round trips are exact, with and without uvs", "[obj]") {
  for (bool uvs : {false, true}) {
    const tri_mesh m = samples::grid(4, 3, uvs);
    const std::string path = samples::out_path(uvs ? "grid_uv.obj" : "grid.obj");
    REQUIRE(tessera::write_obj(path, m).ok());
    const auto back = tessera::read_obj(path);
    REQUIRE(back.ok());
    REQUIRE(*back == m);  // shortest round-trip decimals: bit-exact doubles
  }
  // identical uvs are written once
  const std::string text = tessera::format_obj(samples::grid(4, 3, true));
  std::size_t vt = 0;
  for (std::size_t p = text.find("\nvt "); p != std::string::npos; p = text.find("\nvt ", p + 1)) ++vt;
  REQUIRE(vt == 5 * 4);
}

TEST_CASE("obj: the statements and layouts found in real files", "[obj]") {
  const std::string text =
      "# a comment\r\n"
      "mtllib x.mtl\r\n"
      "o thing\r\n"
      "\r\n"
      "v 0 0 0 1.0\r\n"             // homogeneous w: ignored
      "v 1 0 0 0.5 0.25 0.125\r\n"  // vertex colour: ignored
      "v\t1 1 0\r\n"
      "v 0 1 0  # trailing comment\r\n"
      "v +2 -0 1e0\r\n"
      "vt 0 0\nvt 1 0 0\nvt 1\nvt 0 1\n"
      "vn 0 0 1\n"
      "g group\rusemtl m\rs off\r"   // lone CR endings
      "f 1/1/1 2/2/1 3/3/1 4/4/1\n"  // a quad: two triangles
      "f -5//1 -4//1 \\\n -1//1\n"   // negative indices, no vt, a continued line
      "l 1 2\n";
  const auto r = tessera::parse_obj(text, "sample.obj");
  REQUIRE(r.ok());
  REQUIRE(r->num_vertices() == 5);
  REQUIRE(r->positions[1] == vec3{1, 0, 0});
  REQUIRE(r->positions[4] == vec3{2, 0, 1});
  REQUIRE(r->faces == std::vector<std::array<index_t, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}});
  REQUIRE(r->has_uvs());
  REQUIRE(r->uvs[0] == std::array<vec2, 3>{vec2{0, 0}, vec2{1, 0}, vec2{1, 0}});
  REQUIRE(r->uvs[1] == std::array<vec2, 3>{vec2{0, 0}, vec2{1, 0}, vec2{0, 1}});
  REQUIRE(r->uvs[2] == std::array<vec2, 3>{});  // a face without vt among faces with vt
  REQUIRE(tessera::validate_mesh(*r).ok());

  // a pentagon fans into three triangles; no vt anywhere: no uvs
  const auto p = tessera::parse_obj("v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n");
  REQUIRE(p->faces == std::vector<std::array<index_t, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
  REQUIRE_FALSE(p->has_uvs());
  REQUIRE(tessera::parse_obj("")->num_vertices() == 0);
  REQUIRE(tessera::parse_obj("# only a comment")->num_faces() == 0);
}

TEST_CASE("obj: malformed files name the file and the line", "[obj]") {
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  using samples::require_error_at_line;
  require_error_at_line(tessera::parse_obj(v3 + "f 1 2 4\n", "a.obj"), "a.obj", 4, "outside 1..3");
  require_error_at_line(tessera::parse_obj(v3 + "f 0 1 2\n", "a.obj"), "a.obj", 4, "'0'");
  require_error_at_line(tessera::parse_obj(v3 + "f -1 -2 -4\n", "a.obj"), "a.obj", 4, "'-4'");
  require_error_at_line(tessera::parse_obj(v3 + "f 1 2 x\n", "a.obj"), "a.obj", 4, "'x'");
  require_error_at_line(tessera::parse_obj(v3 + "f 1 2 3.5\n", "a.obj"), "a.obj", 4, "'3.5'");
  require_error_at_line(tessera::parse_obj(v3 + "vt 0 0\nf 1/1 2/2 3/1\n", "a.obj"), "a.obj", 5,
                        "texture coordinate outside 1..1");
  require_error_at_line(tessera::parse_obj(v3 + "vt 0 0\nf 1/1 2 3/1\n", "a.obj"), "a.obj", 5, "mixes");
  require_error_at_line(tessera::parse_obj(v3 + "f 1 2\n", "a.obj"), "a.obj", 4, "at least three corners");
  require_error_at_line(tessera::parse_obj(v3 + "f 1 2 2\n", "a.obj"), "a.obj", 4, "degenerate");
  require_error_at_line(tessera::parse_obj(v3 + "f 1 2 3 1\n", "a.obj"), "a.obj", 4, "degenerate");
  require_error_at_line(tessera::parse_obj("v 1 2\n", "a.obj"), "a.obj", 1, "three coordinates");
  require_error_at_line(tessera::parse_obj("\n\nv 1 nan 2\n", "a.obj"), "a.obj", 3, "'nan'");
  require_error_at_line(tessera::parse_obj("v 1 inf 2\n", "a.obj"), "a.obj", 1, "'inf'");
  require_error_at_line(tessera::parse_obj("v 1 1e999 2\n", "a.obj"), "a.obj", 1, "'1e999'");
  require_error_at_line(tessera::parse_obj("v 1 2a 2\n", "a.obj"), "a.obj", 1, "'2a'");
  require_error_at_line(tessera::parse_obj("vt abc\n", "a.obj"), "a.obj", 1, "not a finite number");
  require_error_at_line(tessera::parse_obj("vt\n", "a.obj"), "a.obj", 1, "at least one value");
  require_error_at_line(tessera::parse_obj(std::string("v 0 0 0\n\x89PNG\0\0", 14), "a.obj"), "a.obj", 2, "binary");
  // CRLF files count lines the same way
  require_error_at_line(tessera::parse_obj("v 0 0 0\r\nv 1 0 0\r\nf 1 2 3\r\n", "a.obj"), "a.obj", 3, "outside 1..2");
  // files
  REQUIRE(tessera::read_obj(samples::out_path("missing.obj")).error().code() == status_code::io_error);
}

TEST_CASE("obj: truncation at every byte and byte flips never crash", "[obj]") {
  const std::string text = tessera::format_obj(samples::grid(2, 1, true));
  for (std::size_t n = 0; n <= text.size(); ++n)
    samples::require_valid_or_parse_error(tessera::parse_obj(text.substr(0, n), "cut.obj"), "cut.obj");
  const tessera::counter_rng rng(4);
  for (std::size_t i = 0; i < text.size(); ++i) {
    std::string bad = text;
    bad[i] = static_cast<char>(rng.below(256, i));
    samples::require_valid_or_parse_error(tessera::parse_obj(bad, "flip.obj"), "flip.obj");
  }
}

TEST_CASE("obj: writing any Mesh, and write errors", "[obj]") {
  const std::vector<float> vb = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<std::uint32_t> ib = {0, 1, 2};
  const std::vector<float> uv = {0, 0, 1, 0, 0, 1};
  const auto view = *tessera::make_mesh_view(vb.data(), 3, ib.data(), 1, uv.data());
  const std::string path = samples::out_path("view.obj");
  REQUIRE(tessera::write_obj(path, view).ok());
  const auto back = tessera::read_obj(path);
  REQUIRE(back->uvs[0][1] == vec2{1, 0});
  REQUIRE(back->positions[2] == vec3{0, 1, 0});

  tri_mesh bad = samples::grid(1, 1, false);
  bad.faces[1][2] = 99;
  const auto s = tessera::write_obj(samples::out_path("bad.obj"), bad);
  REQUIRE(s.code() == status_code::out_of_range);
  REQUIRE(s.message().find("bad.obj") != std::string::npos);
  REQUIRE(tessera::write_obj(samples::out_path("no/such/dir.obj"), view).code() == status_code::io_error);
}
