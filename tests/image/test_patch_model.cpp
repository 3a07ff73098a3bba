#include <tessera/image/patch_model.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/image/exemplars.hpp>
#include "../support/test_support.hpp"

using tessera_test::exemplar;
using tessera_test::user_image;

using tessera::index_t;

namespace {

constexpr int all_sides[4] = {tessera::side_north, tessera::side_east, tessera::side_south, tessera::side_west};

// Brute-force top k of one side: all patches by (overlap error, index).
template <class M>
std::vector<std::pair<double, index_t>> brute_top_k(const M& m, index_t a, int side) {
  std::vector<std::pair<double, index_t>> all;
  for (index_t b = 0; b < m.num_patches(); ++b) all.push_back({m.overlap_error(a, b, side), b});
  std::sort(all.begin(), all.end());
  all.resize(static_cast<std::size_t>(m.candidates()));
  return all;
}

template <class M>
void check_exact_sets(const M& m, index_t step) {
  for (index_t a = 0; a < m.num_patches(); a += step)
    for (int side : all_sides) {
      const auto expected = brute_top_k(m, a, side);
      const auto got = m.compatible(a, side);
      const auto errors = m.compatible_errors(a, side);
      REQUIRE(static_cast<index_t>(got.size()) == m.candidates());
      for (std::size_t r = 0; r < got.size(); ++r) {
        INFO("patch " << a << " side " << tessera::side_name(side) << " rank " << r);
        CHECK(m.overlap_error(a, got[r], side) == expected[r].first);
        CHECK(got[r] == expected[r].second);  // ties broken by the smaller index
        CHECK(errors[r] == static_cast<float>(expected[r].first));
      }
    }
}

}  // namespace

TEST_CASE("patch_model: exact compatible sets equal a brute-force top-k", "[patch_model]") {
  SECTION("uint8 RGBA view") {
    auto ex = exemplar<std::uint8_t, 4>(tessera::exemplar_kind::grass, 40);
    const tessera::image_view<const std::uint8_t, 4> view = ex.cview();
    const auto m =
        tessera::build_patch_model(view, {.patch_width = 12, .patch_height = 10, .overlap = 3, .exact_sets = true})
            .value();
    CHECK(m.num_patches() == (40 - 15 + 1) * (40 - 13 + 1));
    check_exact_sets(m, 7);
  }
  SECTION("float RGB buffer, other PCA sizes") {
    const auto ex = exemplar<float, 3>(tessera::exemplar_kind::cells, 36);
    const auto m =
        tessera::build_patch_model(
            ex,
            {.patch_width = 10, .patch_height = 10, .overlap = 4, .candidates = 5, .exact_sets = true, .pca_dims = 3})
            .value();
    CHECK(m.candidates() == 5);
    check_exact_sets(m, 5);
  }
  SECTION("16-bit member-style user image") {
    const auto ex8 = exemplar(tessera::exemplar_kind::bricks, 32);
    user_image u{32, 32, {}};
    for (index_t y = 0; y < 32; ++y)
      for (index_t x = 0; x < 32; ++x)
        u.px.push_back(tessera::convert_pixel<std::array<std::uint16_t, 3>>(ex8.read(x, y)));
    const auto m =
        tessera::build_patch_model(u, {.patch_width = 8, .patch_height = 8, .overlap = 2, .exact_sets = true}).value();
    check_exact_sets(m, 3);
  }
  SECTION("ties: a tiled exemplar has many identical strips") {
    const auto tile = exemplar(tessera::exemplar_kind::rock, 8);
    tessera::image_buffer<std::uint8_t, 1> tiled(32, 32);
    for (index_t y = 0; y < 32; ++y)
      for (index_t x = 0; x < 32; ++x)
        tiled.write(x, y, tessera::convert_pixel<tessera::pixel<std::uint8_t, 1>>(tile.read(x % 8, y % 8)));
    const auto m =
        tessera::build_patch_model(tiled, {.patch_width = 8, .patch_height = 8, .overlap = 2, .exact_sets = true})
            .value();
    check_exact_sets(m, 11);
    CHECK(m.compatible_errors(0, tessera::side_east)[7] == 0.0f);  // at least 8 perfect continuations
  }
}

