// The body of `tessera synth` for one pixel format (see synth_request.hpp): included by
// cmd_synth_8bit.cpp and cmd_synth_16bit.cpp only, each instantiating it for its formats.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "image_source.hpp"
#include "synth_request.hpp"

namespace cli::synth {

using tessera::status;

template <class T, int C>
int run_format(const arguments& args, const request& r) {
  auto ex = cli::load_image_source<T, C>(args, "--exemplar");
  if (!ex) return cli::fail(args, ex.error());
  tessera::thread_pool_executor pool(r.threads);
  const tessera::patch_model_options mo{.patch_width = r.patch_w,
                                        .patch_height = r.patch_h,
                                        .overlap = r.overlap,
                                        .seams = r.seams == tessera::seam_mode::cut};
  tessera::result<tessera::patch_model<T, C>> model = status::internal_error("not built");
  const double preprocess_ms = cli::time_ms([&] { model = tessera::build_patch_model(*ex, mo, pool); });
  if (!model) return cli::fail(args, model.error());

  auto out = tessera::image_buffer<T, C>::create(r.width, r.height);
  if (!out) return cli::fail(args, out.error());
  const tessera::patch_synthesis_options so{.origin = r.origin, .seed = r.seed, .seams = r.seams};
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
        .add("threads", pool.concurrency())
        .add("preprocess_ms", preprocess_ms)
        .add("synthesis_ms", synthesis_ms)
        .add("repeat", r.repeat)
        .add("mpixels_per_s", static_cast<double>(r.width * r.height) / (synthesis_ms * 1e3))
        .add("cells", st->cells)
        .add("filled", st->filled)
        .add("empty_intersections", st->empty_intersections)
        .add("model_bytes", static_cast<long long>(model->memory_bytes()));
    // the metrics work on float copies (as they do internally), compiled once per channel count
    const auto seams = tessera::patch_seam_lines(*model, cw, ch, {r.origin.x + cx, r.origin.y + cy});
    auto fcrop = tessera::to_buffer<float, C>(crop, "crop");
    auto fex = tessera::to_buffer<float, C>(*ex, "exemplar");
    if (fcrop && fex) add_quality<C>(line, *fcrop, *fex, seams, pool);
    line.print();
  } else {
    std::printf("wrote %s (%td x %td, patch %td x %td, overlap %td, %.2f ms)\n", r.out.c_str(), r.width, r.height,
                model->patch_width(), model->patch_height(), model->overlap(), synthesis_ms);
  }
  return 0;
}

}  // namespace cli::synth
