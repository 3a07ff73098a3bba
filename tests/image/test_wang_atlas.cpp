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
            next.pixel_ptr(x, y)[c] =
                0.25f * (prev.pixel_ptr(2 * x, 2 * y)[c] + prev.pixel_ptr(2 * x + 1, 2 * y)[c] +
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
  static_assert(tessera::edge_order_index(0, 0) == 0 && tessera::edge_order_index(0, 1) == 1 &&
                tessera::edge_order_index(1, 1) == 2 && tessera::edge_order_index(1, 0) == 3);
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
    const std::size_t slot = static_cast<std::size_t>(atlas->slot_row[static_cast<std::size_t>(t)] * 4 +
                                                      atlas->slot_col[static_cast<std::size_t>(t)]);
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

TEST_CASE("wang atlas: default options sample exactly across tile borders and corners at every promised mip level",
          "[wang]") {
  // A model of GPU texturing (box-filtered mips, bilinear, REPEAT) applied to the composed plane is
  // the ground truth. Both layouts, built with default options from a set built with default
  // options, promise 3 levels for tiles of 32 (shared border 4): every sample of the tiles' area,
  // borders and corners included, must match there.
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::cells, 64, 5);
  const index_t ts = 32;
  auto set = tessera::build_wang_tiles(ex, {.tile_size = ts, .seed = 3});
  REQUIRE(set.ok());
  REQUIRE(set->exact_mip_levels() == 3);
  auto plane = tessera::hash_coloring::create(2, 2, 6);
  const index_t cells = 6;
  tessera::image_buffer<std::uint8_t, 3> ground_truth(cells * ts, cells * ts);
  REQUIRE(tessera::compose_tiles(*set, *plane, ground_truth).ok());
  auto ordered = tessera::build_wang_atlas(*set);
  auto padded = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded});
  REQUIRE(ordered.ok());
  REQUIRE(padded.ok());
  REQUIRE(ordered->mip_levels == 3);
  REQUIRE(padded->mip_levels == 3);
  REQUIRE(padded->padding == 4);
  constexpr int levels = 3;
  const mip_texture truth(ground_truth, levels), ordered_tex(ordered->image, levels), padded_tex(padded->image, levels);
  // a naive atlas: tiles in index order without padding (what the layouts exist to avoid)
  tessera::image_buffer<std::uint8_t, 3> naive(4 * ts, 4 * ts);
  for (index_t t = 0; t < 16; ++t)
    for (index_t y = 0; y < ts; ++y)
      for (index_t x = 0; x < ts; ++x) naive.write((t % 4) * ts + x, (t / 4) * ts + y, set->tile(t).read(x, y));
  const mip_texture naive_tex(naive, levels);

  double worst_ordered[levels] = {}, worst_padded[levels] = {}, worst_naive = 0;
  int corner_samples = 0;
  for (int level = 0; level < levels; ++level) {
    const double texel = std::ldexp(1.0, level);
    // every point of cells [1, 4)² on a 0.7-texel grid: the footprint of those within a texel of a
    // border reads the neighbour, within a texel of a corner all four tiles
    for (double py = ts + 0.1; py < 4 * ts; py += 0.7)
      for (double px = ts + 0.35; px < 4 * ts; px += 0.7) {
        const auto expect = truth.sample(px, py, level);
        const tessera::vec2 a = tessera::atlas_coordinates(*ordered, *plane, px, py);
        const tessera::vec2 b = tessera::atlas_coordinates(*padded, *plane, px, py);
        worst_ordered[level] =
            std::max(worst_ordered[level], max_difference(ordered_tex.sample(a.x, a.y, level), expect));
        worst_padded[level] = std::max(worst_padded[level], max_difference(padded_tex.sample(b.x, b.y, level), expect));
        const index_t col = tessera::floor_div(index_t(std::floor(px)), ts),
                      row = tessera::floor_div(index_t(std::floor(py)), ts);
        const index_t t = set->edges().find(tessera::cell_edges(*plane, col, row));
        const double fx = px - double(col * ts), fy = py - double(row * ts);
        worst_naive = std::max(
            worst_naive,
            max_difference(naive_tex.sample(double((t % 4) * ts) + fx, double((t / 4) * ts) + fy, level), expect));
        const bool near_x = std::min(fx, ts - fx) < texel, near_y = std::min(fy, ts - fy) < texel;
        corner_samples += near_x && near_y;
      }
  }
  REQUIRE(corner_samples > 1000);
  for (int level = 0; level < levels; ++level) {
    CAPTURE(level, worst_ordered[level], worst_padded[level]);
    REQUIRE(worst_ordered[level] < 1e-5);
    REQUIRE(worst_padded[level] < 1e-5);
  }
  CAPTURE(worst_naive);
  REQUIRE(worst_naive > 0.05);  // the test can fail: unordered tiles bleed wrong neighbours in
}

