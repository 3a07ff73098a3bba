// tessera wang map: image Wang tiles on a closed mesh (Fu & Leung 2005; paper 000 §4). Reads a
// three-axis tile set (`tessera wang build --colors NX,NY,NZ`), the base mesh and its polycube (given
// as the polycube-deformed mesh of `tessera polycube`, or built here), colours the quad layout, splits
// the base along the quad borders and writes OUT.obj with per-corner uvs, OUT.mtl naming the atlas
// (map_Kd) and the atlas PNG beside them (surface/map_wang_tiles_to_surface.hpp).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include <tessera/core/executor.hpp>
#include <tessera/image/axis_wang_atlas.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/io/png.hpp>
#include <tessera/io/wang_tiles.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/map_wang_tiles_to_surface.hpp>

#include "cli.hpp"

namespace {

int run_map(const cli::arguments& args) {
  using namespace tessera;
  auto tiles = args.required("--tiles");
  auto mesh_path = args.required("--mesh");
  auto out = args.required("--out");
  for (const auto* r : {&tiles, &mesh_path, &out})
    if (!*r) return cli::fail(args, r->error());
  auto tile = args.number("--tile", 0, 0);
  if (!tile) return cli::fail(args, tile.error());
  if (!args.has("--tile") || !(*tile > 0))
    return cli::fail(
        args, status::invalid_argument("--tile W (the quad size in mesh units, > 0) is required, also with --polycube "
                                       "(the tile size the polycube was built with)"));
  auto set = load_axis_wang_tiles<std::uint8_t, 3>(*tiles);
  if (!set) return cli::fail(args, set.error());
  auto atlas = build_axis_wang_atlas(*set);
  if (!atlas) return cli::fail(args, atlas.error());
  auto mesh = read_mesh(*mesh_path);
  if (!mesh) return cli::fail(args, mesh.error());
  thread_pool_executor pool(args.threads());
  result<polycube_map> map = status::internal_error("no polycube");
  if (args.has("--polycube")) {
    auto deformed = read_mesh(args.str("--polycube"));
    if (!deformed) return cli::fail(args, deformed.error());
    map = polycube_map_from_deformed(*mesh, *deformed, *tile, pool);
  } else {
    polycube_options o;
    o.tile_size = *tile;
    map = build_polycube_map(*mesh, o, pool);
  }
  if (!map) return cli::fail(args, map.error());
  // mapping only (no file I/O): colouring, assignment, split and uvs
  result<wang_surface_mesh> r = status::internal_error("not run");
  index_t tiles_used = 0;
  const double ms = cli::median_ms(args.repeat(), [&] {
    auto tiling = tile_polycube(*map, *set, args.seed(), pool);
    if (!tiling) {
      r = tiling.error();
      return;
    }
    tiles_used = tiling->tiles_used;
    r = map_wang_tiles_to_surface(map->base, *map, *tiling, *atlas, pool);
  });
  if (!r) return cli::fail(args, r.error());
  const std::filesystem::path obj(*out);
  std::filesystem::path png = obj;
  png.replace_extension(".png");
  if (png == obj) png += ".atlas.png";
  if (auto s = write_png(png.string(), atlas->image); !s) return cli::fail(args, s);
  if (auto s = write_textured_obj(*out, r->mesh, png.filename().string()); !s) return cli::fail(args, s);
  if (args.stats()) {
    cli::json_line()
        .add("command", "wang map")
        .add("map_ms", ms)
        .add("quads", static_cast<index_t>(map->layout.quads.size()))
        .add("tiles_used", tiles_used)
        .add("vertices", r->mesh.num_vertices())
        .add("faces", r->mesh.num_faces())
        .add("split_faces", r->split_faces)
        .add("refined", map->refined())
        .print();
  } else {
    std::printf("wrote %s, %s and %s (%td faces on %zu quads)\n", out->c_str(),
                obj.parent_path().empty() ? obj.stem().concat(".mtl").string().c_str()
                                          : (obj.parent_path() / obj.stem().concat(".mtl")).string().c_str(),
                png.string().c_str(), r->mesh.num_faces(), map->layout.quads.size());
  }
  return 0;
}

const cli::registrar map_command({
    .name = "wang map",
    .summary = "cover a closed mesh with image Wang tiles (textured OBJ + MTL + atlas PNG)",
    .usage = "tessera wang map --tiles SET --mesh BASE --out OUT.obj --tile W [--polycube PC.obj] [--seed S]",
    .options = {{
        {"--tiles", "SET", "a three-axis tile directory (tessera wang build --colors NX,NY,NZ)"},
        {"--mesh", "BASE", "closed, manifold, oriented triangle mesh (.obj, .off, .ply)"},
        {"--out", "OUT.obj", "textured mesh; OUT.mtl and the atlas OUT.png are written beside it"},
        {"--tile", "W", "quad size in mesh units (with --polycube: the size it was built with)"},
        {"--polycube", "PC.obj",
         "the polycube-deformed base (tessera polycube --out, in BASE's order); default: build it here"},
    }},
    .run = run_map,
});

}  // namespace
