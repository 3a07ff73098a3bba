// tessera convert --in IN --out OUT (or IN OUT): between PNG bit depths / channel counts, and between
// mesh formats.
#include <cstdint>
#include <string>

#include <tessera/core/format.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/io/files.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "png_limits.hpp"

namespace {

using tessera::status;

int convert_image(const cli::arguments& args, const std::string& in, const std::string& out) {
  if (args.has("--binary")) return cli::fail(args, status::invalid_argument("--binary applies to .ply output only"));
  auto info = tessera::read_png_info(in);
  if (!info) return cli::fail(args, info.error());
  auto channels = args.integer("--channels", info->channels);
  if (!channels) return cli::fail(args, channels.error());
  if (*channels < 1 || *channels > 4)
    return cli::fail(args,
                     status::invalid_argument("--channels must be 1, 2, 3 or 4, got " + std::to_string(*channels)));
  auto depth = args.integer("--depth", info->bit_depth);
  if (!depth) return cli::fail(args, depth.error());
  if (*depth != 8 && *depth != 16)
    return cli::fail(args, status::invalid_argument("--depth must be 8 or 16, got " + std::to_string(*depth)));
  status s;
  const double ms = cli::time_ms([&] {
    s = tessera::dispatch_channels<std::uint16_t>(
        static_cast<int>(*channels), [&]<class T, int C>(tessera::format_tag<T, C>) {
          auto img = cli::read_png_file<std::uint16_t, C>(in);  // 16-bit keeps a 16-bit source exact
          if (!img) return img.error();
          if (*depth == 16) return tessera::write_png(out, *img);
          auto bytes = tessera::to_buffer<std::uint8_t, C>(*img);
          if (!bytes) return bytes.error();
          return tessera::write_png(out, *bytes);
        });
  });
  if (!s) return cli::fail(args, s);
  if (args.stats())
    cli::json_line()
        .add("input", in)
        .add("output", out)
        .add("kind", "image")
        .add("width", info->width)
        .add("height", info->height)
        .add("channels", static_cast<int>(*channels))
        .add("bit_depth", static_cast<int>(*depth))
        .add("ms", ms)
        .print();
  else
    std::printf("wrote %s (%td x %td, %lld channel%s, %lld-bit)\n", out.c_str(), info->width, info->height, *channels,
                *channels == 1 ? "" : "s", *depth);
  return 0;
}

int convert_mesh(const cli::arguments& args, const std::string& in, const std::string& out) {
  if (args.has("--channels") || args.has("--depth"))
    return cli::fail(args, status::invalid_argument("--channels and --depth apply to PNG images only"));
  const auto out_format = tessera::mesh_format_of(out);
  if (!out_format) return cli::fail(args, out_format.error());
  if (args.has("--binary") && *out_format != tessera::mesh_format::ply)
    return cli::fail(args, status::invalid_argument("--binary applies to .ply output only"));
  tessera::result<tessera::tri_mesh> mesh = status::internal_error("not read");
  status s;
  const double ms = cli::time_ms([&] {
    mesh = tessera::read_mesh(in);
    if (mesh) s = tessera::write_mesh(out, *mesh, {.binary = args.has("--binary")});
  });
  if (!mesh) return cli::fail(args, mesh.error());
  if (!s) return cli::fail(args, s);
  const bool dropped_uvs = mesh->has_uvs() && *out_format == tessera::mesh_format::off;
  if (args.stats())
    cli::json_line()
        .add("input", in)
        .add("output", out)
        .add("kind", "mesh")
        .add("vertices", mesh->num_vertices())
        .add("faces", mesh->num_faces())
        .add("has_uvs", mesh->has_uvs() && !dropped_uvs)
        .add("ms", ms)
        .print();
  else
    std::printf("wrote %s (%td vertices, %td triangles%s)\n", out.c_str(), mesh->num_vertices(), mesh->num_faces(),
                dropped_uvs       ? "; OFF cannot hold the uvs, they were dropped"
                : mesh->has_uvs() ? ", with uvs"
                                  : "");
  return 0;
}

int run_convert(const cli::arguments& args) {
  if (!args.has("--in") || !args.has("--out"))
    return cli::fail(args, status::invalid_argument("expects IN and OUT files (or --in IN --out OUT; see tessera "
                                                    "convert --help)"));
  const std::string in = args.str("--in");
  const std::string out = args.str("--out");
  const bool in_png = tessera::file_extension(in) == "png", out_png = tessera::file_extension(out) == "png";
  if (in_png && out_png) return convert_image(args, in, out);
  if (tessera::is_mesh_path(in) && tessera::is_mesh_path(out)) return convert_mesh(args, in, out);
  if (in_png != out_png && (in_png || tessera::is_mesh_path(in)) && (out_png || tessera::is_mesh_path(out)))
    return cli::fail(
        args, status::invalid_argument("cannot convert between an image and a mesh (" + in + " -> " + out + ")"));
  const std::string& bad = !in_png && !tessera::is_mesh_path(in) ? in : out;
  return cli::fail(args, status::unsupported(bad + ": unknown file type (expected .png, .obj, .off or .ply)"));
}

const cli::registrar reg({
    .name = "convert",
    .summary = "convert a PNG (channels, bit depth) or a mesh between OBJ, OFF and PLY",
    .usage = "tessera convert --in IN --out OUT [--channels C] [--depth 8|16] [--binary] [--stats]",
    .options = {{"--in", "IN", "input PNG or mesh (or IN as the first argument)"},
                {"--out", "OUT", "output of the same kind (or OUT as the second argument)"},
                {"--channels", "C", "PNG: output channels 1-4 (grey, grey+alpha, RGB, RGBA; default: as input)"},
                {"--depth", "8|16", "PNG: output bit depth (default: as input)"},
                {"--binary", "", "PLY output: binary little-endian instead of ASCII"},
                {"--stats", "", "print one JSON line instead of text"}},
    .run = run_convert,
    .positional = "IN OUT",
    .positional_options = {"--in", "--out"},
    .shared = cli::shared_options::stats_only,
});

}  // namespace
