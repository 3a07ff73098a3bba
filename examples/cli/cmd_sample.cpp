// tessera sample --kind KIND --size WxH --out E.png: a procedural exemplar image (image/exemplars.hpp).
#include <cstdint>
#include <string>

#include <tessera/image/exemplars.hpp>
#include <tessera/io/files.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"

namespace {

using tessera::status;

inline constexpr tessera::index_t max_side = 16384;

int run_sample(const cli::arguments& args) {
  if (!args.has("--kind"))
    return cli::fail(
        args, status::invalid_argument(
                  "expects one KIND: grass, sand, rock, bricks, cells, weave or dots (see tessera sample --help)"));
  const auto kind = tessera::parse_exemplar_kind(args.str("--kind"));
  if (!kind) return cli::fail(args, kind.error());
  auto out = args.required("--out");
  if (!out) return cli::fail(args, out.error());
  if (tessera::file_extension(*out) != "png")
    return cli::fail(args, status::invalid_argument("--out must name a .png file, got '" + *out + "'"));
  std::pair<tessera::index_t, tessera::index_t> size{128, 128};
  if (args.has("--size")) {
    auto s = args.size("--size", max_side);
    if (!s) return cli::fail(args, s.error());
    size = *s;
  }
  tessera::result<tessera::image_buffer<std::uint8_t, 3>> img = status::internal_error("not made");
  const double ms = cli::median_ms(args.repeat(), [&] {
    img = tessera::make_exemplar(*kind, {.width = size.first, .height = size.second, .seed = args.seed()});
  });
  if (!img) return cli::fail(args, img.error());
  if (auto s = tessera::write_png(*out, *img); !s) return cli::fail(args, s);
  if (args.stats())
    cli::json_line()
        .add("kind", tessera::to_string(*kind))
        .add("width", size.first)
        .add("height", size.second)
        .add("seed", args.seed())
        .add("output", *out)
        .add("ms", ms)
        .add("pixels_per_s", static_cast<double>(size.first * size.second) / (ms > 0 ? ms / 1000 : 1e-9))
        .print();
  else
    std::printf("wrote %s (%s, %td x %td, seed %llu)\n", out->c_str(), std::string(tessera::to_string(*kind)).c_str(),
                size.first, size.second, static_cast<unsigned long long>(args.seed()));
  return 0;
}

const cli::registrar reg({
    .name = "sample",
    .summary = "write a procedural exemplar image (grass sand rock bricks cells weave dots)",
    .usage = "tessera sample --kind KIND --size WxH --out E.png [--seed S] [--stats]",
    .options = {{"--kind", "KIND", "grass, sand, rock, bricks, cells, weave or dots (or KIND as the argument)"},
                {"--size", "WxH", "image size (default 128x128; at most 16384 per side)"},
                {"--out", "FILE", "output PNG (required)"},
                {"--seed", "S", "random seed (default 1); same seed, same image"},
                {"--repeat", "N", "time the generation N times and report the median (default 1)"},
                {"--stats", "", "print one JSON line instead of text"}},
    .run = run_sample,
    .positional = "KIND",
    .positional_options = {"--kind"},
});

}  // namespace
