// tessera synth: real-time patch synthesis of large textures (paper 002; image/patch_synthesis.hpp).
//   tessera synth --exemplar E.png --size WxH --out O.png [--seed S] [--threads T] [--patch P]
//                 [--overlap V] [--seams feather|cut] [--window X,Y,W,H] [--source-map M.png]
//                 [--repeat N] [--stats]
// This file parses and dispatches; the per-format work is synth_run.hpp, compiled in
// cmd_synth_8bit.cpp and cmd_synth_16bit.cpp.
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <tessera/core/format.hpp>

#include "cli.hpp"
#include "image_source.hpp"
#include "synth_request.hpp"

namespace cli::synth {

template <int C>
void add_quality(json_line& line, const tessera::image_buffer<float, C>& crop,
                 const tessera::image_buffer<float, C>& exemplar, std::span<const tessera::seam_segment> seams,
                 tessera::thread_pool_executor& pool) {
  const index_t cw = crop.width(), ch = crop.height();
  const tessera::neighborhood_energy_options eo{.window = 5, .sample_step = 4};
  if (auto e = tessera::neighborhood_energy(crop, exemplar, eo, pool)) line.add("neighborhood_energy", *e);
  if (!seams.empty())
    if (auto g = tessera::seam_gradient_ratio(crop, seams, exemplar)) line.add("seam_gradient_ratio", *g);
  if (auto h = tessera::histogram_distance(crop, exemplar)) line.add("histogram_distance", *h);
  if (std::max(cw, ch) >= 32)
    if (auto rep = tessera::repetition_score(crop, std::min<index_t>(16, std::max(cw, ch) / 2)))
      line.add("repetition", *rep);
}

template void add_quality<1>(json_line&, const tessera::image_buffer<float, 1>&, const tessera::image_buffer<float, 1>&,
                             std::span<const tessera::seam_segment>, tessera::thread_pool_executor&);
template void add_quality<2>(json_line&, const tessera::image_buffer<float, 2>&, const tessera::image_buffer<float, 2>&,
                             std::span<const tessera::seam_segment>, tessera::thread_pool_executor&);
template void add_quality<3>(json_line&, const tessera::image_buffer<float, 3>&, const tessera::image_buffer<float, 3>&,
                             std::span<const tessera::seam_segment>, tessera::thread_pool_executor&);
template void add_quality<4>(json_line&, const tessera::image_buffer<float, 4>&, const tessera::image_buffer<float, 4>&,
                             std::span<const tessera::seam_segment>, tessera::thread_pool_executor&);

}  // namespace cli::synth

namespace {

using tessera::index_t;
using tessera::status;

inline constexpr index_t max_side = 32768;
inline constexpr index_t max_pixels = index_t{1} << 28;
inline constexpr double max_origin = 4503599627370496.0;  // 2^52, tessera::max_texture_coordinate

tessera::result<cli::synth::request> parse(const cli::arguments& args) {
  cli::synth::request r;
  auto ex = args.required("--exemplar");
  if (!ex) return ex.error();
  r.exemplar = *ex;
  auto out = args.required("--out");
  if (!out) return out.error();
  r.out = *out;
  if (args.has("--window")) {
    auto w = args.numbers("--window", 4);
    if (!w) return w.error();
    const auto& v = *w;
    // range first, then integrality, then the cast (a double outside index_t's range must never be
    // cast): the origin within the texture plane's +-2^52, the size within the output limit
    const auto window_error = [&](const char* why) {
      return status::invalid_argument(std::string("--window expects integers X,Y,W,H with ") + why + ", got '" +
                                      args.str("--window") + "'");
    };
    for (double d : v)
      if (d != std::floor(d)) return window_error("no fractions");
    if (std::abs(v[0]) > max_origin || std::abs(v[1]) > max_origin)
      return window_error("|X| and |Y| at most 2^52 (the texture plane)");
    if (!(v[2] >= 1 && v[3] >= 1) || v[2] > double(max_side) || v[3] > double(max_side) ||
        v[2] * v[3] > double(max_pixels))
      return window_error(("W and H in [1, " + std::to_string(max_side) + "] and W x H at most 2^28").c_str());
    r.origin = {static_cast<index_t>(v[0]), static_cast<index_t>(v[1])};
    r.width = static_cast<index_t>(v[2]);
    r.height = static_cast<index_t>(v[3]);
  } else {
    auto size = args.size("--size", max_side, max_pixels);
    if (!args.has("--size")) return status::invalid_argument("missing required option --size (or --window)");
    if (!size) return size.error();
    r.width = size->first;
    r.height = size->second;
  }
  if (args.has("--patch")) {
    auto p = args.size("--patch");
    if (!p) return p.error();
    r.patch_w = p->first;
    r.patch_h = p->second;
  }
  auto overlap = args.integer("--overlap", 0, 0, max_side);  // 0: automatic; the model checks the fit
  if (!overlap) return overlap.error();
  r.overlap = static_cast<index_t>(*overlap);
  const std::string seams = args.str("--seams", "feather");
  if (seams == "cut")
    r.seams = tessera::seam_mode::cut;
  else if (seams != "feather")
    return status::invalid_argument("--seams expects feather or cut, got '" + seams + "'");
  r.seed = args.seed();  // --seed, --threads and --repeat were checked by main (check_common)
  r.threads = args.threads();
  r.repeat = args.repeat();
  if (auto es = args.integer("--exemplar-size", 128, 8, 4096); !es) return es.error();
  r.source_map = args.str("--source-map");
  r.stats = args.stats();
  return r;
}

int run_synth(const cli::arguments& args) {
  auto r = parse(args);
  if (!r) return cli::fail(args, r.error());
  auto fmt = cli::image_source_format(args, "--exemplar");
  if (!fmt) return cli::fail(args, fmt.error());
  int code = 0;
  const status s = cli::dispatch_png_format(
      *fmt, [&]<class T, int C>(tessera::format_tag<T, C>) { code = cli::synth::run_format<T, C>(args, *r); });
  if (!s) return cli::fail(args, s);
  return code;
}

std::vector<cli::option_spec> synth_options() {
  std::vector<cli::option_spec> o = {
      {"--exemplar", "E.png",
       "exemplar image (PNG, 8 or 16 bits, 1-4 channels) or a procedural kind: grass, sand, rock, bricks, cells, "
       "weave, dots"},
      cli::exemplar_size_option(),
      {"--size", "WxH", "output size (required unless --window is given)"},
      {"--out", "O.png", "output image"},
      {"--patch", "P", "patch pitch P or WxH (default: chosen by the periodicity analysis, paper 002 section 2.1)"},
      {"--overlap", "V", "overlap width between patches (default: chosen by the analysis)"},
      {"--seams", "MODE", "feather (default, the paper's linear blend) or cut (minimum-error seams)"},
      {"--window", "X,Y,W,H", "render the W x H window at (X, Y) of the infinite texture instead of --size"},
      {"--source-map", "M.png", "also write the exemplar coordinates of every pixel (16-bit RGB: red x, green y)"}};
  return o;
}

const cli::registrar reg(
    {.name = "synth",
     .summary = "synthesize a large texture or any window of an infinite one from an exemplar (patch synthesis)",
     .usage = "tessera synth --exemplar E.png --size WxH --out O.png [--seed S] [--threads T] [--patch P] "
              "[--overlap V] [--seams feather|cut] [--window X,Y,W,H] [--source-map M.png] [--repeat N] [--stats]",
     .options = synth_options(),
     .run = run_synth});

}  // namespace
