// tessera fabric: fabric textures by cat-map iteration and game-of-life perturbation (paper 001).
//   tessera fabric --preset flannel|twill|linen|tweed --size N --out O.png
//   tessera fabric --palette "#000000:0.75,#ffffff:0.25" --layout blocks --size 400 --iterations 60 --out O.png
//   tessera fabric --source S.png --iterations 80 [--fit center] [--generations 3 --K 3 --N 6] --out O.png
#include <algorithm>
#include <cstdio>
#include <string>

#include <tessera/fabric/make_fabric.hpp>
#include <tessera/fabric/tone_proportions.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "fabric_cli.hpp"

namespace {

using tessera::index_t;
using tessera::status;

int run(const cli::arguments& args) {
  auto out_path = args.required("--out");
  if (!out_path) return cli::fail(args, out_path.error());
  const int sources = args.has("--preset") + args.has("--source") + args.has("--palette");
  if (sources != 1)
    return cli::fail(args, status::invalid_argument("give exactly one of --preset, --source or --palette"));
  const std::uint64_t seed = args.seed();

  // the recipe: a preset's, or built from the options
  tessera::fabric_recipe recipe;
  recipe.source.seed = seed;
  recipe.options.perturbation.seed = seed;
  if (args.has("--preset")) {
    auto p = tessera::parse_fabric_preset(args.str("--preset"));
    if (!p) return cli::fail(args, p.error());
    recipe = tessera::fabric_preset_recipe(*p, seed);
  } else if (args.has("--palette")) {
    auto pal = tessera::parse_palette(args.str("--palette"));
    if (!pal) return cli::fail(args, pal.error());
    recipe.tones = *pal;
  }
  if (args.has("--layout")) {
    const std::string l = args.str("--layout");
    if (l == "stripes")
      recipe.source.layout = tessera::source_layout::stripes;
    else if (l == "blocks")
      recipe.source.layout = tessera::source_layout::blocks;
    else if (l == "cells")
      recipe.source.layout = tessera::source_layout::cells;
    else
      return cli::fail(args, status::invalid_argument("--layout expects stripes, blocks or cells, got '" + l + "'"));
  }
  if (args.has("--fit")) {
    const std::string f = args.str("--fit");
    if (f == "reject")
      recipe.options.fit = tessera::source_fit::reject;
    else if (f == "center")
      recipe.options.fit = tessera::source_fit::centered_square;
    else if (f == "crop")
      recipe.options.fit = tessera::source_fit::crop_or_repeat;
    else
      return cli::fail(args, status::invalid_argument("--fit expects reject, center or crop, got '" + f + "'"));
  }
  // every number range-checked before it is used (and before anything is allocated)
  auto feature = args.integer("--feature", recipe.source.feature_size, 0, fabric_cli::max_square);
  auto iterations = args.integer("--iterations", recipe.options.iterations);
  auto generations = args.integer("--generations", recipe.options.perturbation.generations, 0, 10000);
  auto k = args.integer("--K", recipe.options.perturbation.live_count, 0, 8);
  auto n = args.integer("--N", recipe.options.perturbation.dead_count, 1, 8);
  auto tile = args.integer("--tile", 0, 0, fabric_cli::max_square);
  for (const auto* v : {&feature, &iterations, &generations, &k, &n, &tile})
    if (!*v) return cli::fail(args, v->error());
  auto family = fabric_cli::family(args);
  if (!family) return cli::fail(args, family.error());
  recipe.source.feature_size = static_cast<index_t>(*feature);
  recipe.options.iterations = *iterations;
  recipe.options.perturbation.generations = static_cast<int>(*generations);
  recipe.options.perturbation.live_count = static_cast<int>(*k);
  recipe.options.perturbation.dead_count = static_cast<int>(*n);
  recipe.options.tile_size = static_cast<index_t>(*tile);
  if (args.has("--family")) recipe.options.family = *family;

  tessera::image_buffer<float, 3> source;
  if (args.has("--source")) {
    auto s = fabric_cli::read_source(args.str("--source"));
    if (!s) return cli::fail(args, s.error());
    source = std::move(*s);
  }
  // the output size: --size, else the source's size, else 400 x 400
  std::pair<index_t, index_t> size{400, 400};
  if (args.has("--size")) {
    auto s = args.size("--size", fabric_cli::max_side, fabric_cli::max_pixels);
    if (!s) return cli::fail(args, s.error());
    size = *s;
  } else if (!source.empty()) {
    size = {source.width(), source.height()};
  }
  // the side of the periodic square the fabric is generated at
  const index_t square = recipe.options.tile_size > 0 ? recipe.options.tile_size
                         : !source.empty() && recipe.options.fit == tessera::source_fit::centered_square
                             ? std::min(source.width(), source.height())
                             : std::max(size.first, size.second);
  if (square > fabric_cli::max_square)
    return cli::fail(
        args, status::invalid_argument("the fabric would be generated at " + std::to_string(square) + " x " +
                                       std::to_string(square) + " (the larger side of --size); give --tile T <= " +
                                       std::to_string(fabric_cli::max_square) + " to tile a smaller periodic square"));
  if (recipe.photo) {
    auto s = tessera::make_exemplar<float, 3>(*recipe.photo, {.width = square, .height = square, .seed = seed});
    if (!s) return cli::fail(args, s.error());
    source = std::move(*s);
  }
  auto made = tessera::image_buffer<std::uint8_t, 3>::create(size.first, size.second);
  if (!made) return cli::fail(args, made.error());
  tessera::image_buffer<std::uint8_t, 3>& out = *made;

  tessera::thread_pool_executor pool(args.threads());
  status st;
  const double ms = cli::median_ms(args.repeat(), [&] {
    st = source.empty() ? tessera::make_fabric(recipe.tones, recipe.source, out, recipe.options, pool)
                        : tessera::make_fabric(source, out, recipe.options, pool);
  });
  if (!st) return cli::fail(args, st);
  if (auto s = tessera::write_png(*out_path, out); !s) return cli::fail(args, s);
  if (args.stats()) {
    // the tone shares of the output: against the palette when there is one, else its 4 dominant tones
    tessera::palette tones = recipe.tones;
    if (tones.empty()) tones = tessera::dominant_tones(out, 4, {.seed = seed}).value_or(tessera::palette{});
    const auto shares = tessera::tone_proportions(out, tones).value_or(std::vector<double>{});
    cli::json_line()
        .add("command", "fabric")
        .add("width", size.first)
        .add("height", size.second)
        .add("tile", recipe.options.tile_size)
        .add("iterations", static_cast<long long>(recipe.options.iterations))
        .add("generations", recipe.options.perturbation.generations)
        .add("fabric_ms", ms)
        .add("repeat", args.repeat())
        .add("threads", pool.concurrency())
        .raw("tone_shares", fabric_cli::shares_json(shares))
        .print();
  } else {
    std::fprintf(stderr, "wrote %s (%lld x %lld)\n", out_path->c_str(), static_cast<long long>(size.first),
                 static_cast<long long>(size.second));
  }
  return 0;
}

std::vector<cli::option_spec> options() {
  std::vector<cli::option_spec> o = {
      {"--preset", "NAME", "flannel, twill, linen or tweed (the paper's figures 4-9)"},
      {"--source", "S.png", "an existing image as the source (paper 001 §1.3, second way)"},
      {"--fit", "MODE",
       "a --source that is not the fabric's square: reject (default), center (map its largest "
       "centred square at its own size and tile it) or crop (centred window, repeated if smaller)"},
      {"--palette", "LIST", "main tones \"#000000:0.75,#ffffff:0.25\" (weights are normalized; see tessera tones)"},
      {"--layout", "L", "source layout for --palette: stripes (default), blocks or cells"},
      {"--feature", "F", "stripe period / block side / cell spacing in pixels, 0..8192 (default size / 8)"},
      {"--size", "N|WxH", "output size, at most 16384 per side and 2^26 pixels (default: the source's, else 400)"},
      {"--tile", "T",
       "generate a T x T periodic fabric, T <= 8192, and tile it (default: at the output's larger side)"},
      {"--iterations", "n",
       "cat-map steps, any integer, negative inverts (presets: flannel 60, twill 31, linen 80, tweed 45)"},
      {"--family", "a,b", "the cat map [1 a; b ab+1], integers (default 1,1)"},
      {"--generations", "m", "game-of-life perturbation generations, 0..10000 (default 0; tweed 3)"},
      {"--K", "K", "brighten when exactly K neighbours are brighter, 0..8 (default 3)"},
      {"--N", "N", "darken when at least N neighbours are dimmer, 1..8 (default 6)"},
      {"--out", "O.png", "output image (8-bit RGB)"}};
  return o;
}

const cli::registrar reg({"fabric", "fabric textures: cat-map iteration and game-of-life perturbation (paper 001)",
                          "tessera fabric --preset NAME | --source S.png [--fit MODE] | --palette LIST [--layout L] "
                          "--size N --iterations n [--generations m --K 3 --N 6] --out O.png [--seed S]",
                          options(), run});

}  // namespace
