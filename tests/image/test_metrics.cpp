#include <tessera/image/metrics.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/core/random.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include "../support/test_support.hpp"

using tessera_test::crop;
using tessera_test::exemplar;
using tessera_test::user_image;

using tessera::index_t;

namespace {

tessera::image_buffer<std::uint8_t, 3> noise(index_t w, index_t h, std::uint64_t seed) {
  tessera::image_buffer<std::uint8_t, 3> img(w, h);
  const tessera::counter_rng rng(seed);
  for (index_t i = 0; i < w * h * 3; ++i) img.data()[i] = static_cast<std::uint8_t>(rng.below(256, i));
  return img;
}

// Pearson correlation of the image with itself shifted by (dx, dy), all channels pooled.
template <class T, int C>
double brute_autocorrelation(const tessera::image_buffer<T, C>& img, index_t dx, index_t dy) {
  const index_t w = img.width(), h = img.height();
  double cov = 0, va = 0, vb = 0;
  for (int c = 0; c < C; ++c) {
    double sa = 0, sb = 0, n = 0;
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x)
        if (x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h) {
          sa += tessera::channel_to_unit(img.read(x, y)[c]);
          sb += tessera::channel_to_unit(img.read(x + dx, y + dy)[c]);
          n += 1;
        }
    const double ma = sa / n, mb = sb / n;
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x)
        if (x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h) {
          const double a = tessera::channel_to_unit(img.read(x, y)[c]) - ma;
          const double b = tessera::channel_to_unit(img.read(x + dx, y + dy)[c]) - mb;
          cov += a * b;
          va += a * a;
          vb += b * b;
        }
  }
  return cov / std::sqrt(va * vb);
}

}  // namespace

TEST_CASE("neighborhood_energy: zero for the exemplar and its crops, large for noise", "[metrics]") {
  const auto ex = exemplar(tessera::exemplar_kind::rock, 48);
  CHECK(tessera::neighborhood_energy(ex, ex).value() == Approx(0).margin(1e-12));
  const auto part = crop(ex, 7, 11, 30, 25);
  CHECK(tessera::neighborhood_energy(part, ex).value() == Approx(0).margin(1e-12));
  const double e_noise = tessera::neighborhood_energy(noise(40, 40, 3), ex).value();
  const double e_other = tessera::neighborhood_energy(exemplar(tessera::exemplar_kind::dots, 40), ex).value();
  CHECK(e_noise > 0.2);
  CHECK(e_other > 0.05);
}

TEST_CASE("neighborhood_energy: kd-tree search equals brute force, any executor", "[metrics]") {
  const auto ex = exemplar(tessera::exemplar_kind::grass, 40);
  const auto other = exemplar(tessera::exemplar_kind::grass, 36, 7);  // same kind, other seed: near but not equal
  for (index_t window : {3, 5}) {
    const tessera::neighborhood_energy_options fast{.window = window, .sample_step = 3};
    auto brute = fast;
    brute.brute_force = true;
    const double a = tessera::neighborhood_energy(other, ex, fast).value();
    const double b = tessera::neighborhood_energy(other, ex, brute).value();
    CHECK(a == Approx(b).epsilon(1e-12));
    CHECK(a > 0.0);
    tessera::thread_pool_executor pool(2);
    CHECK(tessera::neighborhood_energy(other, ex, fast, pool).value() == a);
  }
}

