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
        const double d =
            tessera::channel_to_unit(ex.read(u + index_t(e[0]), v + index_t(e[1]))[std::size_t(e[2])]) - e[3];
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

namespace {
// Brute force for the cuts: every path of a side's band is enumerated (3 choices per line) and
// costed with the same per-pixel rule the DP uses (the error of the first new pixel, plus a penalty
// per fixed pixel that would become new, infinite when an empty pixel would stay old).
// (written independently of the kernel's cut_pixel_cost; depth a, line b of a side -> window (i, j))
double oracle_cost(const dt::site_window& win, int side, index_t width, index_t x, index_t b) {
  const index_t p = win.p;
  auto ij = [&](index_t a) -> std::pair<index_t, index_t> {
    if (side == tessera::side_west) return {a, b};
    if (side == tessera::side_east) return {p - 1 - a, b};
    if (side == tessera::side_north) return {b, a};
    return {b, p - 1 - a};
  };
  double c = win.error[win.idx(ij(x).first, ij(x).second)];
  for (index_t a = 0; a < width; ++a) {
    const dt::pixel_state st = win.state[win.idx(ij(a).first, ij(a).second)];
    if (a < x && st == dt::pixel_state::empty) return std::numeric_limits<double>::infinity();
    if (a >= x && st == dt::pixel_state::fixed) c += dt::fixed_pixel_penalty;
  }
  return c;
}
double path_cost(const dt::site_window& win, int side, index_t width, const std::vector<index_t>& pos, index_t from) {
  double c = 0;
  for (index_t b = from; b < win.p; ++b) c += oracle_cost(win, side, width, pos[static_cast<std::size_t>(b)], b);
  return c;
}
// cheapest path of `side` over lines [from, p) whose first position is x0 (x0 < 0: any start)
double brute_path(const dt::site_window& win, int side, index_t width, index_t from, index_t x0) {
  double best = std::numeric_limits<double>::infinity();
  const index_t lines = win.p - from;
  index_t codes = 1;
  for (index_t k = 0; k < lines; ++k) codes *= width;
  std::vector<index_t> pos(static_cast<std::size_t>(win.p), 0);
  for (index_t code = 0; code < codes; ++code) {
    index_t c = code;
    bool ok = true;
    for (index_t b = from; b < win.p; ++b, c /= width) {
      pos[static_cast<std::size_t>(b)] = c % width;
      if (b > from && std::abs(pos[static_cast<std::size_t>(b)] - pos[static_cast<std::size_t>(b - 1)]) > 1) ok = false;
    }
    if (!ok || (x0 >= 0 && pos[static_cast<std::size_t>(from)] != x0)) continue;
    best = std::min(best, path_cost(win, side, width, pos, from));
  }
  return best;
}
// a p x p window: pixels within the given bands are known (filled, some fixed), a few band pixels
// and everything else empty; random errors on known pixels
dt::site_window random_window(index_t p, const index_t band[4], const tessera::counter_rng& rng, int trial) {
  dt::site_window win;
  win.p = p;
  win.state.assign(static_cast<std::size_t>(p * p), dt::pixel_state::empty);
  win.outside.assign(static_cast<std::size_t>(p * p), 0);
  win.error.assign(static_cast<std::size_t>(p * p), 0.0);
  for (index_t j = 0; j < p; ++j)
    for (index_t i = 0; i < p; ++i) {
      const bool known = i < band[tessera::side_west] || j < band[tessera::side_north] ||
                         p - 1 - i < band[tessera::side_east] || p - 1 - j < band[tessera::side_south];
      if (!known) continue;
      const double u = rng.uniform(trial, i, j, 1);
      const std::size_t k = win.idx(i, j);
      win.state[k] = u < 0.08 ? dt::pixel_state::fixed : u < 0.12 ? dt::pixel_state::empty : dt::pixel_state::filled;
      if (win.state[k] != dt::pixel_state::empty) win.error[k] = rng.uniform(trial, i, j, 2);
    }
  return win;
}
void check_path_shape(const std::vector<index_t>& path, index_t p, index_t width, index_t from) {
  REQUIRE(path.size() == static_cast<std::size_t>(p));
  for (index_t b = from; b < p; ++b) {
    REQUIRE(path[static_cast<std::size_t>(b)] >= 0);
    REQUIRE(path[static_cast<std::size_t>(b)] < width);
    if (b > from) REQUIRE(std::abs(path[static_cast<std::size_t>(b)] - path[static_cast<std::size_t>(b - 1)]) <= 1);
  }
}
}  // namespace

