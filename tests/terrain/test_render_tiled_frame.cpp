#include <tessera/terrain/render_tiled_frame.hpp>

#include <cmath>
#include <cstdint>

#include <catch2/catch.hpp>

#include <tessera/image/exemplars.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

TEST_CASE("render_tiled_frame: the exemplar repeats over the ground every `repeat` units", "[terrain][tiled]") {
  // a flat plane seen straight down: 16 world units over 128 pixels, so a repeat of 2 is 16 pixels
  const auto mesh = terrain_test::prepared_terrain(8, 1, 0.0);
  const auto cam = tessera::make_camera({.eye = {0.1, 0.05, 8},
                                         .target = {0.1, 0.05, 0},
                                         .up = {0, 1, 0},
                                         .fov_y_degrees = 90,
                                         .near = 0.5,
                                         .far = 20},
                                        128, 128)
                       .value();
  const auto proj = tessera::project_mesh(mesh, cam).value();
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, {.width = 32, .height = 32}).value();
  const auto tex = tessera::prepare_tiled_texture(ex).value();
  REQUIRE(tex.num_levels() == 6);
  REQUIRE(tex.level(5).width() == 1);
  tessera::image_buffer<float, 3> out(128, 128);
  REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, out, {.repeat = 2}));
  double err = 0, contrast = 0;
  for (index_t y = 2; y < 126; ++y)
    for (index_t x = 2; x < 110; ++x) {
      for (std::size_t k = 0; k < 3; ++k) {
        err = std::max<double>(err, std::abs(out.read(x, y)[k] - out.read(x + 16, y)[k]));
        contrast = std::max<double>(contrast, std::abs(out.read(x, y)[k] - out.read(x + 5, y)[k]));
      }
    }
  REQUIRE(err < 2e-3);
  REQUIRE(contrast > 0.1);
  // automatic repeat: about one texel per pixel at the nearest face
  REQUIRE(tessera::auto_tiled_repeat(mesh, proj, 32) == Approx(32 * 16.0 / 128).epsilon(0.02));
}

TEST_CASE("render_tiled_frame: executors, errors", "[terrain][tiled]") {
  const auto mesh = terrain_test::prepared_terrain(16);
  const auto proj =
      tessera::project_mesh(mesh, terrain_test::preset_camera(mesh, tessera::camera_preset::grazing)).value();
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::rock, {.width = 32, .height = 32}).value();
  const auto tex = tessera::prepare_tiled_texture(ex).value();
  tessera::image_buffer<std::uint8_t, 3> a(160, 90), b(160, 90);
  REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, a));
  tessera::thread_pool_executor pool(3);
  REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, b, {}, pool));
  REQUIRE(a == b);
  tessera::image_buffer<std::uint8_t, 3> wrong(16, 16);
  REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, wrong).message().find("viewport") != std::string::npos);
  REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, a, {.repeat = -1}).message().find("repeat") !=
          std::string::npos);
  REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, a, {.sun = {0, 0, NAN}}).message().find("sun") !=
          std::string::npos);
  tessera::image_buffer<std::uint8_t, 3> lit(160, 90);
  REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, lit, {.sun = {1, 0, 0.2}, .ambient = 0.1}));
  long darker = 0;
  for (index_t y = 0; y < 90; ++y)
    for (index_t x = 0; x < 160; ++x) darker += lit.read(x, y)[1] < a.read(x, y)[1] ? 1 : 0;
  REQUIRE(darker > 160 * 20);
  REQUIRE_FALSE(tessera::render_tiled_frame(mesh, proj, tessera::tiled_texture<std::uint8_t, 3>{}, a));
  REQUIRE_FALSE(tessera::prepare_tiled_texture(tessera::image_buffer<std::uint8_t, 3>{}));
}
