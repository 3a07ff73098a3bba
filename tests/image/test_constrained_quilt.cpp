#include <tessera/image/constrained_quilt.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/metrics.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;
using tessera::quilt_options;

namespace {
// masks: a disc, a ring, two rectangles touching the border, scattered specks
tessera::image_buffer<std::uint8_t, 1> make_mask(int kind, index_t w, index_t h) {
  tessera::image_buffer<std::uint8_t, 1> m(w, h);
  const tessera::counter_rng rng(kind);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      const double r = std::hypot(double(x) - w * 0.45, double(y) - h * 0.55);
      bool hole = false;
      if (kind == 0) hole = r < w * 0.22;
      if (kind == 1) hole = r > w * 0.15 && r < w * 0.25;
      if (kind == 2) hole = (x < 14 && y > 10 && y < 30) || (x > w - 20 && y > h - 12);
      if (kind == 3) hole = rng.uniform(x, y) < 0.03;
      m.write(x, y, {std::uint8_t(hole ? 255 : 0)});
    }
  return m;
}
}  // namespace

TEMPLATE_TEST_CASE("constrained quilt: pixels outside the mask are untouched bit for bit, the hole is filled",
                   "[quilt]", std::uint8_t, std::uint16_t, float) {
  const auto ex = quilt_test::exemplar<TestType, 4>(tessera::exemplar_kind::grass, 48, 7);
  const auto base = quilt_test::exemplar<TestType, 4>(tessera::exemplar_kind::grass, 64, 8);
  for (int kind = 0; kind < 4; ++kind) {
    const auto mask = make_mask(kind, 64, 56);
    tessera::image_buffer<TestType, 4> image(64, 56), out(64, 56);
    const auto sentinel =
        tessera::convert_pixel<tessera::pixel<TestType, 4>>(tessera::pixel<float, 4>{1.0f, 0.0f, 1.0f, 0.5f});
    for (index_t y = 0; y < 56; ++y)
      for (index_t x = 0; x < 64; ++x) image.write(x, y, mask.read(x, y)[0] ? sentinel : base.read(x, y));
    REQUIRE(tessera::constrained_quilt(ex, image, mask, out, {.patch_size = 12, .overlap = 3, .seed = 2}).ok());
    for (index_t y = 0; y < 56; ++y)
      for (index_t x = 0; x < 64; ++x) {
        if (mask.read(x, y)[0]) {
          REQUIRE(out.read(x, y) != sentinel);
        } else {
          const auto a = out.read(x, y), b = image.read(x, y);
          REQUIRE(std::memcmp(a.data(), b.data(), sizeof a) == 0);  // bit for bit
        }
      }
  }
}

TEST_CASE("constrained quilt: holes in the corner of the first window are filled", "[quilt]") {
  // isolated hole pixels at (0, 0) and within `overlap` of both the top and the left edge fall in
  // the corner region an L-shaped cut keeps old; they must still be filled
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::sand, 32, 3);
  const std::array<std::uint8_t, 3> sentinel{0, 255, 0};
  for (const auto& holes : std::vector<std::vector<std::pair<index_t, index_t>>>{
           {{0, 0}}, {{1, 1}, {2, 0}}, {{0, 0}, {3, 2}, {20, 20}}, {{0, 2}, {2, 0}, {1, 3}}}) {
    auto image = quilt_test::exemplar(tessera::exemplar_kind::sand, 40, 4);
    tessera::image_buffer<std::uint8_t, 1> mask(40, 40);
    for (const auto& [x, y] : holes) {
      mask.write(x, y, {255});
      image.write(x, y, sentinel);
    }
    tessera::image_buffer<std::uint8_t, 3> out(40, 40);
    REQUIRE(tessera::constrained_quilt(ex, image, mask, out, {.patch_size = 12, .overlap = 4}).ok());
    for (const auto& [x, y] : holes) REQUIRE(out.read(x, y) != sentinel);
  }
}

TEST_CASE("constrained quilt: inpainting from the image itself never copies the hole", "[quilt]") {
  auto image = quilt_test::exemplar(tessera::exemplar_kind::bricks, 96, 3);
  const auto mask = make_mask(0, 96, 96);
  const std::array<std::uint8_t, 3> sentinel{0, 255, 0};
  for (index_t y = 0; y < 96; ++y)
    for (index_t x = 0; x < 96; ++x)
      if (mask.read(x, y)[0]) image.write(x, y, sentinel);
  tessera::image_buffer<std::uint8_t, 3> out(96, 96), pooled(96, 96);
  REQUIRE(tessera::constrained_quilt(image, mask, out, {.patch_size = 16, .overlap = 4}).ok());
  tessera::thread_pool_executor pool(2);
  REQUIRE(tessera::constrained_quilt(image, mask, pooled, {.patch_size = 16, .overlap = 4}, pool).ok());
  REQUIRE(out == pooled);
  for (index_t y = 0; y < 96; ++y)
    for (index_t x = 0; x < 96; ++x) {
      REQUIRE(out.read(x, y) != sentinel);
      if (!mask.read(x, y)[0]) REQUIRE(out.read(x, y) == image.read(x, y));
    }
}

