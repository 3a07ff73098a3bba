// The code blocks of docs/terrain.md that are not cut from example 40, compiled and run
// (tests/structural/snippets.cmake keeps the page identical to the regions between the markers).
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/terrain/render_anchored_frame.hpp>
#include <tessera/terrain/terrain_camera.hpp>
#include <tessera/terrain/terrain_session.hpp>

#include "terrain_test_scenes.hpp"

TEST_CASE("docs: terrain.md cameras") {
  const auto mesh = terrain_test::prepared_terrain(16);
  const tessera::status result = [&] {
    // [snippet:terrain_cameras]
    // a perspective camera: where it is, where it looks, which way is up (z is up in terrain scenes)
    const tessera::look_at_camera look{.eye = {32, -8, 20},    // world position of the eye
                                       .target = {32, 40, 0},  // the point it looks at (not the eye)
                                       .up = {0, 0, 1},        // not parallel to target - eye
                                       .fov_y_degrees = 55,    // vertical field of view, in (0, 180)
                                       .near = 0.05,           // near plane distance, > 0
                                       .far = 500};            // far plane distance, > near
    auto camera = tessera::make_camera(look, 640, 360);        // result<terrain_camera>: view, projection, viewport
    if (!camera) return camera.error();                        // names the field: eye == target, fov 180, ...
    // or a preset fitted to the scene's bounds: grazing (the paper's view), oblique, overview
    auto grazing = tessera::make_camera_preset(tessera::camera_preset::grazing, tessera::bounding_box(mesh), 640, 360);
    if (!grazing) return grazing.error();
    tessera::vec3 eye = tessera::camera_eye(*grazing);  // where the preset put the eye
    // [/snippet]
    CHECK(camera->width == 640);
    CHECK(tessera::is_finite(eye));
    return tessera::status{};
  }();
  CHECK(result.ok());
}

TEST_CASE("docs: terrain.md the session loop") {
  const auto mesh = terrain_test::prepared_terrain(16);
  tessera::thread_pool_executor pool(2);
  const auto exemplar =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::grass, {.width = 64, .height = 64});
  REQUIRE(exemplar);
  const auto pyramid = tessera::build_exemplar_pyramid(*exemplar, {.min_scale = 0.5}, pool).value();
  const std::vector<tessera::terrain_camera> cameras = {
      terrain_test::preset_camera(mesh, tessera::camera_preset::oblique, 96, 54),
      terrain_test::preset_camera(mesh, tessera::camera_preset::overview, 96, 54)};
  tessera::image_buffer<std::uint8_t, 3> frame(96, 54);
  const std::array<double, 3> sun = {0.45, -0.35, 0.8};
  auto check = [](const tessera::status& s) { return s.ok() ? 0 : 1; };
  auto warn = [](const tessera::status& s) { std::fprintf(stderr, "warning: %s\n", s.message().c_str()); };
  const int failed = [&] {
    // [snippet:terrain_session]
    auto session = tessera::make_terrain_session(mesh, exemplar->width(), exemplar->height(),
                                                 {.synthesis = {.seed = 7}, .min_scale = 0.5})
                       .value();
    for (const auto& camera : cameras) {
      if (auto s = session.update(mesh, camera, pool); !s) return check(s);  // another mesh, a bad camera
      const auto& st = session.stats();        // visible, resynthesized, stable_faces, continuous_fraction, ...
      if (!st.warning.ok()) warn(st.warning);  // nothing in view
      // session.corner_uv()[f], session.level()[f]: unchanged bit for bit for faces visible in the
      // previous frame at the same level; export_session_uvs(session) for a TSUV file (mapping 1)
      if (auto s = tessera::render_anchored_frame(mesh, session, pyramid, frame, {.sun = sun}, pool); !s)
        return check(s);
    }
    // [/snippet]
    return 0;
  }();
  CHECK(failed == 0);
}
