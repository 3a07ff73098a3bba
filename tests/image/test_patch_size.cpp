#include <tessera/image/patch_size.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/core/random.hpp>
#include <tessera/image/exemplars.hpp>
#include "../support/test_support.hpp"

using tessera_test::exemplar;

using tessera::index_t;

TEST_CASE("analyze_patch_size: candidates span a quarter to a half of the exemplar", "[patch_size]") {
  const auto ex = exemplar(tessera::exemplar_kind::rock, 64);
  const auto a = tessera::analyze_patch_size(ex).value();
  // 9 evenly spaced sides in [64 / 4, 64 / 2] per axis, every pairing, height-major
  const index_t sides[9] = {16, 18, 20, 22, 24, 26, 28, 30, 32};
  REQUIRE(a.sizes.size() == 9 * 9);
  for (std::size_t i = 0; i < a.sizes.size(); ++i) {
    CHECK(a.sizes[i].width == sides[i % 9]);
    CHECK(a.sizes[i].height == sides[i / 9]);
  }
  // the 1/4-1/2 range follows the smaller exemplar side on both axes
  const auto wide =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::rock, {.width = 96, .height = 40}).value();
  const auto w = tessera::analyze_patch_size(wide, {.candidates_per_axis = 3}).value();
  REQUIRE(w.sizes.size() == 9);
  CHECK(w.sizes.front().width == 10);
  CHECK(w.sizes.back().width == 20);
  CHECK(w.sizes.back().height == 20);
  // overlap: one width, the smallest whose discrimination reaches 90 % of the best
  REQUIRE(!a.overlaps.empty());
  double top = -1;
  for (const auto& o : a.overlaps) top = std::max(top, o.discrimination);
  for (const auto& o : a.overlaps) {
    if (o.overlap < a.overlap) CHECK(o.discrimination < 0.9 * top);
    if (o.overlap == a.overlap) CHECK(o.discrimination >= 0.9 * top);
  }
  CHECK(a.overlaps.front().overlap == std::max<index_t>(2, std::min(a.patch_width, a.patch_height) / 6));
  CHECK(a.overlaps.back().overlap == std::min(a.patch_width, a.patch_height) / 3);
  // square-only
  const auto sq = tessera::analyze_patch_size(ex, {.rectangular = false}).value();
  REQUIRE(sq.sizes.size() == 9);
  for (std::size_t i = 0; i < 9; ++i) CHECK(sq.sizes[i].width == sides[i]);
  for (const auto& m : sq.sizes) CHECK(m.width == m.height);
}

namespace {

// The documented ranking: paper measures passed, then alignment level (steps of 0.05, none below
// min_alignment), then the smaller area, then the first shape.
std::tuple<int, double, index_t> rank_key(const tessera::patch_size_measure& m,
                                          const tessera::patch_size_options& o = {}) {
  const int passed =
      (m.containment >= o.containment_fraction ? 1 : 0) + (m.periodicity_hits >= o.periodicity_hits ? 1 : 0);
  const double level = m.alignment >= o.min_alignment ? std::floor(m.alignment * 20.0) : 0.0;
  return {passed, level, -m.width * m.height};
}

void check_choice(const tessera::patch_size_analysis& a, const tessera::patch_size_options& o = {}) {
  const auto chosen = std::find_if(a.sizes.begin(), a.sizes.end(), [&](const auto& m) {
    return m.width == a.patch_width && m.height == a.patch_height;
  });
  REQUIRE(chosen != a.sizes.end());
  for (auto it = a.sizes.begin(); it != a.sizes.end(); ++it) {
    INFO(it->width << " x " << it->height << " against the chosen " << a.patch_width << " x " << a.patch_height);
    CHECK(it->qualified == (it->containment >= o.containment_fraction && it->periodicity_hits >= o.periodicity_hits));
    if (it < chosen)
      CHECK(rank_key(*it, o) < rank_key(*chosen, o));
    else
      CHECK(!(rank_key(*chosen, o) < rank_key(*it, o)));
  }
}

}  // namespace

TEST_CASE("analyze_patch_size: the paper's two measures rank first, alignment breaks their ties", "[patch_size]") {
  for (auto kind : tessera::all_exemplar_kinds) {
    INFO(tessera::to_string(kind));
    const auto a = tessera::analyze_patch_size(exemplar(kind, 48)).value();
    check_choice(a);
    // a shape the paper accepts always beats one it does not, however well the latter aligns
    const bool any = std::any_of(a.sizes.begin(), a.sizes.end(), [](const auto& m) { return m.qualified; });
    const auto chosen = *std::find_if(a.sizes.begin(), a.sizes.end(), [&](const auto& m) {
      return m.width == a.patch_width && m.height == a.patch_height;
    });
    CHECK(chosen.qualified == any);
  }
  // bricks: shapes of one brick period align best but fail containment; the choice is qualified and
  // aligned (a multiple of the period)
  const auto bricks = tessera::analyze_patch_size(exemplar(tessera::exemplar_kind::bricks, 64)).value();
  check_choice(bricks);
  const auto chosen = *std::find_if(bricks.sizes.begin(), bricks.sizes.end(), [&](const auto& m) {
    return m.width == bricks.patch_width && m.height == bricks.patch_height;
  });
  CHECK(chosen.qualified);
  CHECK(chosen.alignment > 0.8);
  CHECK(std::any_of(bricks.sizes.begin(), bricks.sizes.end(),
                    [](const auto& m) { return !m.qualified && m.alignment > 0.8; }));
  // a looser periodicity rule admits more shapes and ranks by it
  const tessera::patch_size_options loose{.periodicity_hits = 0.5};
  check_choice(tessera::analyze_patch_size(exemplar(tessera::exemplar_kind::grass, 48), loose).value(), loose);
}

