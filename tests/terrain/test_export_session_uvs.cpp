#include <tessera/terrain/export_session_uvs.hpp>
#include <tessera/io/terrain_uv_file.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>

#include <catch2/catch.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

TEST_CASE("export_session_uvs: TSUV mapping 1, records bit-identical between frames for stable faces",
          "[terrain][session][uv]") {
  const auto mesh = terrain_test::prepared_terrain(32, 4, 6);
  auto s = tessera::make_terrain_session(mesh, 64, 64).value();
  REQUIRE(tessera::export_session_uvs(s).error().message().find("no frame yet") != std::string::npos);
  auto look = tessera::camera_preset_look_at(tessera::camera_preset::oblique, tessera::bounding_box(mesh)).value();
  REQUIRE(s.update(mesh, tessera::make_camera(look, 120, 80).value()));
  const auto a = tessera::export_session_uvs(s).value();
  const double step = 0.01 * tessera::norm(look.target - look.eye);
  look.eye.x += step, look.target.x += step;
  REQUIRE(s.update(mesh, tessera::make_camera(look, 120, 80).value()));
  const auto b = tessera::export_session_uvs(s).value();
  REQUIRE(b.mapping == 1);
  REQUIRE(b.levels == s.levels());
  const std::string path = (std::filesystem::temp_directory_path() / "tessera_test_session_uv.tsuv").string();
  REQUIRE(tessera::write_terrain_uv_file(path, b));
  const auto back = tessera::read_terrain_uv_file(path).value();
  std::remove(path.c_str());
  REQUIRE(back.mapping == 1);
  index_t common = 0, same = 0;
  for (std::size_t f = 0; f < b.state.size(); ++f) {
    REQUIRE(back.state[f] == b.state[f]);
    if (b.state[f] == 0) {
      REQUIRE(b.level[f] == -1);
      REQUIRE(std::isnan(b.corner_uv[f][0]));
      continue;
    }
    REQUIRE(std::isnan(b.offset[f][0]));
    REQUIRE(std::memcmp(back.corner_uv[f].data(), b.corner_uv[f].data(), 24) == 0);
    REQUIRE(b.scale[f] == static_cast<float>(s.level_scale(b.level[f])));
    if (a.state[f] == 0) continue;
    ++common;
    if (a.level[f] != b.level[f]) continue;
    ++same;
    REQUIRE(std::memcmp(a.corner_uv[f].data(), b.corner_uv[f].data(), 24) == 0);
  }
  REQUIRE(common > 1000);
  REQUIRE(same >= common * 95 / 100);
}
