// tessera wang build: a Wang tile set from an exemplar (tile PNGs, tiles.json, atlas.png).
//   tessera wang build --exemplar E.png --colors NH,NV --tile T --out DIR [--subset] [--mip-levels L]
//   --colors NX,NY,NZ builds a three-axis set for polycube surfaces (image/axis_wang_tiles.hpp), whose
//   atlas.png `tessera wang map` (cmd_wang_map.cpp) maps onto meshes.
// (wang tile is cmd_wang_tile.cpp: each instantiates its kernels for the 8 PNG formats, so the two
// compile in parallel.)
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/format.hpp>
#include <tessera/image/axis_wang_atlas.hpp>
#include <tessera/image/axis_wang_tiles.hpp>
#include <tessera/image/wang_atlas.hpp>
#include <tessera/image/wang_seam_quality.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/io/png.hpp>
#include <tessera/io/wang_tiles.hpp>
#include <tessera/tiling/tile_set_edges.hpp>

#include "cli.hpp"
#include "image_source.hpp"

namespace {

using tessera::index_t;

// --colors NX,NY,NZ: the three-axis set, its six-face atlas, the seam ratios of each face's planar set
template <class T, int C, class E>
tessera::status build_axis_set(const cli::arguments& args, const E& exemplar, tessera::axis_color_counts colors,
                               const tessera::wang_tile_options& options, const std::string& dir,
                               tessera::thread_pool_executor& pool) {
  tessera::result<tessera::axis_wang_tile_set<T, C>> set = tessera::status::internal_error("not built");
  const double ms =
      cli::median_ms(args.repeat(), [&] { set = tessera::build_axis_wang_tiles(exemplar, colors, options, pool); });
  if (!set) return set.error();
  if (auto st = tessera::save_wang_tiles(dir, *set); !st) return st;
  auto atlas = tessera::build_axis_wang_atlas(*set, {.mip_levels = options.mip_levels});
  if (!atlas) return atlas.error();
  if (auto st = tessera::write_png((std::filesystem::path(dir) / "atlas.png").string(), atlas->image); !st) return st;
  if (args.stats()) {
    double mean = 0, worst = 0;
    for (int f = 0; f < tessera::cube_faces; ++f) {
      auto q = tessera::wang_seam_quality(set->face_set(f), exemplar);
      if (!q) return q.error();
      mean += q->mean_ratio / tessera::cube_faces;
      worst = std::max(worst, q->max_ratio);
    }
    cli::json_line()
        .add("command", "wang build")
        .add("tiles", set->size())
        .add("tile_size", set->tile_size())
        .add("build_ms", ms)
        .add("seam_ratio_mean", mean)
        .add("seam_ratio_max", worst)
        .add("atlas", "three_axis")
        .add("atlas_mip_levels", atlas->mip_levels)
        .add("shared_border", set->shared_border())
        .print();
  }
  return {};
}

int run_build(const cli::arguments& args) {
  auto ex_path = args.required("--exemplar");
  auto dir = args.required("--out");
  if (!ex_path) return cli::fail(args, ex_path.error());
  if (!dir) return cli::fail(args, dir.error());
  auto counts = args.color_counts("--colors", tessera::max_wang_colors);
  if (!counts) return cli::fail(args, counts.error());
  const bool three = counts->size() == 3;
  auto tile = args.integer("--tile", 64, 4, 65536);
  auto overlap = args.integer("--overlap", 0, 0, 65536);
  auto patch = args.integer("--patch", 0, 0, 65536);
  auto border = args.integer("--border", 0, 0, 65536);
  auto mip_levels = args.integer("--mip-levels", 0, 0, 16);
  auto tolerance = args.number("--tolerance", 0.1, 0, 1e30);
  for (const auto* r :
       {&tile.error(), &overlap.error(), &patch.error(), &border.error(), &mip_levels.error(), &tolerance.error()})
    if (!r->ok()) return cli::fail(args, *r);
  const int nh = (*counts)[0], nv = (*counts)[1];
  tessera::wang_tile_options options{.tile_size = static_cast<index_t>(*tile),
                                     .horizontal_colors = nh,
                                     .vertical_colors = nv,
                                     .mip_levels = static_cast<int>(*mip_levels),
                                     .overlap = static_cast<index_t>(*overlap),
                                     .patch_size = static_cast<index_t>(*patch),
                                     .border = static_cast<index_t>(*border),
                                     .tolerance = *tolerance,
                                     .seed = args.seed()};
  if (three && args.has("--subset"))
    return cli::fail(args, tessera::status::invalid_argument("--subset is for planar sets (--colors NH,NV)"));
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
        if (three) return build_axis_set<T, C>(args, *exemplar, {nh, nv, (*counts)[2]}, options, *dir, pool);
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

const cli::registrar build_command({
    .name = "wang build",
    .summary = "build a Wang tile set from an exemplar (tiles, tiles.json, atlas.png)",
    .usage =
        "tessera wang build --exemplar E.png --colors NH,NV|NX,NY,NZ --tile T --out DIR [--subset] [--mip-levels L]",
    .options = {{
        {"--exemplar", "E.png", "exemplar PNG or procedural kind (grass, sand, rock, bricks, cells, weave, dots)"},
        cli::exemplar_size_option(),
        {"--colors", "NH,NV",
         "colours of horizontal (north/south) and vertical (east/west) edges, 1 to 4096 (default 2,2); "
         "three counts NX,NY,NZ make a three-axis set for polycube surfaces (tessera wang map)"},
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
    }},
    .run = run_build,
});

}  // namespace