TEST_CASE("analyze_patch_size: containment grows with the patch, the paper's 90 % rule", "[patch_size]") {
  const auto ex = exemplar(tessera::exemplar_kind::cells, 64);
  const auto a = tessera::analyze_patch_size(ex, {.rectangular = false}).value();
  // larger patches hold more of the exemplar's grey histogram
  CHECK(a.sizes.front().containment_p90 > a.sizes.back().containment_p90);
  CHECK(a.sizes.front().containment <= a.sizes.back().containment);
  // qualified means containment and periodicity hits both reach their thresholds (all references, §2.1.2)
  for (const auto& m : a.sizes) CHECK(m.qualified == (m.containment >= 0.9 && m.periodicity_hits == 1.0));
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
  // a stochastic exemplar has no such alignment
  const auto sand =
      tessera::analyze_patch_size(exemplar(tessera::exemplar_kind::sand, 64), {.rectangular = false}).value();
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

namespace {

// The grey image the analysis works on: the exemplar converted to one float channel.
template <class I>
tessera::image_buffer<float, 1> grey_of(const I& img) {
  return tessera::to_buffer<float, 1>(img).value();
}

// Containment by brute force (§2.1.1): normalized grey histograms of patches every max(1, min(w, h) / 8)
// pixels against the exemplar's, L2 distance relative to the exemplar histogram's norm.
std::pair<double, double> brute_containment(const tessera::image_buffer<float, 1>& g, index_t w, index_t h, int bins,
                                            double tolerance) {
  auto bin = [&](index_t x, index_t y) {
    const double u = std::clamp(static_cast<double>(g.read(x, y)[0]), 0.0, 1.0);
    return std::min<index_t>(bins - 1, static_cast<index_t>(u * bins));
  };
  std::vector<double> global(static_cast<std::size_t>(bins), 0.0);
  for (index_t y = 0; y < g.height(); ++y)
    for (index_t x = 0; x < g.width(); ++x)
      global[static_cast<std::size_t>(bin(x, y))] += 1.0 / double(g.width() * g.height());
  double norm = 0;
  for (double v : global) norm += v * v;
  norm = std::sqrt(norm);
  const index_t step = std::max<index_t>(1, std::min(w, h) / 8);
  std::vector<double> dist;
  for (index_t y0 = 0; y0 + h <= g.height(); y0 += step)
    for (index_t x0 = 0; x0 + w <= g.width(); x0 += step) {
      std::vector<double> hist(static_cast<std::size_t>(bins), 0.0);
      for (index_t y = 0; y < h; ++y)
        for (index_t x = 0; x < w; ++x) hist[static_cast<std::size_t>(bin(x0 + x, y0 + y))] += 1.0 / double(w * h);
      double d2 = 0;
      for (int b = 0; b < bins; ++b) d2 += (hist[b] - global[b]) * (hist[b] - global[b]);
      dist.push_back(std::sqrt(d2) / norm);
    }
  std::sort(dist.begin(), dist.end());
  const double within =
      double(std::upper_bound(dist.begin(), dist.end(), tolerance) - dist.begin()) / double(dist.size());
  return {within, dist[std::min(dist.size() - 1, static_cast<std::size_t>(0.9 * double(dist.size())))]};
}

// Pearson correlation of a grey image with itself shifted by (dx, dy), over the overlapping part.
double brute_correlation(const tessera::image_buffer<float, 1>& g, index_t dx, index_t dy) {
  double sa = 0, sb = 0, n = 0;
  for (index_t y = 0; y + dy < g.height(); ++y)
    for (index_t x = 0; x + dx < g.width(); ++x) sa += g.read(x, y)[0], sb += g.read(x + dx, y + dy)[0], n += 1;
  double cov = 0, va = 0, vb = 0;
  for (index_t y = 0; y + dy < g.height(); ++y)
    for (index_t x = 0; x + dx < g.width(); ++x) {
      const double a = g.read(x, y)[0] - sa / n, b = g.read(x + dx, y + dy)[0] - sb / n;
      cov += a * b, va += a * a, vb += b * b;
    }
  return cov / std::sqrt(va * vb);
}

}  // namespace

TEST_CASE("analyze_patch_size: containment and alignment equal brute force", "[patch_size]") {
  for (auto kind : {tessera::exemplar_kind::cells, tessera::exemplar_kind::grass, tessera::exemplar_kind::bricks}) {
    INFO(tessera::to_string(kind));
    const auto ex = exemplar(kind, 40);
    const auto g = grey_of(ex);
    const tessera::patch_size_options o{.candidates_per_axis = 3, .histogram_bins = 12, .containment_tolerance = 0.4};
    const auto a = tessera::analyze_patch_size(ex, o).value();
    REQUIRE(a.sizes.size() == 9);
    for (const auto& m : a.sizes) {
      INFO(m.width << " x " << m.height);
      const auto [share, p90] = brute_containment(g, m.width, m.height, 12, 0.4);
      CHECK(m.containment == Approx(share).margin(1e-12));
      CHECK(m.containment_p90 == Approx(p90).epsilon(1e-9));
      const double expected = 0.5 * (brute_correlation(g, m.width, 0) + brute_correlation(g, 0, m.height));
      CHECK(m.alignment == Approx(expected).margin(1e-6));
    }
  }
}

TEST_CASE("analyze_patch_size: periodicity counts copies, finds none in noise, everything in a flat image",
          "[patch_size]") {
  // a tiled exemplar of period 16: a reference block has an exact copy every 16 pixels
  const auto tile = exemplar(tessera::exemplar_kind::rock, 16);
  tessera::image_buffer<std::uint8_t, 3> tiled(64, 64);
  for (index_t y = 0; y < 64; ++y)
    for (index_t x = 0; x < 64; ++x) tiled.write(x, y, tile.read(x % 16, y % 16));
  const auto t = tessera::analyze_patch_size(tiled, {.rectangular = false}).value();
  for (const auto& m : t.sizes) {
    INFO(m.width);
    CHECK(m.periodicity_hits == 1.0);
    // at least the copies shifted by whole periods that stay inside: of the 65 - side positions per
    // axis, at least floor((65 - side) / 16) share the reference's phase; minus the reference itself
    const double copies = double((65 - m.width) / 16);
    CHECK(m.periodicity >= copies * copies - 1);
  }
  CHECK(t.patch_width % 16 == 0);  // the qualified candidates aligned with the tiling win
  // independent noise: no block resembles another
  tessera::image_buffer<std::uint8_t, 1> noise(48, 48);
  const tessera::counter_rng rng(5);
  for (index_t i = 0; i < 48 * 48; ++i) noise.data()[i] = static_cast<std::uint8_t>(rng.below(256, i));
  const auto n = tessera::analyze_patch_size(noise, {.rectangular = false}).value();
  for (const auto& m : n.sizes) {
    CHECK(m.periodicity == 0.0);
    CHECK(m.periodicity_hits == 0.0);
    CHECK(!m.qualified);
  }
  // a flat exemplar: zero variance, every block equals every other (no 0 / 0)
  const tessera::image_buffer<std::uint8_t, 3> flat(32, 32, {90, 90, 90});
  const auto f = tessera::analyze_patch_size(flat, {.rectangular = false}).value();
  for (const auto& m : f.sizes) {
    CHECK(m.periodicity_hits == 1.0);
    CHECK(m.periodicity > 0.0);
    CHECK(m.containment == 1.0);
    CHECK(m.qualified);
  }
}

TEST_CASE("analyze_patch_size: elongated exemplars give defined measures", "[patch_size]") {
  // the periodicity copy keeps at least 8 pixels across (it used to shrink 16 x 1024 to 1 x 64)
  tessera::thread_pool_executor pool(2);
  for (auto [w, h] : {std::pair<index_t, index_t>{16, 1024}, {8, 1024}, {1024, 8}, {9, 300}}) {
    INFO(w << " x " << h);
    const auto ex =
        tessera::make_exemplar<std::uint8_t, 1>(tessera::exemplar_kind::grass, {.width = w, .height = h}).value();
    const auto a = tessera::analyze_patch_size(ex).value();
    const index_t lo = std::max<index_t>(2, std::min(w, h) / 4), hi = std::min(w, h) / 2;
    for (const auto& m : a.sizes) {
      CHECK(m.width >= lo);
      CHECK(m.height <= hi);
      CHECK(std::isfinite(m.periodicity));
      CHECK(std::isfinite(m.alignment));
      CHECK(std::isfinite(m.containment_p90));
    }
    // grass repeats along its long axis: references find similar blocks
    CHECK(std::any_of(a.sizes.begin(), a.sizes.end(), [](const auto& m) { return m.periodicity_hits > 0.5; }));
    CHECK(a.overlap >= 1);
    const auto b = tessera::analyze_patch_size(ex, {}, pool).value();
    CHECK(b.patch_width == a.patch_width);
    CHECK(b.patch_height == a.patch_height);
    for (std::size_t i = 0; i < a.sizes.size(); ++i) CHECK(b.sizes[i].periodicity == a.sizes[i].periodicity);
  }
}