TEST_CASE("patch_model: approximate sets (kd-tree + coherence) are close to exact", "[patch_model]") {
  for (auto kind : {tessera::exemplar_kind::sand, tessera::exemplar_kind::bricks, tessera::exemplar_kind::dots}) {
    const auto ex = exemplar(kind, 48);
    const tessera::patch_model_options o{.patch_width = 14, .patch_height = 14, .overlap = 4};
    const auto m = tessera::build_patch_model(ex, o).value();
    double exact_sum = 0, approx_sum = 0;
    index_t found = 0, total = 0;
    for (index_t a = 0; a < m.num_patches(); a += 13)
      for (int side : all_sides) {
        const auto expected = brute_top_k(m, a, side);
        const auto got = m.compatible(a, side);
        for (std::size_t r = 0; r < got.size(); ++r) {
          exact_sum += expected[r].first;
          approx_sum += m.overlap_error(a, got[r], side);
          // sets are sorted, hold distinct patches and report their errors
          const auto errors = m.compatible_errors(a, side);
          CHECK(errors[r] == static_cast<float>(m.overlap_error(a, got[r], side)));
          if (r > 0) CHECK(errors[r - 1] <= errors[r]);
          if (r + 1 == got.size()) CHECK(m.kth_error(a, side) == errors[r]);
          found += std::count(got.begin(), got.end(), static_cast<std::uint32_t>(expected[r].second));
          ++total;
        }
        CHECK(m.overlap_error(a, got[0], side) <= 1.2 * expected[0].first);
      }
    INFO(tessera::to_string(kind) << ": recall " << double(found) / double(total) << ", error ratio "
                                  << exact_sum / approx_sum);
    CHECK(approx_sum <= 1.1 * exact_sum + 1);
    CHECK(double(found) / double(total) > 0.7);
  }
}

TEST_CASE("patch_model: patches grouped by phase", "[patch_model]") {
  const auto ex = exemplar(tessera::exemplar_kind::dots, 40);
  const auto m = tessera::build_patch_model(ex, {.patch_width = 9, .patch_height = 7, .overlap = 3}).value();
  CHECK(m.num_phases() == 63);
  std::vector<int> seen(static_cast<std::size_t>(m.num_patches()), 0);
  for (index_t p = 0; p < m.num_phases(); ++p) {
    const auto members = m.phase_patches(p);
    CHECK(std::is_sorted(members.begin(), members.end()));
    for (std::uint32_t q : members) {
      ++seen[q];
      CHECK(m.phase_of(q) == p);
      const auto o = m.origin(q);
      CHECK(o.x % 9 + 9 * (o.y % 7) == p);  // one uniform partition of the exemplar per phase (Fig. 2)
    }
  }
  for (int s : seen) CHECK(s == 1);
  // phase similarity: every offset once, the zero offset first
  const auto order = m.phase_similarity();
  REQUIRE(static_cast<index_t>(order.size()) == 63);
  CHECK(order[0].dx == 0);
  CHECK(order[0].dy == 0);
  for (std::size_t i = 1; i < order.size(); ++i) CHECK(order[i - 1].similarity >= order[i].similarity);
}

TEST_CASE("patch_model: precomputed seams are minimum-error cuts", "[patch_model]") {
  const auto ex = exemplar(tessera::exemplar_kind::bricks, 40);
  const auto m =
      tessera::build_patch_model(ex, {.patch_width = 12, .patch_height = 10, .overlap = 4, .seams = true}).value();
  REQUIRE(m.has_seams());
  CHECK(m.seam_length(tessera::side_east) == 14);
  CHECK(m.seam_length(tessera::side_south) == 16);
  const auto& img = m.exemplar();
  for (index_t a = 0; a < m.num_patches(); a += 17)
    for (int side : all_sides)
      for (index_t r = 0; r < m.candidates(); ++r) {
        const index_t b = m.compatible(a, side)[static_cast<std::size_t>(r)];
        const bool vertical = side == tessera::side_east || side == tessera::side_west;
        const bool a_first = side == tessera::side_east || side == tessera::side_south;
        const auto first = m.origin(a_first ? a : b), second = m.origin(a_first ? b : a);
        const auto seam = m.seam(a, side, r);
        REQUIRE(static_cast<index_t>(seam.size()) == m.seam_length(side));
        // error of a path: sum over the overlap's length of the squared difference at the cut pixel
        auto err = [&](index_t t, index_t c) {
          const auto p = vertical ? img.read(first.x + 12 + c, first.y + t) : img.read(first.x + t, first.y + 10 + c);
          const auto q = vertical ? img.read(second.x + c, second.y + t) : img.read(second.x + t, second.y + c);
          double s = 0;
          for (int ch = 0; ch < 3; ++ch) s += (double(p[ch]) - q[ch]) * (double(p[ch]) - q[ch]);
          return s;
        };
        double cost = 0;
        for (std::size_t t = 0; t < seam.size(); ++t) {
          CHECK(seam[t] < 4);
          if (t > 0) CHECK(std::abs(int(seam[t]) - int(seam[t - 1])) <= 1);
          cost += err(static_cast<index_t>(t), seam[t]);
        }
        // the cheapest 8-connected path through the overlap, by a dynamic programme of our own
        std::vector<double> best(4);
        for (index_t c = 0; c < 4; ++c) best[c] = err(0, c);
        for (std::size_t t = 1; t < seam.size(); ++t) {
          std::vector<double> next(4);
          for (index_t c = 0; c < 4; ++c)
            next[c] = err(static_cast<index_t>(t), c) +
                      std::min({best[c], best[std::max<index_t>(c - 1, 0)], best[std::min<index_t>(c + 1, 3)]});
          best = next;
        }
        CHECK(cost == *std::min_element(best.begin(), best.end()));
      }
  const auto plain = tessera::build_patch_model(ex, {.patch_width = 12, .patch_height = 10, .overlap = 4}).value();
  CHECK(!plain.has_seams());
  CHECK(plain.seam(0, tessera::side_east, 0).empty());
  CHECK(plain.memory_bytes() < m.memory_bytes());
}

