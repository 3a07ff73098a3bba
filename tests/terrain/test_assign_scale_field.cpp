#include <tessera/terrain/assign_scale_field.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <catch2/catch.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

namespace {
// brute-force maxδ and largest level jump over adjacent visible pairs
void check_field(const tessera::terrain_mesh& mesh, const tessera::screen_projection& proj,
                 const tessera::scale_field& f, const tessera::scale_field_options& opts) {
  double delta = 0, dmin = 1e300, dmax = -1e300;
  int jump = 0;
  for (index_t i = 0; i < mesh.num_faces(); ++i) {
    const auto fi = static_cast<std::size_t>(i);
    if (!proj.is_visible(i)) {
      REQUIRE(f.level[fi] == -1);
      continue;
    }
    const double d = tessera::norm(mesh.centroids[fi] - proj.eye);
    REQUIRE(f.distance[fi] == Approx(d).epsilon(1e-12));
    dmin = std::min(dmin, d), dmax = std::max(dmax, d);
    REQUIRE(f.level[fi] >= 0);
    REQUIRE(f.level[fi] < f.levels);
    REQUIRE(f.scale[fi] >= static_cast<float>(opts.min_scale));
    REQUIRE(f.scale[fi] <= 1.0f);
    for (std::int32_t n : mesh.neighbors[fi])
      if (n >= 0 && proj.is_visible(n)) {
        delta = std::max(delta, std::abs(d - tessera::norm(mesh.centroids[static_cast<std::size_t>(n)] - proj.eye)));
        jump = std::max(jump, std::abs(f.level[fi] - f.level[static_cast<std::size_t>(n)]));
      }
  }
  REQUIRE(jump <= 1);
  REQUIRE(f.max_level_jump == jump);
  REQUIRE(f.max_delta == Approx(delta).epsilon(1e-12));
  REQUIRE(f.min_distance == Approx(dmin));
  REQUIRE(f.max_distance == Approx(dmax));
  // the paper's count: the range cut into maxδ slices, capped by max_levels
  if (delta > 0) {
    const auto raw = static_cast<index_t>(std::floor((dmax - dmin) / delta)) + 1;
    REQUIRE(std::abs(f.levels - std::min(raw, opts.max_levels)) <= 1);
  }
}
}  // namespace

TEST_CASE("scale field: adjacent visible triangles never differ by more than one level (random scenes)",
          "[terrain][scale]") {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto mesh = terrain_test::prepared_terrain(12 + static_cast<index_t>(seed % 4) * 10, seed,
                                                     5.0 * static_cast<double>(seed % 5));
    const auto proj = tessera::project_mesh(mesh, terrain_test::random_camera(mesh, seed)).value();
    for (auto mode : {tessera::scale_mode::stepped, tessera::scale_mode::continuous})
      for (index_t max_levels : {index_t{2}, index_t{7}, index_t{64}, index_t{65536}}) {
        const tessera::scale_field_options opts{
            .min_scale = 0.25 + 0.05 * static_cast<double>(seed % 10), .max_levels = max_levels, .mode = mode};
        const auto f = tessera::assign_scale_field(mesh, proj, opts).value();
        INFO("seed " << seed << " max_levels " << max_levels);
        if (proj.num_visible() == 0) continue;
        check_field(mesh, proj, f, opts);
      }
  }
}

TEST_CASE("scale field: stepped scales follow the levels, nearest is 1, farthest min_scale", "[terrain][scale]") {
  const auto mesh = terrain_test::prepared_terrain(48);
  const auto proj =
      tessera::project_mesh(mesh, terrain_test::preset_camera(mesh, tessera::camera_preset::grazing)).value();
  const auto f = tessera::assign_scale_field(mesh, proj, {.min_scale = 0.4, .max_levels = 20}).value();
  REQUIRE(f.levels == 20);
  REQUIRE(f.level_width >= f.max_delta);
  std::vector<std::pair<double, std::int32_t>> by_distance;
  for (const std::int32_t i : proj.visible) {
    const auto fi = static_cast<std::size_t>(i);
    REQUIRE(f.scale[fi] == Approx(1 - 0.6 * f.level[fi] / 19.0).epsilon(1e-6));
    by_distance.push_back({f.distance[fi], f.level[fi]});
  }
  std::sort(by_distance.begin(), by_distance.end());
  for (std::size_t i = 1; i < by_distance.size(); ++i)
    REQUIRE(by_distance[i].second >= by_distance[i - 1].second);  // monotone
  REQUIRE(by_distance.front().second == 0);
  REQUIRE(by_distance.back().second == 19);
  REQUIRE(f.level_scale(19) == Approx(0.4));
}

TEST_CASE("scale field: the continuous variant ramps the scale with distance", "[terrain][scale]") {
  const auto mesh = terrain_test::prepared_terrain(32);
  const auto proj =
      tessera::project_mesh(mesh, terrain_test::preset_camera(mesh, tessera::camera_preset::oblique)).value();
  const auto f =
      tessera::assign_scale_field(mesh, proj, {.min_scale = 0.5, .mode = tessera::scale_mode::continuous}).value();
  for (const std::int32_t i : proj.visible) {
    const auto fi = static_cast<std::size_t>(i);
    const double t = (f.distance[fi] - f.min_distance) / (f.max_distance - f.min_distance);
    REQUIRE(f.scale[fi] == Approx(1 - 0.5 * t).epsilon(1e-6));
    REQUIRE(std::abs(f.level[fi] - t * static_cast<double>(f.levels - 1)) <= 0.5 + 1e-9);
  }
}

