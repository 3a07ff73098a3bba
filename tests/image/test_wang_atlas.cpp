#include <tessera/image/wang_atlas.hpp>

#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include <cmath>
#include <set>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;
using tessera::wang_edges;

namespace {
// A model of GPU texturing: float mip levels made by 2 x 2 box filtering, bilinear sampling with
// REPEAT addressing (texel i covers [i, i + 1), centre i + 0.5; coordinates in level-0 texels).
struct mip_texture {
  std::vector<tessera::image_buffer<float, 3>> levels;

  template <class T>
  explicit mip_texture(const tessera::image_buffer<T, 3>& base, int count) {
    levels.push_back(tessera::to_buffer<float, 3>(base).value());
    for (int k = 1; k < count; ++k) {
      const auto& prev = levels.back();
      tessera::image_buffer<float, 3> next(prev.width() / 2, prev.height() / 2);
      for (index_t y = 0; y < next.height(); ++y)
        for (index_t x = 0; x < next.width(); ++x)
          for (int c = 0; c < 3; ++c)
            next.pixel_ptr(x, y)[c] = 0.25f * (prev.pixel_ptr(2 * x, 2 * y)[c] + prev.pixel_ptr(2 * x + 1, 2 * y)[c] +
                                               prev.pixel_ptr(2 * x, 2 * y + 1)[c] + prev.pixel_ptr(2 * x + 1, 2 * y + 1)[c]);
      levels.push_back(std::move(next));
    }
  }
  std::array<double, 3> sample(double u, double v, int level) const {
    const auto& img = levels[static_cast<std::size_t>(level)];
    const double s = std::ldexp(1.0, -level);
    const double fx = u * s - 0.5, fy = v * s - 0.5;
    const double x0 = std::floor(fx), y0 = std::floor(fy), ax = fx - x0, ay = fy - y0;
    auto texel = [&](double x, double y, int c) {
      const index_t w = img.width(), h = img.height();
      const index_t xi = ((static_cast<index_t>(x) % w) + w) % w, yi = ((static_cast<index_t>(y) % h) + h) % h;
      return static_cast<double>(img.pixel_ptr(xi, yi)[c]);
    };
    std::array<double, 3> out{};
    for (int c = 0; c < 3; ++c)
      out[static_cast<std::size_t>(c)] = (1 - ay) * ((1 - ax) * texel(x0, y0, c) + ax * texel(x0 + 1, y0, c)) +
                                         ay * ((1 - ax) * texel(x0, y0 + 1, c) + ax * texel(x0 + 1, y0 + 1, c));
    return out;
  }
};

double max_difference(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}
}  // namespace

TEST_CASE("wang atlas: Wei's edge ordering is a bijection along a cycle of matching pairs", "[wang]") {
  for (int n = 1; n <= 7; ++n) {
    std::vector<std::pair<int, int>> order(static_cast<std::size_t>(n * n), {-1, -1});
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const index_t i = tessera::edge_order_index(a, b);
        REQUIRE(i >= 0);
        REQUIRE(i < n * n);
        REQUIRE(order[static_cast<std::size_t>(i)].first == -1);
        order[static_cast<std::size_t>(i)] = {a, b};
      }
    for (std::size_t i = 0; i < order.size(); ++i) REQUIRE(order[i].second == order[(i + 1) % order.size()].first);
  }
  static_assert(tessera::edge_order_index(0, 0) == 0 && tessera::edge_order_index(0, 1) == 1 && tessera::edge_order_index(1, 1) == 2 &&
                tessera::edge_order_index(1, 0) == 3);
}

