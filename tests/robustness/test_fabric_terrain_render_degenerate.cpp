// Degenerate-content matrix of the fabric, terrain and render families: each entry point on flat,
// tiny, one-row, non-finite and zero-alpha images, degenerate meshes, and out-of-range enum values.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/fabric/cat_map.hpp>
#include <tessera/fabric/life_perturbation.hpp>
#include <tessera/fabric/make_fabric.hpp>
#include <tessera/fabric/source_image.hpp>
#include <tessera/fabric/tone_proportions.hpp>
#include <tessera/render/triangle_rasterizer.hpp>
#include <tessera/terrain/assign_scale_field.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/prepare_terrain_mesh.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/render_terrain_frame.hpp>
#include <tessera/terrain/render_tiled_frame.hpp>
#include <tessera/terrain/synthesize_triangles.hpp>
#include <tessera/terrain/terrain_camera.hpp>

#include "robustness_support.hpp"

using robust::index_t;

namespace {

template <class T, int C>
void run_fabric_matrix() {
  for (const auto& [name, img] : robust::degenerate_images<T, C>()) {
    INFO("input: " << name << " (" << img.width() << " x " << img.height() << ")");
    const auto copy = img;
    const bool bad = robust::non_finite_case(name);
    tessera::image_buffer<T, C> out(img.width(), img.height());
    robust::ok_or_refused(tessera::cat_map(img, out, 5));
    robust::ok_or_refused(tessera::cat_map(img, out, 5, {.non_square = tessera::non_square_mode::square_tiles}));
    robust::ok_or_refused(tessera::cat_map_step(img, out, {.non_square = tessera::non_square_mode::centered_square}));
    if (robust::ok_or_refused(tessera::life_perturbation(img, out, {.generations = 2}))) CHECK_FALSE(bad);
    tessera::image_buffer<T, C> cloth(20, 20);
    if (robust::ok_or_refused(tessera::make_fabric(
            img, cloth, {.iterations = 3, .tile_size = 16, .fit = tessera::source_fit::crop_or_repeat})))
      CHECK_FALSE(bad);
    // tones ignore alpha, where the "one -infinity" case puts its value (the last channel)
    const bool bad_colour = bad && !(name == "one -infinity" && (C == 2 || C == 4));
    const tessera::palette tones{{{0.1f, 0.2f, 0.3f}, 0.5}, {{0.9f, 0.8f, 0.7f}, 0.5}};
    if (robust::ok_or_refused_result(tessera::tone_proportions(img, tones))) CHECK_FALSE(bad_colour);
    for (int k : {1, 2, 5}) {
      auto dom = tessera::dominant_tones(img, k);
      if (robust::ok_or_refused_result(dom)) CHECK_FALSE(bad_colour);
    }
    CHECK(std::equal(img.data(), img.data() + img.width() * img.height() * C, copy.data(),
                     [](T a, T b) { return a == b || (a != a && b != b); }));
  }
}

template <class T, int C>
void run_pyramid_matrix() {
  for (const auto& [name, img] : robust::degenerate_images<T, C>()) {
    INFO("input: " << name);
    const bool bad = robust::non_finite_case(name);
    if (robust::ok_or_refused_result(tessera::build_exemplar_pyramid(img, {.min_scale = 0.5, .levels = 4})))
      CHECK_FALSE(bad);
    if (robust::ok_or_refused_result(tessera::prepare_tiled_texture(img))) CHECK_FALSE(bad);
  }
}

}  // namespace

TEST_CASE("robustness: fabric entry points on degenerate uint8 RGB images") { run_fabric_matrix<std::uint8_t, 3>(); }
TEST_CASE("robustness: fabric entry points on degenerate float RGBA images") { run_fabric_matrix<float, 4>(); }
TEST_CASE("robustness: fabric entry points on degenerate uint16 grey images") { run_fabric_matrix<std::uint16_t, 1>(); }