TEST_CASE("quilt: every single-side cut is the minimum-error path (brute force: west, north, east, south)", "[quilt]") {
  const tessera::counter_rng rng(11);
  const index_t p = 7;
  for (int side = 0; side < 4; ++side)
    for (int trial = 0; trial < 12; ++trial) {
      index_t band[4] = {0, 0, 0, 0};
      band[side] = 2 + trial % 2;  // widths 2 and 3
      const dt::site_window win = random_window(p, band, rng, side * 100 + trial);
      dt::cut_plan plan;
      dt::plan_cuts(win, band, plan);
      for (int s = 0; s < 4; ++s) REQUIRE(plan.active[s] == (s == side));
      REQUIRE_FALSE(plan.meet);
      const std::vector<index_t>& path = plan.path[side];
      check_path_shape(path, p, band[side], 0);
      CAPTURE(side, trial);
      REQUIRE(path_cost(win, side, band[side], path, 0) == Approx(brute_path(win, side, band[side], 0, -1)));
      // labels: new exactly at and past the path on each line; empty pixels are always new
      std::vector<std::uint8_t> is_new;
      dt::labels_from_plan(win, plan, is_new);
      for (index_t b = 0; b < p; ++b)
        for (index_t a = 0; a < p; ++a) {
          const dt::window_xy q = dt::side_pixel(side, p, a, b);
          const std::size_t k = win.idx(q.i, q.j);
          REQUIRE(bool(is_new[k]) ==
                  (a >= path[static_cast<std::size_t>(b)] || win.state[k] == dt::pixel_state::empty));
        }
    }
}

TEST_CASE("quilt: the L-shaped cut meets at the cheapest point (brute force), east and south cuts with it", "[quilt]") {
  const tessera::counter_rng rng(12);
  const index_t p = 6;
  for (int trial = 0; trial < 16; ++trial) {
    // west + north always (the L), east and/or south in some trials (a patch closing a ring)
    index_t band[4] = {2 + trial % 2, trial & 4 ? 2 : 0, trial & 8 ? 2 : 0, 3 - trial % 2};
    const dt::site_window win = random_window(p, band, rng, 1000 + trial);
    dt::cut_plan plan;
    dt::plan_cuts(win, band, plan);
    REQUIRE(plan.meet);
    CAPTURE(trial, plan.mx, plan.my);
    const index_t Sw = band[tessera::side_west], Sn = band[tessera::side_north];
    REQUIRE(plan.mx >= 0);
    REQUIRE(plan.mx < Sw);
    REQUIRE(plan.my >= 0);
    REQUIRE(plan.my < Sn);
    check_path_shape(plan.path[tessera::side_west], p, Sw, plan.my);
    check_path_shape(plan.path[tessera::side_north], p, Sn, plan.mx);
    REQUIRE(plan.path[tessera::side_west][static_cast<std::size_t>(plan.my)] == plan.mx);
    REQUIRE(plan.path[tessera::side_north][static_cast<std::size_t>(plan.mx)] == plan.my);
    // cost of the L: west path from row my down, north path from column mx right, meeting pixel once
    const double chosen = path_cost(win, tessera::side_west, Sw, plan.path[tessera::side_west], plan.my) +
                          path_cost(win, tessera::side_north, Sn, plan.path[tessera::side_north], plan.mx) -
                          win.error[win.idx(plan.mx, plan.my)];
    double best = std::numeric_limits<double>::infinity();
    for (index_t y = 0; y < Sn; ++y)
      for (index_t x = 0; x < Sw; ++x)
        best = std::min(best, brute_path(win, tessera::side_west, Sw, y, x) +
                                  brute_path(win, tessera::side_north, Sn, x, y) - win.error[win.idx(x, y)]);
    REQUIRE(chosen == Approx(best));
    for (int s : {tessera::side_east, tessera::side_south}) {
      REQUIRE(plan.active[s] == (band[s] > 0));
      if (!plan.active[s]) continue;
      check_path_shape(plan.path[s], p, band[s], 0);
      REQUIRE(path_cost(win, s, band[s], plan.path[s], 0) == Approx(brute_path(win, s, band[s], 0, -1)));
    }
    // labels: old in the corner region before the meeting point and before each path, new elsewhere;
    // an empty pixel is new wherever it lies (also inside the corner region)
    std::vector<std::uint8_t> is_new;
    dt::labels_from_plan(win, plan, is_new);
    for (index_t j = 0; j < p; ++j)
      for (index_t i = 0; i < p; ++i) {
        bool expect = !(i < plan.mx && j < plan.my);
        if (j >= plan.my) expect = expect && i >= plan.path[tessera::side_west][static_cast<std::size_t>(j)];
        if (i >= plan.mx) expect = expect && j >= plan.path[tessera::side_north][static_cast<std::size_t>(i)];
        if (band[tessera::side_east])
          expect = expect && p - 1 - i >= plan.path[tessera::side_east][static_cast<std::size_t>(j)];
        if (band[tessera::side_south])
          expect = expect && p - 1 - j >= plan.path[tessera::side_south][static_cast<std::size_t>(i)];
        const std::size_t k = win.idx(i, j);
        REQUIRE(bool(is_new[k]) == (expect || win.state[k] == dt::pixel_state::empty));
      }
  }
}

