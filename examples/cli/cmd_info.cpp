// tessera info --in FILE (or info FILE): what an image or mesh file holds.
#include <cstdio>
#include <string>

#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/io/files.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"

namespace {

const char* channel_names(int c) {
  static const char* names[5] = {"?", "grey", "grey + alpha", "RGB", "RGBA"};
  return c >= 1 && c <= 4 ? names[c] : names[0];
}

std::string json_vec(tessera::vec3 v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%.9g,%.9g,%.9g]", v.x, v.y, v.z);
  return buf;
}

int info_image(const cli::arguments& args, const std::string& path) {
  tessera::result<tessera::png_info> read = tessera::status::internal_error("not read");
  const double ms = cli::time_ms([&] { read = tessera::read_png_info(path); });
  if (!read) return cli::fail(args, read.error());
  const tessera::png_info& info = *read;
  if (args.stats()) {
    cli::json_line()
        .add("file", path)
        .add("kind", "image")
        .add("format", "png")
        .add("width", info.width)
        .add("height", info.height)
        .add("channels", info.channels)
        .add("bit_depth", info.bit_depth)
        .add("file_bit_depth", info.file_bit_depth)
        .add("palette", info.palette)
        .add("interlaced", info.interlaced)
        .add("read_ms", ms)
        .print();
    return 0;
  }
  std::printf("%s: PNG image\n", path.c_str());
  std::printf("  size        %td x %td\n", info.width, info.height);
  std::printf("  channels    %d (%s)\n", info.channels, channel_names(info.channels));
  std::printf("  bit depth   %d", info.bit_depth);
  if (info.file_bit_depth != info.bit_depth || info.palette)
    std::printf(" (stored as %d-bit%s)", info.file_bit_depth, info.palette ? " palette indices" : "");
  std::printf("\n");
  if (info.interlaced) std::printf("  interlaced  yes (Adam7)\n");
  return 0;
}

int info_mesh(const cli::arguments& args, const std::string& path) {
  tessera::result<tessera::tri_mesh> mesh = tessera::status::internal_error("not read");
  const double ms = cli::time_ms([&] { mesh = tessera::read_mesh(path); });
  if (!mesh) return cli::fail(args, mesh.error());
  const tessera::tri_mesh& m = *mesh;
  const auto adjacency = tessera::face_adjacency(m);
  const auto components = tessera::connected_components(m);
  const auto box = tessera::bounding_box(m);
  const auto format = *tessera::mesh_format_of(path);
  if (args.stats()) {
    cli::json_line()
        .add("file", path)
        .add("kind", "mesh")
        .add("format", tessera::to_string(format))
        .add("vertices", m.num_vertices())
        .add("faces", m.num_faces())
        .add("components", components.count)
        .add("boundary_edges", adjacency.boundary_edges)
        .add("nonmanifold_edges", adjacency.nonmanifold_edges)
        .raw("bbox_min", box.empty() ? "null" : json_vec(box.min))
        .raw("bbox_max", box.empty() ? "null" : json_vec(box.max))
        .add("has_uvs", m.has_uvs())
        .add("read_ms", ms)
        .print();
    return 0;
  }
  std::string fmt(tessera::to_string(format));
  for (char& c : fmt) c = static_cast<char>(c - 'a' + 'A');
  std::printf("%s: %s mesh\n", path.c_str(), fmt.c_str());
  std::printf("  vertices            %td\n", m.num_vertices());
  std::printf("  faces               %td triangles\n", m.num_faces());
  std::printf("  components          %td\n", components.count);
  std::printf("  boundary edges      %td%s\n", adjacency.boundary_edges,
              m.num_faces() > 0 && adjacency.boundary_edges == 0 ? " (closed)" : "");
  std::printf("  non-manifold edges  %td\n", adjacency.nonmanifold_edges);
  if (box.empty())
    std::printf("  bounding box        (empty)\n");
  else
    std::printf("  bounding box        (%.6g, %.6g, %.6g) - (%.6g, %.6g, %.6g)\n", box.min.x, box.min.y, box.min.z,
                box.max.x, box.max.y, box.max.z);
  std::printf("  uvs                 %s\n", m.has_uvs() ? "yes (per corner)" : "no");
  return 0;
}

int run_info(const cli::arguments& args) {
  if (!args.has("--in"))
    return cli::fail(
        args, tessera::status::invalid_argument("expects exactly one FILE (or --in FILE; see tessera info --help)"));
  const std::string path = args.str("--in");
  if (tessera::file_extension(path) == "png") return info_image(args, path);
  if (tessera::is_mesh_path(path)) return info_mesh(args, path);
  return cli::fail(args,
                   tessera::status::unsupported(path + ": unknown file type (expected .png, .obj, .off or .ply)"));
}

const cli::registrar reg({
    .name = "info",
    .summary = "print what an image (PNG) or mesh (OBJ, OFF, PLY) file holds",
    .usage = "tessera info --in FILE [--stats]",
    .options = {{"--in", "FILE", "the PNG or mesh file (or FILE as the argument)"},
                {"--stats", "", "print one JSON line with the same figures instead of text"}},
    .run = run_info,
    .positional = "FILE",
    .positional_options = {"--in"},
    .shared = cli::shared_options::stats_only,
});

}  // namespace
