// tessera remesh --in IN --out OUT: isotropic remeshing of a closed mesh that keeps its creases
// (surface/remesh_isotropic.hpp), e.g. CAD output before `tessera polycube` or `geo-wang map`.
#include <cstdio>
#include <string>

#include <tessera/io/mesh_file.hpp>
#include <tessera/surface/remesh_isotropic.hpp>

#include "cli.hpp"

namespace {

int run(const cli::arguments& args) {
  using namespace tessera;
  if (!args.has("--in"))
    return cli::fail(args,
                     status::invalid_argument("expects one input mesh (IN or --in IN; see tessera remesh --help)"));
  auto out = args.required("--out");
  if (!out) return cli::fail(args, out.error());
  remesh_options o;
  auto edge = args.number("--edge", 0, 0);
  auto across = args.integer("--edges-across", o.edges_across, 1, 100000);
  auto angle = args.number("--feature-angle", o.feature_angle, 0, 180);
  auto rounds = args.integer("--iterations", o.iterations, 0, 100);
  if (!edge) return cli::fail(args, edge.error());
  if (!across) return cli::fail(args, across.error());
  if (!angle) return cli::fail(args, angle.error());
  if (!rounds) return cli::fail(args, rounds.error());
  if (args.has("--edge") && args.has("--edges-across"))
    return cli::fail(args, status::invalid_argument("give --edge or --edges-across, not both"));
  o.edge_length = *edge, o.edges_across = static_cast<int>(*across), o.feature_angle = *angle;
  o.iterations = static_cast<int>(*rounds);
  auto mesh = read_mesh(args.str("--in"));
  if (!mesh) return cli::fail(args, mesh.error());
  result<remesh_result> r = status::internal_error("not run");
  const double ms = cli::time_ms([&] { r = remesh_isotropic(*mesh, o); });
  if (!r) return cli::fail(args, r.error());
  if (auto s = write_mesh(*out, r->mesh); !s) return cli::fail(args, s);
  const remesh_stats& st = r->stats;
  if (args.stats())
    cli::json_line()
        .add("remesh_ms", ms)
        .add("faces_in", mesh->num_faces())
        .add("faces", r->mesh.num_faces())
        .add("edge_length", st.edge_length)
        .add("feature_edges", st.feature_edges)
        .add("splits", st.splits)
        .add("collapses", st.collapses)
        .add("flips", st.flips)
        .add("min_angle_input", st.min_angle_input)
        .add("min_angle", st.min_angle)
        .add("edge_length_rms", st.edge_length_rms)
        .add("max_deviation", st.max_deviation)
        .print();
  else
    std::printf("wrote %s (%td -> %td triangles, edge %.4g, smallest angle %.1f -> %.1f degrees)\n", out->c_str(),
                mesh->num_faces(), r->mesh.num_faces(), st.edge_length, st.min_angle_input, st.min_angle);
  return 0;
}

const cli::registrar reg({
    .name = "remesh",
    .summary = "isotropic remeshing of a closed mesh, creases kept (e.g. CAD output before polycube / geo-wang map)",
    .usage = "tessera remesh --in IN.(obj|off|ply) --out OUT [--edge L | --edges-across N] [options]",
    .options = {{"--in", "FILE", "closed, manifold, oriented triangle mesh (.obj, .off, .ply)", {"--mesh"}},
                {"--out", "FILE", "the remeshed mesh (.obj, .off, .ply)"},
                {"--edge", "L", "target edge length in mesh units"},
                {"--edges-across", "N", "target edges along the largest bounding-box side (default 64)"},
                {"--feature-angle", "DEG", "dihedral angle from which an edge is a crease that stays (default 40)"},
                {"--iterations", "K", "rounds of split, collapse, flip and relaxation (default 10)"}},
    .run = run,
    .positional = "IN",
    .positional_options = {"--in"},
    .shared = cli::shared_options::stats_only,
});

}  // namespace
