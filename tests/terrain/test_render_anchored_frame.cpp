#include <tessera/terrain/render_anchored_frame.hpp>

#include <string>

#include <catch2/catch.hpp>
#include <tessera/image/exemplars.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;
using frame_t = tessera::image_buffer<float, 3>;

TEST_CASE("render_anchored_frame: perspective-correct coordinates from the session, same for any executor",
          "[terrain][session][render]") {
  const auto mesh = terrain_test::prepared_terrain(24, 1, 6);
  const auto ex =
      tessera::make_exemplar<float, 3>(tessera::exemplar_kind::sand, {.width = 64, .height = 64, .seed = 3}).value();
  const auto pyramid = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.5, .levels = 8}).value();
  auto s = tessera::make_terrain_session(mesh, 64, 64, {.blend_frames = 2}).value();
  const auto cam = terrain_test::preset_camera(mesh, tessera::camera_preset::oblique, 96, 64);
  frame_t a(96, 64), b(96, 64);
  REQUIRE_FALSE(tessera::render_anchored_frame(mesh, s, pyramid, a));  // no frame yet
  REQUIRE(s.update(mesh, cam));
  REQUIRE(tessera::render_anchored_frame(mesh, s, pyramid, a, {.feather = 0}));
  tessera::thread_pool_executor pool(3);
  REQUIRE(tessera::render_anchored_frame(mesh, s, pyramid, b, {.feather = 0}, pool));
  index_t textured = 0;
  for (index_t y = 0; y < 64; ++y)
    for (index_t x = 0; x < 96; ++x) {
      REQUIRE(a.read(x, y) == b.read(x, y));
      textured += a.read(x, y)[2] < 0.8f ? 1 : 0;  // the background is bluish (b = 0.88)
    }
  REQUIRE(textured > 96 * 64 / 5);
  // a pixel of a face: the colour is the pyramid at the face's level scale and its interpolated
  // coordinates; the face's centroid projects to a pixel whose coordinates are the corners' mean
  // (within the pixel's footprint): compare against the nearest sample of a 3 x 3 neighbourhood
  const auto& proj = s.projection();
  index_t checked = 0;
  for (const std::int32_t f : proj.visible) {
    if (checked > 40) break;
    if (proj.state[static_cast<std::size_t>(f)] != 1 || f % 7 != 0) continue;
    const auto& c = mesh.centroids[static_cast<std::size_t>(f)];
    const auto clip = cam.projection * cam.view * glm::dvec4(c.x, c.y, c.z, 1.0);
    const double px = (clip.x / clip.w + 1) * 48, py = (1 - clip.y / clip.w) * 32;
    const auto x = static_cast<index_t>(px), y = static_cast<index_t>(py);
    if (x < 0 || y < 0 || x >= 96 || y >= 64) continue;
    const auto& t = s.atlas().uv[static_cast<std::size_t>(f)];
    const double sc = s.level_scale(s.level()[static_cast<std::size_t>(f)]);
    const auto want = pyramid.sample(sc, ((t[0] + t[2] + t[4]) / 3 + 32) * sc, ((t[1] + t[3] + t[5]) / 3 + 32) * sc);
    REQUIRE(a.read(x, y)[0] == Approx(want[0]).margin(0.12));
    ++checked;
  }
  REQUIRE(checked > 5);
  // feathering changes only some pixels; bad calls are refused
  REQUIRE(tessera::render_anchored_frame(mesh, s, pyramid, b, {.feather = 2}));
  frame_t small(10, 10);
  REQUIRE(tessera::render_anchored_frame(mesh, s, pyramid, small).message().find("viewport") != std::string::npos);
  REQUIRE(tessera::render_anchored_frame(mesh, s, pyramid, a, {.feather = 99}).message().find("feather") !=
          std::string::npos);
  const auto other =
      tessera::build_exemplar_pyramid(
          tessera::make_exemplar<float, 3>(tessera::exemplar_kind::sand, {.width = 32, .height = 32, .seed = 3})
              .value(),
          {.levels = 4})
          .value();
  REQUIRE(tessera::render_anchored_frame(mesh, s, other, a).message().find("session's exemplar") != std::string::npos);
}
