#include <tessera/fabric/life_perturbation.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/fabric/cat_map.hpp>
#include <tessera/fabric/source_image.hpp>

#include "fabric_test_support.hpp"
#include "../support/test_support.hpp"

using tessera_test::hue_distance;

using namespace tessera;
using fabric_test::random_image;

namespace {
// r of pixel (x, y) in generation g, restated from the documentation of detail::life_random: a row
// key from SplitMix64, then the 32-bit hash lowbias32 of key + x, top 24 bits.
double oracle_r(std::uint64_t seed, int g, index_t x, index_t y) {
  const counter_rng rng(seed, stream_id("fabric.life"));
  const auto key = static_cast<std::uint32_t>(
      mix64(rng.bits(static_cast<std::uint64_t>(g)) + static_cast<std::uint64_t>(y + 1) * 0x9e3779b97f4a7c15ULL));
  std::uint32_t v = key + static_cast<std::uint32_t>(x);
  v ^= v >> 16;
  v *= 0x7feb352dU;
  v ^= v >> 15;
  v *= 0x846ca68bU;
  v ^= v >> 16;
  return static_cast<double>(v >> 8) / 16777216.0;
}

// Straightforward oracle of the rule (paper 001 §1.3 as documented in life_perturbation.hpp), in
// double, on a lightness field: returns the field after `generations` synchronous generations.
std::vector<double> oracle(std::vector<double> l, index_t w, index_t h, const life_perturbation_options& o) {
  for (int g = 0; g < o.generations; ++g) {
    std::vector<double> next(l.size());
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x) {
        const double c = l[static_cast<std::size_t>(y * w + x)];
        double sb = 0, sd = 0;
        int nb = 0, nd = 0, above = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const double v = l[static_cast<std::size_t>(((y + dy + h) % h) * w + (x + dx + w) % w)];
            if (v > c) sb += v, ++nb;
            if (v < c) sd += v, ++nd;
            if (v > static_cast<double>(o.threshold)) ++above;
          }
        const bool by_threshold = o.live_test == life_test::above_threshold;
        const int live = by_threshold ? above : nb, dead = by_threshold ? 8 - above : nd;
        const double r = oracle_r(o.seed, g, x, y);
        double out = c;
        if (dead >= o.dead_count || (o.crowding_count > 0 && live >= o.crowding_count)) {
          if (nd > 0) out = sd / nd + (c - sd / nd) * r;
        } else if (o.live_exact ? live == o.live_count : live >= o.live_count) {
          if (nb > 0) out = c + (sb / nb - c) * r;
        }
        next[static_cast<std::size_t>(y * w + x)] = out;
      }
    l = next;
  }
  return l;
}

// The same rule on an 8- or 16-bit image: each output channel is the input pixel relit to the
// oracle's lightness (c' = L' + (c - L) k, k = (1 - |2L' - 1|) / (1 - |2L - 1|)), within one step of
// the channel's rounding; pixels whose lightness the oracle keeps are unchanged bit for bit.
template <class T, int C>
void check_integer_oracle(const image_buffer<T, C>& img, const life_perturbation_options& o) {
  constexpr double top = std::numeric_limits<T>::max();
  const index_t w = img.width(), h = img.height();
  std::vector<double> l;
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      const auto p = img.read(x, y);
      const double mx = C <= 2 ? p[0] : std::max({p[0], p[1], p[2]}), mn = C <= 2 ? p[0] : std::min({p[0], p[1], p[2]});
      l.push_back((mx + mn) / (2 * top));
    }
  const auto expected = oracle(l, w, h, o);
  image_buffer<T, C> out(w, h);
  REQUIRE(life_perturbation(img, out, o).ok());
  int changed = 0;
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      const auto i = static_cast<std::size_t>(y * w + x);
      const auto a = img.read(x, y), b = out.read(x, y);
      INFO("pixel (" << x << ", " << y << "), L " << l[i] << " -> " << expected[i]);
      if (std::abs(expected[i] - l[i]) < 1e-9) {
        REQUIRE(a == b);
        continue;
      }
      ++changed;
      const double span = 1 - std::abs(2 * l[i] - 1), span_new = 1 - std::abs(2 * expected[i] - 1);
      const double k = span > 0 ? span_new / span : 0;
      for (int c = 0; c < std::min(C, 3); ++c) {
        const double v =
            C <= 2 ? expected[i] * top : expected[i] * top + (a[static_cast<std::size_t>(c)] - l[i] * top) * k;
        REQUIRE(std::abs(b[static_cast<std::size_t>(c)] - std::clamp(v, 0.0, top)) <= 0.5 + 1e-3 * top / 255);
      }
      if constexpr (C == 2 || C == 4) REQUIRE(a[C - 1] == b[C - 1]);  // alpha
    }
  CHECK(changed > 0);  // the rule did fire
}

