#include <tessera/image/patch_size.hpp>

#include <algorithm>
#include <cstdint>
#include <string>

#include <catch2/catch.hpp>
#include <tessera/image/exemplars.hpp>

using tessera::index_t;

namespace {
template <class T = std::uint8_t, int C = 3>
tessera::image_buffer<T, C> exemplar(tessera::exemplar_kind kind, index_t size, std::uint64_t seed = 1) {
  return tessera::make_exemplar<T, C>(kind, {.width = size, .height = size, .seed = seed}).value();
}
}  // namespace

TEST_CASE("analyze_patch_size: candidates span a quarter to a half of the exemplar", "[patch_size]") {
  const auto ex = exemplar(tessera::exemplar_kind::rock, 64);
  const auto a = tessera::analyze_patch_size(ex).value();
  REQUIRE(a.sizes.size() == 9 * 9);
  for (const auto& m : a.sizes) {
    CHECK(m.width >= 16);
    CHECK(m.width <= 32);
    CHECK(m.height >= 16);
    CHECK(m.height <= 32);
    CHECK(m.containment >= 0.0);
    CHECK(m.containment <= 1.0);
    CHECK(m.periodicity_hits >= 0.0);
    CHECK(m.periodicity_hits <= 1.0);
    CHECK(m.alignment >= -1.0);
    CHECK(m.alignment <= 1.0);
  }
  CHECK(a.patch_width >= 16);
  CHECK(a.patch_width <= 32);
  CHECK(a.patch_height >= 16);
  CHECK(a.patch_height <= 32);
  // the chosen shape has the best score
  const auto best = std::max_element(a.sizes.begin(), a.sizes.end(), [](const auto& x, const auto& y) { return x.score < y.score; });
  CHECK(best->score == std::find_if(a.sizes.begin(), a.sizes.end(), [&](const auto& m) {
                         return m.width == a.patch_width && m.height == a.patch_height;
                       })->score);
  // overlap: one width, the smallest whose discrimination reaches 90 % of the best
  REQUIRE(!a.overlaps.empty());
  double top = -1;
  for (const auto& o : a.overlaps) top = std::max(top, o.discrimination);
  for (const auto& o : a.overlaps) {
    if (o.overlap < a.overlap) CHECK(o.discrimination < 0.9 * top);
    if (o.overlap == a.overlap) CHECK(o.discrimination >= 0.9 * top);
  }
  CHECK(a.overlap >= 2);
  CHECK(a.overlap <= std::min(a.patch_width, a.patch_height) / 3);
  // square-only
  const auto sq = tessera::analyze_patch_size(ex, {.rectangular = false}).value();
  CHECK(sq.sizes.size() == 9);
  for (const auto& m : sq.sizes) CHECK(m.width == m.height);
}

TEST_CASE("analyze_patch_size: containment grows with the patch, the paper's 90 % rule", "[patch_size]") {
  const auto ex = exemplar(tessera::exemplar_kind::cells, 64);
  const auto a = tessera::analyze_patch_size(ex, {.rectangular = false}).value();
  // larger patches hold more of the exemplar's grey histogram
  CHECK(a.sizes.front().containment_p90 > a.sizes.back().containment_p90);
  CHECK(a.sizes.front().containment <= a.sizes.back().containment);
  // qualified means containment and periodicity hits both reach their thresholds
  for (const auto& m : a.sizes) CHECK(m.qualified == (m.containment >= 0.9 && m.periodicity_hits >= 0.75));
  // a tolerance of 0 admits no patch, a huge one every patch
  const auto none = tessera::analyze_patch_size(ex, {.rectangular = false, .containment_tolerance = 0.0}).value();
  for (const auto& m : none.sizes) CHECK(m.containment == 0.0);
  const auto all = tessera::analyze_patch_size(ex, {.rectangular = false, .containment_tolerance = 100.0}).value();
  for (const auto& m : all.sizes) CHECK(m.containment == 1.0);
}

TEST_CASE("analyze_patch_size: periodic exemplars align with a multiple of their period", "[patch_size]") {
  // weave repeats every size / 8 = 8 pixels: 16, 24 and 32 are periods
  const auto ex = exemplar(tessera::exemplar_kind::weave, 64);
  const auto a = tessera::analyze_patch_size(ex).value();
  for (const auto& m : a.sizes)
    if (m.width % 8 == 0 && m.height % 8 == 0) CHECK(m.alignment > 0.9);
  CHECK(a.patch_width % 8 == 0);
  CHECK(a.patch_height % 8 == 0);
  // a tiled exemplar: every reference block finds its copies
  const auto tile = exemplar(tessera::exemplar_kind::rock, 16);
  tessera::image_buffer<std::uint8_t, 3> tiled(64, 64);
  for (index_t y = 0; y < 64; ++y)
    for (index_t x = 0; x < 64; ++x) tiled.write(x, y, tile.read(x % 16, y % 16));
  const auto t = tessera::analyze_patch_size(tiled, {.rectangular = false}).value();
  for (const auto& m : t.sizes) CHECK(m.periodicity_hits == 1.0);
  CHECK(t.patch_width % 16 == 0);  // a candidate aligned with the tiling
  // a stochastic exemplar has no such alignment
  const auto sand = tessera::analyze_patch_size(exemplar(tessera::exemplar_kind::sand, 64), {.rectangular = false}).value();
  for (const auto& m : sand.sizes) CHECK(m.alignment < 0.5);
}

