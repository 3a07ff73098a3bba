#include <tessera/image/quilt.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/metrics.hpp>

#include <algorithm>
#include <limits>
#include <set>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;
using tessera::quilt_options;
namespace dt = tessera::detail;

TEST_CASE("quilt: deterministic, executor-independent, every output pixel comes from the exemplar", "[quilt]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::cells, 48);
  std::set<std::array<std::uint8_t, 3>> palette;
  for (index_t y = 0; y < 48; ++y)
    for (index_t x = 0; x < 48; ++x) palette.insert(ex.read(x, y));
  for (bool seamless : {false, true}) {
    tessera::image_buffer<std::uint8_t, 3> a(70, 53), b(70, 53), c(70, 53);
    const quilt_options o{.patch_size = 16, .overlap = 4, .seamless = seamless, .seed = 5};
    REQUIRE(tessera::quilt(ex, a, o).ok());
    tessera::thread_pool_executor pool(3);
    REQUIRE(tessera::quilt(ex, b, o, pool).ok());
    REQUIRE(a == b);
    quilt_options other = o;
    other.seed = 6;
    REQUIRE(tessera::quilt(ex, c, other).ok());
    REQUIRE_FALSE(a == c);
    for (index_t y = 0; y < a.height(); ++y)
      for (index_t x = 0; x < a.width(); ++x) REQUIRE(palette.count(a.read(x, y)) == 1);
  }
}

TEST_CASE("quilt: pixel types and user images", "[quilt]") {
  const auto ex8 = quilt_test::exemplar<std::uint8_t, 4>(tessera::exemplar_kind::weave, 40);
  std::vector<std::uint8_t> raw(64 * 48 * 4, 0);
  tessera::image_view<std::uint8_t, 4> view(raw.data(), 64, 48);
  REQUIRE(tessera::quilt(ex8, view, {.patch_size = 12}).ok());
  REQUIRE(std::count(raw.begin(), raw.end(), std::uint8_t{0}) < static_cast<std::ptrdiff_t>(raw.size() / 20));
  const auto exf = quilt_test::exemplar<float, 3>(tessera::exemplar_kind::sand, 40);
  tessera::image_buffer<float, 3> outf(50, 50);
  REQUIRE(tessera::quilt(exf, outf, {.patch_size = 12}).ok());
  quilt_test::user_rgb16 user(50, 50);
  REQUIRE(tessera::quilt(exf, user, {.patch_size = 12}).ok());
  // the user image receives the same texture, converted to 16 bits
  for (index_t y = 0; y < 50; y += 7)
    for (index_t x = 0; x < 50; x += 7)
      REQUIRE(user.read(x, y) == tessera::convert_pixel<std::array<std::uint16_t, 3>>(outf.read(x, y)));
}