std::vector<double> lightness_of(const image_buffer<float, 3>& img) {
  std::vector<double> l;
  for (index_t y = 0; y < img.height(); ++y)
    for (index_t x = 0; x < img.width(); ++x) {
      const auto p = img.read(x, y);
      l.push_back(hls_lightness(p[0], p[1], p[2]));
    }
  return l;
}

// A cat-mapped fabric with some colour: the typical input of the perturbation.
image_buffer<float, 3> fabric(index_t n) {
  image_buffer<float, 3> src(n, n);
  const palette tones = {
      {{0.30f, 0.22f, 0.16f}, 4}, {{0.55f, 0.45f, 0.33f}, 3}, {{0.78f, 0.72f, 0.60f}, 2}, {{0.6f, 0.25f, 0.15f}, 1}};
  REQUIRE(make_source_image(src, tones, {.layout = source_layout::cells, .feature_size = 6}).ok());
  return *cat_map(src, 17);
}
}  // namespace

TEST_CASE("the perturbation follows the paper's brighten / darken rule (oracle)", "[life_perturbation]") {
  const auto noisy = random_image<float, 3>(23, 17, 8);
  const auto cloth = fabric(24);
  std::vector<life_perturbation_options> cases = {
      {},                                                        // K = 3, N = 6
      {.generations = 3, .seed = 9},                             // synchronous generations
      {.live_count = 2, .live_exact = false, .dead_count = 5},   // at least K
      {.generations = 2, .dead_count = 7, .crowding_count = 6},  // §1.2's crowding rule
      {.live_count = 4, .dead_count = 5, .live_test = life_test::above_threshold, .threshold = 0.45f},
      {.live_count = 0, .dead_count = 1},
  };
  for (const auto* img : {&noisy, &cloth})
    for (const auto& o : cases) {
      image_buffer<float, 3> out(img->width(), img->height());
      REQUIRE(life_perturbation(*img, out, o).ok());
      const auto expected = oracle(lightness_of(*img), img->width(), img->height(), o);
      const auto got = lightness_of(out);
      int changed = 0;
      for (std::size_t i = 0; i < got.size(); ++i) {
        REQUIRE(got[i] == Approx(expected[i]).margin(2e-5));
        changed += std::abs(expected[i] - lightness_of(*img)[i]) > 1e-6;
      }
      CHECK(changed > 0);  // the rule did fire
    }
  // 8- and 16-bit images take the integer first generation (exact neighbour sums): same rule
  const auto rgba = random_image<std::uint8_t, 4>(37, 19, 5);
  const auto cloth8 = *to_buffer<std::uint8_t, 3>(cloth);
  const auto grey16 = random_image<std::uint16_t, 1>(21, 13, 6);
  for (const auto& o : cases) {
    INFO("generations " << o.generations << ", K " << o.live_count << ", N " << o.dead_count);
    check_integer_oracle(rgba, o);
    check_integer_oracle(cloth8, o);
    check_integer_oracle(grey16, o);
  }
}

