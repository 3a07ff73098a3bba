#include <tessera/io/geometric_tiles.hpp>

#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/tiling/axis_tile_set.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace tessera;

namespace {
geometric_tile_set tiny_set() {
  // a hand-made 1 x 1-colour set: one tile holding one ring (no border crossing)
  geometric_tile_set s;
  s.tile_size = 2.5;
  s.edge_height = 0.8;
  s.horizontal_colors = s.vertical_colors = 1;
  s.edges = {{0, 0, 0, 0}};
  tri_mesh t;
  detail::add_torus(t, {1.25, 1.25, 0.2}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.1 + 1e-17, 10, 5);
  s.tiles = {t};
  return s;
}
}  // namespace

TEST_CASE("geometric tile sets save and load exactly", "[tile_files]") {
  const std::string dir = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_roundtrip";
  std::filesystem::remove_all(dir);
  const auto set = tiny_set();
  REQUIRE(save_geometric_tile_set(dir, set).ok());
  REQUIRE(std::filesystem::exists(dir + "/tiles.json"));
  REQUIRE(std::filesystem::exists(dir + "/tile_0.obj"));
  const auto back = load_geometric_tile_set(dir);
  REQUIRE(back.ok());
  REQUIRE(back->tile_size == set.tile_size);
  REQUIRE(back->edge_height == set.edge_height);
  REQUIRE(back->edges == set.edges);
  REQUIRE(back->tiles == set.tiles);  // bit-exact positions
  // the manifest holds the exact tile size, not a rounded integer
  std::ifstream json(dir + "/tiles.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  REQUIRE(text.find("\"tile_size\": 2.5,") != std::string::npos);
}

TEST_CASE("tile sets in the older layout (integer tile_size + tile_world_size) still load", "[tile_files]") {
  const std::string dir = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_old_layout";
  std::filesystem::remove_all(dir);
  REQUIRE(save_geometric_tile_set(dir, tiny_set()).ok());
  {
    std::ofstream json(dir + "/tiles.json", std::ios::trunc);
    json << "{\"tile_size\": 3, \"horizontal_colors\": 1, \"vertical_colors\": 1, \"tile_world_size\": 2.5, "
            "\"edge_height\": 0.8,\n"
            " \"tiles\": [{\"index\": 0, \"file\": \"tile_0.obj\", \"edges\": [0, 0, 0, 0]}]}\n";
  }
  const auto back = load_geometric_tile_set(dir);
  REQUIRE(back.ok());
  REQUIRE(back->tile_size == 2.5);
  REQUIRE(back->tiles == tiny_set().tiles);
  // and an integer-only manifest reads its integer size
  {
    std::ofstream json(dir + "/tiles.json", std::ios::trunc);
    json << "{\"tile_size\": 3, \"horizontal_colors\": 1, \"vertical_colors\": 1,"
            " \"tiles\": [{\"index\": 0, \"file\": \"tile_0.obj\", \"edges\": [0, 0, 0, 0]}]}\n";
  }
  REQUIRE(load_geometric_tile_set(dir)->tile_size == 3.0);
  {
    std::ofstream json(dir + "/tiles.json", std::ios::trunc);
    json << "{\"tile_size\": -1, \"horizontal_colors\": 1, \"vertical_colors\": 1,"
            " \"tiles\": [{\"index\": 0, \"file\": \"tile_0.obj\", \"edges\": [0, 0, 0, 0]}]}\n";
  }
  REQUIRE(load_geometric_tile_set(dir).error().message().find("tile_size must be positive, got -1") !=
          std::string::npos);
}

TEST_CASE("loading rejects a tile set whose borders do not match", "[tile_files]") {
  const std::string dir = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_mismatch";
  std::filesystem::remove_all(dir);
  auto set = tiny_set();
  // an element touching the north side only: with one colour, north and south must agree
  tri_mesh& t = set.tiles[0];
  t.add_face(t.add_vertex({0.5, 2.5, 0}), t.add_vertex({0.9, 2.5, 0}), t.add_vertex({0.7, 2.2, 0.3}));
  REQUIRE(save_geometric_tile_set(dir, set).ok());
  const auto r = load_geometric_tile_set(dir);
  REQUIRE(r.error().code() == status_code::invalid_argument);
  REQUIRE(r.error().message().find("border_mismatch 1:") != std::string::npos);
  // a matching south side within the tolerance (1e-6) loads; beyond it, it does not
  for (const double dz : {1e-8, 1e-4}) {
    auto both = set;
    tri_mesh& u = both.tiles[0];
    u.add_face(u.add_vertex({0.5, 0, 0}), u.add_vertex({0.7, 0.3, 0.3}), u.add_vertex({0.9, 0, dz}));
    REQUIRE(save_geometric_tile_set(dir, both).ok());
    REQUIRE(load_geometric_tile_set(dir).ok() == (dz < 1e-6));
  }
}

