// tessera synth: real-time patch synthesis of large textures (paper 002; image/patch_synthesis.hpp).
//   tessera synth --exemplar E.png --size WxH --out O.png [--seed S] [--threads T] [--patch P]
//                 [--overlap V] [--seams feather|cut] [--feather W] [--fallback sets|estimate|overlap] [--candidates K] [--min-patch-fraction F]
//                 [--window X,Y,W,H] [--source-map M.png]
//                 [--repeat N] [--stats]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <string>
#include <vector>

#include <tessera/core/format.hpp>
#include <tessera/image/metrics.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "image_source.hpp"

namespace {

using tessera::index_t;
using tessera::status;

inline constexpr index_t max_side = 32768;
inline constexpr index_t max_pixels = index_t{1} << 28;
inline constexpr double max_origin = 4503599627370496.0;  // 2^52, tessera::max_texture_coordinate
/// --stats warns of a visible patch grid above this seam step ratio (on the 30 photographs of
/// scripts/quality-patch.sh, outputs whose grid does not show measured 0.87-1.29, G'MIC's outputs on the
/// same lines 0.6-1.15; the ones whose grid shows 1.45-3.0)
inline constexpr double seam_warning_ratio = 1.3;

std::string format_ratio(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", r);
  return buf;
}

struct synth_request {
  std::string exemplar, out, source_map;
  index_t width = 0, height = 0, patch_w = 0, patch_h = 0, overlap = 0;
  index_t feather = tessera::patch_synthesis_options{}.feather_width;
  tessera::texture_offset origin;
  tessera::seam_mode seams = tessera::seam_mode::feather;
  tessera::fill_fallback fallback = tessera::fill_fallback::most_sets;
  int candidates = 8;
  double min_patch_fraction = tessera::patch_model_options{}.min_patch_fraction;
  std::uint64_t seed = 1;
  int threads = 0, repeat = 1;
  bool stats = false;
};

tessera::result<synth_request> parse(const cli::arguments& args) {
  synth_request r;
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
    auto size = args.size("--size", max_side, max_pixels);  // required unless --window is given
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
  auto feather = args.integer("--feather", static_cast<long long>(r.feather), 0, max_side);
  if (!feather) return feather.error();
  r.feather = static_cast<index_t>(*feather);
  const std::string fallback = args.str("--fallback", "sets");
  if (fallback == "overlap")
    r.fallback = tessera::fill_fallback::overlap_error;
  else if (fallback == "estimate")
    r.fallback = tessera::fill_fallback::estimated_error;
  else if (fallback == "sets")
    r.fallback = tessera::fill_fallback::most_sets;
  else
    return status::invalid_argument("--fallback expects estimate, sets or overlap, got '" + fallback + "'");
  if (args.has("--min-patch-fraction")) {
    auto f = args.numbers("--min-patch-fraction", 1);
    if (!f) return f.error();
    if (!((*f)[0] > 0 && (*f)[0] <= 0.5))
      return status::invalid_argument("--min-patch-fraction expects a number in (0, 0.5], got '" +
                                      args.str("--min-patch-fraction") + "'");
    r.min_patch_fraction = (*f)[0];
  }
  auto k = args.integer("--candidates", 8, 1, 64);
  if (!k) return k.error();
  r.candidates = static_cast<int>(*k);
  r.seed = args.seed();  // --seed, --threads and --repeat were checked by main (check_common)
  r.threads = args.threads();
  r.repeat = args.repeat();
  if (auto es = args.integer("--exemplar-size", 128, 8, 4096); !es) return es.error();
  r.source_map = args.str("--source-map");
  r.stats = args.stats();
  return r;
}

template <class T, int C>
int run_format(const cli::arguments& args, const synth_request& r) {
  auto ex = cli::load_image_source<T, C>(args, "--exemplar");
  if (!ex) return cli::fail(args, ex.error());
  tessera::thread_pool_executor pool(r.threads);
  const tessera::patch_model_options mo{.patch_width = r.patch_w,
                                        .patch_height = r.patch_h,
                                        .overlap = r.overlap,
                                        .candidates = r.candidates,
                                        .seams = r.seams == tessera::seam_mode::cut,
                                        .min_patch_fraction = r.min_patch_fraction};
  tessera::result<tessera::patch_model<T, C>> model = status::internal_error("not built");
  const double preprocess_ms = cli::time_ms([&] { model = tessera::build_patch_model(*ex, mo, pool); });
  if (!model) return cli::fail(args, model.error());

  auto out = tessera::image_buffer<T, C>::create(r.width, r.height);
  if (!out) return cli::fail(args, out.error());
  const tessera::patch_synthesis_options so{
      .origin = r.origin, .seed = r.seed, .seams = r.seams, .feather_width = r.feather, .fallback = r.fallback};
  tessera::result<tessera::patch_synthesis_stats> st = status::internal_error("not run");
  const double synthesis_ms = cli::median_ms(r.repeat, [&] { st = tessera::synthesize(*model, *out, so, pool); });
  if (!st) return cli::fail(args, st.error());
  if (auto s = tessera::write_png(r.out, *out); !s) return cli::fail(args, s);

  if (!r.source_map.empty()) {
    // exemplar coordinates, shown as 16-bit RGB: red = x, green = y (normalized to the exemplar), blue 0
    tessera::image_buffer<std::uint16_t, 2> coords(r.width, r.height);
    if (auto s = tessera::synthesize_source_map(*model, coords, so, pool); !s) return cli::fail(args, s.error());
    tessera::image_buffer<std::uint16_t, 3> shown(r.width, r.height);
    const double sx = 65535.0 / static_cast<double>(std::max<index_t>(1, ex->width() - 1));
    const double sy = 65535.0 / static_cast<double>(std::max<index_t>(1, ex->height() - 1));
    for (index_t y = 0; y < r.height; ++y)
      for (index_t x = 0; x < r.width; ++x) {
        const auto c = coords.read(x, y);
        shown.write(x, y,
                    {static_cast<std::uint16_t>(c[0] * sx + 0.5), static_cast<std::uint16_t>(c[1] * sy + 0.5), 0});
      }
    if (auto s = tessera::write_png(r.source_map, shown); !s) return cli::fail(args, s);
  }

  if (r.stats) {
    // quality figures on a central crop of at most 256 x 256 (keeps --stats fast on large outputs)
    const index_t cw = std::min<index_t>(r.width, 256), ch = std::min<index_t>(r.height, 256);
    const index_t cx = (r.width - cw) / 2, cy = (r.height - ch) / 2;
    tessera::image_buffer<T, C> crop(cw, ch);
    for (index_t y = 0; y < ch; ++y)
      for (index_t x = 0; x < cw; ++x) crop.write(x, y, out->read(cx + x, cy + y));
    cli::json_line line;
    line.add("command", "synth")
        .add("width", r.width)
        .add("height", r.height)
        .add("exemplar_width", ex->width())
        .add("exemplar_height", ex->height())
        .add("patch", model->patch_width())
        .add("patch_height", model->patch_height())
        .add("overlap", model->overlap())
        .add("seams", r.seams == tessera::seam_mode::cut ? "cut" : "feather")
        .add("feather_width", r.feather > 0 ? std::min(r.feather, model->overlap()) : model->overlap())
        .add("threads", pool.concurrency())
        .add("preprocess_ms", preprocess_ms)
        .add("synthesis_ms", synthesis_ms)
        .add("repeat", r.repeat)
        .add("mpixels_per_s", static_cast<double>(r.width * r.height) / (synthesis_ms * 1e3))
        .add("cells", st->cells)
        .add("filled", st->filled)
        .add("empty_intersections", st->empty_intersections)
        .add("fallback_rate", st->filled > 0 ? static_cast<double>(st->empty_intersections) / st->filled : 0.0)
        .add("fallback", r.fallback == tessera::fill_fallback::most_sets         ? "sets"
                         : r.fallback == tessera::fill_fallback::estimated_error ? "estimate"
                                                                                 : "overlap")
        .add("evaluated_errors", st->evaluated_errors)
        .add("fill_overlap_rms", st->fill_overlap_rms)
        .add("candidates", model->candidates())
        .add("model_bytes", static_cast<long long>(model->memory_bytes()));
    // a patch size that breaks the structure: the chosen pitch does not follow the exemplar's period
    // (low autocorrelation at one pitch) while an analysed shape does (the brick case of issue 16)
    line.add("pitch_alignment", model->pitch_alignment());
    if (const auto& analysis = model->analysis()) {
      const tessera::patch_size_measure* best = nullptr;
      for (const auto& m : analysis->sizes)
        if (best == nullptr || m.alignment > best->alignment) best = &m;
      if (best != nullptr) {
        line.add("best_alignment", best->alignment)
            .add("best_alignment_patch", std::to_string(best->width) + "x" + std::to_string(best->height));
        const bool breaks = best->alignment >= 0.5 && model->pitch_alignment() < best->alignment - 0.2;
        line.add("structure_warning", breaks ? "the patch pitch does not follow the exemplar's period; try --patch " +
                                                   std::to_string(best->width) + "x" + std::to_string(best->height)
                                             : std::string());
      }
    }
    const tessera::neighborhood_energy_options eo{.window = 5, .sample_step = 4};
    if (auto e = tessera::neighborhood_energy(crop, *ex, eo, pool)) line.add("neighborhood_energy", *e);
    const auto seams = tessera::patch_seam_lines(*model, cw, ch, {r.origin.x + cx, r.origin.y + cy});
    if (!seams.empty()) {
      if (auto g = tessera::seam_gradient_ratio(crop, seams, *ex)) line.add("seam_gradient_ratio", *g);
      // a visible patch grid: patches brighter or darker than their neighbours (issue 16: the parquet,
      // paving, cut-block wall, pink marble and rain photographs, 1.5-3), which the energies miss
      if (auto st = tessera::seam_step_ratio(crop, seams, *ex)) {
        line.add("seam_step_ratio", *st);
        line.add("seam_warning", *st > seam_warning_ratio
                                     ? "patches step in brightness or colour across their seams " + format_ratio(*st) +
                                           "x as much as neighbouring regions of the exemplar: the patch grid may "
                                           "show; try --feather 0 (blend the whole overlap) or --seams cut "
                                           "--fallback overlap"
                                     : std::string());
      }
    }
    if (auto h = tessera::histogram_distance(crop, *ex)) line.add("histogram_distance", *h);
    if (std::max(cw, ch) >= 32)
      if (auto rep = tessera::repetition_score(crop, std::min<index_t>(16, std::max(cw, ch) / 2)))
        line.add("repetition", *rep);
    line.print();
  } else {
    std::printf("wrote %s (%td x %td, patch %td x %td, overlap %td, %.2f ms)\n", r.out.c_str(), r.width, r.height,
                model->patch_width(), model->patch_height(), model->overlap(), synthesis_ms);
  }
  return 0;
}

int run_synth(const cli::arguments& args) {
  auto r = parse(args);
  if (!r) return cli::fail(args, r.error());
  auto fmt = cli::image_source_format(args, "--exemplar");
  if (!fmt) return cli::fail(args, fmt.error());
  int code = 0;
  const status s = cli::dispatch_png_format(
      *fmt, [&]<class T, int C>(tessera::format_tag<T, C>) { code = run_format<T, C>(args, *r); });
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
      {"--feather", "W",
       "feathering: width of the blend band centred in each overlap, 0 = the whole overlap (the paper)"},
      {"--fallback", "RULE",
       "cells whose four compatible sets share no patch: sets (default, the paper: the patch in the most sets), "
       "estimate (smallest overlap error, the errors the sets miss estimated) or overlap (missing errors computed "
       "exactly; slowest)"},
      {"--candidates", "K", "size of each compatible set, 1 to 64 (default 8, the paper's)"},
      {"--min-patch-fraction", "F",
       "smallest patch side the automatic size tries, as a fraction of the exemplar's smaller side, in (0, 0.5] "
       "(default 0.375; 0.25 is the paper's range)"},
      {"--window", "X,Y,W,H", "render the W x H window at (X, Y) of the infinite texture instead of --size"},
      {"--source-map", "M.png", "also write the exemplar coordinates of every pixel (16-bit RGB: red x, green y)"}};
  return o;
}

const cli::registrar reg(
    {.name = "synth",
     .summary = "synthesize a large texture or any window of an infinite one from an exemplar (patch synthesis)",
     .usage = "tessera synth --exemplar E.png --size WxH --out O.png [--seed S] [--threads T] [--patch P] "
              "[--overlap V] [--seams feather|cut] [--feather W] [--fallback sets|estimate|overlap] [--candidates K] "
              "[--min-patch-fraction F] [--window "
              "X,Y,W,H] "
              "[--source-map M.png] [--repeat N] [--stats]",
     .options = synth_options(),
     .run = run_synth});

}  // namespace