TEST_CASE("robustness: fabric options out of range are refused") {
  const auto img = robust::noise<std::uint8_t, 3>(16, 16, 1);
  tessera::image_buffer<std::uint8_t, 3> out(16, 16);
  robust::check_refusal(tessera::cat_map(img, out, 1, {.non_square = static_cast<tessera::non_square_mode>(9)}));
  robust::check_refusal(tessera::cat_map(img, out, 1, {.strategy = static_cast<tessera::cat_map_strategy>(-2)}));
  robust::check_refusal(tessera::life_perturbation(img, out, {.live_test = static_cast<tessera::life_test>(5)}));
  robust::check_refusal(tessera::make_fabric(static_cast<tessera::fabric_preset>(17), out));
  robust::check_refusal(tessera::make_fabric(img, out, {.fit = static_cast<tessera::source_fit>(3)}));
  const tessera::palette tones{{{0.1f, 0.2f, 0.3f}, 1.0}};
  robust::check_refusal(tessera::make_source_image(out, tones, {.layout = static_cast<tessera::source_layout>(4)}));
  robust::check_refusal(tessera::make_source_image(out, tessera::palette{}, {}));
  robust::check_refusal(tessera::make_fabric(img, out, {.tile_size = index_t{1} << 40}));
  tessera::image_buffer<std::uint8_t, 3> wide(4096, 1);
  robust::ok_or_refused(
      tessera::make_fabric(img, wide, {.iterations = 1, .tile_size = 32, .fit = tessera::source_fit::crop_or_repeat}));
}

TEST_CASE("robustness: terrain pyramid and tiled texture on degenerate images") {
  run_pyramid_matrix<std::uint8_t, 3>();
  run_pyramid_matrix<float, 1>();
  run_pyramid_matrix<std::uint16_t, 4>();
}

TEST_CASE("robustness: terrain pipeline on degenerate meshes") {
  for (const auto& [name, mesh] : robust::degenerate_meshes()) {
    INFO("mesh: " << name);
    auto prepared = tessera::prepare_terrain_mesh(mesh);
    if (!robust::ok_or_refused_result(prepared)) continue;
    const tessera::aabb box = tessera::bounding_box(mesh);
    for (auto preset :
         {tessera::camera_preset::grazing, tessera::camera_preset::oblique, tessera::camera_preset::overview}) {
      auto cam = tessera::make_camera_preset(preset, box, 48, 32);
      if (!robust::ok_or_refused_result(cam)) continue;
      auto proj = tessera::project_mesh(*prepared, *cam);
      if (!robust::ok_or_refused_result(proj)) continue;
      auto field = tessera::assign_scale_field(*prepared, *proj, {.min_scale = 0.5, .max_levels = 4});
      if (!robust::ok_or_refused_result(field)) continue;
      auto syn = tessera::synthesize_triangles(*prepared, *proj, *field, 24, 24);
      if (!robust::ok_or_refused_result(syn)) continue;
      const auto ex = robust::noise<std::uint8_t, 3>(24, 24, 3);
      auto pyr = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.5, .levels = 4}).value();
      tessera::image_buffer<std::uint8_t, 3> frame(48, 32);
      robust::ok_or_refused(tessera::render_terrain_frame(*prepared, *proj, *field, *syn, pyr, frame));
      auto tex = tessera::prepare_tiled_texture(ex).value();
      robust::ok_or_refused(tessera::render_tiled_frame(*prepared, *proj, tex, frame));
    }
  }
}

TEST_CASE("robustness: terrain options and enums out of range are refused") {
  auto mesh = tessera::prepare_terrain_mesh(tessera::make_terrain({.cells_x = 4, .cells_y = 4}).value()).value();
  const tessera::aabb box = tessera::bounding_box(mesh);
  robust::check_refusal(tessera::make_camera_preset(static_cast<tessera::camera_preset>(3), box, 32, 32).error());
  auto cam = tessera::make_camera_preset(tessera::camera_preset::oblique, box, 32, 32).value();
  auto bad_cam = cam;
  bad_cam.depth = static_cast<tessera::clip_depth>(2);
  robust::check_refusal(tessera::project_mesh(mesh, bad_cam).error());
  auto proj = tessera::project_mesh(mesh, cam).value();
  robust::check_refusal(tessera::assign_scale_field(mesh, proj, {.mode = static_cast<tessera::scale_mode>(2)}).error());
  auto field = tessera::assign_scale_field(mesh, proj, {.min_scale = 0.5, .max_levels = 4}).value();
  tessera::triangle_synthesis_options so;
  so.placement = static_cast<tessera::placement_strategy>(-1);
  robust::check_refusal(tessera::synthesize_triangles(mesh, proj, field, 24, 24, so).error());
  so = {};
  so.continuation = static_cast<tessera::continuation_rule>(2);
  robust::check_refusal(tessera::synthesize_triangles(mesh, proj, field, 24, 24, so).error());
  auto syn = tessera::synthesize_triangles(mesh, proj, field, 24, 24).value();
  const auto ex = robust::noise<std::uint8_t, 3>(24, 24, 3);
  auto pyr = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.5, .levels = 4}).value();
  tessera::image_buffer<std::uint8_t, 3> frame(32, 32);
  robust::check_refusal(tessera::render_terrain_frame(mesh, proj, field, syn, pyr, frame,
                                                      {.shading = static_cast<tessera::terrain_shading>(3)}));
  auto bad_proj = proj;
  bad_proj.depth = static_cast<tessera::clip_depth>(5);
  robust::check_refusal(tessera::synthesize_triangles(mesh, bad_proj, field, 24, 24).error());
  robust::check_refusal(tessera::make_terrain({.cells_x = index_t{1} << 40, .cells_y = 1 << 20}).error());
  robust::check_refusal(tessera::build_exemplar_pyramid(ex, {.levels = 1 << 20}).error());
}

