// tessera exemplar --kind rings|stones|weave --out E.obj: procedural geometric-texture exemplars
// (geometry/mesh_exemplars.hpp) for mesh quilting and geometric Wang tiles.
#include <string>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/io/mesh_file.hpp>

#include "cli.hpp"

namespace {

int run(const cli::arguments& args) {
  using namespace tessera;
  if (!args.has("--kind"))
    return cli::fail(
        args, status::invalid_argument("expects one kind: rings, stones or weave (see tessera exemplar --help)"));
  const std::string kind = args.str("--kind");
  auto out = args.required("--out");
  if (!out) return cli::fail(args, out.error());
  // --size L, or LxL (the one size vocabulary; the exemplar is square)
  auto size = args.number("--size", 8.0, 0.5, 256);
  if (args.str("--size").find('x') != std::string::npos) {
    auto e = args.extent("--size", 256);
    if (!e) return cli::fail(args, e.error());
    if (e->first != e->second || e->first < 0.5)
      return cli::fail(args, status::invalid_argument("--size expects L or LxL with L in [0.5, 256], got '" +
                                                      args.str("--size") + "'"));
    size = e->first;
  }
  auto density = args.number("--density", 1.0, 1.0 / 16, 16);
  auto detail_level = args.integer("--segments", 0, 0, 256);
  if (!size) return cli::fail(args, size.error());
  if (!density) return cli::fail(args, density.error());
  if (!detail_level) return cli::fail(args, detail_level.error());
  const int seg = static_cast<int>(*detail_level);
  result<tri_mesh> mesh = status::invalid_argument("unknown exemplar kind '" + kind + "' (rings, stones or weave)");
  const double ms = cli::median_ms(args.repeat(), [&] {
    if (kind == "rings") {
      ring_exemplar_options o{.size = *size, .chain_mail = args.has("--chain-mail"), .seed = args.seed()};
      o.spacing /= std::sqrt(*density);
      if (o.chain_mail) o.minor_radius = 0.08;
      if (seg > 0) o.ring_segments = seg, o.tube_segments = std::max(3, seg / 3);
      mesh = make_ring_exemplar(o);
    } else if (kind == "stones") {
      stone_exemplar_options o{.size = *size, .coverage = std::min(0.9, 0.55 * *density), .seed = args.seed()};
      if (seg > 0) o.subdivisions = seg;
      mesh = make_stone_exemplar(o);
    } else if (kind == "weave") {
      weave_exemplar_options o{.size = *size, .spacing = 1.0 / *density, .seed = args.seed()};
      if (seg > 0) o.segments_per_spacing = seg, o.around = std::max(4, seg);
      mesh = make_weave_exemplar(o);
    }
  });
  if (!mesh) return cli::fail(args, mesh.error());
  if (auto s = write_mesh(*out, *mesh); !s) return cli::fail(args, s);
  if (args.stats()) {
    const auto rep = check_geometric_texture(*mesh);
    if (!rep) return cli::fail(args, rep.error());
    cli::json_line()
        .add("kind", kind)
        .add("generate_ms", ms)
        .add("vertices", mesh->num_vertices())
        .add("faces", mesh->num_faces())
        .add("elements", rep->elements)
        .add("open_edges_inside", rep->open_edges_inside)
        .add("nonmanifold_edges", rep->nonmanifold_edges)
        .add("intersecting_pairs", rep->intersecting_pairs)
        .print();
  } else {
    std::printf("wrote %s (%lld vertices, %lld faces)\n", out->c_str(), static_cast<long long>(mesh->num_vertices()),
                static_cast<long long>(mesh->num_faces()));
  }
  return 0;
}

const cli::registrar reg{[] {
  cli::command c{
      "exemplar",
      "generate a geometric-texture exemplar mesh (rings, stones, weave)",
      "tessera exemplar --kind rings|stones|weave --out E.obj [--seed S] [--size L] [--density D] [--segments N] "
      "[--chain-mail]",
      {{"--kind", "KIND", "rings, stones or weave (or KIND as the argument)"},
       {"--out", "FILE", "output mesh (.obj, .off or .ply)"},
       {"--size", "L", "the exemplar covers [0, L]^2, L in [0.5, 256] (default 8; LxL also accepted)"},
       {"--density", "D", "relative element density (default 1)"},
       {"--segments", "N", "mesh resolution: ring segments / stone subdivisions / thread segments (0 = default)"},
       {"--chain-mail", "", "rings: interlock them like European 4-in-1 chain mail"}},
      run,
      "KIND",
      {"--kind"}};
  return c;
}()};

}  // namespace