TEST_CASE("patch_model: automatic size, executor independence, memory", "[patch_model]") {
  const auto ex = exemplar<std::uint8_t, 4>(tessera::exemplar_kind::sand, 48);
  const auto m = tessera::build_patch_model(ex).value();
  REQUIRE(m.analysis().has_value());
  CHECK(m.patch_width() == m.analysis()->patch_width);
  CHECK(m.overlap() == m.analysis()->overlap);
  CHECK(m.patch_width() >= 12);
  CHECK(m.patch_width() <= 24);
  tessera::thread_pool_executor pool(3);
  const auto p = tessera::build_patch_model(ex, {}, pool).value();
  for (index_t a = 0; a < m.num_patches(); ++a)
    for (int side : all_sides) {
      const auto x = m.compatible(a, side), y = p.compatible(a, side);
      REQUIRE(std::equal(x.begin(), x.end(), y.begin()));
    }
  // memory: about n * 4 sides * k * 8 bytes plus the exemplar, plus two strip descriptors of 9 floats per
  // strip position (at most about twice as many positions as patches)
  const double per_patch = double(m.memory_bytes() - m.exemplar().size_bytes()) / double(m.num_patches());
  CHECK(per_patch < 4 * (4 + 8 * 4 + 8 * 8) + 32 + 2 * 2 * 9 * 4);
  // given sizes skip the size analysis; a given size with overlap 0 runs only the overlap analysis
  const auto given = tessera::build_patch_model(ex, {.patch_width = 16, .patch_height = 14, .overlap = 5}).value();
  CHECK(!given.analysis().has_value());
  const auto half = tessera::build_patch_model(ex, {.patch_width = 16, .patch_height = 14}).value();
  REQUIRE(half.analysis().has_value());
  CHECK(half.overlap() == half.analysis()->overlap);
  CHECK(half.analysis()->sizes.empty());
}

