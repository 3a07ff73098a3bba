// tessera geo-wang build / geo-wang tile / geo-wang map: geometric-texture Wang tiles (paper 000 §3-4):
// build a complete planar set (--colors NH,NV) or three-axis set for polycube surfaces (--colors
// NX,NY,NZ, §3.1 and §5) from an exemplar mesh, tile a plane from a tile set directory (one face's tiles
// of a three-axis set), and cover a closed mesh with a three-axis set through its polycube map and a
// shell map (§4, surface/map_geometric_tiles.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <tessera/core/mesh_topology.hpp>
#include <tessera/geometry/bvh.hpp>
#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/io/geometric_tiles.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/polycube_file.hpp>
#include <tessera/surface/map_geometric_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/periodic_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include "cli.hpp"
#include "mesh_boolean.hpp"
#include "quality_stats.hpp"

namespace {

int build(const cli::arguments& args) {
  using namespace tessera;
  auto in = args.required("--exemplar");
  auto dir = args.required("--out");
  if (!in) return cli::fail(args, in.error());
  if (!dir) return cli::fail(args, dir.error());
  if (!args.has("--tile")) return cli::fail(args, cli::arguments::missing("--tile"));
  auto colors = args.color_counts("--colors", max_wang_colors);
  auto tile = args.number("--tile", 0, 0, 1e6);
  auto edge = args.number("--edge-height", 0, 0, 1e6);
  if (!colors) return cli::fail(args, colors.error());
  if (!tile) return cli::fail(args, tile.error());
  if (!edge) return cli::fail(args, edge.error());
  auto ex_mesh = read_mesh(*in);
  if (!ex_mesh) return cli::fail(args, ex_mesh.error());
  auto ex = prepare_quilt_exemplar(*ex_mesh);
  if (!ex) return cli::fail(args, ex.error());
  geometric_wang_options o;
  if (colors->size() == 3) {
    o.axis_colors = {(*colors)[0], (*colors)[1], (*colors)[2]};
  } else {
    o.horizontal_colors = (*colors)[0];
    o.vertical_colors = (*colors)[1];
  }
  o.tile_size = *tile;
  o.edge_height = *edge;
  o.quilt.seed = args.seed();
  o.quilt.fill_holes = !args.has("--no-fill-holes");
  o.quilt.fill_relax = !args.has("--no-fill-relax");
  o.quilt.fill_replace = !args.has("--no-fill-replace");
  thread_pool_executor pool(args.threads());
  result<geometric_tile_set> set = status::internal_error("not run");
  const double ms = cli::median_ms(args.repeat(), [&] { set = build_geometric_wang_tiles(*ex, o, pool); });
  if (!set) return cli::fail(args, set.error());
  if (auto s = save_geometric_tile_set(*dir, *set); !s) return cli::fail(args, s);
  if (args.stats()) {
    geometric_texture_report sum;
    for (const auto& t : set->tiles) {
      const auto rep = check_geometric_texture(t, {0, 0, set->tile_size, set->tile_size});
      if (!rep) return cli::fail(args, rep.error());
      sum.open_edges_inside += rep->open_edges_inside;
      sum.nonmanifold_edges += rep->nonmanifold_edges;
      sum.intersecting_pairs += rep->intersecting_pairs;
      sum.elements += rep->elements;
    }
    const auto mismatch = tile_set_border_mismatch(*set);
    // likeness: a sample plane of 6 x 6 tiles (hash colouring of --seed) against the exemplar; for a
    // three-axis set, of its +Z tiles
    auto planar = set->three_axis() ? face_tile_set(*set, 4) : result<geometric_tile_set>(*set);
    if (!planar) return cli::fail(args, planar.error());
    const auto edges = tile_set_edges::create(planar->horizontal_colors, planar->vertical_colors, planar->edges);
    if (!edges) return cli::fail(args, edges.error());
    const auto hash = hash_coloring::for_set(*edges, args.seed());
    if (!hash) return cli::fail(args, hash.error());
    const auto window = hash->window(0, 0, 6, 6);
    if (!window) return cli::fail(args, window.error());
    const auto sample = tile_geometric_plane(*planar, *window, 6, 6, pool);
    if (!sample) return cli::fail(args, sample.error());
    const double w = set->tile_size;
    const auto quality = compare_texture_quality(*ex_mesh, *sample, {0, 0, 6 * w, 6 * w}, {.tile_size = w});
    if (!quality) return cli::fail(args, quality.error());
    cli::json_line line;
    line.add("build_ms", ms)
        .add("tiles", static_cast<index_t>(set->tiles.size()))
        .add("three_axis", set->three_axis())
        .add("ms_per_tile", ms / double(set->tiles.size()))
        .add("tile_size", set->tile_size)
        .add("edge_height", set->edge_height)
        .add("crossing_elements", set->crossing_elements)
        .add("quilted_source", set->quilted_source)
        .add("elements", sum.elements)
        .add("merges_succeeded", set->stats.merges_succeeded)
        .add("merges_attempted", set->stats.merges_attempted)
        .add("elements_merged", set->stats.elements_merged)
        .add("elements_dropped", set->stats.elements_dropped)
        .add("elements_filled", set->stats.elements_filled)
        .add("elements_relaxed", set->stats.elements_relaxed)
        .add("elements_replaced", set->stats.elements_replaced)
        .add("frame_merges_attempted", set->frame_merges_attempted)
        .add("frame_merged", set->frame_merged)
        .add("frame_dropped", set->frame_dropped)
        .add("merge_fail_correspondence", set->stats.merge_fail_correspondence)
        .add("merge_fail_deform", set->stats.merge_fail_deform)
        .add("merge_fail_cut", set->stats.merge_fail_cut)
        .add("merge_fail_loops", set->stats.merge_fail_loops)
        .add("merge_fail_check", set->stats.merge_fail_check)
        .add("merges_plane_cut", set->stats.merges_plane_cut)
        .add("open_edges_inside", sum.open_edges_inside)
        .add("nonmanifold_edges", sum.nonmanifold_edges)
        .add("intersecting_pairs", sum.intersecting_pairs)
        .add("corner_crossings", tile_set_corner_crossings(*set))
        .add("border_mismatch", mismatch ? *mismatch : index_t{-1});
    cli::add_quality(line, *quality, true);
    line.print();
  } else {
    std::printf("wrote %zu tiles to %s\n", set->tiles.size(), dir->c_str());
  }
  return 0;
}

int tile(const cli::arguments& args) {
  using namespace tessera;
  auto dir = args.required("--tiles");
  auto out = args.required("--out");
  if (!dir) return cli::fail(args, dir.error());
  if (!out) return cli::fail(args, out.error());
  // a plane of 2^20 tiles already has tens of millions of vertices: refused before the coloring
  // (hash colouring stores every cell) is allocated
  auto grid = args.size("--grid", 4096, index_t{1} << 20);
  if (!grid) return cli::fail(args, grid.error());
  const index_t cols = grid->first, rows = grid->second;  // not a structured binding: a lambda captures them
  auto kind = args.choice("--coloring", {"hash", "scanline", "periodic"});
  if (!kind) return cli::fail(args, kind.error());
  auto period = args.integer("--period", 4, 1, 8192);
  if (!period) return cli::fail(args, period.error());
  auto face = args.choice("--face", {"+Z", "-Z", "+X", "-X", "+Y", "-Y"});
  if (!face) return cli::fail(args, face.error());
  auto set = load_geometric_tile_set(*dir);
  if (!set) return cli::fail(args, set.error());
  if (set->three_axis()) {  // a plane of the tiles of one face
    int f = 0;
    while (cube_face_name(f) != *face) ++f;
    set = face_tile_set(*set, f);
    if (!set) return cli::fail(args, set.error());
  }
  auto edges = tile_set_edges::create(set->horizontal_colors, set->vertical_colors, set->edges);
  if (!edges) return cli::fail(args, edges.error());
  stored_tile_coloring coloring;
  if (*kind == "hash") {
    auto h = hash_coloring::for_set(*edges, args.seed());
    if (!h) return cli::fail(args, h.error());
    auto w = h->window(0, 0, cols, rows);
    if (!w) return cli::fail(args, w.error());
    coloring = store_coloring(*w);
  } else if (*kind == "scanline") {
    auto s = scanline_coloring::create(*edges, cols, rows, args.seed());
    if (!s) return cli::fail(args, s.error());
    coloring = store_coloring(*s);
  } else {
    auto p = periodic_coloring::create(*edges, *period, *period, cols, rows, args.seed());
    if (!p) return cli::fail(args, p.error());
    coloring = store_coloring(*p);
  }
  thread_pool_executor pool(args.threads());
  result<tri_mesh> plane = status::internal_error("not run");
  const double ms =
      cli::median_ms(args.repeat(), [&] { plane = tile_geometric_plane(*set, coloring, cols, rows, pool); });
  if (!plane) return cli::fail(args, plane.error());
  if (auto s = write_mesh(*out, *plane); !s) return cli::fail(args, s);
  if (args.stats()) {
    const double w = set->tile_size;
    const auto rep = check_geometric_texture(*plane, {0, 0, double(cols) * w, double(rows) * w});
    if (!rep) return cli::fail(args, rep.error());
    const auto mismatch = tile_set_border_mismatch(*set);
    cli::json_line line;
    line.add("tiling_ms", ms)
        .add("tiles", cols * rows)
        .add("vertices", plane->num_vertices())
        .add("faces", plane->num_faces())
        .add("elements", rep->elements)
        .add("open_edges_inside", rep->open_edges_inside)
        .add("nonmanifold_edges", rep->nonmanifold_edges)
        .add("intersecting_pairs", rep->intersecting_pairs)
        .add("corner_crossings", tile_set_corner_crossings(*set))
        .add("border_mismatch", mismatch ? *mismatch : index_t{-1});
    if (args.has("--exemplar")) {  // likeness against the exemplar the set was built from
      auto ex_mesh = read_mesh(args.str("--exemplar"));
      if (!ex_mesh) return cli::fail(args, ex_mesh.error());
      const auto quality =
          compare_texture_quality(*ex_mesh, *plane, {0, 0, double(cols) * w, double(rows) * w}, {.tile_size = w});
      if (!quality) return cli::fail(args, quality.error());
      cli::add_quality(line, *quality, true);
    }
    line.print();
  } else {
    std::printf("wrote %s (%lld x %lld tiles, %lld vertices)\n", out->c_str(), static_cast<long long>(cols),
                static_cast<long long>(rows), static_cast<long long>(plane->num_vertices()));
  }
  return 0;
}

/// The coarsest grid a polycube-deformed mesh's chart planes lie on: the greatest common divisor (to a
/// relative 1e-7) of the plane coordinates of its axis-aligned faces, from `deformed` alone.
tessera::result<double> polycube_grid(const tessera::tri_mesh& deformed) {
  using namespace tessera;
  const aabb box = bounding_box(deformed);
  const double extent = std::max({box.extent().x, box.extent().y, box.extent().z}), tol = 1e-7 * extent;
  if (!(extent > 0)) return status::invalid_argument("--polycube: the polycube mesh is empty or flat");
  double g = 0;
  auto gcd = [tol](double a, double b) {
    a = std::abs(a), b = std::abs(b);
    if (a < b) std::swap(a, b);
    while (b > tol) {
      double r = std::fmod(a, b);
      if (r > b - tol) r = 0;
      a = b;
      b = r;
    }
    return a;
  };
  for (const auto& f : deformed.faces) {
    const vec3 n =
        cross(deformed.position(f[1]) - deformed.position(f[0]), deformed.position(f[2]) - deformed.position(f[0]));
    const vec3 a{std::abs(n.x), std::abs(n.y), std::abs(n.z)};
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    const double plane = deformed.position(f[0])[axis];
    if (std::abs(plane) > tol) g = g > 0 ? gcd(g, plane) : std::abs(plane);
  }
  if (!(g > 4 * tol))
    return status::invalid_argument("--polycube: cannot find the tile grid of the polycube mesh; give --tile W");
  return g;
}

int map(const cli::arguments& args) {
  using namespace tessera;
  // --boolean: the elements joined with (union), engraved into (difference) or cut by (intersection)
  // the base, sunk into it by --sink (default 0.1 for a union, 0.5 otherwise) so that they overlap it
  std::string boolean;
  if (args.has("--boolean")) {
    auto op = args.choice("--boolean", {"union", "difference", "intersection"});
    if (!op) return cli::fail(args, op.error());
    if (!cli::has_mesh_boolean()) return cli::fail(args, cli::mesh_boolean(tri_mesh{}, tri_mesh{}, *op).error());
    if (args.has("--with-base"))
      return cli::fail(args, status::invalid_argument("give --with-base or --boolean, not both (a Boolean's output "
                                                      "holds the base already)"));
    boolean = *op;
  }
  auto sink = args.number("--sink", boolean.empty() ? 0.0 : boolean == "union" ? 0.1 : 0.5, 0, 0.95);
  if (!sink) return cli::fail(args, sink.error());
  auto dir = args.required("--tiles");
  auto in = args.required("--mesh");
  auto out = args.required("--out");
  if (!dir) return cli::fail(args, dir.error());
  if (!in) return cli::fail(args, in.error());
  if (!out) return cli::fail(args, out.error());
  auto tile = args.number("--tile", 0, 0, 1e12);
  auto across = args.integer("--tiles-across", 8, 1, 100000);
  auto height = args.number("--height", 0, 0, 1e12);
  if (!tile) return cli::fail(args, tile.error());
  if (!across) return cli::fail(args, across.error());
  if (!height) return cli::fail(args, height.error());
  if (args.has("--tile") && !(*tile > 0))
    return cli::fail(args, status::invalid_argument("--tile expects a number > 0, got '" + args.str("--tile") + "'"));
  if (args.has("--height") && !(*height > 0))
    return cli::fail(args,
                     status::invalid_argument("--height expects a number > 0, got '" + args.str("--height") + "'"));
  if (args.has("--tile") && args.has("--tiles-across"))
    return cli::fail(args, status::invalid_argument("give --tile or --tiles-across, not both"));
  if (args.has("--polycube") && args.has("--tiles-across"))
    return cli::fail(args, status::invalid_argument("give --polycube or --tiles-across, not both"));
  auto set = load_geometric_tile_set(*dir);
  if (!set) return cli::fail(args, set.error());
  if (!set->three_axis())
    return cli::fail(args,
                     status::invalid_argument(
                         "--tiles: " + *dir +
                         " holds a planar set; a surface needs a three-axis set (geo-wang build --colors NX,NY,NZ)"));
  auto mesh = read_mesh(*in);
  if (!mesh) return cli::fail(args, mesh.error());
  thread_pool_executor pool(args.threads());
  // the polycube map: a saved map (.polycube), a polycube-deformed copy of the mesh, or built here
  result<polycube_map> pc = status::internal_error("not run");
  const double pc_ms = cli::median_ms(1, [&] {
    if (!args.has("--polycube")) {
      polycube_options po;
      po.tile_size = *tile;
      po.tiles_across = static_cast<index_t>(*across);
      pc = build_polycube_map(*mesh, po, pool);
      return;
    }
    const std::string path = args.str("--polycube");
    if (path.size() > 9 && path.substr(path.size() - 9) == ".polycube") {
      pc = load_polycube_map(path);
      if (pc && args.has("--tile") && std::abs(pc->tile_size - *tile) > 1e-12 * *tile)
        pc = status::invalid_argument("--tile " + args.str("--tile") + " differs from the tile size of " + path);
      return;
    }
    auto deformed = read_mesh(path);
    if (!deformed) {
      pc = deformed.error();
      return;
    }
    auto w = args.has("--tile") ? result<double>(*tile) : polycube_grid(*deformed);
    if (!w) {
      pc = w.error();
      return;
    }
    pc = polycube_map_from_deformed(*mesh, *deformed, *w, pool);
  });
  if (!pc) return cli::fail(args, pc.error());
  map_geometric_tiles_options o;
  o.height = *height;
  o.seed = args.seed();
  o.with_base = args.has("--with-base");
  o.shell.sink = *sink;
  if (args.has("--clip")) {  // midpoint when absent
    auto clip = args.choice("--clip", {"exact", "midpoint"});
    if (!clip) return cli::fail(args, clip.error());
    o.mapping.clip = *clip == "exact" ? shell_clip::exact : shell_clip::midpoint;
  }
  result<map_geometric_tiles_result> r = status::internal_error("not run");
  const double ms = cli::median_ms(args.repeat(), [&] { r = map_geometric_tiles(*mesh, *pc, *set, o, pool); });
  if (!r) return cli::fail(args, r.error());
  result<tri_mesh> joined = status::internal_error("not run");
  double boolean_ms = 0;
  if (!boolean.empty()) {
    const tri_mesh elements = r->elements();
    boolean_ms = cli::median_ms(1, [&] { joined = cli::mesh_boolean(pc->base, elements, boolean); });
    if (!joined) return cli::fail(args, joined.error());
  }
  if (auto s = write_mesh(*out, boolean.empty() ? r->mesh : *joined); !s) return cli::fail(args, s);
  if (args.stats()) {
    const tri_mesh elements = r->elements();
    const triangle_bvh base(pc->base);
    std::vector<double> dist(elements.positions.size());
    pool.parallel_for(0, elements.num_vertices(), [&](index_t v) {
      dist[static_cast<std::size_t>(v)] = std::sqrt(base.closest_point(elements.position(v)).squared_distance);
    });
    const double worst = dist.empty() ? 0.0 : *std::max_element(dist.begin(), dist.end());
    cli::json_line()
        .add("map_ms", ms)
        .add("height", r->height)
        .add("height_lowered", r->height_lowered)
        .add("quads", static_cast<index_t>(pc->layout.quads.size()))
        .add("tiles_used", r->tiling.tiles_used)
        .add("vertices", r->mesh.num_vertices())
        .add("faces", r->mesh.num_faces())
        .add("elements", connected_components(elements).count)
        .add("open_edges", static_cast<index_t>(boundary_edges(elements).size()))
        .add("shell_repairs", r->shell_repairs)
        .add("max_offset", worst / r->height)
        .add("polycube_ms", pc_ms)
        .add("tile", r->tile_size)
        .add("refined", pc->refined())
        .add("welded_vertices", r->welded_vertices)
        .add("split_edges", r->split_edges)
        .add("sink", o.shell.sink)
        .add("boolean_ms", boolean_ms)
        .add("boolean_faces", boolean.empty() ? index_t{0} : joined->num_faces())
        .print();
  } else {
    std::printf("wrote %s (%zu quads, %lld tiles used, %lld element faces, H = %g)\n", out->c_str(),
                pc->layout.quads.size(), static_cast<long long>(r->tiling.tiles_used),
                static_cast<long long>(r->element_faces), r->height);
    if (r->height_lowered > 0)
      std::printf("note: the shell folds at the tiles' own height %g; H lowered to %g (%g^%d)\n",
                  r->height / std::pow(auto_height_step, r->height_lowered), r->height, auto_height_step,
                  r->height_lowered);
  }
  return 0;
}

const cli::registrar reg_build{[] {
  cli::command c{
      "geo-wang build",
      "build a complete set of geometric-texture Wang tiles (planar or three-axis) from an exemplar mesh",
      "tessera geo-wang build --exemplar E.obj --tile W --out DIR [--colors NH,NV | NX,NY,NZ] [options]",
      {{"--exemplar", "FILE", "exemplar mesh of closed elements"},
       {"--colors", "NH,NV|NX,NY,NZ",
        "two counts: a planar set, colours of horizontal (north/south) and vertical (east/west) "
        "edges; three: a three-axis set for polycube surfaces (2(nX^2nY^2+nX^2nZ^2+nY^2nZ^2) tiles), "
        "colours of edges along X, Y, Z; 1 to 4096 each (default 2,2)"},
       {"--tile", "W", "tile size in exemplar units"},
       {"--edge-height", "H", "edge strip height h_E (default 1.5 x element size)"},
       {"--no-fill-holes", "", "leave the holes where elements were dropped (no single-element filling)"},
       {"--no-fill-relax", "",
        "fill holes as they stand until the covered area is reached (no size classes, no neighbours moved)"},
       {"--no-fill-replace", "", "filling only adds: no small elements replaced by one of the largest size class"},
       {"--out", "DIR", "output directory: tile_<index>.obj and tiles.json"}},
      build};
  return c;
}()};

const cli::registrar reg_tile{[] {
  cli::command c{
      "geo-wang tile",
      "tile a plane from a geometric Wang tile set into one welded mesh",
      "tessera geo-wang tile --tiles DIR --grid COLSxROWS --out O.obj [--seed S] [--coloring hash|scanline|periodic]",
      {{"--tiles", "DIR", "tile set directory (tiles.json + OBJ tiles)"},
       {"--grid", "COLSxROWS", "number of tiles, at most 4096 a side and 2^20 in all"},
       {"--coloring", "KIND", "hash (default; O(1) per cell), scanline (Cohen) or periodic edge colouring"},
       {"--period", "N", "period in tiles of --coloring periodic (default 4)"},
       {"--face", "F", "three-axis sets: tile the plane with the tiles of face +Z (default), -Z, +X, -X, +Y or -Y"},
       {"--exemplar", "FILE", "with --stats: the exemplar the set was built from, for the likeness figures"},
       {"--out", "FILE", "output mesh"}},
      tile};
  return c;
}()};

const cli::registrar reg_map{[] {
  cli::command c{
      "geo-wang map",
      "cover a closed mesh with a three-axis geometric Wang tile set (polycube map + shell map, paper 000 §4)",
      "tessera geo-wang map --tiles SET --mesh BASE --out OUT.obj [--polycube PC.obj | --tile W] [--height H] "
      "[--with-base | --boolean union|difference|intersection] [--sink S] [--clip exact|midpoint] [--seed S] "
      "[--threads T] [--stats]",
      {{"--tiles", "DIR", "three-axis tile set directory (geo-wang build --colors NX,NY,NZ)"},
       {"--clip", "MODE",
        "midpoint (default): split tile edges until the shell is followed within a tolerance; exact: clip "
        "tile triangles at the shell's tetrahedra (no crossing faces, 2.6-5x the faces, 7.5-15x the time)"},
       {"--mesh", "FILE", "closed, manifold, outward-oriented base mesh (.obj, .off, .ply)"},
       {"--out", "FILE", "output mesh: the texture elements (then the base with --with-base)"},
       {"--polycube", "FILE",
        "use this polycube: a map file (.polycube, tessera polycube --map-out) or the polycube-deformed mesh "
        "(tessera polycube --out; its grid from --tile W, else the coarsest grid its planes lie on)"},
       {"--tile", "W", "quad size in base-mesh units (builds the polycube map; default: 8 tiles across)"},
       {"--tiles-across", "N", "build the polycube map with N tiles across the largest extent (default 8)"},
       {"--height", "H",
        "shell height in base-mesh units (default: the tiles' own proportions, lowered where the shell folds)"},
       {"--with-base", "", "append the base mesh to the output"},
       {"--boolean", "OP",
        "union (one solid, e.g. for 3D printing), difference (the elements engraved into the base) or "
        "intersection of the base and the elements (CGAL's corefinement; needs a build with CGAL, then GPL; the "
        "elements must not cross each other: use --clip exact)"},
       {"--sink", "S",
        "share of the shell height sunk below the surface, 0 to 0.95 (default 0, with --boolean 0.1 for a union "
        "and 0.5 otherwise, so that elements overlap the base)"}},
      map};
  return c;
}()};

}  // namespace
