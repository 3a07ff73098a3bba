#include <tessera/fabric/hls.hpp>

#include <cmath>

#include <catch2/catch.hpp>

#include <tessera/core/random.hpp>
#include "../support/test_support.hpp"

using tessera_test::hue_distance;

using namespace tessera;

TEST_CASE("HLS conversions: known colours and round trips", "[hls]") {
  const auto red = rgb_to_hls(1, 0, 0);
  CHECK(red.h == Approx(0));
  CHECK(red.l == Approx(0.5));
  CHECK(red.s == Approx(1));
  const auto teal = rgb_to_hls(0.2f, 0.6f, 0.6f);
  CHECK(teal.h == Approx(180));
  CHECK(teal.l == Approx(0.4));
  CHECK(teal.s == Approx(0.5));
  const auto grey = rgb_to_hls(0.3f, 0.3f, 0.3f);
  CHECK(grey.s == 0);
  CHECK(hls_lightness(0.2f, 0.9f, 0.4f) == Approx(0.55));
  const counter_rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    const float r = static_cast<float>(rng.uniform(i, 0)), g = static_cast<float>(rng.uniform(i, 1)),
                b = static_cast<float>(rng.uniform(i, 2));
    const auto back = hls_to_rgb(rgb_to_hls(r, g, b));
    REQUIRE(back[0] == Approx(r).margin(1e-5));
    REQUIRE(back[1] == Approx(g).margin(1e-5));
    REQUIRE(back[2] == Approx(b).margin(1e-5));
  }
}

TEST_CASE("relight changes lightness only: hue and saturation are kept", "[hls]") {
  const counter_rng rng(4);
  for (int i = 0; i < 5000; ++i) {
    const float r = static_cast<float>(rng.uniform(i, 0)), g = static_cast<float>(rng.uniform(i, 1)),
                b = static_cast<float>(rng.uniform(i, 2));
    const float l_new = static_cast<float>(0.02 + 0.96 * rng.uniform(i, 3));
    const auto before = rgb_to_hls(r, g, b);
    const auto c = relight(r, g, b, hls_lightness(r, g, b), l_new);
    const auto after = rgb_to_hls(c[0], c[1], c[2]);
    REQUIRE(after.l == Approx(l_new).margin(1e-5));
    if (before.s > 1e-3f && before.l > 1e-3f && before.l < 1 - 1e-3f) {
      REQUIRE(after.s == Approx(before.s).margin(2e-4));
      REQUIRE(hue_distance(after.h, before.h) < 0.05);
    }
    // it is also what hls_to_rgb gives for (H, L', S)
    const auto direct = hls_to_rgb({before.h, l_new, before.s});
    for (int k = 0; k < 3; ++k)
      REQUIRE(c[static_cast<std::size_t>(k)] == Approx(direct[static_cast<std::size_t>(k)]).margin(1e-4));
  }
  // black and white relight to grey
  const auto g = relight(0, 0, 0, 0, 0.4f);
  CHECK(g[0] == Approx(0.4));
  CHECK(g[1] == Approx(0.4));
  CHECK(g[2] == Approx(0.4));
}