TEST_CASE("loading a tile directory with a missing file fails with a clear status", "[tile_files]") {
  const std::string dir = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_missing";
  std::filesystem::remove_all(dir);
  REQUIRE(load_geometric_tile_set(dir).error().code() == status_code::io_error);  // no tiles.json
  REQUIRE(save_geometric_tile_set(dir, tiny_set()).ok());
  std::filesystem::remove(dir + "/tile_0.obj");
  const auto r = load_geometric_tile_set(dir);
  REQUIRE(r.error().code() == status_code::io_error);
  REQUIRE(r.error().message().find("tile_0.obj") != std::string::npos);
  REQUIRE_FALSE(save_geometric_tile_set(dir, geometric_tile_set{}).ok());
}

TEST_CASE("loading rejects a tile with geometry outside the tile", "[tile_files]") {
  const std::string dir = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_outside";
  std::filesystem::remove_all(dir);
  auto set = tiny_set();
  for (vec3& p : set.tiles[0].positions) p.x += 2;
  REQUIRE(save_geometric_tile_set(dir, set).ok());
  REQUIRE(load_geometric_tile_set(dir).error().message().find("outside the tile") != std::string::npos);
}

namespace {
// a complete three-axis set for one colour per axis: six tiles, one per cube face, a torus in each
geometric_tile_set tiny_three_axis_set() {
  geometric_tile_set s;
  s.tile_size = 2.5;
  s.axis_colors = {1, 1, 1};
  for (int f = 0; f < 6; ++f) {
    const axis_tile at = axis_tile_at(f, s.axis_colors);
    tri_mesh t;
    detail::add_torus(t, {1.25, 1.25, 0.2 + 0.01 * f}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.1, 10, 5);
    s.tiles.push_back(t);
    s.edges.push_back(at.edges);
    s.faces.push_back(at.face);
  }
  return s;
}
std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }
}  // namespace

TEST_CASE("three-axis tile sets save and load exactly (manifest version 2)", "[tile_files]") {
  const std::string dir = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_three_axis";
  std::filesystem::remove_all(dir);
  const auto set = tiny_three_axis_set();
  REQUIRE(save_geometric_tile_set(dir, set).ok());
  const std::string text = read_text(dir + "/tiles.json");
  REQUIRE(text.find("\"version\": 2") != std::string::npos);
  REQUIRE(text.find("\"axis_colors\": [1, 1, 1]") != std::string::npos);
  REQUIRE(text.find("\"face\": 5") != std::string::npos);
  REQUIRE(text.find("horizontal_colors") == std::string::npos);
  const auto back = load_geometric_tile_set(dir);
  REQUIRE(back.ok());
  REQUIRE(back->three_axis());
  REQUIRE(back->axis_colors == set.axis_colors);
  REQUIRE(back->faces == set.faces);
  REQUIRE(back->edges == set.edges);
  REQUIRE(back->tiles == set.tiles);
  // planar sets keep the version-1 layout older readers know
  const std::string planar = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_planar_v1";
  std::filesystem::remove_all(planar);
  REQUIRE(save_geometric_tile_set(planar, tiny_set()).ok());
  REQUIRE(read_text(planar + "/tiles.json").find("version") == std::string::npos);
  REQUIRE_FALSE(load_geometric_tile_set(planar)->three_axis());
}

TEST_CASE("three-axis manifests of another version, or with bad faces, fail clearly", "[tile_files]") {
  const std::string dir = std::string(TESSERA_TEST_OUTPUT_DIR) + "/geometric_tiles_three_axis_bad";
  std::filesystem::remove_all(dir);
  REQUIRE(save_geometric_tile_set(dir, tiny_three_axis_set()).ok());
  const std::string good = read_text(dir + "/tiles.json");
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    write_text(dir + "/tiles.json", t);
    return load_geometric_tile_set(dir);
  };
  auto newer = with("\"version\": 2", "\"version\": 3");
  REQUIRE_FALSE(newer.ok());
  REQUIRE(newer.error().message().find("version 3") != std::string::npos);
  REQUIRE(with("\"version\": 2", "\"version\": 1").error().message().find("needs \"version\": 2") != std::string::npos);
  REQUIRE(with("\"face\": 5", "\"face\": 6").error().message().find("\"face\" must be in [0, 6)") != std::string::npos);
  REQUIRE(with(", \"face\": 5", "").error().message().find("missing \"face\"") != std::string::npos);
  REQUIRE(with("\"axis_colors\": [1, 1, 1]", "\"axis_colors\": [1, 0, 1]").error().message().find("axis_colors") !=
          std::string::npos);
  // a colour beyond its axis' range: the +Z tile's south side runs along X, which has one colour
  REQUIRE(with("[0, 0, 0, 0], \"face\": 4", "[0, 0, 1, 0], \"face\": 4").error().message().find("along X") !=
          std::string::npos);
  // image manifests may be three-axis too (image/axis_wang_tiles.hpp), with a whole tile size
  tile_manifest m;
  m.kind = tile_set_kind::image;
  m.tile_size = 8;
  m.axis_colors = {1, 1, 1};
  m.tiles.push_back({0, "tile_0.png", {}, {}, 0});
  REQUIRE(validate_tile_manifest(m).ok());
  m.tile_size = 8.5;
  REQUIRE(validate_tile_manifest(m).message().find("whole number") != std::string::npos);
}
