// tessera mesh-quilt --exemplar E.obj --size WxH --out O.obj: mesh quilting of a larger geometric
// texture (geometry/mesh_quilt.hpp). Mesh quilting is the subject of US patent US7800627B2.
#include <string>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/io/mesh_file.hpp>

#include "cli.hpp"
#include "quality_stats.hpp"

namespace {

int run(const cli::arguments& args) {
  using namespace tessera;
  auto in = args.required("--exemplar");
  auto out = args.required("--out");
  if (!in) return cli::fail(args, in.error());
  if (!out) return cli::fail(args, out.error());
  auto size = args.extent("--size", 1e6);  // WxH in exemplar units; the older X,Y is an alias
  if (!size) return cli::fail(args, size.error());
  auto lambda = args.number("--lambda", 1.0, 0, 1e6);
  if (!lambda) return cli::fail(args, lambda.error());
  auto ex_mesh = read_mesh(*in);
  if (!ex_mesh) return cli::fail(args, ex_mesh.error());
  auto ex = prepare_quilt_exemplar(*ex_mesh);
  if (!ex) return cli::fail(args, ex.error());
  mesh_quilt_options o;
  o.seed = args.seed();
  o.lambda = *lambda;
  o.fill_holes = !args.has("--no-fill-holes");
  o.fill_relax = !args.has("--no-fill-relax");
  o.fill_replace = !args.has("--no-fill-replace");
  thread_pool_executor pool(args.threads());
  result<mesh_quilt_result> r = status::internal_error("not run");
  const double ms = cli::median_ms(args.repeat(), [&] { r = mesh_quilt(*ex, size->first, size->second, o, pool); });
  if (!r) return cli::fail(args, r.error());
  if (auto s = write_mesh(*out, r->mesh); !s) return cli::fail(args, s);
  if (args.stats()) {
    const auto rep = check_geometric_texture(r->mesh);
    if (!rep) return cli::fail(args, rep.error());
    const auto quality = compare_texture_quality(*ex_mesh, r->mesh, {0, 0, size->first, size->second});
    if (!quality) return cli::fail(args, quality.error());
    cli::json_line line;
    line.add("quilt_ms", ms)
        .add("vertices", r->mesh.num_vertices())
        .add("faces", r->mesh.num_faces())
        .add("elements", rep->elements)
        .add("patches", r->stats.patches)
        .add("elements_added", r->stats.elements_added)
        .add("elements_merged", r->stats.elements_merged)
        .add("elements_dropped", r->stats.elements_dropped)
        .add("elements_filled", r->stats.elements_filled)
        .add("elements_relaxed", r->stats.elements_relaxed)
        .add("elements_replaced", r->stats.elements_replaced)
        .add("merges_attempted", r->stats.merges_attempted)
        .add("merges_succeeded", r->stats.merges_succeeded)
        .add("merge_fail_correspondence", r->stats.merge_fail_correspondence)
        .add("merge_fail_deform", r->stats.merge_fail_deform)
        .add("merge_fail_cut", r->stats.merge_fail_cut)
        .add("merge_fail_loops", r->stats.merge_fail_loops)
        .add("merge_fail_check", r->stats.merge_fail_check)
        .add("merges_plane_cut", r->stats.merges_plane_cut)
        .add("icp_iterations", r->stats.icp_iterations)
        .add("icp_discarded", r->stats.icp_discarded)
        .add("open_edges_inside", rep->open_edges_inside)
        .add("nonmanifold_edges", rep->nonmanifold_edges)
        .add("intersecting_pairs", rep->intersecting_pairs);
    cli::add_quality(line, *quality, false);
    line.print();
  } else {
    std::printf("wrote %s (%lld vertices, %zu elements)\n", out->c_str(),
                static_cast<long long>(r->mesh.num_vertices()), r->elements.size());
  }
  return 0;
}

const cli::registrar reg{[] {
  cli::command c{
      "mesh-quilt",
      "grow a larger geometric texture from an exemplar mesh (mesh quilting)",
      "tessera mesh-quilt --exemplar E.obj --size WxH --out O.obj [options]",
      {{"--exemplar", "FILE", "exemplar mesh of closed elements (.obj, .off, .ply)"},
       {"--size", "WxH", "output extent in exemplar units (W alone: W x W; the older X,Y is accepted)"},
       {"--out", "FILE", "output mesh"},
       {"--lambda", "L", "weight of the normal term of the matching cost (default 1)"},
       {"--no-fill-holes", "", "leave the holes where elements were dropped (no single-element filling)"},
       {"--no-fill-relax", "",
        "fill holes as they stand until the covered area is reached (no size classes, no neighbours moved)"},
       {"--no-fill-replace", "", "filling only adds: no small elements replaced by one of the largest size class"}},
      run};
  return c;
}()};

}  // namespace
