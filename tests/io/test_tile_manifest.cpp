#include <tessera/io/tile_manifest.hpp>

#include <tessera/io/geometric_tiles.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/io/png.hpp>
#include <tessera/io/wang_tiles.hpp>

#include <filesystem>
#include <fstream>
#include <limits>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::tile_manifest;

namespace {
std::string manifest_scratch(const std::string& name) {
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
  const auto dir = manifest_scratch("roundtrip");
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
       "inside the tile directory"},
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
  const auto dir = manifest_scratch("missing");
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

TEST_CASE("tile manifest: duplicate members are rejected, so a rewrite never loses the tiles", "[tiling][bad_input]") {
  // a second "tiles" member used to be kept as-is and rewritten before the array: unreadable after
  const std::string tiles = R"([{"index": 0, "file": "a.png", "edges": [0, 0, 0, 0]}])";
  const std::string twice = R"({"tile_size": 16, "horizontal_colors": 1, "vertical_colors": 1, "tiles": )" + tiles +
                            R"(, "tiles": )" + tiles + "}";
  auto m = tessera::parse_tile_manifest(twice, "dup.json");
  REQUIRE(m.error().code() == tessera::status_code::parse_error);
  REQUIRE_THAT(m.error().message(), Catch::StartsWith("dup.json:1:") && Catch::Contains("duplicate member \"tiles\""));
  const std::vector<std::string> duplicates = {
      R"({"tile_size": 16, "tile_size": 16, "horizontal_colors": 1, "vertical_colors": 1, "tiles": )" + tiles + "}",
      R"({"tile_size": 16, "horizontal_colors": 1, "vertical_colors": 1, "tiles": [{"index": 0, "index": 0, "file": "a.png", "edges": [0, 0, 0, 0]}]})",
      R"({"tile_size": 16, "horizontal_colors": 1, "vertical_colors": 1, "h": 1, "h": 2, "tiles": )" + tiles + "}"};
  for (const std::string& text : duplicates) {
    INFO(text);
    REQUIRE_THAT(tessera::parse_tile_manifest(text, "dup.json").error().message(), Catch::Contains("duplicate member"));
  }
  REQUIRE(tessera::detail::parse_json(R"({"a": {"x": 1}, "b": {"x": 2}})", "ok.json").ok());  // per object
  // extra fields that would collide with the format's own members, or be written twice, are refused
  tile_manifest bad = sample();
  bad.extra.push_back({"tiles", 1});
  REQUIRE_THAT(tessera::validate_tile_manifest(bad).message(), Catch::Contains("reserved"));
  bad = sample();
  bad.extra.push_back({"height", 2});
  REQUIRE_THAT(tessera::validate_tile_manifest(bad).message(), Catch::Contains("twice"));
  bad = sample();
  bad.tiles[2].extra = {{"edges", 1}};
  REQUIRE_FALSE(tessera::validate_tile_manifest(bad).ok());
  bad = sample();
  bad.extra[0].value = std::numeric_limits<double>::infinity();
  REQUIRE_THAT(tessera::validate_tile_manifest(bad).message(), Catch::Contains("finite"));
}

TEST_CASE("tile manifest: tile files never leave the directory", "[tiling][bad_input]") {
  const std::vector<std::string> hostile = {"../a.png",    "sub/../../a.png",
                                            "/etc/passwd", "\\\\server\\x.png",
                                            "a\\..\\b",    "C:a.png",
                                            "C:\\x.png",   std::string("a.png\0.txt", 10),
                                            "a\nb.png",    "",
                                            ".",           "..",
                                            "sub//a.png",  "./a.png",
                                            "a/",          std::string(300, 'a')};
  for (const std::string& file : hostile) {
    INFO(file);
    tile_manifest m = sample();
    m.tiles[1].file = file;
    const auto s = tessera::validate_tile_manifest(m, "t.json");
    REQUIRE(s.code() == tessera::status_code::invalid_argument);
    REQUIRE_THAT(s.message(),
                 Catch::StartsWith("t.json: tile 1: file") && Catch::Contains("inside the tile directory"));
    // never written, never read: the JSON form of the same name is refused by the parser too
    const auto dir = manifest_scratch("hostile");
    REQUIRE_FALSE(tessera::write_tile_manifest(dir, m).ok());
    REQUIRE_FALSE(std::filesystem::exists(tessera::tile_manifest_path(dir)));
    std::string text = tessera::format_tile_manifest(m);
    REQUIRE_FALSE(tessera::parse_tile_manifest(text, "t.json").ok());
  }
  // the NUL byte as a JSON escape: "a.png\u0000../../x" would open "a.png" and pass a check on a C string
  const std::string nul =
      R"({"tile_size": 16, "horizontal_colors": 1, "vertical_colors": 1, "tiles": [{"index": 0, "file": "a.png\u0000x", "edges": [0, 0, 0, 0]}]})";
  REQUIRE_THAT(tessera::parse_tile_manifest(nul, "nul.json").error().message(),
               Catch::Contains("control character") && Catch::Contains("\\u0000"));
  // plain names and subdirectories are fine
  for (const std::string file : {"tile_1.png", "sub/tile_1.png", "a..b.png", "..a.png"}) {
    tile_manifest m = sample();
    m.tiles[1].file = file;
    INFO(file);
    REQUIRE(tessera::validate_tile_manifest(m).ok());
  }
}

TEST_CASE("tile directories: image and geometric sets refuse manifests pointing outside", "[tiling][bad_input]") {
  const auto root = manifest_scratch("escape");
  const auto dir = (std::filesystem::path(root) / "set").string();
  std::filesystem::create_directories(dir);
  // real files outside the directory: a manifest naming them must not read them
  REQUIRE(tessera::write_png(root + "/outside.png", tessera::image_buffer<std::uint8_t, 3>(16, 16)).ok());
  tessera::tri_mesh tri;
  tri.positions = {{0.1, 0.1, 0}, {0.9, 0.1, 0}, {0.1, 0.9, 0}};
  tri.faces = {{0, 1, 2}};
  REQUIRE(tessera::write_obj(root + "/outside.obj", tri).ok());
  for (const std::string& file :
       std::vector<std::string>{"../outside", root + "/outside", std::string("tile\0/../../outside", 19)}) {
    for (const char* ext : {".png", ".obj"}) {
      const std::string name = file + ext;
      INFO(name);
      const std::string text =
          R"({"tile_size": 16, "horizontal_colors": 1, "vertical_colors": 1, "tiles": [{"index": 0, "file": )" +
          tessera::detail::json_quote(name) + R"(, "edges": [0, 0, 0, 0]}]})";
      REQUIRE(tessera::detail::write_file(tessera::tile_manifest_path(dir), text).ok());
      const auto image = tessera::load_wang_tiles<std::uint8_t, 3>(dir);
      REQUIRE(image.error().code() == tessera::status_code::invalid_argument);
      REQUIRE_THAT(image.error().message(), Catch::Contains("inside the tile directory"));
      const auto geometric = tessera::load_geometric_tile_set(dir);
      REQUIRE(geometric.error().code() == tessera::status_code::invalid_argument);
      REQUIRE_THAT(geometric.error().message(), Catch::Contains("inside the tile directory"));
    }
  }
}

TEST_CASE("tile directories: an empty tile file is written and refused cleanly", "[tiling][bad_input]") {
  // found by the tile_dir fuzz target under UBSan: writing an empty view passed its null pointer to fwrite
  const auto dir = manifest_scratch("empty_tile");
  REQUIRE(tessera::detail::write_file(dir + "/tile_0.png", std::string_view{}).ok());
  REQUIRE(std::filesystem::file_size(dir + "/tile_0.png") == 0);
  REQUIRE(
      tessera::detail::write_file(
          tessera::tile_manifest_path(dir),
          R"({"tile_size": 16, "horizontal_colors": 1, "vertical_colors": 1, "tiles": [{"index": 0, "file": "tile_0.png", "edges": [0, 0, 0, 0]}]})")
          .ok());
  const auto set = tessera::load_wang_tiles<std::uint8_t, 3>(dir);
  REQUIRE(set.error().code() == tessera::status_code::parse_error);
  REQUIRE_THAT(set.error().message(), Catch::Contains("tile_0.png") && Catch::Contains("empty file"));
}