TEST_CASE("patch_model: bad input and cancellation", "[patch_model]") {
  const auto ex = exemplar(tessera::exemplar_kind::sand, 32);
  tessera::image_view<const std::uint8_t, 3> empty;
  CHECK(tessera::build_patch_model(empty).error().code() == tessera::status_code::invalid_argument);
  auto bad = [&](const tessera::patch_model_options& o, const char* word) {
    auto r = tessera::build_patch_model(ex, o);
    REQUIRE(!r);
    CHECK(r.error().code() == tessera::status_code::invalid_argument);
    INFO(r.error().message());
    CHECK(r.error().message().find(word) != std::string::npos);
  };
  bad({.patch_width = -1, .patch_height = 8, .overlap = 2}, "patch_width");
  bad({.patch_width = 30, .patch_height = 8, .overlap = 4}, "do not fit");
  bad({.patch_width = 16, .patch_height = 16, .overlap = 16}, "fewer than two patches");
  bad({.patch_width = 8, .patch_height = 8, .overlap = 9}, "overlap");
  bad({.patch_width = 1, .patch_height = 8, .overlap = 1}, "patch sides >= 2");
  bad({.patch_width = 8, .patch_height = 8, .overlap = 2, .candidates = 0}, "candidates");
  bad({.patch_width = 8, .patch_height = 8, .overlap = 2, .candidates = 65}, "candidates");
  bad({.patch_width = 8, .patch_height = 8, .overlap = 2, .pca_dims = 0}, "pca_dims");
  bad({.patch_width = 8, .patch_height = 8, .overlap = 2, .pca_samples = 1}, "pca_samples");
  bad({.patch_width = 8, .patch_height = 8, .overlap = 2, .search_pool = 0}, "search_pool");
  // an exemplar too small for the automatic analysis
  const auto tiny = exemplar(tessera::exemplar_kind::sand, 6);
  CHECK(!tessera::build_patch_model(tiny));
  // k larger than the number of patches is clamped
  const auto small = tessera::build_patch_model(ex, {.patch_width = 12, .patch_height = 12, .overlap = 4}).value();
  CHECK(small.num_patches() == 17 * 17);
  const auto two =
      tessera::build_patch_model(ex, {.patch_width = 16, .patch_height = 17, .overlap = 15, .candidates = 8});
  REQUIRE(two.ok());
  CHECK(two->num_patches() == 2);
  CHECK(two->candidates() == 2);
  // cancellation
  tessera::cancellation_token stop;
  stop.cancel();
  tessera::patch_model_options o{.patch_width = 8, .patch_height = 8, .overlap = 2};
  o.progress.token = &stop;
  CHECK(tessera::build_patch_model(ex, o).error().code() == tessera::status_code::cancelled);
  int calls = 0;
  tessera::patch_model_options p{.patch_width = 8, .patch_height = 8, .overlap = 2};
  p.progress.callback = [&](double, std::string_view) { return ++calls < 4; };
  CHECK(tessera::build_patch_model(ex, p).error().code() == tessera::status_code::cancelled);
}

TEST_CASE("patch_model: exact overlap errors on rows longer than 65536 channel values", "[patch_model]") {
  // 17000 RGBA pixels a row: 68000 squared differences of 255, 4.4e9 in all, more than 32 bits hold
  tessera::image_buffer<std::uint8_t, 4> wide(17000, 2);
  for (index_t x = 0; x < 17000; ++x) wide.write(x, 1, {255, 255, 255, 255});
  const double expected = 68000.0 * 255.0 * 255.0;
  CHECK(tessera::detail::window_ssd(wide, 0, 0, 0, 1, 17000, 1) == expected);
  CHECK(tessera::detail::window_ssd(wide, 0, 1, 0, 0, 17000, 1) == expected);
  CHECK(tessera::detail::window_ssd(wide, 5, 0, 9, 0, 16990, 2) == 0.0);
  // other channel types agree (16 bits: 257 x the difference)
  tessera::image_buffer<std::uint16_t, 4> wide16(17000, 2);
  REQUIRE(tessera::copy_image(wide, wide16).ok());
  CHECK(tessera::detail::window_ssd(wide16, 0, 0, 0, 1, 17000, 1) == 68000.0 * 65535.0 * 65535.0);
  // a mixed row against brute force
  tessera::image_buffer<std::uint8_t, 4> mixed(17000, 2);
  double brute = 0;
  for (index_t x = 0; x < 17000; ++x) {
    const auto a = static_cast<std::uint8_t>((x * 37) % 256), b = static_cast<std::uint8_t>(255 - (x * 11) % 256);
    mixed.write(x, 0, {a, b, a, b});
    mixed.write(x, 1, {b, a, 0, 255});
    brute += 2.0 * (double(a) - b) * (double(a) - b) + double(a) * a + (double(b) - 255) * (double(b) - 255);
  }
  CHECK(tessera::detail::window_ssd(mixed, 0, 0, 0, 1, 17000, 1) == brute);
}

TEST_CASE("patch_model: elongated exemplars", "[patch_model]") {
  // automatic size on a 256 x 12 strip (the periodicity analysis keeps 8 pixels across)
  const auto strip =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::bricks, {.width = 256, .height = 12}).value();
  const auto m = tessera::build_patch_model(strip).value();
  CHECK(m.patch_height() >= 3);
  CHECK(m.patch_height() <= 6);
  CHECK(m.patch_width() <= 6);
  CHECK(m.num_patches() == (256 - m.patch_width() - m.overlap() + 1) * (12 - m.patch_height() - m.overlap() + 1));
}

