// Example 61: three-axis geometric Wang tiles on polycube surfaces (paper 000 §3.1, §4-5): the complete
// set for two colours per axis (96 tiles) laid out one row per cube face, then the polycubes of a cube
// and of an L-shaped block (convex and concave edges) coloured and tiled, each tile placed flat on its
// quad over the polycube surface (no shell map: across a polycube edge the two halves of an element
// stand at 90 degrees, joined only on the edge line).
//   example_61_polycube_tiles [OUT_DIR] [rings|stones] [NX,NY,NZ colours: 2 (default) or 1]
#include <array>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>

#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_tiling.hpp>

namespace {
using tessera::vec3;
// The outer surface of unit voxels, every unit face cut into s x s squares (two triangles each), each
// face's squares counter-clockwise seen from outside (the face frames of tiling/axis_tile_set.hpp).
tessera::tri_mesh voxel_surface(const std::set<std::array<int, 3>>& vox, int s) {
  tessera::tri_mesh m;
  std::map<std::array<int, 3>, tessera::index_t> id;
  const auto vertex = [&](std::array<int, 3> g) {
    const auto [it, fresh] = id.emplace(g, m.num_vertices());
    if (fresh) m.add_vertex({double(g[0]) / s, double(g[1]) / s, double(g[2]) / s});
    return it->second;
  };
  for (const auto& v : vox)
    for (int f = 0; f < tessera::cube_faces; ++f) {
      const int a = f / 2, outward = f % 2 == 0 ? 1 : 0;
      auto beyond = v;
      beyond[a] += 2 * outward - 1;
      if (vox.count(beyond)) continue;  // an inner face
      const auto ax = tessera::cube_face_axes(f);
      for (int c = 0; c < s * s; ++c) {
        std::array<tessera::index_t, 4> q;
        for (int k = 0; k < 4; ++k) {
          std::array<int, 3> g{v[0] * s, v[1] * s, v[2] * s};
          g[a] += outward * s;
          g[ax[0]] += c % s + (k == 1 || k == 2 ? 1 : 0);
          g[ax[1]] += c / s + (k >= 2 ? 1 : 0);
          q[k] = vertex(g);
        }
        m.add_face(q[0], q[1], q[2]);
        m.add_face(q[0], q[2], q[3]);
      }
    }
  return m;
}

// Every quad's tile placed flat: tile-local -> quad-local (placement) -> polycube (quad frame).
tessera::tri_mesh place_flat(const tessera::polycube_map& map, const tessera::geometric_tile_set& set,
                             const tessera::polycube_tiling& tiling) {
  tessera::tri_mesh out;
  for (std::size_t q = 0; q < tiling.quads.size(); ++q) {
    const auto& quad = map.layout.quads[q];
    const auto& p = tiling.quads[q];
    vec3 c0, du, dv;
    for (int a = 0; a < 3; ++a) {
      c0[a] = double(quad.corners[0][a]) * map.tile_size;
      du[a] = double(quad.corners[1][a] - quad.corners[0][a]) * map.tile_size;
      dv[a] = double(quad.corners[3][a] - quad.corners[0][a]) * map.tile_size;
    }
    const vec3 n = tessera::label_direction(p.face) * map.tile_size;
    tessera::tri_mesh t = set.tiles[std::size_t(p.tile)];
    for (vec3& x : t.positions) {
      const vec3 uvh = p.to_quad(x);
      x = c0 + uvh.x * du + uvh.y * dv + uvh.z * n;
    }
    out.append(t);
  }
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace tessera;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const std::string kind = argc > 2 ? argv[2] : "rings";
  const int colors = argc > 3 ? std::atoi(argv[3]) : 2;
  const auto exemplar = kind == "stones" ? make_stone_exemplar() : make_ring_exemplar();
  if (!exemplar) return std::fprintf(stderr, "%s\n", exemplar.error().to_string().c_str()), 1;
  const auto prepared = prepare_quilt_exemplar(*exemplar);
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().to_string().c_str()), 1;
  // [snippet:polycube_tiles_build]
  geometric_wang_options o;
  o.axis_colors = {colors, colors, colors};  // nX, nY, nZ: 2 (nX²nY² + nX²nZ² + nY²nZ²) tiles, 96 for 2
  o.tile_size = 6.4;
  o.quilt.seed = 3;
  thread_pool_executor pool;
  const auto set = build_geometric_wang_tiles(*prepared, o, pool);  // set->faces[i]: the face of tile i
  // [/snippet]
  if (!set) return std::fprintf(stderr, "%s\n", set.error().to_string().c_str()), 1;
  const auto mismatches = tile_set_border_mismatch(*set);
  if (!mismatches) return std::fprintf(stderr, "%s\n", mismatches.error().to_string().c_str()), 1;
  std::printf("%zu tiles from %d + %d + %d strips (%lld elements cross edges), border mismatches %lld\n",
              set->tiles.size(), colors, colors, colors, static_cast<long long>(set->crossing_elements),
              static_cast<long long>(*mismatches));
  // the set, one row per face (+X, -X, +Y, -Y, +Z, -Z), in tile order
  tri_mesh layout;
  const double w = set->tile_size, gap = 0.15 * w;
  const index_t per_face = axis_face_tile_count(0, set->axis_colors);
  for (std::size_t i = 0; i < set->tiles.size(); ++i) {
    const double col = double(index_t(i) % per_face), row = double(set->faces[i]);
    layout.append(set->tiles[i], vec3{col * (w + gap), (5 - row) * (w + gap), 0});
  }
  const std::string set_png = dir + "/axis_tileset_" + kind + ".png";
  if (auto s = write_mesh_preview(set_png, layout,
                                  {.width = 1600, .height = 640, .azimuth_degrees = 0, .elevation_degrees = 90}, pool);
      !s)
    return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
  // a cube (convex edges only) and an L-shaped block (concave edges too), 3 tiles a unit
  const std::set<std::array<int, 3>> shapes[2] = {{{0, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const char* names[2] = {"cube", "lblock"};
  for (int k = 0; k < 2; ++k) {
    polycube_options po;
    po.tile_size = 1.0 / 3;
    const auto map = build_polycube_map(voxel_surface(shapes[k], 3), po);
    if (!map) return std::fprintf(stderr, "%s\n", map.error().to_string().c_str()), 1;
    // [snippet:polycube_tiles_assign]
    const auto tiling = tile_polycube(*map, *set, 7, pool);  // colour the grid edges (seed 7), match tiles
    // tiling->quads[q]: .tile, .face, .to_quad(p): tile-local p -> quad-local (u, v, h)
    // [/snippet]
    if (!tiling) return std::fprintf(stderr, "%s\n", tiling.error().to_string().c_str()), 1;
    tri_mesh covered = place_flat(*map, *set, *tiling);
    covered.append(quad_layout_mesh(*map));  // the polycube surface under the tiles
    const std::string png = dir + "/axis_tiles_" + names[k] + "_" + kind + ".png";
    if (auto s = write_mesh_preview(
            png, covered, {.width = 800, .height = 700, .azimuth_degrees = -35, .elevation_degrees = 30}, pool);
        !s)
      return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
    std::printf("%s: %zu quads, %lld different tiles -> %s\n", names[k], tiling->quads.size(),
                static_cast<long long>(tiling->tiles_used), png.c_str());
  }
  std::printf("wrote %s\n", set_png.c_str());
  return 0;
}