TEST_CASE("wang atlas: edge-ordered neighbours match across every border, wrapping", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::sand, 40);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 8, .horizontal_colors = 3, .vertical_colors = 2});
  REQUIRE(set.ok());
  auto atlas = tessera::build_wang_atlas(*set);
  REQUIRE(atlas.ok());
  REQUIRE(atlas->image.width() == 4 * 8);   // nv² columns
  REQUIRE(atlas->image.height() == 9 * 8);  // nh² rows
  std::vector<index_t> at(36, -1);
  for (index_t t = 0; t < set->size(); ++t) {
    const std::size_t slot = static_cast<std::size_t>(atlas->slot_row[static_cast<std::size_t>(t)] * 4 + atlas->slot_col[static_cast<std::size_t>(t)]);
    REQUIRE(at[slot] == -1);
    at[slot] = t;
    for (index_t y = 0; y < 8; ++y)
      for (index_t x = 0; x < 8; ++x) {
        const tessera::vec2 p = atlas->texel(t, x, y);
        REQUIRE(atlas->image.read(index_t(p.x), index_t(p.y)) == set->tile(t).read(x, y));
      }
  }
  for (index_t r = 0; r < 9; ++r)
    for (index_t c = 0; c < 4; ++c) {
      const wang_edges e = set->edges()[at[static_cast<std::size_t>(r * 4 + c)]];
      REQUIRE(e.east == set->edges()[at[static_cast<std::size_t>(r * 4 + (c + 1) % 4)]].west);
      REQUIRE(e.south == set->edges()[at[static_cast<std::size_t>(((r + 1) % 9) * 4 + c)]].north);
    }
}

TEST_CASE("wang atlas: bilinear samples across tile borders match the tiled plane at every mip level", "[wang]") {
  // Tiles with the same edge colour share their outer `border` texels (copied from the edge strip),
  // so sampling across a border reads the same texels in the atlas as in the plane as long as the
  // filter footprint (2^level texels deep) stays within the border and away from tile corners.
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::cells, 96, 5);
  const index_t ts = 48, ov = 10, border = 8;
  auto set = tessera::build_wang_tiles(ex, {.tile_size = ts, .overlap = ov, .border = border, .seed = 3});
  REQUIRE(set.ok());
  auto plane = tessera::hash_coloring::create(2, 2, 6);
  const index_t cells = 6;
  tessera::image_buffer<std::uint8_t, 3> ground_truth(cells * ts, cells * ts);
  REQUIRE(tessera::compose_tiles(*set, *plane, ground_truth).ok());
  constexpr int levels = 4;  // footprints of 1, 2, 4 and 8 texels
  const mip_texture truth(ground_truth, levels);

  auto ordered = tessera::build_wang_atlas(*set);
  auto padded = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .padding = 4});
  REQUIRE(ordered.ok());
  REQUIRE(padded.ok());
  const mip_texture ordered_tex(ordered->image, levels), padded_tex(padded->image, levels);
  // a naive atlas: tiles in index order without padding (what the layouts exist to avoid)
  tessera::image_buffer<std::uint8_t, 3> naive(4 * ts, 4 * ts);
  for (index_t t = 0; t < 16; ++t)
    for (index_t y = 0; y < ts; ++y)
      for (index_t x = 0; x < ts; ++x) naive.write((t % 4) * ts + x, (t / 4) * ts + y, set->tile(t).read(x, y));
  const mip_texture naive_tex(naive, levels);

  double worst_ordered[levels] = {}, worst_padded[levels] = {}, worst_naive = 0;
  int samples = 0;
  for (int level = 0; level < levels; ++level) {
    const double texel = std::ldexp(1.0, level);
    for (index_t cell = 1; cell < cells - 1; ++cell)
      for (double along = ov; along < ts - ov; along += 0.75) {
        const double first = texel * std::floor(along / texel - 0.5);  // texels the filter reads along the edge
        if (first < ov || first + 2 * texel > ts - ov) continue;
        for (double offset : {-0.75 * texel, -0.25 * texel, 0.0, 0.3 * texel, 0.7 * texel})
          for (int vertical = 0; vertical < 2; ++vertical) {
            const double px = vertical ? double(cell * ts) + offset : double(2 * ts) + along;
            const double py = vertical ? double(3 * ts) + along : double(cell * ts) + offset;
            const auto expect = truth.sample(px, py, level);
            const tessera::vec2 a = tessera::atlas_coordinates(*ordered, *plane, px, py);
            worst_ordered[level] = std::max(worst_ordered[level], max_difference(ordered_tex.sample(a.x, a.y, level), expect));
            if (level <= 2) {  // padding 4 covers footprints up to 4 texels
              const tessera::vec2 b = tessera::atlas_coordinates(*padded, *plane, px, py);
              worst_padded[level] = std::max(worst_padded[level], max_difference(padded_tex.sample(b.x, b.y, level), expect));
            }
            const index_t col = tessera::floor_div(index_t(std::floor(px)), ts), row = tessera::floor_div(index_t(std::floor(py)), ts);
            const index_t t = set->edges().find(tessera::cell_edges(*plane, col, row));
            const double fx = px - double(col * ts), fy = py - double(row * ts);
            worst_naive = std::max(worst_naive, max_difference(naive_tex.sample(double((t % 4) * ts) + fx, double((t / 4) * ts) + fy, level), expect));
            ++samples;
          }
      }
  }
  REQUIRE(samples > 500);
  for (int level = 0; level < levels; ++level) {
    CAPTURE(level, worst_ordered[level], worst_padded[level]);
    REQUIRE(worst_ordered[level] < 1e-5);
    REQUIRE(worst_padded[level] < 1e-5);
  }
  CAPTURE(worst_naive);
  REQUIRE(worst_naive > 0.05);  // the test can fail: unordered tiles bleed wrong neighbours in
}