TEST_CASE("neighborhood_energy: pixel types and channel conversion", "[metrics]") {
  const auto ex8 = exemplar(tessera::exemplar_kind::sand, 32);
  const auto exf = tessera::to_buffer<float, 3>(ex8).value();
  const auto out8 = exemplar(tessera::exemplar_kind::sand, 24, 9);
  user_image out16{24, 24, {}};
  for (index_t y = 0; y < 24; ++y)
    for (index_t x = 0; x < 24; ++x)
      out16.px.push_back(tessera::convert_pixel<std::array<std::uint16_t, 3>>(out8.read(x, y)));
  const double e8 = tessera::neighborhood_energy(out8, ex8).value();
  CHECK(tessera::neighborhood_energy(out16, exf).value() == Approx(e8).epsilon(1e-5));
  CHECK(tessera::neighborhood_energy(out8.cview(), exf).value() == Approx(e8).epsilon(1e-5));
  // a grey output against a colour exemplar: the exemplar is converted to grey (convert_pixel), so the
  // energy equals the one against a grey copy of the exemplar, and is 0 against its own source
  tessera::image_buffer<std::uint8_t, 1> grey(24, 24);
  tessera::image_buffer<float, 1> grey_ex(32, 32);
  REQUIRE(tessera::copy_image(out8, grey).ok());
  REQUIRE(tessera::copy_image(ex8, grey_ex).ok());
  const double e_grey = tessera::neighborhood_energy(grey, ex8).value();
  CHECK(e_grey == Approx(tessera::neighborhood_energy(grey, grey_ex).value()).epsilon(1e-6));
  CHECK(e_grey > 0.01);
  const auto grey_crop = crop(grey_ex, 4, 3, 20, 20);
  CHECK(tessera::neighborhood_energy(grey_crop, ex8).value() == Approx(0).margin(1e-6));
}

TEST_CASE("neighborhood_energy: bad input", "[metrics]") {
  const auto ex = exemplar(tessera::exemplar_kind::sand, 16);
  tessera::image_view<const std::uint8_t, 3> empty;
  CHECK(tessera::neighborhood_energy(empty, ex).error().code() == tessera::status_code::invalid_argument);
  CHECK(tessera::neighborhood_energy(ex, empty).error().code() == tessera::status_code::invalid_argument);
  auto r = tessera::neighborhood_energy(ex, ex, {.window = 0});
  CHECK(r.error().message().find("window") != std::string::npos);
  CHECK(!tessera::neighborhood_energy(ex, ex, {.window = 17}));
  CHECK(!tessera::neighborhood_energy(crop(ex, 0, 0, 4, 16), ex, {.window = 5}));
  CHECK(tessera::neighborhood_energy(ex, ex, {.window = 5, .sample_step = 0}).error().message().find("sample_step") !=
        std::string::npos);
}

TEST_CASE("seam_gradient_ratio: hand-computed values", "[metrics]") {
  // 4 x 2 grey image: columns 0 1 | 2 3 with a jump between columns 1 and 2
  tessera::image_buffer<float, 1> img(4, 2);
  const float v[2][4] = {{0.0f, 0.1f, 0.9f, 1.0f}, {0.0f, 0.1f, 0.9f, 1.0f}};
  for (index_t y = 0; y < 2; ++y)
    for (index_t x = 0; x < 4; ++x) img.write(x, y, {v[y][x]});
  // reference: horizontal steps of 0.1, no vertical change
  tessera::image_buffer<float, 1> ref(3, 3);
  for (index_t y = 0; y < 3; ++y)
    for (index_t x = 0; x < 3; ++x) ref.write(x, y, {0.1f * static_cast<float>(x)});
  const std::vector<tessera::seam_segment> seams = {{.vertical = true, .position = 2, .begin = 0, .end = 2}};
  CHECK(tessera::seam_gradient_ratio(img, seams, ref).value() == Approx(8.0).epsilon(1e-5));
  const std::vector<tessera::seam_segment> smooth = {{.vertical = true, .position = 1, .begin = 0, .end = 2}};
  CHECK(tessera::seam_gradient_ratio(img, smooth, ref).value() == Approx(1.0).epsilon(1e-5));
  // a horizontal seam needs vertical gradients, which this reference lacks
  const std::vector<tessera::seam_segment> horizontal = {{.vertical = false, .position = 1, .begin = 0, .end = 4}};
  CHECK(tessera::seam_gradient_ratio(img, horizontal, ref).error().code() == tessera::status_code::invalid_argument);
}

