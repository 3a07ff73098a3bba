// tessera wang build / wang tile: Wang tile sets from an exemplar and tiled images from a tile directory.
//   tessera wang build --exemplar E.png --colors NH,NV --tile T --out DIR [--subset] [--mip-levels L]
//   tessera wang tile --tiles DIR --grid COLSxROWS --out O.png [--coloring scanline|hash|periodic] [--outline]
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/format.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/wang_atlas.hpp>
#include <tessera/image/wang_seam_quality.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/io/png.hpp>
#include <tessera/io/tile_manifest.hpp>
#include <tessera/io/wang_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/periodic_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>
#include <tessera/tiling/tile_set_edges.hpp>

#include "cli.hpp"
#include "image_source.hpp"

namespace {

using tessera::index_t;

int run_build(const cli::arguments& args) {
  auto ex_path = args.required("--exemplar");
  auto dir = args.required("--out");
  if (!ex_path) return cli::fail(args, ex_path.error());
  if (!dir) return cli::fail(args, dir.error());
  auto colors = args.has("--colors") ? args.numbers("--colors", 2)
                                     : tessera::result<std::vector<double>>(std::vector<double>{2, 2});
  if (!colors) return cli::fail(args, colors.error());
  // range-checked before any conversion to int (1e10 must not wrap)
  for (double c : *colors)
    if (!(c >= 1 && c <= tessera::max_wang_colors) || c != std::floor(c))
      return cli::fail(args, tessera::status::invalid_argument("--colors expects two integers NH,NV in [1, " +
                                                               std::to_string(tessera::max_wang_colors) + "], got '" +
                                                               args.str("--colors") + "'"));
  auto tile = args.integer("--tile", 64, 4, 65536);
  auto overlap = args.integer("--overlap", 0, 0, 65536);
  auto patch = args.integer("--patch", 0, 0, 65536);
  auto border = args.integer("--border", 0, 0, 65536);
  auto mip_levels = args.integer("--mip-levels", 0, 0, 16);
  auto tolerance = args.number("--tolerance", 0.1, 0, 1e30);
  for (const auto* r :
       {&tile.error(), &overlap.error(), &patch.error(), &border.error(), &mip_levels.error(), &tolerance.error()})
    if (!r->ok()) return cli::fail(args, *r);
  const int nh = static_cast<int>((*colors)[0]), nv = static_cast<int>((*colors)[1]);
  tessera::wang_tile_options options{.tile_size = static_cast<index_t>(*tile),
                                     .horizontal_colors = nh,
                                     .vertical_colors = nv,
                                     .mip_levels = static_cast<int>(*mip_levels),
                                     .overlap = static_cast<index_t>(*overlap),
                                     .patch_size = static_cast<index_t>(*patch),
                                     .border = static_cast<index_t>(*border),
                                     .tolerance = *tolerance,
                                     .seed = args.seed()};
  if (args.has("--subset")) {
    auto subset = tessera::tile_set_edges::modular_subset(nh, nv, 2);
    if (!subset) return cli::fail(args, subset.error());
    options.tiles.assign(subset->tiles().begin(), subset->tiles().end());
  }
  tessera::thread_pool_executor pool(args.threads());
  auto s =
      cli::with_image_source(args, "--exemplar", [&]<class T, int C>(tessera::format_tag<T, C>) -> tessera::status {
        auto exemplar = cli::load_image_source<T, C>(args, "--exemplar");
        if (!exemplar) return exemplar.error();
        tessera::result<tessera::wang_tile_set<T, C>> set = tessera::status::internal_error("not built");
        const double ms =
            cli::median_ms(args.repeat(), [&] { set = tessera::build_wang_tiles(*exemplar, options, pool); });
        if (!set) return set.error();
        if (auto st = tessera::save_wang_tiles(*dir, *set); !st) return st;
        // the GPU atlas: Wei's edge-ordered layout for complete sets, padded otherwise
        const auto layout =
            set->edges().is_complete() ? tessera::atlas_layout::edge_ordered : tessera::atlas_layout::padded;
        auto atlas = tessera::build_wang_atlas(*set, {.layout = layout});
        if (!atlas) return atlas.error();
        if (auto st = tessera::write_png((std::filesystem::path(*dir) / "atlas.png").string(), atlas->image); !st)
          return st;
        if (args.stats()) {
          auto quality = tessera::wang_seam_quality(*set, *exemplar);
          if (!quality) return quality.error();
          cli::json_line()
              .add("command", "wang build")
              .add("tiles", set->size())
              .add("tile_size", set->tile_size())
              .add("build_ms", ms)
              .add("seam_ratio_mean", quality->mean_ratio)
              .add("seam_ratio_max", quality->max_ratio)
              .add("atlas", layout == tessera::atlas_layout::edge_ordered ? "edge_ordered" : "padded")
              .add("atlas_mip_levels", atlas->mip_levels)
              .add("shared_border", set->shared_border())
              .print();
        }
        return {};
      });
  if (!s) return cli::fail(args, s);
  return 0;
}

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
  tessera::status composed;
  double ms = 0;
  auto compose = [&](const auto& coloring) {
    ms = cli::median_ms(args.repeat(), [&] { composed = tessera::compose_tiles(*set, coloring, *out, options, pool); });
  };
  if (kind == "scanline") {
    auto c = tessera::scanline_coloring::create(set->edges(), cols, rows, args.seed());
    if (!c) return c.error();
    compose(*c);
  } else if (kind == "hash") {
    auto c = tessera::hash_coloring::for_set(set->edges(), args.seed());
    if (!c) return c.error();
    compose(*c);
  } else {
    auto c = tessera::periodic_coloring::create(set->edges(), *period, *period, cols, rows, args.seed());
    if (!c) return c.error();
    compose(*c);
  }
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
  if (!args.has("--grid")) return cli::fail(args, tessera::status::invalid_argument("missing required option --grid"));
  auto grid = args.size("--grid");
  if (!grid) return cli::fail(args, grid.error());
  const std::string kind = args.str("--coloring", "scanline");
  if (kind != "scanline" && kind != "hash" && kind != "periodic")
    return cli::fail(
        args, tessera::status::invalid_argument("--coloring expects scanline, hash or periodic, got '" + kind + "'"));
  // the tiles' pixel format, from the first tile file
  auto manifest = tessera::read_tile_manifest(*dir);
  if (!manifest) return cli::fail(args, manifest.error());
  auto info = tessera::read_png_info((std::filesystem::path(*dir) / manifest->tiles.front().file).string());
  if (!info) return cli::fail(args, info.error());
  const tessera::pixel_format fmt{info->bit_depth == 16 ? tessera::channel_type::uint16 : tessera::channel_type::uint8,
                                  info->channels};
  auto s = tessera::dispatch_format(fmt, [&]<class T, int C>(tessera::format_tag<T, C>) {
    return tile_with<T, C>(args, *dir, kind, grid->first, grid->second);
  });
  if (!s) return cli::fail(args, s);
  return 0;
}