TEST_CASE("wang atlas: a set built for more mip levels gives an atlas exact for them", "[wang]") {
  // tiles of 32 built with mip_levels = 4 (border 8): levels 0-3, sampled across the corner point
  // of four tiles and along the borders, match the plane in both layouts
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::weave, 64, 2);
  const index_t ts = 32;
  auto set = tessera::build_wang_tiles(ex, {.tile_size = ts, .mip_levels = 4, .seed = 5});
  REQUIRE(set.ok());
  auto plane = tessera::hash_coloring::create(2, 2, 2);
  tessera::image_buffer<std::uint8_t, 3> ground_truth(4 * ts, 4 * ts);
  REQUIRE(tessera::compose_tiles(*set, *plane, ground_truth).ok());
  auto ordered = tessera::build_wang_atlas(*set, {.mip_levels = 4});
  auto padded = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .mip_levels = 4});
  REQUIRE(ordered.ok());
  REQUIRE(padded.ok());
  REQUIRE(padded->padding == 8);
  const mip_texture truth(ground_truth, 4), ordered_tex(ordered->image, 4), padded_tex(padded->image, 4);
  for (int level = 0; level < 4; ++level) {
    const double reach = std::ldexp(1.0, level);
    double worst = 0;
    for (index_t c = 1; c < 4; ++c)
      for (index_t r = 1; r < 4; ++r)
        for (double dy = -reach; dy <= reach; dy += 0.3 * reach)
          for (double dx = -reach; dx <= reach; dx += 0.3 * reach)
            for (double along : {0.0, 0.37 * double(ts)}) {  // at the corner point and half-way along the borders
              for (int dir = 0; dir < 2; ++dir) {
                const double px = double(c * ts) + dx + (dir ? along : 0), py = double(r * ts) + dy + (dir ? 0 : along);
                const auto expect = truth.sample(px, py, level);
                const tessera::vec2 a = tessera::atlas_coordinates(*ordered, *plane, px, py);
                const tessera::vec2 b = tessera::atlas_coordinates(*padded, *plane, px, py);
                worst = std::max({worst, max_difference(ordered_tex.sample(a.x, a.y, level), expect),
                                  max_difference(padded_tex.sample(b.x, b.y, level), expect)});
              }
            }
    CAPTURE(level, worst);
    REQUIRE(worst < 1e-5);
  }
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
  // mip levels: the set (tiles of 16, border 2) promises 2; asking for more names the fix
  REQUIRE(set->exact_mip_levels() == 2);
  auto deep = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .mip_levels = 3});
  REQUIRE(deep.error().code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(deep.error().message(),
               Catch::Contains("shared border is 2") && Catch::Contains("wang_tile_options::mip_levels = 3"));
  auto odd = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .mip_levels = 2, .padding = 3});
  REQUIRE_THAT(odd.error().message(), Catch::Contains("padding 3 serves 1 exact mip levels"));
  REQUIRE(tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .padding = 3})->mip_levels == 1);
  REQUIRE_FALSE(tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .mip_levels = -1}).ok());
  REQUIRE_FALSE(tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded, .mip_levels = 17}).ok());
  // a colouring asking for a missing tile maps to (-1, -1)
  auto atlas = tessera::build_wang_atlas(*set, {.layout = tessera::atlas_layout::padded});
  auto complete_plane = tessera::hash_coloring::create(2, 2, 1);
  bool missing = false;
  for (int i = 0; i < 50 && !missing; ++i)
    missing = tessera::atlas_coordinates(*atlas, *complete_plane, 16.0 * i + 1, 3.0).x < 0;
  REQUIRE(missing);
  REQUIRE(tessera::atlas_coordinates(*atlas, *complete_plane, std::nan(""), 3.0).x == -1);
  REQUIRE(tessera::atlas_coordinates(*atlas, *complete_plane, 1e300, 3.0).x == -1);
}
