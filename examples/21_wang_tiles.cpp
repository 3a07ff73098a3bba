// 21_wang_tiles: a complete Wang tile set (2 x 2 colours, 16 tiles) built from an exemplar, a plane
// tiled with it (with and without tile borders), the GPU atlas in Wei's edge-ordered layout, and
// Cohen's 8-tile subset tiled by the O(1) hash colouring.
// Usage: example_21_wang_tiles [OUTPUT_DIR]
//   writes wang_tile_set.png, wang_plane.png, wang_plane_outlined.png, wang_atlas.png,
//   wang_cohen_subset.png (docs/images/wang/)
#include <tessera/core/executor.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/wang_atlas.hpp>
#include <tessera/image/wang_seam_quality.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/io/png.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>
#include <tessera/tiling/tile_set_edges.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>

using tessera::index_t;
using rgb8 = tessera::image_buffer<std::uint8_t, 3>;

namespace {

// Tiles on a sheet, `per_row` across, each edge's colour drawn as a bar beside it: horizontal (north /
// south) colours red and blue, vertical (east / west) colours green and yellow.
rgb8 tile_sheet(const tessera::wang_tile_set<std::uint8_t, 3>& set, index_t per_row) {
  const index_t ts = set.tile_size(), m = 7, cell = ts + 2 * m;
  const index_t rows = (set.size() + per_row - 1) / per_row;
  rgb8 out(per_row * cell, rows * cell, {255, 255, 255});
  const std::array<std::array<std::uint8_t, 3>, 2> horizontal = {{{215, 50, 50}, {50, 90, 215}}};
  const std::array<std::array<std::uint8_t, 3>, 2> vertical = {{{40, 170, 60}, {235, 190, 30}}};
  for (index_t t = 0; t < set.size(); ++t) {
    const index_t ox = (t % per_row) * cell + m, oy = (t / per_row) * cell + m;
    for (index_t y = 0; y < ts; ++y)
      for (index_t x = 0; x < ts; ++x) out.write(ox + x, oy + y, set.tile(t).read(x, y));
    const tessera::wang_edges e = set.edges()[t];
    for (index_t k = 2; k < ts - 2; ++k)
      for (index_t d = 2; d < m - 1; ++d) {
        out.write(ox + k, oy - d, horizontal[static_cast<std::size_t>(e.north % 2)]);
        out.write(ox + k, oy + ts - 1 + d, horizontal[static_cast<std::size_t>(e.south % 2)]);
        out.write(ox - d, oy + k, vertical[static_cast<std::size_t>(e.west % 2)]);
        out.write(ox + ts - 1 + d, oy + k, vertical[static_cast<std::size_t>(e.east % 2)]);
      }
  }
  return out;
}

bool save(const std::string& path, const rgb8& img) {
  if (auto s = tessera::write_png(path, img); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), false;
  std::printf("wrote %s (%td x %td)\n", path.c_str(), img.width(), img.height());
  return true;
}

int fail(const tessera::status& s) {
  std::fprintf(stderr, "%s\n", s.to_string().c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::thread_pool_executor pool;
  auto exemplar =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, {.width = 128, .height = 128, .seed = 3});
  if (!exemplar) return fail(exemplar.error());

  // [snippet:wang_build]
  // The complete set for 2 horizontal and 2 vertical colours: 2² · 2² = 16 tiles of 64 x 64.
  auto set =
      tessera::build_wang_tiles(*exemplar, {.tile_size = 64, .horizontal_colors = 2, .vertical_colors = 2}, pool);
  if (!set) return fail(set.error());
  // A 10 x 6 plane by Cohen's scanline colouring, composed by row memcpys.
  auto coloring = tessera::scanline_coloring::create(set->edges(), 10, 6, /*seed=*/5);
  if (!coloring) return fail(coloring.error());
  rgb8 plane(10 * 64, 6 * 64);
  if (auto s = tessera::compose_tiles(*set, *coloring, plane, {}, pool); !s) return fail(s);
  // [/snippet]
  rgb8 outlined(plane.width(), plane.height());
  if (auto s = tessera::compose_tiles(*set, *coloring, outlined, {.outline = true}, pool); !s) return fail(s);
  if (!save(dir + "/wang_tile_set.png", tile_sheet(*set, 8)) || !save(dir + "/wang_plane.png", plane) ||
      !save(dir + "/wang_plane_outlined.png", outlined))
    return 1;

  // Every pair of tiles that can touch, measured across its shared edge.
  auto quality = tessera::wang_seam_quality(*set, *exemplar);
  if (!quality) return fail(quality.error());
  std::printf("seam gradient ratio over %zu touching pairs: mean %.3f, max %.3f\n", quality->pairs.size(),
              quality->mean_ratio, quality->max_ratio);

  // [snippet:wang_atlas]
  // Wei's edge-ordered atlas. Tiles of 64 built with default options share an 8-texel border and
  // the same corners, so bilinear samples of mip levels 0-3 read the tiled plane's own texels across
  // tile borders and corners (atlas->mip_levels == 4). A shader maps plane -> atlas texels.
  auto atlas = tessera::build_wang_atlas(*set);
  if (!atlas) return fail(atlas.error());
  auto plane_coloring = tessera::hash_coloring::for_set(set->edges(), /*seed=*/5);  // O(1) per cell
  if (!plane_coloring) return fail(plane_coloring.error());
  const tessera::vec2 texel = tessera::atlas_coordinates(*atlas, *plane_coloring, 1000.25, -77.5);
  // [/snippet]
  std::printf("plane texel (1000.25, -77.5) -> atlas texel (%.2f, %.2f); exact mip levels: %d\n", texel.x, texel.y,
              atlas->mip_levels);
  if (!save(dir + "/wang_atlas.png", atlas->image)) return 1;

  // Cohen's 8 tiles (two per (north, west) pair) tiled by the hash colouring of the plane.
  auto cohen = tessera::tile_set_edges::modular_subset(2, 2, 2);
  if (!cohen) return fail(cohen.error());
  auto subset = tessera::build_wang_tiles(
      *exemplar, {.tile_size = 64, .tiles = {cohen->tiles().begin(), cohen->tiles().end()}, .seed = 2}, pool);
  if (!subset) return fail(subset.error());
  auto hash = tessera::hash_coloring::for_set(subset->edges(), 3);
  if (!hash) return fail(hash.error());
  const rgb8 sheet = tile_sheet(*subset, 4);
  rgb8 subset_plane(6 * 64, sheet.height());
  if (auto s = tessera::compose_tiles(*subset, *hash, subset_plane, {.x = -100, .y = 40}, pool); !s) return fail(s);
  rgb8 both(sheet.width() + 8 + subset_plane.width(), sheet.height(), {255, 255, 255});
  for (index_t y = 0; y < sheet.height(); ++y) {
    for (index_t x = 0; x < sheet.width(); ++x) both.write(x, y, sheet.read(x, y));
    for (index_t x = 0; x < subset_plane.width(); ++x) both.write(sheet.width() + 8 + x, y, subset_plane.read(x, y));
  }
  return save(dir + "/wang_cohen_subset.png", both) ? 0 : 1;
}