TEST_CASE("scale field: maxδ = 0 and maxδ larger than the range", "[terrain][scale]") {
  const auto cam = tessera::make_camera(
                       {.eye = {0, 0, 0}, .target = {0, 1, 0}, .fov_y_degrees = 90, .near = 0.1, .far = 100}, 64, 64)
                       .value();
  // isolated triangles at different distances: no adjacent pair, maxδ = 0 -> the finest division
  tessera::tri_mesh soup;
  for (int i = 0; i < 4; ++i) {
    const double y = 3.0 + 2 * i;
    const index_t a = soup.add_vertex({-0.3, y, -0.3}), b = soup.add_vertex({0.3, y, -0.3}),
                  c = soup.add_vertex({0, y, 0.3});
    soup.add_face(a, b, c);
  }
  auto mesh = tessera::prepare_terrain_mesh(soup).value();
  auto proj = tessera::project_mesh(mesh, cam).value();
  auto f = tessera::assign_scale_field(mesh, proj, {.max_levels = 10}).value();
  REQUIRE(f.max_delta == 0);
  REQUIRE(f.adjacent_pairs == 0);
  REQUIRE(f.levels == 10);
  REQUIRE(f.level[0] == 0);
  REQUIRE(f.level[3] == 9);
  // one triangle: a single level of scale 1
  tessera::tri_mesh one;
  one.add_vertex({-1, 5, -1}), one.add_vertex({1, 5, -1}), one.add_vertex({0, 5, 1}), one.add_face(0, 1, 2);
  mesh = tessera::prepare_terrain_mesh(one).value();
  proj = tessera::project_mesh(mesh, cam).value();
  f = tessera::assign_scale_field(mesh, proj).value();
  REQUIRE(f.levels == 1);
  REQUIRE(f.scale[0] == 1.0f);
  // two adjacent triangles, one near and one far: maxδ equals the range -> one level, stepped scale 1
  tessera::tri_mesh pair;
  pair.add_vertex({-1, 2, -1}), pair.add_vertex({1, 2, -1}), pair.add_vertex({0, 3, -1}), pair.add_vertex({0, 60, -1});
  pair.add_face(0, 1, 2), pair.add_face(1, 3, 2);
  mesh = tessera::prepare_terrain_mesh(pair).value();
  proj = tessera::project_mesh(mesh, cam).value();
  REQUIRE(proj.num_visible() == 2);
  f = tessera::assign_scale_field(mesh, proj, {.min_scale = 0.5}).value();
  REQUIRE(f.max_delta == Approx(f.max_distance - f.min_distance));
  REQUIRE(f.levels == 1);
  REQUIRE(f.scale[0] == 1.0f);
  REQUIRE(f.scale[1] == 1.0f);
  f = tessera::assign_scale_field(mesh, proj, {.min_scale = 0.5, .mode = tessera::scale_mode::continuous}).value();
  REQUIRE(f.scale[0] == 1.0f);
  REQUIRE(f.scale[1] == 0.5f);
  REQUIRE(f.level[1] == 0);
}

TEST_CASE("scale field: bad options, foreign projections, nothing visible", "[terrain][scale]") {
  const auto mesh = terrain_test::prepared_terrain(8);
  const auto proj =
      tessera::project_mesh(mesh, terrain_test::preset_camera(mesh, tessera::camera_preset::oblique)).value();
  for (double s : {0.0, -0.5, 1.5, std::nan("")}) {
    const auto r = tessera::assign_scale_field(mesh, proj, {.min_scale = s});
    REQUIRE(r.error().code() == tessera::status_code::invalid_argument);
    REQUIRE(r.error().message().find("min_scale") != std::string::npos);
  }
  REQUIRE(tessera::assign_scale_field(mesh, proj, {.min_scale = 1.0}));
  REQUIRE(tessera::assign_scale_field(mesh, proj, {.max_levels = 0}).error().message().find("max_levels") !=
          std::string::npos);
  const auto other = terrain_test::prepared_terrain(9);
  REQUIRE(tessera::assign_scale_field(other, proj).error().message().find("project this mesh") != std::string::npos);
  tessera::screen_projection none = proj;
  std::fill(none.state.begin(), none.state.end(), std::uint8_t{0});
  none.visible.clear();
  const auto f = tessera::assign_scale_field(mesh, none).value();
  REQUIRE(f.levels == 0);
  REQUIRE(f.max_level_jump == 0);
}

TEST_CASE("scale field: identical for any executor", "[terrain][scale]") {
  const auto mesh = terrain_test::prepared_terrain(150);  // > one 16384-face chunk
  const auto proj =
      tessera::project_mesh(mesh, terrain_test::preset_camera(mesh, tessera::camera_preset::grazing)).value();
  const auto a = tessera::assign_scale_field(mesh, proj).value();
  tessera::thread_pool_executor pool(3);
  const auto b = tessera::assign_scale_field(mesh, proj, {}, pool).value();
  REQUIRE(a.level == b.level);
  REQUIRE(a.scale == b.scale);
  REQUIRE(a.max_delta == b.max_delta);
}
