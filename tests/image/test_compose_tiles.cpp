#include <tessera/image/compose_tiles.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/image/metrics.hpp>
#include <tessera/image/wang_atlas.hpp>
#include <tessera/image/wang_seam_quality.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/periodic_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include <map>

#include <catch2/catch.hpp>

#include "quilt_test_support.hpp"

using tessera::index_t;
using tessera::wang_edges;

namespace {
// tiles whose pixels spell (tile, x, y): composition can be checked pixel by pixel
tessera::wang_tile_set<std::uint16_t, 3> labelled_set(int nh, int nv, index_t ts, std::vector<wang_edges> extra = {}) {
  auto edges = tessera::complete_tile_set_edges(nh, nv).value();
  edges.insert(edges.end(), extra.begin(), extra.end());
  std::vector<tessera::image_buffer<std::uint16_t, 3>> tiles;
  for (std::size_t t = 0; t < edges.size(); ++t) {
    tessera::image_buffer<std::uint16_t, 3> img(ts, ts);
    for (index_t y = 0; y < ts; ++y)
      for (index_t x = 0; x < ts; ++x) img.write(x, y, {std::uint16_t(t), std::uint16_t(x), std::uint16_t(y)});
    tiles.push_back(img);
  }
  return tessera::wang_tile_set<std::uint16_t, 3>::create(tessera::tile_set_edges::create(nh, nv, edges).value(), ts,
                                                          tiles)
      .value();
}

template <class Coloring, class Image>
void check_composition(const tessera::wang_tile_set<std::uint16_t, 3>& set, const Coloring& coloring, const Image& out,
                       const tessera::compose_options& o) {
  const index_t ts = set.tile_size();
  for (index_t y = 0; y < tessera::height_of(out); ++y)
    for (index_t x = 0; x < tessera::width_of(out); ++x) {
      const index_t px = o.x + x, py = o.y + y, c = tessera::floor_div(px, ts), r = tessera::floor_div(py, ts);
      const index_t t = tessera::tile_at_cell(set.edges(), tessera::cell_edges(coloring, c, r), o.seed, c, r);
      REQUIRE(set.edges()[t] == tessera::cell_edges(coloring, c, r));
      const auto p =
          tessera::convert_pixel<std::array<std::uint16_t, 3>>(tessera::image_traits<Image>::read(out, x, y));
      REQUIRE(p ==
              std::array<std::uint16_t, 3>{std::uint16_t(t), std::uint16_t(px - c * ts), std::uint16_t(py - r * ts)});
    }
}
}  // namespace

TEST_CASE("compose tiles: every pixel is the right tile's pixel (grid and plane colourings, any window)", "[wang]") {
  const auto set = labelled_set(2, 3, 7);
  auto scan = tessera::scanline_coloring::create(set.edges(), 9, 6, 3);
  tessera::image_buffer<std::uint16_t, 3> whole(63, 42), window(20, 13);
  REQUIRE(tessera::compose_tiles(set, *scan, whole).ok());
  check_composition(set, *scan, whole, {});
  const tessera::compose_options inside{.x = 30, .y = 5};
  REQUIRE(tessera::compose_tiles(set, *scan, window, inside).ok());
  check_composition(set, *scan, window, inside);
  auto plane = tessera::hash_coloring::create(2, 3, 77);
  for (const tessera::compose_options o :
       {tessera::compose_options{.x = -45, .y = -3}, tessera::compose_options{.x = 1'000'003, .y = -77}}) {
    tessera::image_buffer<std::uint16_t, 3> out(31, 29), pooled(31, 29);
    REQUIRE(tessera::compose_tiles(set, *plane, out, o).ok());
    check_composition(set, *plane, out, o);
    tessera::thread_pool_executor pool(2);
    REQUIRE(tessera::compose_tiles(set, *plane, pooled, o, pool).ok());
    REQUIRE(out == pooled);
  }
  // a generic user image (per-pixel path) and a raw view (memcpy path) agree
  quilt_test::user_rgb16 user(25, 17);
  std::vector<std::uint16_t> raw(25 * 17 * 3);
  tessera::image_view<std::uint16_t, 3> view(raw.data(), 25, 17);
  REQUIRE(tessera::compose_tiles(set, *plane, user, {.x = 3, .y = 4}).ok());
  REQUIRE(tessera::compose_tiles(set, *plane, view, {.x = 3, .y = 4}).ok());
  for (index_t y = 0; y < 17; ++y)
    for (index_t x = 0; x < 25; ++x) REQUIRE(user.read(x, y) == view.read(x, y));
  // any TileColoring with an explicit column count
  const tessera::stored_tile_coloring stored = tessera::store_coloring(*scan);
  tessera::image_buffer<std::uint16_t, 3> again(63, 42);
  REQUIRE(tessera::compose_tiles(set, stored, 9, again).ok());
  REQUIRE(again == whole);
}