TEST_CASE("seam_gradient_ratio: texture seams against the exemplar", "[metrics]") {
  const auto grass = exemplar(tessera::exemplar_kind::grass, 64);
  // a seam inside the exemplar itself is as smooth as the texture
  const std::vector<tessera::seam_segment> inside = {{.vertical = true, .position = 32, .begin = 0, .end = 64},
                                                     {.vertical = false, .position = 20, .begin = 0, .end = 64}};
  const double own = tessera::seam_gradient_ratio(grass, inside, grass).value();
  CHECK(own > 0.5);
  CHECK(own < 1.6);
  // two unrelated textures side by side: a hard seam
  auto mixed = grass;
  const auto dots = exemplar(tessera::exemplar_kind::dots, 64);
  for (index_t y = 0; y < 64; ++y)
    for (index_t x = 32; x < 64; ++x) mixed.write(x, y, dots.read(x, y));
  const std::vector<tessera::seam_segment> cut = {{.vertical = true, .position = 32, .begin = 0, .end = 64}};
  CHECK(tessera::seam_gradient_ratio(mixed, cut, grass).value() > 2.0 * own);
}

TEST_CASE("seam_gradient_ratio: bad input", "[metrics]") {
  const auto img = exemplar(tessera::exemplar_kind::sand, 16);
  const std::vector<tessera::seam_segment> none;
  CHECK(!tessera::seam_gradient_ratio(img, none, img));
  for (auto s : {tessera::seam_segment{true, 0, 0, 4}, tessera::seam_segment{true, 16, 0, 4},
                 tessera::seam_segment{false, 5, 3, 3}, tessera::seam_segment{false, 5, 0, 17},
                 tessera::seam_segment{true, 5, -1, 2}}) {
    const std::vector<tessera::seam_segment> one = {s};
    auto r = tessera::seam_gradient_ratio(img, one, img);
    REQUIRE(!r);
    CHECK(r.error().code() == tessera::status_code::out_of_range);
    CHECK(r.error().message().find("seams[0]") != std::string::npos);
  }
  const std::vector<tessera::seam_segment> ok = {{true, 4, 0, 4}};
  tessera::image_buffer<std::uint8_t, 3> flat(8, 8, {7, 7, 7});
  CHECK(!tessera::seam_gradient_ratio(img, ok, flat));
  tessera::image_view<const std::uint8_t, 3> empty;
  CHECK(!tessera::seam_gradient_ratio(empty, ok, img));
  CHECK(!tessera::seam_gradient_ratio(img, ok, empty));
}

namespace {
// seam_step_ratio by its definition, with every box mean summed directly (no integral image)
template <int C>
double brute_step_ratio(const tessera::image_buffer<float, C>& img, const std::vector<tessera::seam_segment>& seams,
                        const tessera::image_buffer<float, C>& ref, index_t box) {
  auto mean = [&](const tessera::image_buffer<float, C>& im, index_t x0, index_t y0, int c) {
    double s = 0;
    for (index_t y = y0; y < y0 + box; ++y)
      for (index_t x = x0; x < x0 + box; ++x) s += im.pixel_ptr(x, y)[c];
    return s / static_cast<double>(box * box);
  };
  auto step = [&](const tessera::image_buffer<float, C>& im, bool vertical, index_t x, index_t y) {
    double d = 0;
    for (int c = 0; c < C; ++c)
      d += vertical ? std::abs(mean(im, x - box, y, c) - mean(im, x, y, c))
                    : std::abs(mean(im, x, y - box, c) - mean(im, x, y, c));
    return d / C;
  };
  double sum = 0, nv = 0, nh = 0;
  for (const auto& s : seams) {
    const index_t across = s.vertical ? img.width() : img.height();
    if (s.position < box || s.position + box > across) continue;
    for (index_t t = s.begin; t + box <= s.end; t += box) {
      sum += s.vertical ? step(img, true, s.position, t) : step(img, false, t, s.position);
      (s.vertical ? nv : nh) += 1;
    }
  }
  double rx = 0, ry = 0, cx = 0, cy = 0;
  for (index_t y = 0; y + box <= ref.height(); ++y)
    for (index_t x = box; x + box <= ref.width(); ++x, ++cx) rx += step(ref, true, x, y);
  for (index_t y = box; y + box <= ref.height(); ++y)
    for (index_t x = 0; x + box <= ref.width(); ++x, ++cy) ry += step(ref, false, x, y);
  const double expected = (nv * (cx > 0 ? rx / cx : 0) + nh * (cy > 0 ? ry / cy : 0)) / (nv + nh);
  return sum / (nv + nh) / expected;
}
}  // namespace

