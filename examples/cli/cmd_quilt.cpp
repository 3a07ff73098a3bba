// tessera quilt: image quilting (Efros & Freeman 2001), seamless output, and hole filling with a mask.
//   tessera quilt --exemplar E.png --size WxH --out O.png [--patch P --overlap V --tolerance T] [--seamless]
//   tessera quilt --in I.png --mask M.png --out O.png [--exemplar E.png] [...]
#include <string>

#include <tessera/core/executor.hpp>
#include <tessera/core/format.hpp>
#include <tessera/image/constrained_quilt.hpp>
#include <tessera/image/quilt.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "png_limits.hpp"
#include "image_source.hpp"

namespace {

using tessera::index_t;

int run_quilt(const cli::arguments& args) {
  auto out_path = args.required("--out");
  if (!out_path) return cli::fail(args, out_path.error());
  const bool inpaint = args.has("--mask") || args.has("--in");
  if (inpaint && !(args.has("--mask") && args.has("--in")))
    return cli::fail(args,
                     tessera::status::invalid_argument("--mask and --in go together (fill the masked pixels of --in)"));
  if (!inpaint && !args.has("--exemplar")) return cli::fail(args, cli::arguments::missing("--exemplar"));
  auto patch = args.integer("--patch", 0, 0, 65536);
  auto overlap = args.integer("--overlap", 0, 0, 65536);
  auto tolerance = args.number("--tolerance", 0.1, 0, 1e30);
  for (const auto* r : {&patch.error(), &overlap.error(), &tolerance.error()})
    if (!r->ok()) return cli::fail(args, *r);
  // the output size (quilting only), checked before any file is read
  tessera::result<std::pair<index_t, index_t>> size = std::pair<index_t, index_t>{0, 0};
  if (!inpaint) size = args.size("--size", 65536, tessera::max_quilt_pixels);
  if (!size) return cli::fail(args, size.error());
  tessera::quilt_options options{.patch_size = static_cast<index_t>(*patch),
                                 .overlap = static_cast<index_t>(*overlap),
                                 .tolerance = *tolerance,
                                 .seamless = args.has("--seamless"),
                                 .seed = args.seed()};
  tessera::thread_pool_executor pool(args.threads());
  double ms = 0;
  index_t width = 0, height = 0;
  auto s = cli::with_image_source(
      args, inpaint ? "--in" : "--exemplar", [&]<class T, int C>(tessera::format_tag<T, C>) -> tessera::status {
        tessera::image_buffer<T, C> out;
        if (inpaint) {
          auto image = cli::load_image_source<T, C>(args, "--in");
          if (!image) return image.error();
          auto mask = cli::read_png_file<std::uint8_t, 1>(args.str("--mask"));
          if (!mask) return mask.error();
          out = tessera::image_buffer<T, C>(image->width(), image->height());
          tessera::status result;
          if (args.has("--exemplar")) {
            auto ex = cli::load_image_source<T, C>(args, "--exemplar");
            if (!ex) return ex.error();
            ms = cli::median_ms(args.repeat(),
                                [&] { result = tessera::constrained_quilt(*ex, *image, *mask, out, options, pool); });
          } else {
            ms = cli::median_ms(args.repeat(),
                                [&] { result = tessera::constrained_quilt(*image, *mask, out, options, pool); });
          }
          if (!result) return result;
        } else {
          auto ex = cli::load_image_source<T, C>(args, "--exemplar");
          if (!ex) return ex.error();
          auto buffer = tessera::image_buffer<T, C>::create(size->first, size->second);
          if (!buffer) return buffer.error();
          out = std::move(*buffer);
          tessera::status result;
          ms = cli::median_ms(args.repeat(), [&] { result = tessera::quilt(*ex, out, options, pool); });
          if (!result) return result;
        }
        width = out.width();
        height = out.height();
        return tessera::write_png(*out_path, out);
      });
  if (!s) return cli::fail(args, s);
  if (args.stats())
    cli::json_line()
        .add("command", "quilt")
        .add("mode", inpaint            ? "inpaint"
                     : options.seamless ? "seamless"
                                        : "quilt")
        .add("width", width)
        .add("height", height)
        .add("quilt_ms", ms)
        .print();
  return 0;
}

std::vector<cli::option_spec> quilt_options_spec() {
  std::vector<cli::option_spec> o = {
      {"--exemplar", "E.png",
       "exemplar PNG or procedural kind (grass, ...); optional with --in: the image itself, hole excluded"},
      cli::exemplar_size_option(),
      {"--size", "WxH", "output size (quilting)"},
      {"--out", "O.png", "output PNG"},
      {"--patch", "P", "patch side in pixels (default: a quarter of the exemplar's smaller side, 8..64)"},
      {"--overlap", "V", "overlap between patches (default: patch / 6)"},
      {"--tolerance", "T", "draw among candidates within (1 + T) of the best overlap error (default 0.1)"},
      {"--seamless", "", "synthesize on a torus: the output tiles with itself"},
      {"--in", "I.png", "image (PNG or procedural kind) whose masked pixels are filled; other pixels are kept exactly"},
      {"--mask", "M.png", "mask of --in's size: pixels brighter than half are filled"},
  };
  return o;
}

const cli::registrar quilt_command({
    .name = "quilt",
    .summary = "image quilting (Efros-Freeman), seamless textures and mask inpainting",
    .usage = "tessera quilt --exemplar E.png --size WxH --out O.png [--patch P --overlap V --tolerance T] [--seamless] "
             "[--mask M.png --in I.png]",
    .options = quilt_options_spec(),
    .run = run_quilt,
});

}  // namespace