TEST_CASE("quilt: an empty pixel in the L-cut's corner region is labelled new", "[quilt]") {
  // the west and north bands are known except one hole at (0, 0), inside the region the L-cut
  // keeps old whenever the meeting point is not (0, 0): make the meeting point (2, 2) cheapest
  dt::site_window win;
  win.p = 8;
  win.state.assign(64, dt::pixel_state::empty);
  win.outside.assign(64, 0);
  win.error.assign(64, 5.0);
  for (index_t j = 0; j < 8; ++j)
    for (index_t i = 0; i < 8; ++i)
      if (i < 3 || j < 3) win.state[win.idx(i, j)] = dt::pixel_state::filled;
  win.state[win.idx(0, 0)] = dt::pixel_state::empty;
  win.error[win.idx(0, 0)] = 0;
  for (index_t k = 2; k < 8; ++k)
    win.error[win.idx(2, k)] = win.error[win.idx(k, 2)] = 0.0;  // the cheap L through (2, 2)
  const index_t band[4] = {3, 0, 0, 3};
  dt::cut_plan plan;
  dt::plan_cuts(win, band, plan);
  REQUIRE(plan.meet);
  REQUIRE(plan.mx == 2);
  REQUIRE(plan.my == 2);
  std::vector<std::uint8_t> is_new;
  dt::labels_from_plan(win, plan, is_new);
  REQUIRE(is_new[win.idx(0, 0)] == 1);  // the hole is filled by this patch
  REQUIRE(is_new[win.idx(1, 1)] == 0);  // its known neighbours in the corner region stay old
  REQUIRE(is_new[win.idx(1, 0)] == 0);
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
  REQUIRE_THAT(tessera::quilt(ex, out, {.patch_size = 33}).message(),
               Catch::Contains("patch_size 33") && Catch::Contains("32 x 32"));
  REQUIRE(code({.patch_size = 1}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.patch_size = -4}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.patch_size = 16, .overlap = 9}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.overlap = -1}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tolerance = -0.5}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.boundary_weight = 0.5}) == tessera::status_code::invalid_argument);
  REQUIRE(code({.tolerance = std::numeric_limits<double>::quiet_NaN()}) == tessera::status_code::invalid_argument);
  tessera::image_buffer<std::uint8_t, 3> small(10, 40);
  REQUIRE(tessera::quilt(ex, small, {.patch_size = 16, .seamless = true}).code() ==
          tessera::status_code::invalid_argument);
  REQUIRE(tessera::quilt(ex, small, {.patch_size = 16}).ok());  // non-seamless output may be smaller than a patch
  tessera::image_view<std::uint8_t, 3> empty;
  REQUIRE(tessera::quilt(ex, empty).code() == tessera::status_code::invalid_argument);
  REQUIRE(tessera::quilt(empty, out).code() == tessera::status_code::invalid_argument);
  // NaN or infinite exemplar values would make every overlap error NaN: refused, naming the pixel
  auto nan = quilt_test::exemplar<float, 3>(tessera::exemplar_kind::sand, 32);
  nan.write(3, 4, {std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f});
  tessera::image_buffer<float, 3> outf(40, 40);
  auto s = tessera::quilt(nan, outf, {.patch_size = 8});
  REQUIRE(s.code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(s.message(), Catch::Contains("exemplar: pixel (3, 4) channel 0 is nan"));
  nan.write(3, 4, {0.5f, -std::numeric_limits<float>::infinity(), 0.5f});
  REQUIRE_THAT(tessera::quilt(nan, outf, {.patch_size = 8}).message(), Catch::Contains("channel 1 is -inf"));
  // outputs beyond max_quilt_pixels (2^28) and exemplars beyond max_quilt_exemplar_pixels (2^26):
  // size_overflow before anything is allocated
  quilt_test::huge_rgb8 huge_out{1 << 15, (1 << 13) + 1};
  auto big = tessera::quilt(ex, huge_out);
  REQUIRE(big.code() == tessera::status_code::size_overflow);
  REQUIRE_THAT(big.message(), Catch::Contains("output: 32768 x 8193 pixels exceed max_quilt_pixels"));
  const quilt_test::huge_rgb8 huge_ex{1 << 13, (1 << 13) + 1};
  REQUIRE_THAT(tessera::quilt(huge_ex, out).message(),
               Catch::Contains("exemplar: 8192 x 8193 pixels exceed max_quilt_exemplar_pixels"));
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