TEST_CASE("seam_step_ratio: equals its definition computed directly", "[metrics]") {
  // random images, seams and box sizes; the integral images must give the brute-force value
  const tessera::counter_rng rng(41);
  for (std::uint64_t trial = 0; trial < 12; ++trial) {
    const index_t w = 20 + static_cast<index_t>(rng.below(30, trial, 0)),
                  h = 20 + static_cast<index_t>(rng.below(30, trial, 1));
    const index_t box = 1 + static_cast<index_t>(rng.below(6, trial, 2));
    tessera::image_buffer<float, 3> img(w, h), ref(w + 3, h - 2);
    for (index_t i = 0; i < w * h * 3; ++i) img.data()[i] = static_cast<float>(rng.uniform(trial, 3, i));
    for (index_t i = 0; i < (w + 3) * (h - 2) * 3; ++i) ref.data()[i] = static_cast<float>(rng.uniform(trial, 4, i));
    std::vector<tessera::seam_segment> seams;
    for (std::uint64_t k = 0; k < 4; ++k) {
      const bool vertical = rng.below(2, trial, 5, k) == 0;
      const index_t across = vertical ? w : h, along = vertical ? h : w;
      const index_t begin = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(along / 2), trial, 6, k));
      seams.push_back(
          {vertical, 1 + static_cast<index_t>(rng.below(static_cast<std::uint64_t>(across - 1), trial, 7, k)), begin,
           begin + 1 + static_cast<index_t>(rng.below(static_cast<std::uint64_t>(along - begin), trial, 8, k))});
    }
    seams.push_back({true, w / 2, 0, h});  // at least one position that fits
    INFO("trial " << trial << ", box " << box);
    CHECK(tessera::seam_step_ratio(img, seams, ref, box).value() ==
          Approx(brute_step_ratio(img, seams, ref, box)).epsilon(1e-9));
  }
}

TEST_CASE("seam_step_ratio: a grid of brighter and darker patches shows more than in the one-pixel gradient",
          "[metrics]") {
  const auto rock = exemplar(tessera::exemplar_kind::rock, 96);
  // the exemplar itself, measured across a grid of lines: about as much as any two of its regions
  const auto lines = tessera::patch_seam_lines(24, 24, 6, 96, 96);
  const double own = tessera::seam_step_ratio(rock, lines, rock).value();
  CHECK(own > 0.6);
  CHECK(own < 1.5);
  // cells of 24 pixels alternately 0.12 brighter and darker, blended over a 5-pixel band around each line
  // (as a narrow feather band does): the step ratio rises clearly more than the one-pixel gradient ratio
  auto grid = tessera::to_buffer<float, 3>(rock, "rock").value();
  auto ramp = [](index_t p) {  // -1 / +1 by cell (lines at 3, 27, 51, 75), linear over the 5 pixels around each line
    auto sign = [](index_t q) { return ((q + 21) / 24) % 2 == 0 ? -1.0 : 1.0; };  // cell of q: floor((q - 3) / 24)
    const index_t line = (p + 21) / 24 * 24 - 21, near = p - line < 12 ? line : line + 24;
    if (std::abs(p - near) > 2) return sign(p);
    const double before = sign(near - 1), after = sign(near);
    return before + (after - before) * (static_cast<double>(p - (near - 2)) + 0.5) / 5.0;
  };
  for (index_t y = 0; y < 96; ++y)
    for (index_t x = 0; x < 96; ++x)
      for (int c = 0; c < 3; ++c) {
        float& v = grid.pixel_ptr(x, y)[c];
        v = std::clamp(v + static_cast<float>(0.06 * (ramp(x) + ramp(y))), 0.0f, 1.0f);
      }
  const double steps = tessera::seam_step_ratio(grid, lines, rock).value();
  const double gradient = tessera::seam_gradient_ratio(grid, lines, rock).value();
  const double own_gradient = tessera::seam_gradient_ratio(rock, lines, rock).value();
  CHECK(steps > 2.0 * own);                               // measured 2.09 against 0.78
  CHECK(steps / own > 1.25 * (gradient / own_gradient));  // measured 2.66 against 1.77
}

