#include <tessera/image/wang_seam_quality.hpp>

#include <tessera/image/exemplars.hpp>

#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;

namespace {
// mean over channels of |a - b| in unit range
double unit_diff(const std::array<std::uint8_t, 3>& a, const std::array<std::uint8_t, 3>& b) {
  double s = 0;
  for (std::size_t c = 0; c < 3; ++c) s += std::abs(double(a[c]) - double(b[c])) / 255.0;
  return s / 3;
}
}  // namespace

TEST_CASE("wang seam quality: every pair that can touch, seams as smooth as the exemplar", "[wang]") {
  for (auto kind : {tessera::exemplar_kind::grass, tessera::exemplar_kind::cells, tessera::exemplar_kind::bricks}) {
    const auto ex = quilt_test::exemplar(kind, 64, 2);
    auto set = tessera::build_wang_tiles(ex, {.tile_size = 32, .seed = 3});
    REQUIRE(set.ok());
    auto report = tessera::wang_seam_quality(*set, ex);
    REQUIRE(report.ok());
    // brute force: every ordered pair (a west of b, or a above b) whose touching colours agree, its
    // ratio recomputed from the pixels (mean difference across the edge over the exemplar's mean
    // difference between neighbours in the same direction)
    const index_t ts = 32, n = set->size();
    double mean_x = 0, mean_y = 0;
    for (index_t y = 0; y < 64; ++y)
      for (index_t x = 0; x < 64; ++x) {
        if (x > 0) mean_x += unit_diff(ex.read(x - 1, y), ex.read(x, y));
        if (y > 0) mean_y += unit_diff(ex.read(x, y - 1), ex.read(x, y));
      }
    mean_x /= 63.0 * 64.0;
    mean_y /= 64.0 * 63.0;
    std::map<std::tuple<bool, index_t, index_t>, double> expected;
    for (index_t a = 0; a < n; ++a)
      for (index_t b = 0; b < n; ++b)
        for (bool vertical : {true, false}) {
          const auto& ea = set->edges()[a];
          const auto& eb = set->edges()[b];
          if (vertical ? ea.east != eb.west : ea.south != eb.north) continue;
          double sum = 0;
          for (index_t k = 0; k < ts; ++k)
            sum += vertical ? unit_diff(set->tile(a).read(ts - 1, k), set->tile(b).read(0, k))
                            : unit_diff(set->tile(a).read(k, ts - 1), set->tile(b).read(k, 0));
          expected[{vertical, a, b}] = sum / double(ts) / (vertical ? mean_x : mean_y);
        }
    REQUIRE(report->pairs.size() == expected.size());
    REQUIRE(expected.size() == 256u);  // complete 2 x 2 set: each of 16 tiles has 8 east and 8 south partners
    double max_ratio = 0, sum = 0;
    for (const auto& [key, ratio] : expected) {
      sum += ratio;
      max_ratio = std::max(max_ratio, ratio);
    }
    for (const auto& p : report->pairs) {
      const auto it = expected.find({p.vertical, p.first, p.second});
      REQUIRE(it != expected.end());
      REQUIRE(p.ratio == Approx(it->second).epsilon(1e-6));
    }
    REQUIRE(report->max_ratio == Approx(max_ratio).epsilon(1e-6));
    REQUIRE(report->mean_ratio == Approx(sum / double(expected.size())).epsilon(1e-6));
    REQUIRE(expected.at({report->worst.vertical, report->worst.first, report->worst.second}) ==
            Approx(max_ratio).epsilon(1e-6));
    CAPTURE(to_string(kind), report->mean_ratio, report->max_ratio);
    REQUIRE(report->mean_ratio < 1.0);
    REQUIRE(report->max_ratio < 1.6);
  }
}

TEST_CASE("wang seam quality: mislabelled tiles show their seams", "[wang]") {
  // the same images with edge labels shuffled: touching edges no longer come from one strip
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::cells, 64, 2);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 32, .seed = 3});
  REQUIRE(set.ok());
  std::vector<tessera::image_buffer<std::uint8_t, 3>> images;
  for (index_t t = 0; t < 16; ++t) images.push_back(tessera::to_buffer(set->tile((t * 7 + 3) % 16)).value());
  auto shuffled = tessera::wang_tile_set<std::uint8_t, 3>::create(set->edges(), 32, images);
  REQUIRE(shuffled.ok());
  const double good = tessera::wang_seam_quality(*set, ex)->mean_ratio;
  const double bad = tessera::wang_seam_quality(*shuffled, ex)->mean_ratio;
  CAPTURE(good, bad);
  REQUIRE(bad > 1.5 * good);
}

TEST_CASE("wang seam quality: tile border seams and bad input", "[wang]") {
  const auto seams = tessera::tile_border_seams(70, 40, 16, 5, 30);
  // vertical borders where 5 + x is a multiple of 16: x = 11, 27, 43, 59; horizontal: 30 + y: y = 2, 18, 34
  REQUIRE(seams.size() == 7u);
  REQUIRE(seams[0].vertical);
  REQUIRE(seams[0].position == 11);
  REQUIRE(seams[0].end == 40);
  REQUIRE_FALSE(seams[4].vertical);
  REQUIRE(seams[4].position == 2);
  REQUIRE(seams[4].end == 70);
  REQUIRE(tessera::tile_border_seams(10, 10, 0).empty());
  tessera::wang_tile_set<std::uint8_t, 3> empty;
  REQUIRE_FALSE(tessera::wang_seam_quality(empty, quilt_test::exemplar(tessera::exemplar_kind::sand, 16)).ok());
  auto set = tessera::build_wang_tiles(quilt_test::exemplar(tessera::exemplar_kind::sand, 32),
                                       {.tile_size = 8, .horizontal_colors = 1, .vertical_colors = 1});
  tessera::image_buffer<std::uint8_t, 3> flat(16, 16, {9, 9, 9});
  REQUIRE(tessera::wang_seam_quality(*set, flat).error().code() == tessera::status_code::invalid_argument);
  tessera::image_buffer<float, 3> nan(16, 16, {0.5f, 0.5f, 0.5f});
  nan.write(2, 3, {0.5f, 0.5f, std::nanf("")});
  REQUIRE_THAT(tessera::wang_seam_quality(*set, nan).error().message(),
               Catch::Contains("pixel (2, 3) channel 2 is nan"));
  // the complete set for 7 x 7 colours (2401 tiles of 1 pixel) has 1.6 million touching pairs
  auto many = tessera::tile_set_edges::complete(7, 7);
  std::vector<tessera::image_buffer<std::uint8_t, 3>> dots(2401, tessera::image_buffer<std::uint8_t, 3>(1, 1));
  auto big = tessera::wang_tile_set<std::uint8_t, 3>::create(*many, 1, dots);
  REQUIRE(big.ok());
  auto over = tessera::wang_seam_quality(*big, quilt_test::exemplar(tessera::exemplar_kind::sand, 16));
  REQUIRE(over.error().code() == tessera::status_code::size_overflow);
  REQUIRE_THAT(over.error().message(), Catch::Contains("1647086 touching pairs"));
}