TEST_CASE("analyze_patch_size: deterministic, executor-independent, any pixel type", "[patch_size]") {
  const auto ex = exemplar(tessera::exemplar_kind::grass, 48);
  const auto a = tessera::analyze_patch_size(ex, {.seed = 3}).value();
  tessera::thread_pool_executor pool(2);
  const auto b = tessera::analyze_patch_size(ex, {.seed = 3}, pool).value();
  REQUIRE(a.sizes.size() == b.sizes.size());
  for (std::size_t i = 0; i < a.sizes.size(); ++i) {
    CHECK(a.sizes[i].containment == b.sizes[i].containment);
    CHECK(a.sizes[i].periodicity == b.sizes[i].periodicity);
    CHECK(a.sizes[i].alignment == b.sizes[i].alignment);
  }
  CHECK(a.patch_width == b.patch_width);
  CHECK(a.overlap == b.overlap);
  // the grey image is what counts: a float RGBA copy gives nearly the same measures
  tessera::image_buffer<float, 4> f(48, 48);
  REQUIRE(tessera::copy_image(ex, f).ok());
  const auto c = tessera::analyze_patch_size(f, {.seed = 3}).value();
  CHECK(c.sizes.size() == a.sizes.size());
  CHECK(c.sizes[5].alignment == Approx(a.sizes[5].alignment).margin(0.02));
}

TEST_CASE("analyze_overlap: the overlap for a caller's patch size", "[patch_size]") {
  const auto ex = exemplar(tessera::exemplar_kind::sand, 64);
  const auto a = tessera::analyze_overlap(ex, 20, 24).value();
  CHECK(a.patch_width == 20);
  CHECK(a.patch_height == 24);
  CHECK(a.overlaps.front().overlap == 20 / 6);
  CHECK(a.overlaps.back().overlap == 20 / 3);
  const auto b = tessera::analyze_overlap(ex, 20, 24, {.min_overlap = 4, .max_overlap = 5}).value();
  REQUIRE(b.overlaps.size() == 2);
  CHECK((b.overlap == 4 || b.overlap == 5));
  CHECK(!tessera::analyze_overlap(ex, 1, 24));
  CHECK(!tessera::analyze_overlap(ex, 64, 24));
  CHECK(!tessera::analyze_overlap(ex, 62, 62, {.min_overlap = 4}));  // no room for the overlap
}

TEST_CASE("analyze_patch_size: bad input and cancellation", "[patch_size]") {
  const auto ex = exemplar(tessera::exemplar_kind::sand, 32);
  tessera::image_view<const std::uint8_t, 3> empty;
  CHECK(tessera::analyze_patch_size(empty).error().code() == tessera::status_code::invalid_argument);
  const auto tiny = exemplar(tessera::exemplar_kind::sand, 7);
  CHECK(tessera::analyze_patch_size(tiny).error().message().find("8 x 8") != std::string::npos);
  auto bad = [&](tessera::patch_size_options o, const char* word) {
    auto r = tessera::analyze_patch_size(ex, o);
    REQUIRE(!r);
    CHECK(r.error().code() == tessera::status_code::invalid_argument);
    CHECK(r.error().message().find(word) != std::string::npos);
  };
  bad({.min_size = 20, .max_size = 10}, "min_size");
  bad({.max_size = 32}, "max_size");
  bad({.candidates_per_axis = 0}, "candidates_per_axis");
  bad({.histogram_bins = 1}, "histogram_bins");
  bad({.containment_fraction = 1.5}, "containment_fraction");
  bad({.reference_grid = 0}, "reference_grid");
  bad({.similarity = 0}, "similarity");
  bad({.periodicity_hits = -1}, "periodicity_hits");
  bad({.analysis_size = 4}, "analysis_size");
  bad({.min_overlap = 5, .max_overlap = 3}, "overlap");
  bad({.overlap_pairs = 2}, "overlap_pairs");
  tessera::cancellation_token stop;
  stop.cancel();
  tessera::patch_size_options o;
  o.progress.token = &stop;
  CHECK(tessera::analyze_patch_size(ex, o).error().code() == tessera::status_code::cancelled);
  int calls = 0;
  tessera::patch_size_options p;
  p.progress.callback = [&](double, std::string_view) { return ++calls < 3; };
  CHECK(tessera::analyze_patch_size(ex, p).error().code() == tessera::status_code::cancelled);
  CHECK(calls == 3);
}
