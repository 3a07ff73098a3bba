// tessera catmap: Arnold's cat map on a square image (paper 001, eq. 1-4), or its period.
//   tessera catmap --in I.png --iterations n --out O.png [--family a,b] [--non-square center|tiles]
//   tessera catmap --period N [--family a,b]
#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>

#include <tessera/core/format.hpp>
#include <tessera/fabric/cat_map.hpp>
#include <tessera/fabric/cat_map_period.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "png_limits.hpp"
#include "fabric_cli.hpp"

namespace {

int run(const cli::arguments& args) {
  auto family = fabric_cli::family(args);
  if (!family) return cli::fail(args, family.error());
  if (args.has("--period")) {
    auto n = args.integer("--period", 0, 1, tessera::max_cat_map_modulus);
    if (!n) return cli::fail(args, n.error());
    double ms = 0;
    tessera::result<std::uint64_t> p = std::uint64_t{0};
    ms = cli::median_ms(args.repeat(), [&] { p = tessera::cat_map_period(*n, *family); });
    if (!p) return cli::fail(args, p.error());
    if (args.stats())
      cli::json_line()
          .add("command", "catmap")
          .add("N", static_cast<long long>(*n))
          .add("period", static_cast<std::uint64_t>(*p))
          .add("period_ms", ms)
          .print();
    else
      std::printf("%llu\n", static_cast<unsigned long long>(*p));
    return 0;
  }
  auto in = args.required("--in");
  if (!in) return cli::fail(args, in.error());
  auto out = args.required("--out");
  if (!out) return cli::fail(args, out.error());
  auto steps = args.integer("--iterations", 1);
  if (!steps) return cli::fail(args, steps.error());
  tessera::cat_map_options options{.family = *family};
  const std::string mode = args.str("--non-square", "reject");
  if (mode == "center")
    options.non_square = tessera::non_square_mode::centered_square;
  else if (mode == "tiles")
    options.non_square = tessera::non_square_mode::square_tiles;
  else if (mode != "reject")
    return cli::fail(
        args, tessera::status::invalid_argument("--non-square expects reject, center or tiles, got '" + mode + "'"));
  auto tile = args.integer("--tile", 0, 0, fabric_cli::max_side);
  if (!tile) return cli::fail(args, tile.error());
  options.tile_size = static_cast<tessera::index_t>(*tile);
  auto info = tessera::read_png_info(*in);
  if (!info) return cli::fail(args, info.error());
  if (info->width > fabric_cli::max_side || info->height > fabric_cli::max_side ||
      info->width * info->height > fabric_cli::max_pixels)
    return cli::fail(args, tessera::status::invalid_argument(
                               *in + ": " + std::to_string(info->width) + " x " + std::to_string(info->height) +
                               " is larger than the " + std::to_string(fabric_cli::max_side) + " per side and " +
                               std::to_string(fabric_cli::max_pixels) + " pixels catmap accepts"));
  tessera::thread_pool_executor pool(args.threads());
  double ms = 0;
  auto s = cli::dispatch_png_format(
      cli::png_format(*info), [&]<class T, int C>(tessera::format_tag<T, C>) -> tessera::status {
        auto img = cli::read_png_file<T, C>(*in);
        if (!img) return img.error();
        tessera::image_buffer<T, C> result(img->width(), img->height());
        tessera::status st;
        ms = cli::median_ms(args.repeat(), [&] { st = tessera::cat_map(*img, result, *steps, options, pool); });
        if (!st) return st;
        return tessera::write_png(*out, result);
      });
  if (!s) return cli::fail(args, s);
  // the side of the squares that were mapped: the image, its largest centred square, or the tiles
  const tessera::index_t side = info->width == info->height ? info->width
                                : options.non_square == tessera::non_square_mode::square_tiles
                                    ? (options.tile_size > 0 ? options.tile_size : std::gcd(info->width, info->height))
                                    : std::min(info->width, info->height);
  auto period = tessera::cat_map_period(side, *family);
  if (args.stats())
    cli::json_line()
        .add("command", "catmap")
        .add("width", info->width)
        .add("height", info->height)
        .add("iterations", static_cast<long long>(*steps))
        .add("side", side)
        .add("period", static_cast<std::uint64_t>(period.value_or(0)))
        .add("catmap_ms", ms)
        .add("repeat", args.repeat())
        .add("threads", pool.concurrency())
        .print();
  else
    std::fprintf(stderr, "wrote %s (%lld steps of the cat map on %lld x %lld squares; period %llu)\n", out->c_str(),
                 static_cast<long long>(*steps), static_cast<long long>(side), static_cast<long long>(side),
                 static_cast<unsigned long long>(period.value_or(0)));
  return 0;
}

std::vector<cli::option_spec> options() {
  std::vector<cli::option_spec> o = {
      {"--in", "I.png", "square input image (8- or 16-bit PNG, 1-4 channels)"},
      {"--out", "O.png", "output image"},
      {"--iterations", "n", "number of cat-map steps, any integer; negative inverts (default 1)"},
      {"--period", "N", "print the period of the cat map on an N x N image, N in [1, 2^62], and exit"},
      {"--family", "a,b", "the map [1 a; b ab+1], integers (default 1,1: Arnold's [1 1; 1 2])"},
      {"--non-square", "MODE", "reject (default), center (largest centred square) or tiles"},
      {"--tile", "T", "square tile side for --non-square tiles (default gcd of the sides)"}};
  return o;
}

const cli::registrar reg({"catmap", "Arnold's cat map on a square image, in one pass for any step count (paper 001)",
                          "tessera catmap --in I.png --iterations n --out O.png | tessera catmap --period N", options(),
                          run});

}  // namespace
