#include <tessera/image/wang_seam_quality.hpp>

#include <tessera/image/exemplars.hpp>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;

TEST_CASE("wang seam quality: every pair that can touch, seams as smooth as the exemplar", "[wang]") {
  for (auto kind : {tessera::exemplar_kind::grass, tessera::exemplar_kind::cells, tessera::exemplar_kind::bricks}) {
    const auto ex = quilt_test::exemplar(kind, 64, 2);
    auto set = tessera::build_wang_tiles(ex, {.tile_size = 32, .seed = 3});
    REQUIRE(set.ok());
    auto report = tessera::wang_seam_quality(*set, ex);
    REQUIRE(report.ok());
    // complete 2 x 2 set: each of 16 tiles has 8 east and 8 south partners
    REQUIRE(report->pairs.size() == 256u);
    for (const auto& p : report->pairs) {
      const auto& a = set->edges()[p.first];
      const auto& b = set->edges()[p.second];
      REQUIRE((p.vertical ? a.east == b.west : a.south == b.north));
      REQUIRE(report->max_ratio >= p.ratio);
    }
    CAPTURE(to_string(kind), report->mean_ratio, report->max_ratio);
    REQUIRE(report->mean_ratio < 1.0);
    REQUIRE(report->max_ratio < 1.6);
    REQUIRE(report->worst.ratio == report->max_ratio);
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
  auto set = tessera::build_wang_tiles(quilt_test::exemplar(tessera::exemplar_kind::sand, 32), {.tile_size = 8, .horizontal_colors = 1, .vertical_colors = 1});
  tessera::image_buffer<std::uint8_t, 3> flat(16, 16, {9, 9, 9});
  REQUIRE(tessera::wang_seam_quality(*set, flat).error().code() == tessera::status_code::invalid_argument);
}