TEST_CASE("seam_step_ratio: bad input", "[metrics]") {
  const auto img = exemplar(tessera::exemplar_kind::sand, 32);
  const std::vector<tessera::seam_segment> none, mid = {{true, 16, 0, 32}};
  CHECK(tessera::seam_step_ratio(img, none, img).error().message().find("seam_step_ratio: seams is empty") !=
        std::string::npos);
  const std::vector<tessera::seam_segment> outside = {{true, 32, 0, 4}};
  CHECK(tessera::seam_step_ratio(img, outside, img).error().code() == tessera::status_code::out_of_range);
  CHECK(tessera::seam_step_ratio(img, mid, img, 0).error().message().find("box must be >= 1") != std::string::npos);
  const std::vector<tessera::seam_segment> near_border = {{true, 3, 0, 32}};  // no 8-pixel square left of it
  CHECK(tessera::seam_step_ratio(img, near_border, img).error().message().find("no seam position") !=
        std::string::npos);
  tessera::image_buffer<std::uint8_t, 3> small(10, 10, {1, 2, 3}), flat(32, 32, {7, 7, 7});
  CHECK(tessera::seam_step_ratio(img, mid, small).error().message().find("too small") != std::string::npos);
  CHECK(tessera::seam_step_ratio(img, mid, flat).error().message().find("flat") != std::string::npos);
  auto nan = tessera::to_buffer<float, 3>(img, "img").value();
  nan.pixel_ptr(5, 5)[1] = std::numeric_limits<float>::quiet_NaN();
  CHECK(!tessera::seam_step_ratio(nan, mid, img));
}

TEST_CASE("histogram_distance: identities and bounds", "[metrics]") {
  const auto a = exemplar(tessera::exemplar_kind::bricks, 32);
  CHECK(tessera::histogram_distance(a, a).value() == 0.0);
  // the same image in another pixel type and twice as large (2x2 replicated) has the same histogram
  tessera::image_buffer<float, 3> big(64, 64);
  for (index_t y = 0; y < 64; ++y)
    for (index_t x = 0; x < 64; ++x)
      big.write(x, y, tessera::convert_pixel<tessera::pixel<float, 3>>(a.read(x / 2, y / 2)));
  CHECK(tessera::histogram_distance(a, big, 16).value() == Approx(0).margin(1e-12));
  tessera::image_buffer<std::uint8_t, 1> black(4, 4, {0}), white(5, 3, {255});
  CHECK(tessera::histogram_distance(black, white).value() == Approx(2.0));
  // half black half white against all black: |0.5 - 1| + |0.5 - 0| = 1
  tessera::image_buffer<std::uint8_t, 1> half(2, 1);
  half.write(1, 0, {255});
  CHECK(tessera::histogram_distance(half, black, 4).value() == Approx(1.0));
  const double d1 = tessera::histogram_distance(a, exemplar(tessera::exemplar_kind::grass, 32)).value();
  const double d2 = tessera::histogram_distance(exemplar(tessera::exemplar_kind::grass, 32), a).value();
  CHECK(d1 == Approx(d2));
  CHECK(d1 > 0.5);
  CHECK(d1 <= 2.0);
  // out-of-range floats are clamped, NaN counts as 0
  tessera::image_buffer<float, 1> odd(3, 1);
  odd.write(0, 0, {-1.0f});
  odd.write(1, 0, {std::nanf("")});
  odd.write(2, 0, {0.0f});
  CHECK(tessera::histogram_distance(odd, black).value() == Approx(0).margin(1e-12));
  CHECK(!tessera::histogram_distance(a, a, 0));
  CHECK(tessera::histogram_distance(a, a, 70000).error().message().find("bins") != std::string::npos);
  tessera::image_view<const std::uint8_t, 3> empty;
  CHECK(!tessera::histogram_distance(empty, a));
}

