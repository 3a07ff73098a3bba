#include <tessera/terrain/project_mesh.hpp>

#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>
#include <glm/vec4.hpp>

#include "terrain_test_scenes.hpp"

using tessera::face_visibility;
using tessera::index_t;

namespace {
tessera::terrain_mesh triangles(std::initializer_list<std::array<tessera::vec3, 3>> tris) {
  tessera::tri_mesh m;
  for (const auto& t : tris) {
    const index_t a = m.add_vertex(t[0]), b = m.add_vertex(t[1]), c = m.add_vertex(t[2]);
    m.add_face(a, b, c);
  }
  return tessera::prepare_terrain_mesh(m).value();
}
// eye at the origin looking down -y... along +y, z up; 90 degree fov, 100 x 100 pixels
tessera::terrain_camera simple_camera() {
  return tessera::make_camera(
             {.eye = {0, 0, 0}, .target = {0, 1, 0}, .up = {0, 0, 1}, .fov_y_degrees = 90, .near = 0.1, .far = 100},
             100, 100)
      .value();
}
}  // namespace

TEST_CASE("project_mesh: screen positions follow projection * view and the viewport", "[terrain][project]") {
  const auto mesh = terrain_test::prepared_terrain(12);
  const auto cam = terrain_test::preset_camera(mesh, tessera::camera_preset::oblique, 200, 120);
  const auto proj = tessera::project_mesh(mesh, cam).value();
  REQUIRE(proj.width == 200);
  const glm::dvec4 eye = glm::inverse(cam.view) * glm::dvec4(0, 0, 0, 1);
  REQUIRE(tessera::norm(proj.eye - tessera::vec3{eye.x, eye.y, eye.z}) < 1e-9);
  for (index_t v = 0; v < mesh.num_vertices(); ++v) {
    const auto& p = mesh.position(v);
    const glm::dvec4 c = cam.projection * cam.view * glm::dvec4(p.x, p.y, p.z, 1);
    const auto& s = proj.screen[static_cast<std::size_t>(v)];
    REQUIRE(s.x == Approx((c.x / c.w + 1) * 100).margin(1e-9));
    REQUIRE(s.y == Approx((1 - c.y / c.w) * 60).margin(1e-9));
  }
  // the oblique preset sees the whole terrain
  REQUIRE(proj.num_visible() == mesh.num_faces());
  REQUIRE(proj.near_clipped == 0);
}

TEST_CASE("project_mesh: culling, partial visibility and the near plane", "[terrain][project]") {
  const auto mesh = triangles({
      {{{-1, 5, -1}, {1, 5, -1}, {0, 5, 1}}},        // 0: in front, inside
      {{{-1, -5, -1}, {1, -5, -1}, {0, -5, 1}}},     // 1: behind the eye
      {{{20, 5, -1}, {22, 5, -1}, {21, 5, 1}}},      // 2: far to the right, outside
      {{{4, 5, -1}, {6, 5, -1}, {5, 5, 1}}},         // 3: straddles the right border: kept whole
      {{{-3, -4, -1}, {3, -4, -1}, {0, 30, -1}}},    // 4: ground passing under and behind the eye
      {{{-1, 500, -1}, {1, 500, -1}, {0, 500, 1}}},  // 5: beyond the far plane
  });
  const auto proj = tessera::project_mesh(mesh, simple_camera()).value();
  auto st = [&](index_t f) { return static_cast<face_visibility>(proj.state[static_cast<std::size_t>(f)]); };
  REQUIRE(st(0) == face_visibility::inside);
  REQUIRE(st(1) == face_visibility::culled);
  REQUIRE(st(2) == face_visibility::culled);
  REQUIRE(st(3) == face_visibility::inside);
  REQUIRE(st(4) == face_visibility::near_clipped);
  REQUIRE(st(5) == face_visibility::culled);
  REQUIRE(proj.visible == std::vector<std::int32_t>{0, 3, 4});
  REQUIRE(proj.near_clipped == 1);
  // face 3 keeps its true corners (beyond the right border) but its bounds are clipped
  const auto& v3 = mesh.faces[3];
  REQUIRE(proj.screen[static_cast<std::size_t>(v3[1])].x > 100);
  REQUIRE(proj.bounds[3][2] == 100.0f);
  REQUIRE(proj.bounds[3][0] > 50.0f);
  // face 4: corners behind the eye have no screen position; the bounds come from the clipped part
  REQUIRE(std::isnan(proj.screen[static_cast<std::size_t>(mesh.faces[4][0])].x));
  REQUIRE(proj.bounds[4][3] == 100.0f);  // reaches the bottom of the screen
  REQUIRE(proj.bounds[4][1] > 50.0f);    // and stays below the horizon
}

TEST_CASE("project_mesh: back faces, empty and fully culled meshes", "[terrain][project]") {
  const auto mesh = triangles({{{{-1, 5, -1}, {1, 5, -1}, {0, 5, 1}}}, {{{-1, 5, -1}, {0, 5, 1}, {1, 5, -1}}}});
  const auto all = tessera::project_mesh(mesh, simple_camera()).value();
  REQUIRE(all.num_visible() == 2);
  const auto front = tessera::project_mesh(mesh, simple_camera(), {.cull_back_faces = true}).value();
  REQUIRE(front.num_visible() == 1);
  const auto empty = tessera::prepare_terrain_mesh(tessera::tri_mesh{}).value();
  const auto pe = tessera::project_mesh(empty, simple_camera());
  REQUIRE(pe);
  REQUIRE(pe->num_visible() == 0);
  const auto behind = triangles({{{{-1, -5, -1}, {1, -5, -1}, {0, -5, 1}}}});
  REQUIRE(tessera::project_mesh(behind, simple_camera())->num_visible() == 0);
}

TEST_CASE("project_mesh: invalid cameras and executor independence", "[terrain][project]") {
  const auto mesh = terrain_test::prepared_terrain(40);
  auto cam = terrain_test::preset_camera(mesh, tessera::camera_preset::grazing);
  cam.width = 0;
  REQUIRE(tessera::project_mesh(mesh, cam).error().message().find("viewport") != std::string::npos);
  cam = terrain_test::preset_camera(mesh, tessera::camera_preset::grazing);
  const auto a = tessera::project_mesh(mesh, cam).value();
  tessera::thread_pool_executor pool(3);
  tessera::screen_projection b;
  REQUIRE(tessera::project_mesh(mesh, cam, b, {}, pool));
  REQUIRE(a.visible == b.visible);
  REQUIRE(a.state == b.state);
  REQUIRE(a.bounds == b.bounds);
  REQUIRE(a.num_visible() > 100);
  REQUIRE(a.num_visible() < mesh.num_faces());
  // reusing the output for another camera gives the same as a fresh projection
  const auto cam2 = terrain_test::preset_camera(mesh, tessera::camera_preset::oblique);
  REQUIRE(tessera::project_mesh(mesh, cam2, b, {}, pool));
  REQUIRE(b.visible == tessera::project_mesh(mesh, cam2)->visible);
}
