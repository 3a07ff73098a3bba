// Image Wang tiles on a closed surface (Fu & Leung 2005, paper 000's ref. [5]; paper 000 §4): a
// three-axis image tile set, a polycube map of the mesh, its quads coloured and given tiles, the mesh
// split along the quad borders with atlas uvs, written as a textured OBJ (+ MTL + atlas PNG) and
// rendered. Usage: example_64_wang_surface OUT_DIR [MESH.(obj|off|ply) [EXEMPLAR.png [TILES_ACROSS]]]
// (without a mesh: a torus; without an exemplar: the procedural "cells").
#include <tessera/core/executor.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/image/axis_wang_atlas.hpp>
#include <tessera/image/axis_wang_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/io/png.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/map_wang_tiles_to_surface.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

using namespace tessera;

namespace {
int fail(const status& s) {
  std::fprintf(stderr, "%s\n", s.to_string().c_str());
  return 1;
}
tri_mesh torus(double big, double small, int nu, int nv) {
  tri_mesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
      m.add_vertex(
          {(big + small * std::cos(v)) * std::cos(u), (big + small * std::cos(v)) * std::sin(u), small * std::sin(v)});
    }
  auto id = [&](int i, int j) { return static_cast<index_t>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return m;
}
}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  thread_pool_executor pool;
  tri_mesh mesh = torus(2, 0.7, 48, 16);
  if (argc > 2) {
    auto m = read_mesh(argv[2]);
    if (!m) return fail(m.error());
    mesh = std::move(*m);
  }
  image_buffer<std::uint8_t, 3> exemplar;
  if (argc > 3) {
    auto e = read_png<std::uint8_t, 3>(argv[3]);
    if (!e) return fail(e.error());
    exemplar = std::move(*e);
  } else {
    auto e = make_exemplar<std::uint8_t, 3>(exemplar_kind::cells, {.width = 128, .height = 128});
    if (!e) return fail(e.error());
    exemplar = std::move(*e);
  }
  const index_t across = argc > 4 ? std::atoi(argv[4]) : 8;

  // [snippet:wang_surface_use]
  // 1. a three-axis set: 2 colours per axis, 96 tiles, and its atlas
  auto set = build_axis_wang_tiles(exemplar, {2, 2, 2}, {.tile_size = 64, .seed = 3}, pool);
  if (!set) return fail(set.error());
  auto atlas = build_axis_wang_atlas(*set);
  if (!atlas) return fail(atlas.error());
  // 2. the polycube map of the mesh, its grid edges coloured, a tile per quad
  polycube_options po;
  po.tiles_across = across;
  auto map = build_polycube_map(mesh, po, pool);
  if (!map) return fail(map.error());
  auto tiling = tile_polycube(*map, *set, /*seed=*/7, pool);
  if (!tiling) return fail(tiling.error());
  // 3. the base (map->base: the input, refined when the construction refined it) split along the
  //    quad borders, with per-corner uvs into the atlas
  auto textured = map_wang_tiles_to_surface(map->base, *map, *tiling, *atlas, pool);
  if (!textured) return fail(textured.error());
  // 4. OBJ + MTL (map_Kd) + atlas PNG
  if (auto s = write_png(dir + "/64_wang_surface_atlas.png", atlas->image); !s) return fail(s);
  if (auto s = write_textured_obj(dir + "/64_wang_surface.obj", textured->mesh, "64_wang_surface_atlas.png"); !s)
    return fail(s);
  // [/snippet]

  for (int view = 0; view < 2; ++view) {
    mesh_preview_options o;
    o.width = 640;
    o.height = 480;
    o.azimuth_degrees = view == 0 ? -60 : 120;
    o.elevation_degrees = view == 0 ? 35 : -25;
    const std::string path = dir + "/64_wang_surface_view" + std::to_string(view) + ".png";
    if (auto s = write_textured_mesh_preview(path, textured->mesh, atlas->image, o, pool); !s) return fail(s);
  }
  std::printf("wrote %s/64_wang_surface.obj (+ .mtl, atlas, 2 views): %zu quads, %td tiles used, %td faces\n",
              dir.c_str(), map->layout.quads.size(), tiling->tiles_used, textured->mesh.num_faces());
  return 0;
}
