#include <tessera/io/off.hpp>

#include <array>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/core/random.hpp>

#include "mesh_samples.hpp"

using tessera::index_t;
using tessera::status_code;
using tessera::tri_mesh;
using tessera::vec3;

TEST_CASE("off: round trips are exact, uvs are dropped", "[off]") {
  const tri_mesh m = samples::grid(3, 2, false);
  const std::string path = samples::out_path("grid.off");
  REQUIRE(tessera::write_off(path, m).ok());
  const auto back = tessera::read_off(path);
  REQUIRE(back.ok());
  REQUIRE(*back == m);
  const auto no_uv = tessera::parse_off(tessera::format_off(samples::grid(3, 2, true)));
  REQUIRE(no_uv.ok());
  REQUIRE_FALSE(no_uv->has_uvs());
  REQUIRE(no_uv->positions == m.positions);
}

TEST_CASE("off: header variants, comments, colours and polygons", "[off]") {
  const std::string text =
      "COFF 5 2 0   # counts on the header line\r\n"
      "# a comment line\r\n"
      "\r\n"
      "0 0 0 255 0 0 255\r\n"
      "1 0 0 0 255 0 255\r\n"
      "1 1 0 0 0 255 255\r\n"
      "0 1 0 9 9 9 255\r\n"
      "2 2 2 9 9 9 255\r\n"
      "4 0 1 2 3 0.5 0.5 0.5\r\n"  // a quad with a face colour
      "3\t4 0 1\r\n";
  const auto r = tessera::parse_off(text, "c.off");
  REQUIRE(r.ok());
  REQUIRE(r->num_vertices() == 5);
  REQUIRE(r->positions[4] == vec3{2, 2, 2});
  REQUIRE(r->faces == std::vector<std::array<index_t, 3>>{{0, 1, 2}, {0, 2, 3}, {4, 0, 1}});
  for (const char* header : {"OFF\n3 1 3\n", "NOFF\n3 1\n", "STOFF 3 1 0\n", "OFF\n\n# c\n3 1 0\n", "CNOFF\n3 1 0\n"}) {
    const auto t = tessera::parse_off(std::string(header) + "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
    INFO(header);
    REQUIRE(t.ok());
    REQUIRE(t->num_faces() == 1);
  }
  REQUIRE(tessera::parse_off("OFF\n0 0 0\n")->num_vertices() == 0);
}

TEST_CASE("off: malformed files name the file and the line", "[off]") {
  using samples::require_error_at_line;
  const std::string v3 = "0 0 0\n1 0 0\n0 1 0\n";
  require_error_at_line(tessera::parse_off("", "e.off"), "e.off", 1, "empty file");
  require_error_at_line(tessera::parse_off("PLY\n", "e.off"), "e.off", 1, "OFF keyword");
  require_error_at_line(tessera::parse_off("XOFF\n", "e.off"), "e.off", 1, "OFF keyword");
  require_error_at_line(tessera::parse_off("OFF\n", "e.off"), "e.off", 1, "missing the vertex and face counts");
  require_error_at_line(tessera::parse_off("OFF\n3 x 0\n", "e.off"), "e.off", 2, "counts");
  require_error_at_line(tessera::parse_off("OFF\n-3 1 0\n", "e.off"), "e.off", 2, "non-negative");
  require_error_at_line(tessera::parse_off("OFF\n999999999999 1 0\n" + v3, "e.off"), "e.off", 2,
                        "declares 999999999999 vertices");
  const std::string pad = "# padding, so that the counts fit the file size\n";
  require_error_at_line(tessera::parse_off("OFF\n4 1 0\n" + v3 + pad, "e.off"), "e.off", 6,
                        "expected 4 vertices, the file ends after 3");
  require_error_at_line(tessera::parse_off("OFF\n3 2 0\n" + v3 + "3 0 1 2\n" + pad, "e.off"), "e.off", 7,
                        "expected 2 faces, the file ends after 1");
  require_error_at_line(tessera::parse_off("OFF\n3 1 0\n0 0\n1 0 0\n0 1 0\n3 0 1 2\n" + pad, "e.off"), "e.off", 3,
                        "three coordinates");
  require_error_at_line(tessera::parse_off("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "e.off"), "e.off", 4,
                        "'nan'");
  require_error_at_line(tessera::parse_off("OFF\n3 1 0\n" + v3 + "2 0 1 0 0 0 0\n", "e.off"), "e.off", 6, "at least 3");
  require_error_at_line(tessera::parse_off("OFF\n3 1 0\n" + v3 + "3 0 1 3\n", "e.off"), "e.off", 6, "outside 0..2");
  require_error_at_line(tessera::parse_off("OFF\n3 1 0\n" + v3 + "3 0 1 -1\n", "e.off"), "e.off", 6, "'-1'");
  require_error_at_line(tessera::parse_off("OFF\n3 1 0\n" + v3 + "4 0 1 2\n", "e.off"), "e.off", 6, "lists 3");
  require_error_at_line(tessera::parse_off("OFF\n3 1 0\n" + v3 + "3 0 1 1\n", "e.off"), "e.off", 6, "degenerate");
  require_error_at_line(tessera::parse_off(std::string("OFF\n\0\x01\x02", 7), "e.off"), "e.off", 2, "binary");
  REQUIRE(tessera::parse_off("4OFF\n").error().code() == status_code::unsupported);
  REQUIRE(tessera::parse_off("nOFF\n4\n").error().code() == status_code::unsupported);
  REQUIRE(tessera::parse_off("OFF BINARY\n").error().code() == status_code::unsupported);
  REQUIRE(tessera::read_off(samples::out_path("missing.off")).error().code() == status_code::io_error);
}

TEST_CASE("off: truncation at every byte and byte flips never crash", "[off]") {
  const std::string text = tessera::format_off(samples::grid(2, 1, false));
  for (std::size_t n = 0; n <= text.size(); ++n)
    samples::require_valid_or_parse_error(tessera::parse_off(text.substr(0, n), "cut.off"), "cut.off");
  const tessera::counter_rng rng(5);
  for (std::size_t i = 0; i < text.size(); ++i) {
    std::string bad = text;
    bad[i] = static_cast<char>(rng.below(256, i));
    const auto r = tessera::parse_off(bad, "flip.off");
    if (!r.ok() && r.error().code() == status_code::unsupported) continue;  // e.g. "OFF" -> "4FF"-like keywords
    samples::require_valid_or_parse_error(r, "flip.off");
  }
}

TEST_CASE("off: write errors", "[off]") {
  tri_mesh bad = samples::grid(1, 1, false);
  bad.positions[0].x = std::numeric_limits<double>::infinity();
  const auto s = tessera::write_off(samples::out_path("bad.off"), bad);
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(s.message().find("non-finite") != std::string::npos);
  REQUIRE(tessera::write_off(samples::out_path("no/dir.off"), samples::grid(1, 1, false)).code() ==
          status_code::io_error);
}

TEST_CASE("off: counts reserve only what the file can hold", "[off][bad_input]") {
  // 10^7 vertices need at least 60 MB; a short file claiming them is refused before any allocation
  const auto claims = tessera::parse_off("OFF\n10000000 0 0\n0 0 0\n", "claims.off");
  REQUIRE(claims.error().code() == status_code::parse_error);
  REQUIRE_THAT(claims.error().message(), Catch::Contains("10000000 vertices"));
  // a file whose claim fits its size but whose data is garbage: a parse error at the first bad line
  std::string text = "OFF\n100000 0 0\n0 0 0\n";
  for (int i = 0; i < 120000; ++i) text += "x y z\n";
  const auto garbage = tessera::parse_off(text, "garbage.off");
  REQUIRE(garbage.error().code() == status_code::parse_error);
  REQUIRE_THAT(garbage.error().message(), Catch::Contains("garbage.off, line 4"));
}
