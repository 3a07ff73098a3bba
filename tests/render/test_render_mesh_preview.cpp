#include <tessera/render/render_mesh_preview.hpp>

#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

TEST_CASE("mesh preview renders a shaded mesh on the background", "[mesh_preview]") {
  const auto m = make_ring_exemplar({.size = 4, .ring_segments = 12, .tube_segments = 6});
  REQUIRE(m.ok());
  const auto img = render_mesh_preview(*m, {.width = 160, .height = 120});
  REQUIRE(img.ok());
  REQUIRE(img->width() == 160);
  index_t background = 0, covered = 0;
  for (index_t y = 0; y < 120; ++y)
    for (index_t x = 0; x < 160; ++x) {
      const std::uint8_t* p = img->pixel_ptr(x, y);
      (p[0] == 255 && p[1] == 255 && p[2] == 255 ? background : covered)++;
    }
  REQUIRE(covered > 500);
  REQUIRE(background > 500);
  // deterministic for any executor; top view differs from the oblique one
  thread_pool_executor pool(3);
  REQUIRE(render_mesh_preview(*m, {.width = 160, .height = 120}, pool)->data()[5000] == img->data()[5000]);
  const auto top = render_mesh_preview(*m, {.width = 160, .height = 120, .elevation_degrees = 90});
  REQUIRE(std::vector<std::uint8_t>(top->data(), top->data() + 160 * 120 * 3) !=
          std::vector<std::uint8_t>(img->data(), img->data() + 160 * 120 * 3));
  // grid overlay draws red lines
  const auto grid = render_mesh_preview(*m, {.width = 160, .height = 120, .elevation_degrees = 90, .grid_spacing = 2});
  index_t red = 0;
  for (index_t i = 0; i < 160 * 120; ++i) {
    const std::uint8_t* p = grid->data() + 3 * i;
    red += p[0] > 200 && p[1] < 60 && p[2] < 60;
  }
  REQUIRE(red > 100);
}

TEST_CASE("mesh preview rejects bad input", "[mesh_preview]") {
  const auto m = make_ring_exemplar({.size = 3, .ring_segments = 8, .tube_segments = 4});
  REQUIRE_FALSE(render_mesh_preview(*m, {.width = 0}).ok());
  REQUIRE_FALSE(render_mesh_preview(*m, {.azimuth_degrees = std::nan("")}).ok());
  REQUIRE_FALSE(render_mesh_preview(tri_mesh{}).ok());
  REQUIRE_FALSE(render_mesh_preview(*m, {.grid_spacing = -1}).ok());
}

TEST_CASE("mesh preview: coarse, huge and far-away grids finish quickly", "[mesh_preview][bad_input]") {
  const auto m = make_ring_exemplar({.size = 3, .ring_segments = 8, .tube_segments = 4});
  REQUIRE(m.ok());
  // `tessera render --grid 1e9` stepped along lines ~1e11 pixels long; 1e20 converted a double out
  // of index_t's range. Lines are now clipped to the image first.
  for (double g : {1e9, 1e20, 1e300, std::numeric_limits<double>::max()}) {
    INFO(g);
    REQUIRE(render_mesh_preview(*m, {.width = 64, .height = 48, .grid_spacing = g}).ok());
  }
  REQUIRE_FALSE(render_mesh_preview(*m, {.grid_spacing = std::numeric_limits<double>::infinity()}).ok());
  REQUIRE_FALSE(render_mesh_preview(*m, {.grid_spacing = std::nan("")}).ok());
  REQUIRE_FALSE(render_mesh_preview(*m, {.grid_spacing = 1e-300}).ok());  // too fine
  REQUIRE_FALSE(render_mesh_preview(*m, {.grid_spacing = 1, .grid_line_width = 0}).ok());
  REQUIRE_FALSE(render_mesh_preview(*m, {.grid_spacing = 1, .grid_line_width = 1 << 30}).ok());
  // far from the origin, x += spacing would not advance (1e17 + 1 == 1e17)
  tri_mesh far;
  far.positions = {{1e17, 0, 0}, {1e17 + 64, 0, 0}, {1e17, 64, 0}};
  far.faces = {{0, 1, 2}};
  REQUIRE(render_mesh_preview(far, {.width = 32, .height = 32, .elevation_degrees = 90, .grid_spacing = 1}).ok());
}

TEST_CASE("face-coloured preview: each face in its colour, shaded, bad colours and counts refused", "[mesh_preview]") {
  // two triangles side by side in the plane z = 0, seen from the top: the left one red, the right blue
  tri_mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  m.faces = {{0, 1, 2}, {1, 4, 5}};
  const std::vector<std::array<float, 3>> colors{{1, 0, 0}, {0, 0, 1}};
  const mesh_preview_options top{.width = 120, .height = 60, .elevation_degrees = 90};
  const auto img = render_face_colored_mesh_preview(m, colors, top);
  REQUIRE(img.ok());
  index_t reds = 0, blues = 0, others = 0;
  for (index_t i = 0; i < 120 * 60; ++i) {
    const std::uint8_t* p = img->data() + 3 * i;
    if (p[0] == 255 && p[1] == 255 && p[2] == 255) continue;  // background
    if (p[0] > 50 && p[1] == 0 && p[2] == 0)
      ++reds;
    else if (p[2] > 50 && p[0] == 0 && p[1] == 0)
      ++blues;
    else
      ++others;
  }
  REQUIRE(reds > 200);
  REQUIRE(blues > 200);
  REQUIRE(others == 0);
  // the left face is left of the right one in the picture
  index_t red_x = 0, blue_x = 0;
  for (index_t y = 0; y < 60; ++y)
    for (index_t x = 0; x < 120; ++x) {
      const std::uint8_t* p = img->pixel_ptr(x, y);
      if (p[0] > 50 && p[1] == 0 && p[2] == 0) red_x += x;
      if (p[2] > 50 && p[0] == 0 && p[1] == 0) blue_x += x;
    }
  REQUIRE(red_x / reds < blue_x / blues);
  // same picture on a pool
  thread_pool_executor pool(2);
  const auto again = render_face_colored_mesh_preview(m, colors, top, pool);
  REQUIRE(std::equal(img->data(), img->data() + 120 * 60 * 3, again->data()));
  // non-finite and out-of-range components are drawn as 0 and clamped, never undefined
  const std::vector<std::array<float, 3>> odd{{std::nanf(""), 7.0f, -3.0f},
                                              {std::numeric_limits<float>::infinity(), 0.5f, 0.5f}};
  const auto clamped = render_face_colored_mesh_preview(m, odd, top);
  REQUIRE(clamped.ok());
  // the count must match the faces
  REQUIRE(render_face_colored_mesh_preview(m, std::span(colors).first(1), top).error().code() ==
          status_code::invalid_argument);
  REQUIRE_FALSE(render_face_colored_mesh_preview(tri_mesh{}, {}, top).ok());
}
