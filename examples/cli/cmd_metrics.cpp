// tessera metrics: quality figures of a synthesized image against its exemplar (image/metrics.hpp),
// as one JSON line, for any image (ours or another program's): scripts/quality-patch.sh compares
// patch synthesis with G'MIC through it.
//   tessera metrics --exemplar E.png --in I.png [--window 7] [--levels 2] [--step 2]
//                   [--min-offset 16] [--patch WxH --overlap V] [--threads T]
#include <algorithm>
#include <string>

#include <tessera/core/format.hpp>
#include <tessera/image/metrics.hpp>
#include <tessera/image/patch_synthesis.hpp>

#include "cli.hpp"
#include "image_source.hpp"

namespace {

using tessera::index_t;

template <class T, int C>
int run_format(const cli::arguments& args) {
  auto image = cli::load_image_source<T, C>(args, "--in");
  if (!image) return cli::fail(args, image.error());
  auto ex = cli::load_image_source<T, C>(args, "--exemplar");
  if (!ex) return cli::fail(args, ex.error());
  auto window = args.integer("--window", 7, 1, 255);
  if (!window) return cli::fail(args, window.error());
  auto levels = args.integer("--levels", 2, 1, 6);
  if (!levels) return cli::fail(args, levels.error());
  auto step = args.integer("--step", 2, 1, 4096);
  if (!step) return cli::fail(args, step.error());
  const index_t max_offset = std::max(image->width(), image->height()) / 2;
  auto min_offset =
      args.integer("--min-offset", std::min<index_t>(16, max_offset), 1, std::max<index_t>(1, max_offset));
  if (!min_offset) return cli::fail(args, min_offset.error());
  std::vector<tessera::seam_segment> seams;  // --patch (and --overlap): the seam lines of a patch grid
  if (args.has("--patch")) {
    auto pitch = args.size("--patch", 32768);
    if (!pitch) return cli::fail(args, pitch.error());
    auto overlap = args.integer("--overlap", 0, 0, std::min(pitch->first, pitch->second));
    if (!overlap) return cli::fail(args, overlap.error());
    seams = tessera::patch_seam_lines(pitch->first, pitch->second, static_cast<index_t>(*overlap), image->width(),
                                      image->height());
  }
  tessera::thread_pool_executor pool(args.threads());

  const tessera::multiscale_energy_options mo{.window = static_cast<index_t>(*window),
                                              .sample_step = static_cast<index_t>(*step),
                                              .levels = static_cast<int>(*levels)};
  tessera::result<std::vector<double>> energy = tessera::status::internal_error("not run");
  const double ms = cli::time_ms([&] { energy = tessera::multiscale_energy(*image, *ex, mo, pool); });
  if (!energy) return cli::fail(args, energy.error());
  auto histogram = tessera::histogram_distance(*image, *ex);
  if (!histogram) return cli::fail(args, histogram.error());
  auto repetition = tessera::repetition_score(*image, static_cast<index_t>(*min_offset));
  if (!repetition) return cli::fail(args, repetition.error());

  cli::json_line line;
  line.add("command", "metrics")
      .add("width", image->width())
      .add("height", image->height())
      .add("exemplar_width", ex->width())
      .add("exemplar_height", ex->height())
      .add("window", static_cast<index_t>(*window));
  for (std::size_t l = 0; l < energy->size(); ++l)
    line.add(("energy_" + std::to_string(index_t{1} << l) + "x").c_str(), (*energy)[l]);  // 1x, 2x: 1/2 resolution
  line.add("histogram_distance", *histogram).add("repetition", *repetition);
  if (!seams.empty()) {
    auto gradient = tessera::seam_gradient_ratio(*image, seams, *ex);
    if (!gradient) return cli::fail(args, gradient.error());
    auto steps = tessera::seam_step_ratio(*image, seams, *ex);
    if (!steps) return cli::fail(args, steps.error());
    line.add("seam_gradient_ratio", *gradient).add("seam_step_ratio", *steps);
  }
  line.add("metrics_ms", ms).print();
  return 0;
}

int run_metrics(const cli::arguments& args) {
  int code = 0;
  const tessera::status s = cli::with_image_source(
      args, "--in", [&]<class T, int C>(tessera::format_tag<T, C>) { code = run_format<T, C>(args); });
  if (!s) return cli::fail(args, s);
  return code;
}

const cli::registrar reg(
    {.name = "metrics",
     .summary = "quality figures of an image against its exemplar (multi-scale neighbourhood energy, histogram, "
                "repetition, seams of a patch grid) as JSON",
     .usage = "tessera metrics --exemplar E.png --in I.png [--window 7] [--levels 2] [--step 2] [--min-offset 16] "
              "[--patch WxH --overlap V] [--threads T]",
     .options = {{"--exemplar", "E.png", "the exemplar (PNG or a procedural kind)"},
                 {"--in", "I.png",
                  "the image to measure (PNG or a procedural kind); the exemplar is converted to its format"},
                 cli::exemplar_size_option(),
                 {"--window", "N", "neighbourhood side (default 7)"},
                 {"--levels", "L", "energy at 1x, 1/2x, ... 1/2^(L-1) resolution (default 2)"},
                 {"--step", "S", "output neighbourhoods every S pixels (default 2)"},
                 {"--min-offset", "D", "repetition: smallest shift considered (default 16)"},
                 {"--patch", "P",
                  "also measure the seams of a patch grid of pitch P (or WxH) at the image's origin, at the "
                  "centres of its overlaps (seam_gradient_ratio, seam_step_ratio), as tessera synth --patch"},
                 {"--overlap", "V", "the overlap of that grid (default 0: the lines at the cell borders)"}},
     .run = run_metrics});

}  // namespace
