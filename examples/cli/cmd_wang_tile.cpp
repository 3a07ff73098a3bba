// tessera wang tile: a tiled image composed from a Wang tile directory.
//   tessera wang tile --tiles DIR --grid COLSxROWS --out O.png [--coloring hash|scanline|periodic] [--outline]
#include <filesystem>
#include <string>

#include <tessera/core/executor.hpp>
#include <tessera/core/format.hpp>
#include <tessera/core/tile_coloring.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/io/png.hpp>
#include <tessera/io/tile_manifest.hpp>
#include <tessera/io/wang_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/periodic_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include "cli.hpp"
#include "png_limits.hpp"

namespace {

using tessera::index_t;

template <class T, int C>
tessera::status tile_with(const cli::arguments& args, const std::string& dir, const std::string& kind, index_t cols,
                          index_t rows) {
  auto period = args.integer("--period", 4, 1, 8192);
  if (!period) return period.error();
  auto set = tessera::load_wang_tiles<T, C>(dir);
  if (!set) return set.error();
  const index_t ts = set->tile_size();
  if (cols > 65536 / ts || rows > 65536 / ts || (cols * ts) * (rows * ts) > (index_t{1} << 28))
    return tessera::status::invalid_argument("--grid " + args.str("--grid") + " of " + std::to_string(ts) +
                                             "-pixel tiles exceeds the 65536 pixels per side and 2^28 pixels in all "
                                             "this command writes");
  auto out = tessera::image_buffer<T, C>::create(cols * ts, rows * ts);
  if (!out) return out.error();
  tessera::thread_pool_executor pool(args.threads());
  const tessera::compose_options options{.outline = args.has("--outline"), .seed = args.seed()};
  // every colouring is stored first, so compose_tiles is compiled once per pixel format, not once per
  // colouring type too (same cells, same tiles: a hash window's cell (c, r) is the plane's (c, r))
  tessera::stored_tile_coloring coloring;
  if (kind == "scanline") {
    auto c = tessera::scanline_coloring::create(set->edges(), cols, rows, args.seed());
    if (!c) return c.error();
    coloring = tessera::store_coloring(*c);
  } else if (kind == "hash") {
    auto h = tessera::hash_coloring::for_set(set->edges(), args.seed());
    if (!h) return h.error();
    auto c = h->window(0, 0, cols, rows);
    if (!c) return c.error();
    coloring = tessera::store_coloring(*c);
  } else {
    auto c = tessera::periodic_coloring::create(set->edges(), *period, *period, cols, rows, args.seed());
    if (!c) return c.error();
    coloring = tessera::store_coloring(*c);
  }
  tessera::status composed;
  const double ms = cli::median_ms(
      args.repeat(), [&] { composed = tessera::compose_tiles(*set, coloring, cols, *out, options, pool); });
  if (!composed) return composed;
  if (auto s = tessera::write_png(args.str("--out"), *out); !s) return s;
  if (args.stats())
    cli::json_line()
        .add("command", "wang tile")
        .add("coloring", kind)
        .add("width", out->width())
        .add("height", out->height())
        .add("tiling_ms", ms)
        .add("mpixels_per_s", static_cast<double>(out->width() * out->height()) / (ms * 1e3))
        .print();
  return {};
}

int run_tile(const cli::arguments& args) {
  auto dir = args.required("--tiles");
  auto out_path = args.required("--out");
  if (!dir) return cli::fail(args, dir.error());
  if (!out_path) return cli::fail(args, out_path.error());
  auto grid = args.size("--grid");
  if (!grid) return cli::fail(args, grid.error());
  // hash by default, as geo-wang tile: O(1) per cell, and a grid is a window of the infinite tiling
  auto kind = args.choice("--coloring", {"hash", "scanline", "periodic"});
  if (!kind) return cli::fail(args, kind.error());
  // the tiles' pixel format, from the first tile file
  auto manifest = tessera::read_tile_manifest(*dir);
  if (!manifest) return cli::fail(args, manifest.error());
  auto info = tessera::read_png_info((std::filesystem::path(*dir) / manifest->tiles.front().file).string());
  if (!info) return cli::fail(args, info.error());
  auto s = cli::dispatch_png_format(cli::png_format(*info), [&]<class T, int C>(tessera::format_tag<T, C>) {
    return tile_with<T, C>(args, *dir, *kind, grid->first, grid->second);
  });
  if (!s) return cli::fail(args, s);
  return 0;
}

const cli::registrar tile_command({
    .name = "wang tile",
    .summary = "compose a tiled image from a Wang tile directory",
    .usage =
        "tessera wang tile --tiles DIR --grid COLSxROWS --out O.png [--seed S] [--coloring hash|scanline|periodic] "
        "[--repeat N]",
    .options = {{
        {"--tiles", "DIR", "tile directory written by tessera wang build"},
        {"--grid", "COLSxROWS", "number of tiles across and down"},
        {"--out", "O.png", "output PNG"},
        {"--coloring", "KIND", "hash (default; O(1) per cell), scanline (Cohen) or periodic"},
        {"--period", "N", "period in tiles of --coloring periodic (default 4)"},
        {"--outline", "", "draw the tile borders"},
    }},
    .run = run_tile,
});

}  // namespace