TEST_CASE("a single row or column wraps around: neighbours across the edge count", "[life_perturbation]") {
  // The line 0.9, 0.1 x 7, 0.5. Its rows above and below are the line itself, so pixel 0 sees 0.5
  // (across the edge) and 0.1 three times each, and itself twice: 6 dimmer neighbours, so it darkens
  // towards L_dim = 0.3 (N = 6). Pixel 8 sees 0.9 (across the edge) three times: exactly K = 3
  // brighter, so it brightens towards L_bright = 0.9.
  for (const bool column : {false, true}) {
    INFO((column ? "column" : "row"));
    const index_t w = column ? 1 : 9, h = column ? 9 : 1;
    auto at = [&](index_t i) { return std::pair{column ? 0 : i, column ? i : 0}; };
    image_buffer<float, 1> line(w, h, {0.1f});
    image_buffer<std::uint8_t, 1> line8(w, h, {26});
    line.write(at(0).first, at(0).second, {0.9f}), line8.write(at(0).first, at(0).second, {230});
    line.write(at(8).first, at(8).second, {0.5f}), line8.write(at(8).first, at(8).second, {128});
    image_buffer<float, 1> out(w, h);
    image_buffer<std::uint8_t, 1> out8(w, h);
    REQUIRE(life_perturbation(line, out).ok());
    REQUIRE(life_perturbation(line8, out8).ok());
    const double r0 = oracle_r(1, 0, at(0).first, at(0).second), r8 = oracle_r(1, 0, at(8).first, at(8).second);
    CHECK(out.read(at(0).first, at(0).second)[0] == Approx(0.3 + (0.9 - 0.3) * r0).epsilon(1e-6));
    CHECK(out.read(at(8).first, at(8).second)[0] == Approx(0.5 + (0.9 - 0.5) * r8).epsilon(1e-6));
    // 8-bit: L_dim = (3 128 + 3 26) / 6 = 77, L_bright = 230, in channel units
    CHECK(std::abs(out8.read(at(0).first, at(0).second)[0] - (77 + (230 - 77) * r0)) <= 0.5 + 1e-4);
    CHECK(std::abs(out8.read(at(8).first, at(8).second)[0] - (128 + (230 - 128) * r8)) <= 0.5 + 1e-4);
  }
}

TEST_CASE("the SIMD paths of the integer generation equal the portable loops", "[life_perturbation]") {
  using namespace tessera::detail;
  const index_t w = 61;  // not a multiple of 4 or 8: the tails run too
  const auto img = random_image<std::uint8_t, 4>(w, 3, 12);
  std::vector<std::int16_t> rows(static_cast<std::size_t>(3 * (w + 2))), plain(static_cast<std::size_t>(w + 2));
  for (index_t y = 0; y < 3; ++y) {  // lightness rows
    life_q_row<std::uint8_t, 4, true>(img.row(y), w, rows.data() + y * (w + 2));
    life_q_row<std::uint8_t, 4, false>(img.row(y), w, plain.data());
    REQUIRE(std::equal(plain.begin(), plain.end(), rows.begin() + y * (w + 2)));
  }
  // classification and fired-pixel arithmetic: the AVX2 build of the loops (when this machine has
  // it) against the default one, for every rule shape
  using default_loops = life_int_loops<std::uint8_t, false>;
  using avx2_loops = life_int_loops<std::uint8_t, true>;
  const life_int_rule<std::int16_t> rule{3, 6, 7, 300, true, false};
  std::vector<std::uint16_t> toward(static_cast<std::size_t>(w)), kind(toward.size()), toward2(toward.size()),
      kind2(toward.size());
  const std::int16_t* r = rows.data();
  const index_t p = w + 2;
  default_loops::classify<false, true>(r, r + p, r + 2 * p, w, rule, toward.data(), kind.data());
  if (life_has_avx2()) {
    avx2_loops::classify<false, true>(r, r + p, r + 2 * p, w, rule, toward2.data(), kind2.data());
    REQUIRE(toward == toward2);
    REQUIRE(kind == kind2);
    avx2_loops::classify<true, false>(r, r + p, r + 2 * p, w, rule, toward2.data(), kind2.data());
    default_loops::classify<true, false>(r, r + p, r + 2 * p, w, rule, toward.data(), kind.data());
    REQUIRE(toward == toward2);
    REQUIRE(kind == kind2);
  }
  // compaction of the fired columns
  life_int_scratch<std::uint8_t> a(w), b(w);
  for (std::size_t x = 0; x < kind.size(); ++x) kind[x] = static_cast<std::uint16_t>(x % 3 == 0 ? 0 : 1 + x % 2);
  const std::size_t n = life_compact<std::uint16_t, true>(kind.data(), w, a.fired.data());
  REQUIRE(n == life_compact<std::uint16_t, false>(kind.data(), w, b.fired.data()));
  REQUIRE(std::equal(a.fired.begin(), a.fired.begin() + static_cast<std::ptrdiff_t>(n), b.fired.begin()));
  REQUIRE(n == 40);
  // fired arithmetic and relighting
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t x = a.fired[i];
    a.up[i] = b.up[i] = kind[x] == 1 ? ~0u : 0u;
    a.sum[i] = b.sum[i] = static_cast<std::uint32_t>((1 + i % 8) << 12 | ((1 + i % 8) * (i * 37 % 511)));
    a.q[i] = b.q[i] = static_cast<std::uint32_t>(rows[x + 1 + static_cast<std::size_t>(p)] & 0xfff);
  }
  default_loops::fired(n, 0x12345678u, a);
  avx2_loops::fired(n, 0x12345678u, b);  // the default build when this machine lacks AVX2
  REQUIRE(a.lq == b.lq);
  REQUIRE(a.k == b.k);
  REQUIRE(a.base == b.base);
  auto simd = img, portable = img;
  life_int_relight_row<std::uint8_t, 4, true>(img.row(1), simd.row(1), a, n);
  life_int_relight_row<std::uint8_t, 4, false>(img.row(1), portable.row(1), a, n);
  REQUIRE(simd == portable);
  CHECK_FALSE(simd == img);
}