TEST_CASE("wang atlas: atlas coordinates point at the composed plane's texels", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::grass, 48);
  auto cohen = tessera::tile_set_edges::modular_subset(2, 2, 2);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 16, .tiles = {cohen->tiles().begin(), cohen->tiles().end()}});
  REQUIRE(set.ok());
  auto scan = tessera::scanline_coloring::create(set->edges(), 6, 5, 2);
  tessera::image_buffer<std::uint8_t, 3> plane(96, 80);
  REQUIRE(tessera::compose_tiles(*set, *scan, plane).ok());
  auto atlas = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded});
  REQUIRE(atlas.ok());
  REQUIRE(atlas->padding == 2);
  for (index_t y = 0; y < 80; ++y)
    for (index_t x = 0; x < 96; ++x) {
      const tessera::vec2 a = tessera::atlas_coordinates(*atlas, *scan, x + 0.5, y + 0.5);
      REQUIRE(atlas->image.read(index_t(a.x), index_t(a.y)) == plane.read(x, y));
    }
  REQUIRE(tessera::atlas_coordinates(*atlas, *scan, 96.5, 3.0).x == -1);  // outside the 6 x 5 grid
  REQUIRE(tessera::atlas_coordinates(*atlas, *scan, -0.5, 3.0).x == -1);
}

TEST_CASE("wang atlas: bad input", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::grass, 48);
  auto cohen = tessera::tile_set_edges::modular_subset(2, 2, 2);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 16, .tiles = {cohen->tiles().begin(), cohen->tiles().end()}});
  auto ordered = tessera::build_wang_atlas(*set);
  REQUIRE(ordered.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(ordered.error().message(), Catch::Contains("complete set") && Catch::Contains("padded"));
  REQUIRE_FALSE(tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .padding = 16}).ok());
  REQUIRE_FALSE(tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .padding = -1}).ok());
  // a colouring asking for a missing tile maps to (-1, -1)
  auto atlas = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded});
  auto complete_plane = tessera::hash_coloring::create(2, 2, 1);
  bool missing = false;
  for (int i = 0; i < 50 && !missing; ++i) missing = tessera::atlas_coordinates(*atlas, *complete_plane, 16.0 * i + 1, 3.0).x < 0;
  REQUIRE(missing);
  REQUIRE(tessera::atlas_coordinates(*atlas, *complete_plane, std::nan(""), 3.0).x == -1);
  REQUIRE(tessera::atlas_coordinates(*atlas, *complete_plane, 1e300, 3.0).x == -1);
}
