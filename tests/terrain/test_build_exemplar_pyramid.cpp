#include <tessera/terrain/build_exemplar_pyramid.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/core/image_view.hpp>
#include <tessera/core/random.hpp>
#include <tessera/image/exemplars.hpp>

using tessera::index_t;

namespace {
// a member-style user image: grey floats from a function
struct wave_image {
  index_t w = 96, h = 80;
  double period = 24;
  [[nodiscard]] index_t width() const { return w; }
  [[nodiscard]] index_t height() const { return h; }
  [[nodiscard]] float read(index_t x, index_t y) const {
    return static_cast<float>(0.5 + 0.4 * std::sin(6.283185307179586 * (static_cast<double>(x) + 0.5) / period) *
                                        std::cos(6.283185307179586 * (static_cast<double>(y) + 0.5) / period));
  }
};
}  // namespace

TEST_CASE("exemplar pyramid: finely spaced levels from 1 to min_scale", "[terrain][pyramid]") {
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::rock, {.width = 64, .height = 48}).value();
  const auto p = tessera::build_exemplar_pyramid(ex).value();
  REQUIRE(p.num_levels() == 64);  // (1 - 0.5) / 0.008 = 62.5 steps -> 63 steps
  REQUIRE(p.scale(0) == 1.0);
  REQUIRE(p.scale(63) == Approx(0.5));
  for (index_t k = 1; k < p.num_levels(); ++k) {
    REQUIRE(p.scale(k - 1) - p.scale(k) <= 0.008 + 1e-12);
    REQUIRE(p.level(k).width() == std::llround(64 * p.scale(k)));
    REQUIRE(p.level(k).height() == std::llround(48 * p.scale(k)));
  }
  REQUIRE(p.level(0) == ex);
  const auto q = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.25, .levels = 4}).value();
  REQUIRE(q.num_levels() == 4);
  REQUIRE(q.level(3).width() == 16);
  REQUIRE(tessera::build_exemplar_pyramid(ex, {.min_scale = 1.0}).value().num_levels() == 1);
}

TEST_CASE("exemplar pyramid: low-pass resampling (constants stay, detail above Nyquist is removed)",
          "[terrain][pyramid]") {
  // constant
  const tessera::image_buffer<float, 1> flat(40, 40, {0.3f});
  const auto pf = tessera::build_exemplar_pyramid(flat, {.min_scale = 0.5, .levels = 5}).value();
  for (index_t k = 0; k < 5; ++k)
    for (index_t y = 0; y < pf.level(k).height(); ++y)
      for (index_t x = 0; x < pf.level(k).width(); ++x) REQUIRE(pf.level(k).read(x, y)[0] == Approx(0.3f).margin(1e-5));
  // stripes at the Nyquist frequency: point sampling would keep full contrast
  tessera::image_buffer<std::uint8_t, 1> stripes(64, 16);
  for (index_t y = 0; y < 16; ++y)
    for (index_t x = 0; x < 64; ++x) stripes.write(x, y, {static_cast<std::uint8_t>(x % 2 ? 255 : 0)});
  const auto ps = tessera::build_exemplar_pyramid(stripes, {.min_scale = 0.7, .levels = 2}).value();
  const auto& lv = ps.level(1);
  double mean = 0, var = 0, n = 0;
  for (index_t x = 4; x < lv.width() - 4; ++x) mean += lv.read(x, 8)[0], n += 1;
  mean /= n;
  for (index_t x = 4; x < lv.width() - 4; ++x) var += (lv.read(x, 8)[0] - mean) * (lv.read(x, 8)[0] - mean);
  REQUIRE(mean == Approx(127.5).margin(6));
  REQUIRE(std::sqrt(var / n) < 0.1 * 127.5);
  // smooth content keeps its place: level k at pixel i shows the exemplar at (i + 0.5) / s
  const wave_image wave;
  const auto pw = tessera::build_exemplar_pyramid(wave, {.min_scale = 0.6, .levels = 3}).value();
  const auto& l2 = pw.level(2);
  const double sx = static_cast<double>(l2.width()) / 96, sy = static_cast<double>(l2.height()) / 80;
  for (index_t y = 4; y < l2.height() - 4; ++y)
    for (index_t x = 4; x < l2.width() - 4; ++x) {
      const double u = (static_cast<double>(x) + 0.5) / sx, v = (static_cast<double>(y) + 0.5) / sy;
      const double expect = 0.5 + 0.4 * std::sin(6.283185307179586 * u / 24) * std::cos(6.283185307179586 * v / 24);
      REQUIRE(l2.read(x, y)[0] == Approx(expect).margin(0.03));
    }
}