TEST_CASE("the perturbation keeps hue and saturation (float and 8-bit)", "[life_perturbation]") {
  // float: exact up to float rounding, where hue and saturation are defined
  const auto img = random_image<float, 3>(40, 40, 3);
  for (int gens : {1, 4}) {
    image_buffer<float, 3> out(40, 40);
    REQUIRE(life_perturbation(img, out, {.generations = gens}).ok());
    for (index_t y = 0; y < 40; ++y)
      for (index_t x = 0; x < 40; ++x) {
        const auto a = img.read(x, y), b = out.read(x, y);
        const auto ha = rgb_to_hls(a[0], a[1], a[2]), hb = rgb_to_hls(b[0], b[1], b[2]);
        if (ha.s < 1e-3f || hb.l < 1e-3f || hb.l > 1 - 1e-3f) continue;
        REQUIRE(hb.s == Approx(ha.s).margin(2e-4));
        REQUIRE(hue_distance(ha.h, hb.h) < 0.05);
      }
  }
  // 8-bit RGBA: within the error of rounding each channel to 1/255; alpha exact
  const auto rgba = random_image<std::uint8_t, 4>(48, 48, 4);
  image_buffer<std::uint8_t, 4> out(48, 48);
  REQUIRE(life_perturbation(rgba, out, {.generations = 3}).ok());
  const float eps = 0.5f / 255.0f;
  int checked = 0, changed = 0;
  for (index_t y = 0; y < 48; ++y)
    for (index_t x = 0; x < 48; ++x) {
      const auto a = rgba.read(x, y), b = out.read(x, y);
      REQUIRE(a[3] == b[3]);
      changed += a != b;
      auto u = [](std::uint8_t v) { return static_cast<float>(v) / 255.0f; };
      const auto ha = rgb_to_hls(u(a[0]), u(a[1]), u(a[2])), hb = rgb_to_hls(u(b[0]), u(b[1]), u(b[2]));
      const float chroma = std::max({u(b[0]), u(b[1]), u(b[2])}) - std::min({u(b[0]), u(b[1]), u(b[2])});
      const float span = 1.0f - std::abs(2.0f * hb.l - 1.0f);
      if (chroma < 24.0f / 255.0f || span < 0.1f) continue;  // hue / saturation ill-conditioned
      ++checked;
      REQUIRE(hue_distance(ha.h, hb.h) <= 60.0 * 4 * eps / (chroma - 2 * eps) + 1e-3);
      REQUIRE(std::abs(hb.s - ha.s) <= 4 * eps / span * (1 + ha.s) + 1e-4);
    }
  CHECK(checked > 500);
  CHECK(changed > 100);
}