TEST_CASE("constrained quilt: the filled hole continues its surroundings", "[quilt]") {
  // a rectangular hole filled from the rest of the image: the seam across its border stays far
  // below pasting another window of the image into it (the cut cannot leave the hole, so this
  // measures how well the chosen patches continue the fixed surroundings)
  for (auto kind : {tessera::exemplar_kind::bricks, tessera::exemplar_kind::grass}) {
    const auto big = quilt_test::exemplar(kind, 96, 5);
    tessera::image_buffer<std::uint8_t, 1> mask(96, 96);
    for (index_t y = 30; y < 66; ++y)
      for (index_t x = 28; x < 70; ++x) mask.write(x, y, {255});
    tessera::image_buffer<std::uint8_t, 3> out(96, 96), pasted = big;
    REQUIRE(tessera::constrained_quilt(big, mask, out, {.patch_size = 16, .overlap = 5}).ok());
    for (index_t y = 30; y < 66; ++y)
      for (index_t x = 28; x < 70; ++x) pasted.write(x, y, big.read(x - 20, y - 25));
    const std::vector<tessera::seam_segment> border = {
        {true, 28, 30, 66}, {true, 70, 30, 66}, {false, 30, 28, 70}, {false, 66, 28, 70}};
    const double filled = tessera::seam_gradient_ratio(out, border, big).value();
    const double naive = tessera::seam_gradient_ratio(pasted, border, big).value();
    CAPTURE(to_string(kind), filled, naive);
    REQUIRE(filled < 0.6 * naive);
  }
}

TEST_CASE("constrained quilt: bad input", "[quilt]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::sand, 32);
  const auto image = quilt_test::exemplar(tessera::exemplar_kind::sand, 40);
  tessera::image_buffer<std::uint8_t, 1> mask(40, 40), wrong(40, 39);
  mask.write(20, 20, {255});
  tessera::image_buffer<std::uint8_t, 3> out(40, 40), wrong_out(41, 40);
  auto s = tessera::constrained_quilt(ex, image, wrong, out);
  REQUIRE(s.code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(s.message(), Catch::Contains("mask is 40 x 39") && Catch::Contains("image is 40 x 40"));
  REQUIRE(tessera::constrained_quilt(ex, image, mask, wrong_out).code() == tessera::status_code::invalid_argument);
  REQUIRE(tessera::constrained_quilt(image, wrong, out).code() == tessera::status_code::invalid_argument);
  REQUIRE(tessera::constrained_quilt(ex, image, mask, out, {.patch_size = 33}).code() ==
          tessera::status_code::invalid_argument);
  const auto tiny = quilt_test::exemplar(tessera::exemplar_kind::sand, 12);
  tessera::image_buffer<std::uint8_t, 1> tiny_mask(12, 12);
  tessera::image_buffer<std::uint8_t, 3> tiny_out(12, 12);
  REQUIRE_THAT(tessera::constrained_quilt(ex, tiny, tiny_mask, tiny_out, {.patch_size = 16}).message(),
               Catch::Contains("larger than the 12 x 12 image"));
  tessera::image_buffer<std::uint8_t, 1> everything(40, 40, {255});
  auto none = tessera::constrained_quilt(image, everything, out, {.patch_size = 8});
  REQUIRE(none.code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(none.message(), Catch::Contains("free of masked pixels"));
  // non-finite values in a float image or exemplar; images beyond the caps
  auto fex = quilt_test::exemplar<float, 3>(tessera::exemplar_kind::sand, 32);
  auto fimg = quilt_test::exemplar<float, 3>(tessera::exemplar_kind::sand, 40);
  tessera::image_buffer<float, 3> fout(40, 40);
  fimg.write(39, 0, {0.5f, 0.5f, std::numeric_limits<float>::infinity()});
  REQUIRE_THAT(tessera::constrained_quilt(fex, fimg, mask, fout).message(),
               Catch::Contains("image: pixel (39, 0) channel 2 is inf"));
  REQUIRE_THAT(tessera::constrained_quilt(fimg, mask, fout).message(),
               Catch::Contains("image: pixel (39, 0) channel 2 is inf"));
  fimg.write(39, 0, {0.5f, 0.5f, 0.5f});
  fex.write(0, 31, {std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f});
  REQUIRE_THAT(tessera::constrained_quilt(fex, fimg, mask, fout).message(),
               Catch::Contains("exemplar: pixel (0, 31) channel 0 is nan"));
  const quilt_test::huge_rgb8 huge{1 << 15, (1 << 13) + 1};
  quilt_test::huge_rgb8 huge_out = huge;
  auto big = tessera::constrained_quilt(ex, huge, huge, huge_out);
  REQUIRE(big.code() == tessera::status_code::size_overflow);
  REQUIRE_THAT(big.message(), Catch::Contains("image: 32768 x 8193 pixels exceed max_quilt_pixels"));
  const quilt_test::huge_rgb8 self{1 << 13, (1 << 13) + 1};  // inpainting from itself: the exemplar cap applies
  quilt_test::huge_rgb8 self_out = self;
  REQUIRE_THAT(tessera::constrained_quilt(self, self, self_out).message(),
               Catch::Contains("exceed max_quilt_exemplar_pixels"));
  // an empty mask copies the image
  tessera::image_buffer<std::uint8_t, 1> nothing(40, 40);
  REQUIRE(tessera::constrained_quilt(ex, image, nothing, out).ok());
  REQUIRE(out == image);
}