TEST_CASE("quilt: overlap errors equal a brute-force SSD, selection stays within tolerance", "[quilt]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::rock, 30);
  const dt::quilt_source<std::uint8_t, 3> src(ex);
  const index_t p = 9, U = 30 - p + 1;
  const tessera::counter_rng rng(3);
  std::vector<dt::template_element> elements;
  std::vector<std::array<float, 5>> brute;  // (i, j, c, value, weight)
  for (index_t j = 0; j < p; ++j)
    for (index_t i = 0; i < p; ++i)
      if (rng.uniform(i, j) < 0.4)  // an irregular mask
        for (int c = 0; c < 3; ++c) {
          const float v = static_cast<float>(rng.uniform(i, j, c));
          const float weight = i == 4 ? 8.0f : 1.0f;  // some weighted elements
          elements.push_back({c * 30 * 30 + j * 30 + i, v, weight});
          brute.push_back({float(i), float(j), float(c), v, weight});
        }
  std::vector<float> err, generic;
  tessera::serial_executor serial;
  dt::overlap_errors(src, elements, p, err, serial);  // the fastest kernel this CPU has (AVX2 or SSE2)
  dt::overlap_errors(src, elements, p, generic, serial, dt::overlap_row_generic);
  REQUIRE(err == generic);  // bit-identical whichever instruction set runs
  REQUIRE(err.size() == static_cast<std::size_t>(U * U));
  for (index_t v = 0; v < U; ++v)
    for (index_t u = 0; u < U; ++u) {
      double ssd = 0;
      for (const auto& e : brute) {
        const double d = tessera::channel_to_unit(ex.read(u + index_t(e[0]), v + index_t(e[1]))[std::size_t(e[2])]) - e[3];
        ssd += e[4] * d * d;
      }
      REQUIRE(err[static_cast<std::size_t>(v * U + u)] == Approx(ssd).epsilon(1e-5).margin(1e-5));
    }
  const float best = *std::min_element(err.begin(), err.end());
  for (std::uint64_t key = 0; key < 50; ++key) {
    const index_t k = dt::pick_candidate(err, 0.3, rng, key, 0, 0);
    REQUIRE(err[static_cast<std::size_t>(k)] <= best * 1.3f + 1e-6f);
  }
  REQUIRE(dt::pick_candidate(err, 0.0, rng, 1, 2, 3) == std::min_element(err.begin(), err.end()) - err.begin());
  // at least the 5 best are drawn from, and every one of them is drawn for some key
  std::vector<float> sorted = err;
  std::sort(sorted.begin(), sorted.end());
  std::set<index_t> drawn;
  for (std::uint64_t key = 0; key < 200; ++key) {
    const index_t k = dt::pick_candidate(err, 0.0, rng, key, 0, 0, 5);
    REQUIRE(err[static_cast<std::size_t>(k)] <= sorted[4]);
    drawn.insert(k);
  }
  REQUIRE(drawn.size() == 5u);
}

TEST_CASE("quilt: the boundary cut is the minimum-error path (brute force)", "[quilt]") {
  // a 6 x 6 window whose west band (3 columns) is filled: every |dx| <= 1 path is enumerated
  const tessera::counter_rng rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    dt::site_window win;
    win.p = 6;
    win.state.assign(36, dt::pixel_state::empty);
    win.outside.assign(36, 0);
    win.error.assign(36, 0.0);
    for (index_t j = 0; j < 6; ++j)
      for (index_t i = 0; i < 3; ++i) {
        win.state[win.idx(i, j)] = trial % 2 && i == 0 && j == 2 ? dt::pixel_state::fixed : dt::pixel_state::filled;
        win.error[win.idx(i, j)] = rng.uniform(trial, i, j);
      }
    const index_t band[4] = {0, 0, 0, 3};
    std::vector<std::uint8_t> is_new;
    dt::cut_labels(win, band, is_new);
    // recover the path: first new column of each row
    double cut_cost = 0;
    std::vector<index_t> path;
    for (index_t j = 0; j < 6; ++j) {
      index_t x = 0;
      while (!is_new[win.idx(x, j)]) ++x;
      for (index_t i = x; i < 6; ++i) REQUIRE(is_new[win.idx(i, j)]);  // one boundary per row
      path.push_back(x);
      cut_cost += win.error[win.idx(x, j)] + (trial % 2 && j == 2 && x == 0 ? dt::fixed_pixel_penalty : 0);
    }
    for (std::size_t j = 1; j < path.size(); ++j) REQUIRE(std::abs(path[j] - path[j - 1]) <= 1);
    double best = std::numeric_limits<double>::infinity();
    for (int code = 0; code < 729; ++code) {  // 3^6 paths
      int c = code;
      double cost = 0;
      bool ok = true;
      index_t prev = -1;
      for (index_t j = 0; j < 6; ++j, c /= 3) {
        const index_t x = c % 3;
        ok = ok && (prev < 0 || std::abs(x - prev) <= 1);
        prev = x;
        cost += win.error[win.idx(x, j)] + (trial % 2 && j == 2 && x == 0 ? dt::fixed_pixel_penalty : 0);
      }
      if (ok) best = std::min(best, cost);
    }
    REQUIRE(cut_cost == Approx(best));
    if (trial % 2) REQUIRE_FALSE(is_new[win.idx(0, 2)]);  // the fixed pixel stays on the old side
  }
}

