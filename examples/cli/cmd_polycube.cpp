// tessera polycube --in IN --out PC.obj: the polycube map of a closed triangle mesh
// (surface/build_polycube_map.hpp, paper 000 §4). PC.obj is the polycube-deformed mesh in the input's
// vertex and face order, unless the construction refined the base mesh (chords of the labelling split,
// `refined` true in --stats): then PC.obj follows the refined base, which --base-out writes (input
// vertices and faces first, new ones after).
#include <charconv>
#include <cstdio>
#include <map>
#include <string>

#include <tessera/core/mesh_topology.hpp>
#include <tessera/io/files.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/polycube_file.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_distortion.hpp>

#include "cli.hpp"

namespace {

/// Appends the shortest decimal that reads back as exactly `v` (what the library's OBJ writer writes).
template <class Number>
void append_number(std::string& out, Number v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

/// The quad layout as an OBJ quad mesh (corners shared between quads).
std::string quad_obj(const tessera::polycube_map& m) {
  using namespace tessera;
  std::map<grid_point, index_t> id;
  std::string v, f;
  for (const auto& q : m.layout.quads) {
    f += 'f';
    for (const auto& p : q.corners) {
      auto [it, fresh] = id.emplace(p, static_cast<index_t>(id.size()) + 1);
      if (fresh) {
        v += 'v';
        for (auto c : p) v += ' ', append_number(v, static_cast<double>(c) * m.tile_size);
        v += '\n';
      }
      f += ' ';
      append_number(f, it->second);
    }
    f += '\n';
  }
  return "# tessera polycube quad layout\n" + v + f;
}

int run(const cli::arguments& args) {
  using namespace tessera;
  auto in = args.required("--in");
  auto out = args.required("--out");
  if (!in) return cli::fail(args, in.error());
  if (!out) return cli::fail(args, out.error());
  if (args.has("--tile") && args.has("--tiles-across"))
    return cli::fail(args, status::invalid_argument("give --tile or --tiles-across, not both"));
  polycube_options o;
  auto tile = args.number("--tile", 0, 0);
  auto across = args.integer("--tiles-across", 8, 1, 100000);
  if (!tile) return cli::fail(args, tile.error());
  if (!across) return cli::fail(args, across.error());
  if (args.has("--tile") && !(*tile > 0))
    return cli::fail(args, status::invalid_argument("--tile expects a number > 0, got '" + args.str("--tile") + "'"));
  o.tile_size = *tile;
  o.tiles_across = static_cast<index_t>(*across);
  auto retries = args.integer("--distortion-retries", 0, 0, 5);
  if (!retries) return cli::fail(args, retries.error());
  o.distortion_retries = static_cast<int>(*retries);
  auto mesh = read_mesh(*in);
  if (!mesh) return cli::fail(args, mesh.error());
  result<std::vector<std::uint8_t>> labels_in = std::vector<std::uint8_t>{};
  if (args.has("--labels-in")) {
    labels_in = read_polycube_labels(args.str("--labels-in"));
    if (!labels_in) return cli::fail(args, labels_in.error());
  }
  thread_pool_executor pool(args.threads());
  result<polycube_map> r = status::internal_error("not run");
  const double ms = cli::median_ms(args.repeat(), [&] {
    r = args.has("--labels-in") ? build_polycube_map_from_labels(*mesh, *labels_in, o, pool)
                                : build_polycube_map(*mesh, o, pool);
  });
  if (!r) return cli::fail(args, r.error());
  // nothing is written unless the map is valid; then every output
  if (auto s = write_mesh(*out, r->deformed_mesh()); !s) return cli::fail(args, s);
  if (args.has("--base-out"))
    if (auto s = write_mesh(args.str("--base-out"), r->base); !s) return cli::fail(args, s);
  if (args.has("--labels-out"))
    if (auto s = write_polycube_labels(args.str("--labels-out"), r->labels); !s) return cli::fail(args, s);
  if (args.has("--quads-out"))
    if (auto s = write_file(args.str("--quads-out"), quad_obj(*r)); !s) return cli::fail(args, s);
  if (args.has("--map-out"))
    if (auto s = save_polycube_map(args.str("--map-out"), *r); !s) return cli::fail(args, s);
  if (args.stats()) {
    const auto d = polycube_distortion(*r);
    // genus of the (closed) base: V - E + F = 2 (components - genus), E = 3F / 2
    const index_t chi = r->base.num_vertices() - 3 * r->base.num_faces() / 2 + r->base.num_faces();
    const index_t genus = (2 * connected_components(r->base).count - chi) / 2;
    cli::json_line()
        .add("polycube_ms", ms)
        .add("faces", r->base.num_faces())
        .add("genus", genus)
        .add("tile", r->tile_size)
        .add("charts", static_cast<index_t>(r->charts.size()))
        .add("corners", static_cast<index_t>(r->corners.size()))
        .add("quads", static_cast<index_t>(r->layout.quads.size()))
        .add("flipped_faces", 0)
        .add("area_distortion", d.area_distortion)
        .add("angle_distortion", d.angle_distortion)
        .add("refined", r->refined())
        .add("valid", true)
        .print();
  } else {
    std::printf("wrote %s (%zu charts, %zu quads)\n", out->c_str(), r->charts.size(), r->layout.quads.size());
  }
  return 0;
}

const cli::registrar reg{[] {
  cli::command c{"polycube",
                 "polycube map of a closed triangle mesh, with its tile-grid quad layout (paper 000 §4)",
                 "tessera polycube --in IN.(obj|off|ply) --out PC.obj [--tile W | --tiles-across N] [options]",
                 {{"--in", "FILE", "closed, manifold, oriented triangle mesh (.obj, .off, .ply)", {"--mesh"}},
                  {"--out", "FILE", "polycube-deformed mesh, in the input's order (the refined base's when refined)"},
                  {"--tile", "W", "tile size in mesh units"},
                  {"--tiles-across", "N", "tiles across the largest bounding-box extent (default 8)"},
                  {"--distortion-retries", "N",
                   "after the first valid map, try N more labellings (0-5) and keep the least distorted"},
                  {"--labels-in", "FILE", "start from these face labels (one 0..5 per line: +X -X +Y -Y +Z -Z)"},
                  {"--labels-out", "FILE", "write the face labels"},
                  {"--quads-out", "FILE", "write the quad layout as an OBJ quad mesh"},
                  {"--base-out", "FILE", "write the base mesh PC.obj follows (the input, or its refinement)"},
                  {"--map-out", "FILE", "write the whole map (io/polycube_file.hpp)"}},
                 run};
  return c;
}()};

}  // namespace
