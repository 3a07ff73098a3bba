// tessera fabric: fabric textures by cat-map iteration and game-of-life perturbation (paper 001).
//   tessera fabric --preset flannel|twill|linen|tweed --size N --out O.png
//   tessera fabric --palette "#000000:0.75,#ffffff:0.25" --layout blocks --size 400 --iterations 60 --out O.png
//   tessera fabric --source S.png --iterations 80 [--generations 3 --K 3 --N 6] --out O.png
#include <cstdio>
#include <string>

#include <tessera/fabric/make_fabric.hpp>
#include <tessera/fabric/tone_proportions.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"

namespace {

using tessera::status;

int run(const cli::arguments& args) {
  auto out_path = args.required("--out");
  if (!out_path) return cli::fail(args, out_path.error());
  const int sources = args.has("--preset") + args.has("--source") + args.has("--palette");
  if (sources != 1)
    return cli::fail(args, status::invalid_argument("give exactly one of --preset, --source or --palette"));
  std::pair<tessera::index_t, tessera::index_t> size{400, 400};
  if (args.has("--size")) {
    auto s = args.size("--size");
    if (!s) return cli::fail(args, s.error());
    size = *s;
  }
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
    if (l == "stripes") recipe.source.layout = tessera::source_layout::stripes;
    else if (l == "blocks") recipe.source.layout = tessera::source_layout::blocks;
    else if (l == "cells") recipe.source.layout = tessera::source_layout::cells;
    else return cli::fail(args, status::invalid_argument("--layout expects stripes, blocks or cells, got '" + l + "'"));
  }
  auto feature = args.integer("--feature", recipe.source.feature_size);
  auto iterations = args.integer("--iterations", recipe.options.iterations);
  auto generations = args.integer("--generations", recipe.options.perturbation.generations);
  auto k = args.integer("--K", recipe.options.perturbation.live_count);
  auto n = args.integer("--N", recipe.options.perturbation.dead_count);
  auto tile = args.integer("--tile", 0);
  for (const auto* v : {&feature, &iterations, &generations, &k, &n, &tile})
    if (!*v) return cli::fail(args, v->error());
  recipe.source.feature_size = static_cast<tessera::index_t>(*feature);
  recipe.options.iterations = *iterations;
  recipe.options.perturbation.generations = static_cast<int>(*generations);
  recipe.options.perturbation.live_count = static_cast<int>(*k);
  recipe.options.perturbation.dead_count = static_cast<int>(*n);
  recipe.options.tile_size = static_cast<tessera::index_t>(*tile);
  if (args.has("--family")) {
    auto f = args.numbers("--family", 2);
    if (!f) return cli::fail(args, f.error());
    recipe.options.family = {static_cast<std::int64_t>((*f)[0]), static_cast<std::int64_t>((*f)[1])};
  }

  tessera::thread_pool_executor pool(args.threads());
  tessera::image_buffer<std::uint8_t, 3> out(size.first, size.second);
  tessera::image_buffer<float, 3> source;
  if (args.has("--source")) {
    auto s = tessera::read_png<float, 3>(args.str("--source"));
    if (!s) return cli::fail(args, s.error());
    source = std::move(*s);
  } else if (recipe.photo) {
    const tessera::index_t side = *tile > 0 ? static_cast<tessera::index_t>(*tile) : std::max(size.first, size.second);
    auto s = tessera::make_exemplar<float, 3>(*recipe.photo, {.width = side, .height = side, .seed = seed});
    if (!s) return cli::fail(args, s.error());
    source = std::move(*s);
  }
  status st;
  const double ms = cli::median_ms(args.repeat(), [&] {
    st = source.empty() ? tessera::make_fabric(recipe.tones, recipe.source, out, recipe.options, pool)
                        : tessera::make_fabric(source, out, recipe.options, pool);
  });
  if (!st) return cli::fail(args, st);
  if (auto s = tessera::write_png(*out_path, out); !s) return cli::fail(args, s);
  if (args.stats()) {
    // the tone shares of the output: against the palette when there is one, else its 4 dominant tones
    std::string shares = "[";
    tessera::palette tones = recipe.tones;
    if (tones.empty()) tones = tessera::dominant_tones(out, 4).value_or(tessera::palette{});
    auto p = tessera::tone_proportions(out, tones);
    for (std::size_t i = 0; p && i < p->size(); ++i) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%s%.4f", i ? "," : "", (*p)[i]);
      shares += buf;
    }
    shares += "]";
    cli::json_line().add("command", "fabric").add("width", size.first).add("height", size.second)
        .add("tile", recipe.options.tile_size).add("iterations", static_cast<long long>(recipe.options.iterations))
        .add("generations", recipe.options.perturbation.generations).add("fabric_ms", ms).add("repeat", args.repeat())
        .add("threads", pool.concurrency()).raw("tone_shares", shares).print();
  } else {
    std::fprintf(stderr, "wrote %s\n", out_path->c_str());
  }
  return 0;
}

std::vector<cli::option_spec> options() {
  std::vector<cli::option_spec> o = {
      {"--preset", "NAME", "flannel, twill, linen or tweed (the paper's figures 4-9)"},
      {"--source", "S.png", "an existing image as the source (paper 001 §1.3, second way)"},
      {"--palette", "LIST", "main tones \"#000000:0.75,#ffffff:0.25\" (weights are normalized)"},
      {"--layout", "L", "source layout for --palette: stripes (default), blocks or cells"},
      {"--feature", "F", "stripe period / block side / cell spacing in pixels (default size / 8)"},
      {"--size", "N|WxH", "output size (default 400)"},
      {"--tile", "T", "generate a T x T periodic fabric and tile it (default: generate at the output size)"},
      {"--iterations", "n", "cat-map steps (presets: flannel 60, twill 31, linen 80, tweed 45)"},
      {"--family", "a,b", "the cat map [1 a; b ab+1] (default 1,1)"},
      {"--generations", "m", "game-of-life perturbation generations (default 0; tweed 3)"},
      {"--K", "K", "brighten when exactly K neighbours are brighter (default 3)"},
      {"--N", "N", "darken when at least N neighbours are dimmer (default 6)"},
      {"--out", "O.png", "output image (8-bit RGB)"}};
  for (auto& c : cli::common_options()) o.push_back(c);
  return o;
}

const cli::registrar reg({"fabric", "fabric textures: cat-map iteration and game-of-life perturbation (paper 001)",
                          "tessera fabric --preset NAME | --source S.png | --palette LIST [--layout L] --size N "
                          "--iterations n [--generations m --K 3 --N 6] --out O.png [--seed S]",
                          options(), run});

}  // namespace
