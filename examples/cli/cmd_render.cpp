// tessera render --in IN.obj --out P.png: a shaded preview of a mesh (io/mesh_preview.hpp), coloured
// by polycube chart label with --labels (io/polycube_file.hpp, surface/polycube_map.hpp).
#include <string>
#include <vector>

#include <tessera/io/mesh_file.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/polycube_file.hpp>
#include <tessera/surface/polycube_map.hpp>

#include "cli.hpp"

namespace {

int run(const cli::arguments& args) {
  using namespace tessera;
  if (!args.has("--in"))
    return cli::fail(args,
                     status::invalid_argument("expects one input mesh (IN or --in IN; see tessera render --help)"));
  auto out = args.required("--out");
  if (!out) return cli::fail(args, out.error());
  mesh_preview_options o;
  const std::string view = args.str("--view", "oblique");
  if (view == "oblique")
    o.azimuth_degrees = -60, o.elevation_degrees = 45;
  else if (view == "top")
    o.azimuth_degrees = 0, o.elevation_degrees = 90;
  else if (view == "front")
    o.azimuth_degrees = 0, o.elevation_degrees = 20;
  else if (view == "side")
    o.azimuth_degrees = 90, o.elevation_degrees = 20;
  else
    return cli::fail(args, status::invalid_argument("--view expects oblique, top, front or side, got '" + view + "'"));
  auto az = args.number("--azimuth", o.azimuth_degrees);
  auto el = args.number("--elevation", o.elevation_degrees);
  auto grid = args.number("--tile", 0);
  if (!az) return cli::fail(args, az.error());
  if (!el) return cli::fail(args, el.error());
  if (!grid) return cli::fail(args, grid.error());
  o.azimuth_degrees = *az, o.elevation_degrees = *el, o.grid_spacing = *grid;
  o.wireframe = args.has("--wire");
  if (args.has("--size")) {
    auto sz = args.size("--size");
    if (!sz) return cli::fail(args, sz.error());
    o.width = sz->first, o.height = sz->second;
  }
  auto mesh = read_mesh(args.str("--in"));
  if (!mesh) return cli::fail(args, mesh.error());
  // --labels: one polycube chart label per face (tessera polycube --labels-out), drawn in its colour
  std::vector<std::array<float, 3>> colors;
  if (args.has("--labels")) {
    auto labels = read_polycube_labels(args.str("--labels"));
    if (!labels) return cli::fail(args, labels.error());
    if (static_cast<index_t>(labels->size()) != mesh->num_faces())
      return cli::fail(args,
                       status::invalid_argument("--labels: " + std::to_string(labels->size()) + " labels for " +
                                                std::to_string(mesh->num_faces()) + " faces of " + args.str("--in")));
    for (std::uint8_t l : *labels) colors.push_back(polycube_label_color(static_cast<polycube_label>(l)));
  }
  thread_pool_executor pool(args.threads());
  result<image_buffer<std::uint8_t, 3>> img = status::internal_error("not run");
  const double ms = cli::median_ms(args.repeat(), [&] {
    img = args.has("--labels") ? render_face_colored_mesh_preview(*mesh, colors, o, pool)
                               : render_mesh_preview(*mesh, o, pool);
  });
  if (!img) return cli::fail(args, img.error());
  if (auto s = write_png(*out, *img); !s) return cli::fail(args, s);
  if (args.stats())
    cli::json_line()
        .add("render_ms", ms)
        .add("faces", mesh->num_faces())
        .add("width", o.width)
        .add("height", o.height)
        .print();
  else
    std::printf("wrote %s\n", out->c_str());
  return 0;
}

const cli::registrar reg({
    .name = "render",
    .summary = "render a shaded preview of a mesh to PNG",
    .usage = "tessera render --in IN.obj --out P.png [--view oblique|top|front|side] [options]",
    .options = {{"--in", "IN", "the mesh (.obj, .off, .ply; or IN as the argument)"},
                {"--out", "FILE", "output PNG"},
                {"--view", "V", "oblique (default), top, front or side"},
                {"--azimuth", "DEG", "camera azimuth around +Z (overrides the view)"},
                {"--elevation", "DEG", "camera elevation, 90 = top (overrides the view)"},
                {"--size", "WxH", "image size (default 800x600)", {"--image-size"}},
                {"--wire", "", "draw the triangles' edges"},
                {"--tile", "W", "draw the borders of W x W tiles (in mesh units) over the mesh", {"--grid"}},
                {"--labels", "FILE",
                 "colour faces by polycube chart label (tessera polycube --labels-out: +X red, -X purple, "
                 "+Y green, -Y yellow, +Z blue, -Z cyan)"}},
    .run = run,
    .positional = "IN",
    .positional_options = {"--in"},
});

}  // namespace