TEST_CASE("robustness: the rasterizer on degenerate triangles and bad enums") {
  using tessera::raster_triangle;
  const tessera::pixel_rect clip{0, 0, 16, 16};
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<raster_triangle> tris = {
      raster_triangle{{{1, 1, 0, 1}, {1, 1, 0, 1}, {1, 1, 0, 1}}},               // a point
      raster_triangle{{{1, 1, 0, 1}, {5, 5, 0, 1}, {9, 9, 0, 1}}},               // a line
      raster_triangle{{{nan, 1, 0, 1}, {5, 5, 0, 1}, {9, 1, 0, 1}}},             // NaN
      raster_triangle{{{inf, 1, 0, 1}, {5, 5, 0, 1}, {9, 1, 0, 1}}},             // infinity
      raster_triangle{{{1e300, 1, 0, 1}, {-1e300, 5, 0, 1}, {9, 1e300, 0, 1}}},  // huge
      raster_triangle{{{1, 1, 0, 0}, {5, 5, 0, 1}, {9, 1, 0, 1}}},               // inv_w 0
      raster_triangle{{{-5, -5, 0, 1}, {40, -5, 0, 1}, {-5, 40, 0, 1}}},         // covers the clip
  };
  for (std::size_t i = 0; i < tris.size(); ++i) {
    INFO("triangle " << i);
    index_t n = 0;
    bool inside = true;
    REQUIRE(tessera::rasterize_triangle(tris[i], clip, [&](const tessera::fragment& f) {
      ++n;
      inside = inside && f.x >= 0 && f.x < 16 && f.y >= 0 && f.y < 16;
    }));
    CHECK(inside);
    CHECK(n <= 256);
  }
  auto get = [&](index_t i, raster_triangle& t) {
    t = tris[static_cast<std::size_t>(i)];
    return true;
  };
  std::vector<int> hits(256, 0);
  REQUIRE(tessera::rasterize_triangles(
      static_cast<index_t>(tris.size()), clip, get,
      [&](index_t, const tessera::fragment& f) { ++hits[static_cast<std::size_t>(f.y * 16 + f.x)]; }));
  auto noop = [](const tessera::fragment&) {};
  robust::check_refusal(tessera::rasterize_triangle(tris[6], clip, noop, static_cast<tessera::face_culling>(3)));
  robust::check_refusal(tessera::rasterize_triangles(1, clip, get, [](index_t, const tessera::fragment&) {},
                                                     {.culling = static_cast<tessera::face_culling>(-1)}));
  tessera::raster_viewport vp{0, 0, 16, 16};
  vp.depth = static_cast<tessera::clip_depth>(4);
  const tessera::clip_triangle ct{{{-1, -1, 0, 1}, {1, -1, 0, 1}, {0, 1, 0, 1}}};
  robust::check_refusal(tessera::rasterize_clip_triangle(ct, vp, clip, noop));
  robust::check_refusal(tessera::rasterize_triangle(tris[0], {0, 0, index_t{1} << 40, 4}, noop));
  robust::check_refusal(tessera::depth_buffer::create(index_t{1} << 19, index_t{1} << 19).error());
  robust::check_refusal(tessera::depth_buffer::create(0, 4).error());
}
