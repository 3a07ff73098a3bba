// tessera geo-wang build / geo-wang tile: geometric-texture Wang tiles (paper 000 §3): build a complete
// planar set (--colors NH,NV) or three-axis set for polycube surfaces (--colors NX,NY,NZ, §3.1 and §5)
// from an exemplar mesh, and tile a plane from a tile set directory (one face's tiles of a three-axis set).
#include <cmath>
#include <string>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/io/geometric_tiles.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/periodic_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include "cli.hpp"
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
        .add("frame_merges_attempted", set->frame_merges_attempted)
        .add("frame_merged", set->frame_merged)
        .add("frame_dropped", set->frame_dropped)
        .add("merge_fail_correspondence", set->stats.merge_fail_correspondence)
        .add("merge_fail_deform", set->stats.merge_fail_deform)
        .add("merge_fail_cut", set->stats.merge_fail_cut)
        .add("merge_fail_loops", set->stats.merge_fail_loops)
        .add("merge_fail_check", set->stats.merge_fail_check)
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

const cli::registrar reg_build{[] {
  cli::command c{"geo-wang build",
                 "build a complete set of geometric-texture Wang tiles (planar or three-axis) from an exemplar mesh",
                 "tessera geo-wang build --exemplar E.obj --tile W --out DIR [--colors NH,NV | NX,NY,NZ] [options]",
                 {{"--exemplar", "FILE", "exemplar mesh of closed elements"},
                  {"--colors", "NH,NV|NX,NY,NZ",
                   "two counts: a planar set, colours of horizontal (north/south) and vertical (east/west) "
                   "edges; three: a three-axis set for polycube surfaces (2(nX^2nY^2+nX^2nZ^2+nY^2nZ^2) tiles), "
                   "colours of edges along X, Y, Z; 1 to 4096 each (default 2,2)"},
                  {"--tile", "W", "tile size in exemplar units"},
                  {"--edge-height", "H", "edge strip height h_E (default 1.5 x element size)"},
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

}  // namespace