TEST_CASE("repetition_score: tiled images repeat, noise does not, and the score matches brute force", "[metrics]") {
  const auto tile = exemplar(tessera::exemplar_kind::rock, 24);
  tessera::image_buffer<std::uint8_t, 3> tiled(48, 48);
  for (index_t y = 0; y < 48; ++y)
    for (index_t x = 0; x < 48; ++x) tiled.write(x, y, tile.read(x % 24, y % 24));
  CHECK(tessera::repetition_score(tiled, 8).value() == Approx(1.0).margin(1e-9));
  CHECK(tessera::repetition_score(noise(48, 48, 5), 4).value() < 0.25);
  // brute-force oracle: the score is the max over the allowed offsets
  const auto img = exemplar(tessera::exemplar_kind::weave, 20);
  double best = 0;
  for (index_t dy = 0; dy <= 10; ++dy)
    for (index_t dx = -10; dx <= 10; ++dx)
      if (std::max(std::abs(dx), dy) >= 3) best = std::max(best, brute_autocorrelation(img, dx, dy));
  CHECK(tessera::repetition_score(img, 3).value() == Approx(best).epsilon(1e-9));
}

TEST_CASE("repetition_score: flat images and bad input", "[metrics]") {
  tessera::image_buffer<std::uint16_t, 2> flat(16, 8, {100, 65535});
  CHECK(tessera::repetition_score(flat, 2).value() == 0.0);
  CHECK(!tessera::repetition_score(flat, 0));
  auto r = tessera::repetition_score(flat, 9);
  REQUIRE(!r);
  CHECK(r.error().message().find("min_offset") != std::string::npos);
  tessera::image_view<const float, 1> empty;
  CHECK(!tessera::repetition_score(empty, 1));
}

namespace {
// Brute-force energy at 1/f: the output shrunk by f (f x f block means from (0, 0)) against every
// window of the exemplar shrunk by f at every block phase.
double brute_energy_at(const tessera::image_buffer<std::uint8_t, 3>& out,
                       const tessera::image_buffer<std::uint8_t, 3>& ex, index_t f, index_t window, index_t step) {
  auto shrink = [f](const tessera::image_buffer<std::uint8_t, 3>& img, index_t dx, index_t dy) {
    const index_t w = (img.width() - dx) / f, h = (img.height() - dy) / f;
    std::vector<double> v(static_cast<std::size_t>(w * h * 3), 0.0);
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) {
          double s = 0;
          for (index_t r = 0; r < f; ++r)
            for (index_t q = 0; q < f; ++q) s += tessera::channel_to_unit(img.read(dx + x * f + q, dy + y * f + r)[c]);
          v[static_cast<std::size_t>((y * w + x) * 3 + c)] = s / static_cast<double>(f * f);
        }
    return std::tuple{v, w, h};
  };
  const auto [o, ow, oh] = shrink(out, 0, 0);
  std::vector<std::tuple<std::vector<double>, index_t, index_t>> phases;
  for (index_t dy = 0; dy < f; ++dy)
    for (index_t dx = 0; dx < f; ++dx) phases.push_back(shrink(ex, dx, dy));
  double sum = 0;
  index_t count = 0;
  for (index_t qy = 0; qy + window <= oh; qy += step)
    for (index_t qx = 0; qx + window <= ow; qx += step) {
      double best = 1e300;
      for (const auto& [e, ew, eh] : phases)
        for (index_t y = 0; y + window <= eh; ++y)
          for (index_t x = 0; x + window <= ew; ++x) {
            double d = 0;
            for (index_t r = 0; r < window; ++r)
              for (index_t q = 0; q < window * 3; ++q) {
                const double a = o[static_cast<std::size_t>(((qy + r) * ow + qx) * 3 + q)];
                const double b = e[static_cast<std::size_t>(((y + r) * ew + x) * 3 + q)];
                d += (a - b) * (a - b);
              }
            best = std::min(best, d);
          }
      sum += std::sqrt(best / static_cast<double>(window * window * 3));
      ++count;
    }
  return sum / static_cast<double>(count);
}
}  // namespace