TEST_CASE("patch_model: the deprecated patch_side spelling reads as core's sides") {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  STATIC_REQUIRE(tessera::patch_side::north == tessera::side_north);
  STATIC_REQUIRE(tessera::patch_side::east == tessera::side_east);
  STATIC_REQUIRE(tessera::patch_side::south == tessera::side_south);
  STATIC_REQUIRE(tessera::patch_side::west == tessera::side_west);
#pragma GCC diagnostic pop
  CHECK(tessera::side_name(tessera::side_west) == "west");
  CHECK(tessera::side_name(4) == "invalid side");
  CHECK(tessera::side_name(-1) == "invalid side");
}

TEST_CASE("patch_model: estimated overlap errors from the strip descriptors", "[patch_model]") {
  // strips of 3 values (patch 2 x 2, overlap 1, one channel) lie in the PCA span (8 dimensions):
  // the estimate is the exact error up to float rounding
  const auto grey = exemplar<std::uint8_t, 1>(tessera::exemplar_kind::sand, 16);
  const auto small = tessera::build_patch_model(grey, {.patch_width = 2, .patch_height = 2, .overlap = 1}).value();
  for (index_t a = 0; a < small.num_patches(); a += 7)
    for (index_t b = 0; b < small.num_patches(); b += 5)
      for (int side : all_sides) {
        const double exact = small.overlap_error(a, b, side), est = small.estimated_error(a, b, side);
        INFO("a " << a << " b " << b << " side " << side);
        CHECK(est == Approx(exact).margin(0.5).epsilon(1e-3));
      }
  // larger strips: never negative, and on average close to the true error of unrelated pairs (the
  // projections' distance plus both residuals)
  const auto ex = exemplar(tessera::exemplar_kind::sand, 48);
  const auto m = tessera::build_patch_model(ex, {.patch_width = 12, .patch_height = 12, .overlap = 4}).value();
  double sum_exact = 0, sum_est = 0;
  for (index_t a = 0; a < m.num_patches(); a += 37)
    for (index_t b = 3; b < m.num_patches(); b += 41)
      for (int side : all_sides) {
        const double e = m.estimated_error(a, b, side);
        CHECK(e >= 0);
        sum_est += e;
        sum_exact += m.overlap_error(a, b, side);
      }
  INFO("estimated " << sum_est << " exact " << sum_exact);
  CHECK(sum_est > 0.7 * sum_exact);
  CHECK(sum_est < 1.3 * sum_exact);
  // a flat exemplar: every estimate is 0
  tessera::image_buffer<std::uint8_t, 3> flat(24, 24, {90, 90, 90});
  const auto f = tessera::build_patch_model(flat, {.patch_width = 6, .patch_height = 6, .overlap = 2}).value();
  for (int side : all_sides) CHECK(f.estimated_error(0, f.num_patches() - 1, side) == 0.0);
}

TEST_CASE("patch_model: min_patch_fraction bounds the automatic size", "[patch_model]") {
  const auto ex = exemplar(tessera::exemplar_kind::sand, 64);
  const auto ours = tessera::build_patch_model(ex).value();  // default 0.375: sides 24 to 32
  CHECK(ours.patch_width() >= 24);
  CHECK(ours.patch_height() >= 24);
  REQUIRE(ours.analysis().has_value());
  for (const auto& s : ours.analysis()->sizes) CHECK(std::min(s.width, s.height) >= 24);
  const auto paper = tessera::build_patch_model(ex, {.min_patch_fraction = 0.25}).value();  // the paper's 16 to 32
  CHECK(paper.analysis()->sizes.front().width == 16);
  // an explicit analysis range wins; a max_size below the fraction's side lowers it
  {
    tessera::patch_model_options o;
    o.analysis.max_size = 20;
    const auto capped = tessera::build_patch_model(ex, o).value();
    CHECK(capped.patch_width() <= 20);
  }
  for (double bad : {0.0, -1.0, 0.51, std::numeric_limits<double>::quiet_NaN()}) {
    auto r = tessera::build_patch_model(ex, {.min_patch_fraction = bad});
    REQUIRE(!r);
    CHECK(r.error().code() == tessera::status_code::invalid_argument);
    CHECK(r.error().message().find("min_patch_fraction") != std::string::npos);
  }
  // tiny exemplars still get a size (8 x 8: sides 3 to 4) or a clear status, never a crash
  for (index_t side : {8, 9, 12}) {
    auto r = tessera::build_patch_model(exemplar(tessera::exemplar_kind::sand, side));
    if (!r) CHECK(!r.error().message().empty());
  }
}