std::vector<cli::option_spec> with_common(std::vector<cli::option_spec> o) {
  for (auto& c : cli::common_options()) o.push_back(c);
  return o;
}

const cli::registrar build_command({
    .name = "wang build",
    .summary = "build a Wang tile set from an exemplar (tiles, tiles.json, atlas.png)",
    .usage = "tessera wang build --exemplar E.png --colors NH,NV --tile T --out DIR [--subset] [--mip-levels L]",
    .options = with_common({
        {"--exemplar", "E.png", "exemplar PNG or procedural kind (grass, sand, rock, bricks, cells, weave, dots)"},
        cli::exemplar_size_option(),
        {"--colors", "NH,NV", "colours of horizontal (north/south) and vertical (east/west) edges (default 2,2)"},
        {"--tile", "T", "tile size in pixels (default 64; at most the exemplar's smaller side)"},
        {"--out", "DIR", "output directory: tile_<index>.png, tiles.json, atlas.png"},
        {"--subset", "", "build the modular subset (Cohen's 8 tiles for 2,2) instead of all NH^2 NV^2"},
        {"--overlap", "V",
         "quilting overlap = depth of each edge sample in a tile (default max(tile / 10, border + 2))"},
        {"--patch", "P", "quilting patch size (default about tile / 3)"},
        {"--mip-levels", "L",
         "mip levels of atlas.png that sample exactly across tile borders and corners "
         "(border 2^(L-1); default: up to 4 as the tile size allows)"},
        {"--border", "B", "outer pixels copied from the edge samples and never cut (default 2^(L-1))"},
        {"--tolerance", "T", "candidate tolerance (default 0.1)"},
    }),
    .run = run_build,
});

const cli::registrar tile_command({
    .name = "wang tile",
    .summary = "compose a tiled image from a Wang tile directory",
    .usage =
        "tessera wang tile --tiles DIR --grid COLSxROWS --out O.png [--seed S] [--coloring scanline|hash|periodic] "
        "[--repeat N]",
    .options = with_common({
        {"--tiles", "DIR", "tile directory written by tessera wang build"},
        {"--grid", "COLSxROWS", "number of tiles across and down"},
        {"--out", "O.png", "output PNG"},
        {"--coloring", "KIND", "scanline (Cohen, default), hash (O(1) per cell) or periodic"},
        {"--period", "N", "period in tiles of --coloring periodic (default 4)"},
        {"--outline", "", "draw the tile borders"},
    }),
    .run = run_tile,
});

}  // namespace
