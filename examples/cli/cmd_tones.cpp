// tessera tones: the main tones of an image and their shares (paper 001 §1.3), so a source image can
// be designed to match a target fabric.
//   tessera tones --in IN.png [--max N]                   dominant tones by k-means, largest share first
//   tessera tones --in IN.png --palette "#000000:1,..."   share of the pixels nearest to each given tone
// The text output ends with a --palette line ready for `tessera fabric`.
#include <cstdio>
#include <string>
#include <vector>

#include <tessera/fabric/tone_proportions.hpp>

#include "cli.hpp"
#include "fabric_cli.hpp"

namespace {

using tessera::status;

int run(const cli::arguments& args) {
  if (!args.has("--in"))
    return cli::fail(
        args, status::invalid_argument("expects exactly one image IN.png (or --in IN.png; see tessera tones --help)"));
  const std::string path = args.str("--in");
  auto max = args.integer("--max", 4, 1, 64);
  if (!max) return cli::fail(args, max.error());
  tessera::palette given;
  if (args.has("--palette")) {
    auto p = tessera::parse_palette(args.str("--palette"));
    if (!p) return cli::fail(args, p.error());
    given = std::move(*p);
  }
  auto img = fabric_cli::read_source(path);
  if (!img) return cli::fail(args, img.error());

  tessera::palette tones;  // colour and share of each reported tone
  status st;
  const double ms = cli::median_ms(args.repeat(), [&] {
    if (given.empty()) {
      auto d = tessera::dominant_tones(*img, static_cast<int>(*max), {.seed = args.seed()});
      if (!d)
        st = d.error();
      else
        tones = std::move(*d);
    } else {
      auto shares = tessera::tone_proportions(*img, given);
      if (!shares) {
        st = shares.error();
        return;
      }
      tones = given;
      for (std::size_t i = 0; i < tones.size(); ++i) tones[i].proportion = (*shares)[i];
    }
  });
  if (!st) return cli::fail(args, st);

  if (args.stats()) {
    std::string list = "[";
    for (std::size_t i = 0; i < tones.size(); ++i) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%s{\"color\":\"%s\",\"share\":%.4f}", i ? "," : "",
                    fabric_cli::hex(tones[i].color).c_str(), tones[i].proportion);
      list += buf;
    }
    list += "]";
    cli::json_line()
        .add("command", "tones")
        .add("file", path)
        .add("width", img->width())
        .add("height", img->height())
        .add("method", given.empty() ? "dominant" : "nearest")
        .raw("tones", list)
        .add("palette", fabric_cli::palette_text(tones))
        .add("tones_ms", ms)
        .print();
    return 0;
  }
  std::printf("%s: %lld x %lld, %s\n", path.c_str(), static_cast<long long>(img->width()),
              static_cast<long long>(img->height()),
              given.empty() ? "dominant tones (k-means)" : "share of the pixels nearest to each tone");
  for (const tessera::tone& t : tones)
    std::printf("  %s  %6.2f %%\n", fabric_cli::hex(t.color).c_str(), 100.0 * t.proportion);
  std::printf("--palette \"%s\"\n", fabric_cli::palette_text(tones).c_str());
  return 0;
}

std::vector<cli::option_spec> options() {
  std::vector<cli::option_spec> o = {
      {"--in", "IN.png", "the image (or IN.png as the argument)"},
      {"--max", "N", "how many dominant tones to find, 1..64 (default 4; fewer if the image has fewer colours)"},
      {"--palette", "LIST",
       "measure these tones instead (\"#000000:1,#ffffff:1\"; weights ignored): each pixel "
       "counts for the nearest"}};
  return o;
}

const cli::registrar reg({
    .name = "tones",
    .summary = "the main tones of an image and their shares, to design a matching fabric source (paper 001)",
    .usage = "tessera tones --in IN.png [--max N | --palette LIST] [--stats]",
    .options = options(),
    .run = run,
    .positional = "IN.png",
    .positional_options = {"--in"},
});

}  // namespace