TEST_CASE("compose tiles: variants are drawn per cell, outlines mark tile borders", "[wang]") {
  const auto set = labelled_set(1, 1, 4, {{0, 0, 0, 0}, {0, 0, 0, 0}});  // three variants of the only tile
  auto plane = tessera::hash_coloring::create(1, 1);
  tessera::image_buffer<std::uint16_t, 3> out(80, 80);
  REQUIRE(tessera::compose_tiles(set, *plane, out, {.seed = 5}).ok());
  check_composition(set, *plane, out, {.seed = 5});
  std::map<int, int> used;
  for (index_t y = 0; y < 80; y += 4)
    for (index_t x = 0; x < 80; x += 4) ++used[out.read(x, y)[0]];
  REQUIRE(used.size() == 3u);
  tessera::image_buffer<std::uint8_t, 3> lines(20, 20);
  const auto grey = tessera::build_wang_tiles(quilt_test::exemplar(tessera::exemplar_kind::sand, 32),
                                              {.tile_size = 8, .horizontal_colors = 1, .vertical_colors = 1});
  REQUIRE(grey.ok());
  REQUIRE(tessera::compose_tiles(*grey, *plane, lines, {.x = 3, .y = 2, .outline = true, .outline_color = {0, 0, 1, 1}})
              .ok());
  for (index_t y = 0; y < 20; ++y)
    for (index_t x = 0; x < 20; ++x) {
      const bool border = (x + 3) % 8 == 0 || (y + 2) % 8 == 0;
      if (border)
        REQUIRE(lines.read(x, y) == std::array<std::uint8_t, 3>{0, 0, 255});
      else
        REQUIRE(lines.read(x, y) == grey->tile(0).read((x + 3) % 8, (y + 2) % 8));
    }
}

TEST_CASE("compose tiles: a built set tiles the plane without visible seams", "[wang]") {
  const auto ex = quilt_test::exemplar(tessera::exemplar_kind::cells, 64, 11);
  auto set = tessera::build_wang_tiles(ex, {.tile_size = 32, .seed = 2});
  REQUIRE(set.ok());
  auto plane = tessera::hash_coloring::create(2, 2, 4);
  tessera::image_buffer<std::uint8_t, 3> out(160, 160);
  REQUIRE(tessera::compose_tiles(*set, *plane, out).ok());
  const auto seams = tessera::tile_border_seams(160, 160, 32);
  REQUIRE(seams.size() == 8u);
  const double ratio = tessera::seam_gradient_ratio(out, seams, ex).value();
  CAPTURE(ratio);
  REQUIRE(ratio < 1.3);
}

TEST_CASE("compose tiles: bad input", "[wang]") {
  const auto set = labelled_set(2, 2, 5);
  auto scan = tessera::scanline_coloring::create(set.edges(), 4, 4);
  tessera::image_buffer<std::uint16_t, 3> out(10, 10);
  auto outside = tessera::compose_tiles(set, *scan, out, {.x = 12});
  REQUIRE(outside.code() == tessera::status_code::out_of_range);
  REQUIRE_THAT(outside.message(), Catch::Contains("20 x 20 pixels"));
  REQUIRE(tessera::compose_tiles(set, *scan, out, {.y = -1}).code() == tessera::status_code::out_of_range);
  // a colouring that asks for tiles the set lacks
  const auto cohen_edges = tessera::tile_set_edges::modular_subset(2, 2, 2).value();
  std::vector<tessera::image_buffer<std::uint16_t, 3>> tiles(8, tessera::image_buffer<std::uint16_t, 3>(5, 5));
  const auto cohen = tessera::wang_tile_set<std::uint16_t, 3>::create(cohen_edges, 5, tiles).value();
  auto complete_plane = tessera::hash_coloring::create(2, 2, 1);
  auto violated = tessera::compose_tiles(cohen, *complete_plane, out);
  REQUIRE(violated.code() == tessera::status_code::invalid_argument);
  REQUIRE_THAT(violated.message(), Catch::Contains("violates the tile set") && Catch::Contains("cell ("));
  auto cohen_plane = tessera::hash_coloring::for_set(cohen_edges, 1);
  REQUIRE(tessera::compose_tiles(cohen, *cohen_plane, out).ok());
  auto three = tessera::hash_coloring::create(3, 2);
  REQUIRE_THAT(tessera::compose_tiles(set, *three, out).message(), Catch::Contains("3 x 2 colours"));
  tessera::image_view<std::uint16_t, 3> empty;
  REQUIRE(tessera::compose_tiles(set, *scan, empty).code() == tessera::status_code::invalid_argument);
  const tessera::stored_tile_coloring stored = tessera::store_coloring(*scan);
  REQUIRE(tessera::compose_tiles(set, stored, 3, out).code() == tessera::status_code::invalid_argument);
  // a user grid colouring whose cols() x rows() disagrees with its face count: refused before any
  // face beyond the stored ones is read
  struct lying_grid {
    const tessera::stored_tile_coloring* cells;
    index_t c, r;
    index_t cols() const { return c; }
    index_t rows() const { return r; }
    index_t num_faces() const { return cells->num_faces(); }
    int num_colors(int side) const { return cells->num_colors(side); }
    int edge_color(index_t f, int side) const { return cells->edge_color(f, side); }
  };
  static_assert(tessera::GridTileColoring<lying_grid>);
  tessera::image_buffer<std::uint16_t, 3> big(40, 40);
  for (const lying_grid g : {lying_grid{&stored, 8, 4}, lying_grid{&stored, 4, 8}, lying_grid{&stored, 0, 16},
                             lying_grid{&stored, -4, -4}}) {
    auto s = tessera::compose_tiles(set, g, big);
    REQUIRE(s.code() == tessera::status_code::invalid_argument);
    REQUIRE_THAT(s.message(), Catch::Contains("does not match num_faces() = 16"));
    REQUIRE(tessera::atlas_coordinates(tessera::build_wang_atlas(set).value(), g, 1.5, 1.5).x == -1);
  }
  REQUIRE(tessera::compose_tiles(set, lying_grid{&stored, 4, 4}, out).ok());
}