TEST_CASE("exemplar pyramid: sampling at a scale", "[terrain][pyramid]") {
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 4>(tessera::exemplar_kind::sand, {.width = 32, .height = 32}).value();
  const tessera::image_view<const std::uint8_t, 4> view(ex.data(), 32, 32);
  const auto p = tessera::build_exemplar_pyramid(view, {.min_scale = 0.5, .levels = 3}).value();
  // scale 1, pixel centres: the exemplar itself
  for (index_t y = 0; y < 32; ++y)
    for (index_t x = 0; x < 32; ++x) {
      const auto c = p.sample(1.0, static_cast<double>(x) + 0.5, static_cast<double>(y) + 0.5);
      for (std::size_t k = 0; k < 4; ++k) REQUIRE(c[k] == Approx(ex.read(x, y)[k] / 255.0f).margin(1e-6));
    }
  // a level's own scale: that level; halfway between two levels: their average
  const auto& l1 = p.level(1);
  const auto a = p.sample(0.75, 10.5, 7.5);
  REQUIRE(a[0] == Approx(l1.read(10, 7)[0] / 255.0f).margin(1e-6));
  const double s = 0.875;
  const auto m = p.sample(s, 9.0 * s, 5.0 * s), c0 = p.sample(1.0, 9.0, 5.0),
             c1 = p.sample(0.75, 9.0 * 0.75, 5.0 * 0.75);
  REQUIRE(m[1] == Approx(0.5f * (c0[1] + c1[1])).margin(1e-5));
  REQUIRE(p.level_position(0.875) == Approx(0.5));
}

TEST_CASE("exemplar pyramid: bad options, cancellation, executors", "[terrain][pyramid]") {
  const auto ex = tessera::make_exemplar<float, 3>(tessera::exemplar_kind::grass, {.width = 40, .height = 40}).value();
  for (double s : {0.0, 1.2, -1.0, std::nan("")})
    REQUIRE(tessera::build_exemplar_pyramid(ex, {.min_scale = s}).error().message().find("min_scale") !=
            std::string::npos);
  REQUIRE(tessera::build_exemplar_pyramid(ex, {.levels = -1}).error().message().find("levels") != std::string::npos);
  REQUIRE(tessera::build_exemplar_pyramid(ex, {.levels = 5000}).error().message().find("levels") != std::string::npos);
  REQUIRE(tessera::build_exemplar_pyramid(ex, {.max_step = 0}).error().message().find("max_step") != std::string::npos);
  REQUIRE(tessera::build_exemplar_pyramid(ex, {.min_scale = 0.001, .max_step = 1e-4}).error().message().find("4096") !=
          std::string::npos);
  REQUIRE_FALSE(tessera::build_exemplar_pyramid(tessera::image_buffer<float, 3>{}));
  int calls = 0;
  tessera::exemplar_pyramid_options stop{.levels = 10};
  stop.progress.callback = [&](double, std::string_view) { return ++calls < 3; };
  REQUIRE(tessera::build_exemplar_pyramid(ex, stop).error().code() == tessera::status_code::cancelled);
  const auto a = tessera::build_exemplar_pyramid(ex, {.levels = 6}).value();
  tessera::thread_pool_executor pool(3);
  const auto b = tessera::build_exemplar_pyramid(ex, {.levels = 6}, pool).value();
  for (index_t k = 0; k < 6; ++k) REQUIRE(a.level(k) == b.level(k));
}