TEST_CASE("quilt: overlap search and cuts beat random patches (neighbourhood energy)", "[quilt]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::bricks, 64, 2);
  tessera::image_buffer<std::uint8_t, 3> good(96, 96), random(96, 96);
  REQUIRE(tessera::quilt(ex, good, {.patch_size = 20, .overlap = 5}).ok());
  // an effectively infinite tolerance accepts every candidate: random placement, same cuts
  REQUIRE(tessera::quilt(ex, random, {.patch_size = 20, .overlap = 5, .tolerance = 1e30}).ok());
  auto e_good = tessera::neighborhood_energy(good, ex, {.window = 7, .sample_step = 3});
  auto e_random = tessera::neighborhood_energy(random, ex, {.window = 7, .sample_step = 3});
  REQUIRE(e_good.ok());
  REQUIRE(e_random.ok());
  CAPTURE(*e_good, *e_random);
  REQUIRE(*e_good < 0.7 * *e_random);
}

TEST_CASE("quilt: seamless output tiles with itself", "[quilt]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::cells, 64, 4);
  auto wrap_ratio = [&](bool seamless) {
    tessera::image_buffer<std::uint8_t, 3> out(80, 72);
    REQUIRE(tessera::quilt(ex, out, {.patch_size = 20, .overlap = 5, .seamless = seamless, .seed = 9}).ok());
    tessera::image_buffer<std::uint8_t, 3> twice(160, 144);  // 2 x 2 repetition
    for (index_t y = 0; y < 144; ++y)
      for (index_t x = 0; x < 160; ++x) twice.write(x, y, out.read(x % 80, y % 72));
    const std::vector<tessera::seam_segment> seams = {{true, 80, 0, 144}, {false, 72, 0, 160}};
    return tessera::seam_gradient_ratio(twice, seams, ex).value();
  };
  const double seamless = wrap_ratio(true), plain = wrap_ratio(false);
  CAPTURE(seamless, plain);
  REQUIRE(seamless < 1.6);
  REQUIRE(seamless < plain);
}

TEST_CASE("quilt: bad input", "[quilt]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::sand, 32);
  tessera::image_buffer<std::uint8_t, 3> out(40, 40);
  auto code = [&](const quilt_options& o) { return tessera::quilt(ex, out, o).code(); };
  REQUIRE(code({.patch_size = 33}) == tessera::status_code::invalid_argument);
  REQUIRE_THAT(tessera::quilt(ex, out, {.patch_size = 33}).message(), Catch::Contains("patch_size 33") && Catch::Contains("32 x 32"));
  REQUIRE(code({.patch_size = 1}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.patch_size = -4}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.patch_size = 16, .overlap = 9}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.overlap = -1}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tolerance = -0.5}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.boundary_weight = 0.5}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tolerance = std::numeric_limits<double>::quiet_NaN()}) == tessera::status_code::invalid_argument);
  tessera::image_buffer<std::uint8_t, 3> small(10, 40);
  REQUIRE(tessera::quilt(ex, small, {.patch_size = 16, .seamless = true}).code() == tessera::status_code::invalid_argument);
  REQUIRE(tessera::quilt(ex, small, {.patch_size = 16}).ok());  // non-seamless output may be smaller than a patch
  tessera::image_view<std::uint8_t, 3> empty;
  REQUIRE(tessera::quilt(ex, empty).code() == tessera::status_code::invalid_argument);
  REQUIRE(tessera::quilt(empty, out).code() == tessera::status_code::invalid_argument);
  tessera::cancellation_token stop;
  stop.cancel();
  quilt_options cancelled{.patch_size = 8};
  cancelled.progress.token = &stop;
  REQUIRE(code(cancelled) == tessera::status_code::cancelled);
  int calls = 0;
  quilt_options midway{.patch_size = 8};
  midway.progress.callback = [&](double, std::string_view) { return ++calls < 3; };
  REQUIRE(code(midway) == tessera::status_code::cancelled);
  REQUIRE(calls == 3);
}