TEST_CASE("multiscale_energy: every level against brute force, and copies at any offset score 0", "[metrics]") {
  const auto ex = exemplar(tessera::exemplar_kind::rock, 48);
  // a crop at an odd offset: shrinking on one block grid would score it like a different texture
  const auto part = crop(ex, 7, 11, 33, 29);
  const auto e = tessera::multiscale_energy(part, ex, {.window = 5, .sample_step = 2, .levels = 3}).value();
  REQUIRE(e.size() == 3);
  for (double v : e) CHECK(v == Approx(0).margin(1e-6));
  // another texture: level 0 is neighborhood_energy, every level matches brute force, any executor
  const auto other = exemplar(tessera::exemplar_kind::rock, 40, 9);
  const tessera::multiscale_energy_options o{.window = 3, .sample_step = 2, .levels = 3};
  const auto f = tessera::multiscale_energy(other, ex, o).value();
  CHECK(f[0] == tessera::neighborhood_energy(other, ex, {.window = 3, .sample_step = 2}).value());
  for (index_t l = 0; l < 3; ++l) {
    INFO("level " << l);
    CHECK(f[static_cast<std::size_t>(l)] == Approx(brute_energy_at(other, ex, index_t{1} << l, 3, 2)).epsilon(1e-5));
    CHECK(f[static_cast<std::size_t>(l)] > 0.0);
  }
  tessera::thread_pool_executor pool(2);
  CHECK(tessera::multiscale_energy(other, ex, o, pool).value() == f);
  auto brute = o;
  brute.brute_force = true;
  const auto g = tessera::multiscale_energy(other, ex, brute).value();
  for (std::size_t l = 0; l < 3; ++l) CHECK(g[l] == Approx(f[l]).epsilon(1e-9));
  // noise scores far higher than a texture of the same kind at every level
  const auto n = tessera::multiscale_energy(noise(40, 40, 3), ex, o).value();
  for (std::size_t l = 0; l < 3; ++l) CHECK(n[l] > f[l]);
}

TEST_CASE("multiscale_energy: bad input", "[metrics]") {
  const auto ex = exemplar(tessera::exemplar_kind::rock, 32);
  for (int levels : {0, 7}) {
    auto r = tessera::multiscale_energy(ex, ex, {.levels = levels});
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().message().find("levels") != std::string::npos);
  }
  auto too_small = tessera::multiscale_energy(ex, ex, {.window = 7, .levels = 4});  // 7 x 8 > 32
  REQUIRE_FALSE(too_small.ok());
  CHECK(too_small.error().message().find("window") != std::string::npos);
  CHECK_FALSE(tessera::multiscale_energy(ex, ex, {.sample_step = 0}).ok());
  CHECK_FALSE(tessera::multiscale_energy(tessera::image_buffer<std::uint8_t, 3>(), ex).ok());
}
