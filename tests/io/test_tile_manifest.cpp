#include <tessera/io/tile_manifest.hpp>

#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::tile_manifest;

namespace {
std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "tiling" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}
void touch(const std::string& dir, const std::string& file) { std::ofstream(std::filesystem::path(dir) / file) << "x"; }

tile_manifest sample() {
  tile_manifest m;
  m.tile_size = 32;
  m.horizontal_colors = 2;
  m.vertical_colors = 3;
  m.extra = {{"height", 0.25}, {"exemplar_seed", 7}};
  for (index_t i = 0; i < 4; ++i)
    m.tiles.push_back({i, "tile_" + std::to_string(i) + ".png", tessera::complete_tile_edges(i * 5, 2, 3), {}});
  m.tiles[1].extra = {{"weight", 1.5}};
  return m;
}
}  // namespace

TEST_CASE("tile manifest: write then read round-trips, extra fields kept", "[tiling]") {
  const auto dir = scratch("roundtrip");
  const tile_manifest m = sample();
  REQUIRE(tessera::write_tile_manifest(dir, m).ok());
  for (const auto& t : m.tiles) touch(dir, t.file);
  auto back = tessera::read_tile_manifest(dir);
  REQUIRE(back.ok());
  REQUIRE(*back == m);
  REQUIRE(back->extra_value("height") == 0.25);
  REQUIRE(back->extra_value("missing", -1) == -1);
  auto set = tessera::manifest_tile_set(*back);
  REQUIRE(set.ok());
  REQUIRE(set->size() == 4);
  REQUIRE((*set)[3] == tessera::complete_tile_edges(15, 2, 3));
}

TEST_CASE("tile manifest: tolerant reading", "[tiling]") {
  const std::string text = R"(  // written by hand
  {
    "tiles": [
      {"edges": [1, 0, 1, 1], "file": "b.png", "index": 1, "note": "ignored"},
      {"index": 0, "file": "a.png", "edges": [0, 0, 0, 0], "height": 2,},  /* trailing comma */
    ],
    "vertical_colors": 2, "horizontal_colors": 2, "tile_size": 16, "name": "x"
  })";
  auto m = tessera::parse_tile_manifest(text, "hand.json");
  REQUIRE(m.ok());
  REQUIRE(m->tiles.size() == 2u);
  REQUIRE(m->tiles[0].file == "a.png");  // sorted by index
  REQUIRE(m->tiles[0].extra == std::vector<tessera::manifest_field>{{"height", 2}});
  REQUIRE(m->tiles[1].edges == tessera::wang_edges{1, 0, 1, 1});
  REQUIRE(m->extra.empty());  // string members are not numeric extras
}

TEST_CASE("tile manifest: malformed and inconsistent files name the file", "[tiling]") {
  struct bad_case {
    std::string text, expect;
  };
  const std::vector<bad_case> cases = {
      {"{\"tile_size\": 16, ", "bad.json:1:"},
      {"[1, 2]", "must be a JSON object"},
      {R"({"horizontal_colors": 2, "vertical_colors": 2, "tiles": []})", "missing \"tile_size\""},
      {R"({"tile_size": 1.5, "horizontal_colors": 2, "vertical_colors": 2, "tiles": []})", "must be an integer"},
      {R"({"tile_size": 16, "horizontal_colors": 0, "vertical_colors": 2, "tiles": []})", "colour counts"},
      {R"({"tile_size": 16, "horizontal_colors": 2, "vertical_colors": 2})", "missing \"tiles\""},
      {R"({"tile_size": 16, "horizontal_colors": 2, "vertical_colors": 2, "tiles": []})", "is empty"},
      {R"({"tile_size": 16, "horizontal_colors": 2, "vertical_colors": 2, "tiles": [{"index": 0, "file": "a.png", "edges": [0, 0, 0]}]})",
       "four colours"},
      {R"({"tile_size": 16, "horizontal_colors": 2, "vertical_colors": 2, "tiles": [{"index": 0, "file": "a.png", "edges": [0, 0, 2, 0]}]})",
       "south colour 2"},
      {R"({"tile_size": 16, "horizontal_colors": 2, "vertical_colors": 2, "tiles": [{"index": 1, "file": "a.png", "edges": [0, 0, 0, 0]}]})",
       "tile index 1"},
      {R"({"tile_size": 16, "horizontal_colors": 2, "vertical_colors": 2, "tiles": [{"index": 0, "file": "../a.png", "edges": [0, 0, 0, 0]}]})",
       "plain name"},
      {R"({"tile_size": 16, "horizontal_colors": 2, "vertical_colors": 2, "tiles": [{"index": 0, "edges": [0, 0, 0, 0]}]})",
       "\"file\""},
      {R"({"tile_size": -16, "horizontal_colors": 2, "vertical_colors": 2, "tiles": [{"index": 0, "file": "a", "edges": [0, 0, 0, 0]}]})",
       "tile_size must be positive"},
      {"{\"a\": \"unterminated}", "unterminated string"},
      {"{\"a\": 1} extra", "after the JSON value"},
  };
  for (const auto& c : cases) {
    auto m = tessera::parse_tile_manifest(c.text, "bad.json");
    INFO(c.text);
    REQUIRE_FALSE(m.ok());
    REQUIRE_THAT(m.error().message(), Catch::StartsWith("bad.json") && Catch::Contains(c.expect));
  }
}

TEST_CASE("tile manifest: missing directory, manifest and tile files", "[tiling]") {
  const auto dir = scratch("missing");
  auto none = tessera::read_tile_manifest(dir);
  REQUIRE(none.error().code() == tessera::status_code::io_error);
  REQUIRE_THAT(none.error().message(), Catch::Contains("tiles.json"));
  REQUIRE(tessera::write_tile_manifest(dir, sample()).ok());
  touch(dir, "tile_0.png");
  touch(dir, "tile_1.png");
  touch(dir, "tile_3.png");
  auto missing = tessera::read_tile_manifest(dir);
  REQUIRE(missing.error().code() == tessera::status_code::io_error);
  REQUIRE_THAT(missing.error().message(), Catch::Contains("tile_2.png") && Catch::Contains("missing"));
  tile_manifest invalid = sample();
  invalid.tiles[0].index = 3;
  REQUIRE_FALSE(tessera::write_tile_manifest(dir, invalid).ok());
}
