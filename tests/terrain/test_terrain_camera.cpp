#include <tessera/terrain/terrain_camera.hpp>

#include <cmath>
#include <string>

#include <catch2/catch.hpp>
#include <glm/vec4.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

TEST_CASE("make_camera: builds GLM look-at and perspective matrices", "[terrain][camera]") {
  tessera::look_at_camera l{
      .eye = {1, 2, 3}, .target = {4, 6, 3}, .up = {0, 0, 1}, .fov_y_degrees = 70, .near = 0.5, .far = 50};
  const auto cam = tessera::make_camera(l, 320, 200).value();
  REQUIRE(cam.width == 320);
  REQUIRE(cam.height == 200);
  const glm::dmat4 ref = glm::perspective(glm::radians(70.0), 1.6, 0.5, 50.0) *
                         glm::lookAt(glm::dvec3(1, 2, 3), glm::dvec3(4, 6, 3), glm::dvec3(0, 0, 1));
  const glm::dmat4 got = cam.projection * cam.view;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) REQUIRE(got[i][j] == Approx(ref[i][j]).margin(1e-12));
  // the target projects to the viewport centre
  const glm::dvec4 c = got * glm::dvec4(4, 6, 3, 1);
  REQUIRE(c.x / c.w == Approx(0).margin(1e-12));
  REQUIRE(c.y / c.w == Approx(0).margin(1e-12));
}

TEST_CASE("make_camera: degenerate cameras are rejected with a message", "[terrain][camera]") {
  const tessera::look_at_camera ok{.eye = {0, 0, 5}, .target = {0, 10, 0}};
  REQUIRE(tessera::make_camera(ok, 64, 48));
  auto bad = [&](tessera::look_at_camera l, index_t w, index_t h, const std::string& needle) {
    const auto r = tessera::make_camera(l, w, h);
    REQUIRE_FALSE(r);
    REQUIRE(r.error().code() == tessera::status_code::invalid_argument);
    INFO(r.error().message());
    REQUIRE(r.error().message().find(needle) != std::string::npos);
  };
  auto l = ok;
  l.target = l.eye;
  bad(l, 64, 48, "equals its target");
  l = ok, l.up = {0, 10, -5};
  bad(l, 64, 48, "parallel");
  l = ok, l.up = {0, 0, 0};
  bad(l, 64, 48, "parallel");
  for (double fov : {0.0, 180.0, -10.0, 200.0, std::nan("")}) {
    l = ok, l.fov_y_degrees = fov;
    bad(l, 64, 48, "fov_y_degrees");
  }
  l = ok, l.near = 0;
  bad(l, 64, 48, "near");
  l = ok, l.far = l.near;
  bad(l, 64, 48, "far");
  l = ok, l.eye.x = INFINITY;
  bad(l, 64, 48, "finite");
  bad(ok, 0, 48, "viewport");
  bad(ok, 64, tessera::max_viewport_side + 1, "viewport");
}

TEST_CASE("validate_camera: non-finite or singular matrices", "[terrain][camera]") {
  auto cam = tessera::make_camera({.eye = {0, 0, 5}, .target = {0, 10, 0}}, 64, 48).value();
  REQUIRE(tessera::validate_camera(cam));
  auto c = cam;
  c.view[1][2] = NAN;
  REQUIRE(tessera::validate_camera(c).message().find("finite") != std::string::npos);
  c = cam;
  c.projection = glm::dmat4(0.0);
  REQUIRE(tessera::validate_camera(c).message().find("singular") != std::string::npos);
}

TEST_CASE("validate_camera: a projective view (eye at infinity) is rejected", "[terrain][camera]") {
  const auto cam = tessera::make_camera({.eye = {0, 0, 5}, .target = {0, 10, 0}}, 64, 48).value();
  REQUIRE(tessera::camera_eye(cam).z == Approx(5));
  // an invertible view whose inverse maps the origin to w = 0: the eye would be a point at infinity
  auto c = cam;
  c.view = glm::dmat4(1.0);
  // rows (1 0 0 0), (0 1 0 0), (0 0 0 1), (0 0 1 0): view * (0, 0, 1, 0) = (0, 0, 0, 1), so the
  // inverse maps the origin to (0, 0, 1, 0), w = 0 (GLM: view[column][row])
  c.view[2][2] = 0;
  c.view[3][2] = 1;
  c.view[2][3] = 1;
  c.view[3][3] = 0;
  REQUIRE(std::abs(glm::determinant(c.view)) > 0.5);
  REQUIRE((glm::inverse(c.view) * glm::dvec4(0, 0, 0, 1)).w == 0);
  const auto s = tessera::validate_camera(c);
  REQUIRE(s.code() == tessera::status_code::invalid_argument);
  REQUIRE(s.message().find("affine") != std::string::npos);
  // and project_mesh, which takes the eye from it, refuses it instead of making NaN distances
  const auto mesh = terrain_test::prepared_terrain(4);
  REQUIRE(tessera::project_mesh(mesh, c).error().message().find("affine") != std::string::npos);
  c = cam;
  c.view[3][3] = -1;  // negative w mirrors the eye
  REQUIRE_FALSE(tessera::validate_camera(c));
  c = cam;
  c.view[3][3] = 2;  // a uniformly scaled affine view is fine: the eye is still a point
  REQUIRE(tessera::validate_camera(c));
}

TEST_CASE("camera presets look at the scene", "[terrain][camera]") {
  const auto mesh = terrain_test::prepared_terrain(16);
  for (auto p : {tessera::camera_preset::grazing, tessera::camera_preset::oblique, tessera::camera_preset::overview}) {
    const auto cam = terrain_test::preset_camera(mesh, p);
    const auto b = tessera::bounding_box(mesh);
    const glm::dvec4 c = cam.projection * cam.view * glm::dvec4(b.center().x, b.center().y, b.min.z, 1);
    REQUIRE(c.w > 0);
    REQUIRE(std::abs(c.x / c.w) < 1);
    REQUIRE(std::abs(c.y / c.w) < 1);
  }
  REQUIRE(tessera::parse_camera_preset("grazing").value() == tessera::camera_preset::grazing);
  REQUIRE(tessera::parse_camera_preset("sideways").error().message().find("sideways") != std::string::npos);
  REQUIRE_FALSE(tessera::camera_preset_look_at(tessera::camera_preset::oblique, tessera::aabb{}));
}