TEST_CASE("perturbation output does not depend on the executor, in place works", "[life_perturbation]") {
  const auto img = random_image<std::uint8_t, 4>(70, 53, 6);
  for (int gens : {1, 2}) {
    image_buffer<std::uint8_t, 4> serial(70, 53);
    REQUIRE(life_perturbation(img, serial, {.generations = gens, .seed = 4}).ok());
    for (int threads : {1, 2, 3, 7}) {
      thread_pool_executor pool(threads);
      image_buffer<std::uint8_t, 4> par(70, 53);
      REQUIRE(life_perturbation(img, par, {.generations = gens, .seed = 4}, pool).ok());
      REQUIRE(par == serial);
      auto inplace = img;
      REQUIRE(life_perturbation(inplace, inplace, {.generations = gens, .seed = 4}, pool).ok());
      REQUIRE(inplace == serial);
    }
  }
  // views of one buffer that overlap without being the same rows: the input is read as it was
  const index_t w = 31, h = 17;
  std::vector<std::uint8_t> raw(static_cast<std::size_t>((h + 2) * w * 3));
  for (int gens : {1, 2}) {
    for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = static_cast<std::uint8_t>(i * 89 + 3);
    image_view<std::uint8_t, 3> in(raw.data(), w, h, w * 3), out(raw.data() + 2 * w * 3, w, h, w * 3);
    const auto before = *to_buffer(in);
    image_buffer<std::uint8_t, 3> expected(w, h);
    REQUIRE(life_perturbation(before, expected, {.generations = gens}).ok());
    REQUIRE(life_perturbation(image_view<const std::uint8_t, 3>(in), out, {.generations = gens}).ok());
    REQUIRE(*to_buffer(out) == expected);
  }
  // a member-style user type and other formats
  const auto tex = fabric_test::random_user_texture(30, 20, 2);
  fabric_test::user_texture out(30, 20);
  REQUIRE(life_perturbation(tex, out).ok());
  const auto buf = *to_buffer(tex);
  image_buffer<float, 3> expected(30, 20);
  REQUIRE(life_perturbation(buf, expected).ok());
  REQUIRE(*to_buffer(out) == expected);
}

TEST_CASE("perturbation special cases: flat images, zero generations, grey and alpha", "[life_perturbation]") {
  image_buffer<std::uint8_t, 3> flat(16, 16, {120, 80, 40});
  image_buffer<std::uint8_t, 3> out(16, 16);
  REQUIRE(life_perturbation(flat, out, {.generations = 5}).ok());
  CHECK(out == flat);  // no brighter or dimmer neighbour anywhere
  const auto img = random_image<std::uint16_t, 2>(20, 20, 1);
  image_buffer<std::uint16_t, 2> o2(20, 20);
  REQUIRE(life_perturbation(img, o2, {.generations = 0}).ok());
  CHECK(o2 == img);
  REQUIRE(life_perturbation(img, o2).ok());
  int changed = 0;
  for (index_t y = 0; y < 20; ++y)
    for (index_t x = 0; x < 20; ++x) {
      REQUIRE(o2.read(x, y)[1] == img.read(x, y)[1]);  // alpha
      changed += o2.read(x, y)[0] != img.read(x, y)[0];
    }
  CHECK(changed > 0);
}

TEST_CASE("perturbation rejects bad options and images, and can be cancelled", "[life_perturbation]") {
  const auto img = random_image<std::uint8_t, 3>(8, 8, 1);
  image_buffer<std::uint8_t, 3> out(8, 8);
  struct bad_case {
    life_perturbation_options o;
    const char* name;
  };
  const std::vector<bad_case> bad = {
      {{.generations = -1}, "generations"},
      {{.live_count = 9}, "live_count"},
      {{.live_count = -1}, "live_count"},
      {{.dead_count = 0}, "dead_count"},
      {{.dead_count = 9}, "dead_count"},
      {{.crowding_count = 9}, "crowding_count"},
      {{.threshold = 1.5f}, "threshold"},
      {{.threshold = std::nanf("")}, "threshold"},
      {{.live_test = static_cast<life_test>(5)}, "live_test"},
  };
  for (const auto& b : bad) {
    auto s = life_perturbation(img, out, b.o);
    INFO(s.to_string());
    REQUIRE(s.code() == status_code::invalid_argument);
    CHECK(s.message().find(b.name) != std::string::npos);
  }
  image_buffer<std::uint8_t, 3> small(4, 8);
  CHECK(life_perturbation(img, small).code() == status_code::invalid_argument);
  image_view<const std::uint8_t, 3> empty;
  CHECK(life_perturbation(empty, out).code() == status_code::invalid_argument);

  cancellation_token stop;
  stop.cancel();
  life_perturbation_options o{.generations = 3};
  o.progress.token = &stop;
  CHECK(life_perturbation(img, out, o).code() == status_code::cancelled);
  int calls = 0;
  o.progress = {};
  o.progress.callback = [&](double, std::string_view) { return ++calls < 2; };
  CHECK(life_perturbation(img, out, o).code() == status_code::cancelled);
}
