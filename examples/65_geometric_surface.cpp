// Example 65: paper 000 Fig. 6 remade: one precomputed three-axis geometric Wang tile set (96 tiles,
// two colours per axis) covers closed meshes through their polycube maps and shell maps
// (surface/map_geometric_tiles.hpp). Writes, per mesh, the elements with the base (OBJ) and two
// renderings: elements on the base, and the elements alone.
//   example_65_geometric_surface [OUT_DIR [rings|stones|weave [MESH[@TILES_ACROSS]...]]]
// Without meshes: a torus at 6 tiles across with a small exemplar (the quick smoke test). With meshes
// (.obj, .off, .ply; e.g. CGAL's fandisk, blobby, handle from scripts/polycube_meshes.sh): the full
// 4.8k-vertex exemplar of the kind, tile 4.0 (the paper's tile sizes), default 12 tiles across; the
// command that made docs/images/surface/geo_*.png is in docs/surface.md.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/geometry/bvh.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/map_geometric_tiles.hpp>

using namespace tessera;

namespace {
int fail(const std::string& what, const status& s) {
  std::fprintf(stderr, "%s: %s\n", what.c_str(), s.to_string().c_str());
  return 1;
}
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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
  const std::string kind = argc > 2 ? argv[2] : "rings";
  const bool quick = argc <= 3;
  thread_pool_executor pool;
  // the exemplar: the full one of the kind, or a small ring patch for the smoke test
  const auto exemplar =
      quick ? make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 12, .tube_segments = 5, .seed = 3})
      : kind == "stones" ? make_stone_exemplar()
      : kind == "weave"  ? make_weave_exemplar()
                         : make_ring_exemplar();
  if (!exemplar) return fail("exemplar", exemplar.error());
  const auto prepared = prepare_quilt_exemplar(*exemplar);
  if (!prepared) return fail("exemplar", prepared.error());
  // [snippet:geometric_surface_use]
  // 1. one three-axis set: 2 colours for edges along X, Y and Z = 2 (4·4 + 4·4 + 4·4) = 96 tiles
  geometric_wang_options wo;
  wo.axis_colors = {2, 2, 2};
  wo.tile_size = 4.0;  // the paper's tile sizes: 0.5k-2.6k triangles a tile (Table 1)
  wo.quilt.seed = 11;
  auto t0 = std::chrono::steady_clock::now();
  const auto set = build_geometric_wang_tiles(*prepared, wo, pool);
  if (!set) return fail("tile set", set.error());
  std::printf("%s: %zu tiles from a %lld-vertex exemplar in %.1f s\n", kind.c_str(), set->tiles.size(),
              static_cast<long long>(exemplar->num_vertices()), seconds_since(t0));
  // [/snippet]
  struct job {
    std::string path, name;
    index_t across;
  };
  std::vector<job> jobs;
  if (quick) jobs.push_back({"", "torus", 6});
  for (int i = 3; i < argc; ++i) {
    std::string a = argv[i];
    index_t across = 12;
    if (const auto at = a.rfind('@'); at != std::string::npos) {
      across = std::atoi(a.c_str() + at + 1);
      a.resize(at);
    }
    const auto slash = a.find_last_of('/'), dot = a.find_last_of('.');
    const auto from = slash == std::string::npos ? 0 : slash + 1;
    jobs.push_back(
        {a, a.substr(from, dot == std::string::npos || dot < from ? std::string::npos : dot - from), across});
  }
  int failures = 0;
  for (const job& j : jobs) {
    tri_mesh mesh = torus(2, 0.7, 48, 16);
    if (!j.path.empty()) {
      auto m = read_mesh(j.path);
      if (!m) return fail(j.path, m.error());
      mesh = std::move(*m);
    }
    // 2. the polycube map of the mesh (built once per mesh; a user keeps it), 3. the texture
    polycube_options po;
    po.tiles_across = j.across;
    t0 = std::chrono::steady_clock::now();
    auto map = build_polycube_map(mesh, po, pool);
    if (!map) {
      std::printf("%s: %s\n", j.name.c_str(), map.error().to_string().c_str());
      ++failures;
      continue;
    }
    const double polycube_s = seconds_since(t0);
    map_geometric_tiles_options o;
    o.seed = 7;
    o.with_base = true;
    // faces of the elements that cross each other (pairs sharing a vertex skipped): the exact clip at the
    // shell's texture-space tetrahedra (the default) gives none where the shell is not folded; midpoint
    // refinement (the earlier approximation, mapped too for comparison) can; see docs/surface.md
    auto count_crossings = [](const tri_mesh& elements) {
      index_t crossing = 0;
      triangle_bvh(elements).for_each_self_intersection(
          [&](index_t a, index_t b) {
            for (index_t x : elements.faces[static_cast<std::size_t>(a)])
              for (index_t y : elements.faces[static_cast<std::size_t>(b)])
                if (x == y) return true;
            return false;
          },
          [&](index_t, index_t) { ++crossing; });
      return crossing;
    };
    o.mapping.clip = shell_clip::midpoint;
    t0 = std::chrono::steady_clock::now();
    auto mid = map_geometric_tiles(map->base, *map, *set, o, pool);
    const double mid_s = seconds_since(t0);
    o.mapping.clip = shell_clip::exact;
    t0 = std::chrono::steady_clock::now();
    auto r = map_geometric_tiles(map->base, *map, *set, o, pool);
    if (!r) {
      std::printf("%s: %s\n", j.name.c_str(), r.error().to_string().c_str());
      ++failures;
      continue;
    }
    const double map_s = seconds_since(t0);
    const tri_mesh elements = r->elements();
    const index_t crossing = count_crossings(elements);
    std::printf(
        "%s (%lld vertices, %lld across): polycube %.2f s, %zu quads, %lld tiles used; mapping %.2f s: H = %.3g, "
        "%lld shell repairs, %lld element vertices, %lld faces, %lld elements, %zu open edges, %lld split edges, "
        "%lld crossing face pairs\n",
        j.name.c_str(), static_cast<long long>(mesh.num_vertices()), static_cast<long long>(j.across), polycube_s,
        map->layout.quads.size(), static_cast<long long>(r->tiling.tiles_used), map_s, r->height,
        static_cast<long long>(r->shell_repairs), static_cast<long long>(r->element_vertices),
        static_cast<long long>(r->element_faces), static_cast<long long>(connected_components(elements).count),
        boundary_edges(elements).size(), static_cast<long long>(r->split_edges), static_cast<long long>(crossing));
    if (mid)
      std::printf("  midpoint refinement: mapping %.2f s, %lld faces, %lld crossing face pairs\n", mid_s,
                  static_cast<long long>(mid->element_faces), static_cast<long long>(count_crossings(mid->elements())));
    const std::string stem = dir + "/geo_" + kind + "_" + j.name;
    bool ok = write_obj(stem + ".obj", r->mesh).ok();
    mesh_preview_options view;
    view.width = view.height = quick ? 400 : 600;
    view.azimuth_degrees = -55;
    view.elevation_degrees = 30;
    view.color = kind == "stones"  ? std::array<float, 3>{0.72f, 0.70f, 0.66f}
                 : kind == "weave" ? std::array<float, 3>{0.55f, 0.62f, 0.80f}
                                   : std::array<float, 3>{0.85f, 0.68f, 0.35f};
    ok = write_mesh_preview(stem + ".png", r->mesh, view, pool).ok() && ok;
    ok = write_mesh_preview(stem + "_elements.png", elements, view, pool).ok() && ok;
    if (!ok) {
      std::fprintf(stderr, "%s: could not write %s.*\n", j.name.c_str(), stem.c_str());
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
