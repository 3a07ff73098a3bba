// Example 52: planar geometric-texture Wang tiles (paper 000 §3): a complete 2 x 2-colour set (16
// tiles) from an exemplar, saved as a tile directory, the set laid out for inspection, and a plane of
// 5 x 4 tiles welded into one mesh, rendered with and without tile borders.
//   example_52_geometric_wang_tiles [OUT_DIR] [rings|stones|weave]
#include <cstdio>
#include <string>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/io/geometric_tiles.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/tiling/hash_coloring.hpp>

int main(int argc, char** argv) {
  using namespace tessera;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const std::string kind = argc > 2 ? argv[2] : "rings";
  const auto exemplar = kind == "stones"  ? make_stone_exemplar()
                        : kind == "weave" ? make_weave_exemplar()
                                          : make_ring_exemplar();
  if (!exemplar) return std::fprintf(stderr, "%s\n", exemplar.error().to_string().c_str()), 1;
  const auto prepared = prepare_quilt_exemplar(*exemplar);
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().to_string().c_str()), 1;
  geometric_wang_options o;
  o.tile_size = kind == "weave" ? 6.0 : 6.4;
  o.quilt.seed = 3;
  thread_pool_executor pool;
  const auto set = build_geometric_wang_tiles(*prepared, o, pool);
  if (!set) return std::fprintf(stderr, "%s\n", set.error().to_string().c_str()), 1;
  const std::string tiles_dir = dir + "/tiles_" + kind;
  if (auto s = save_geometric_tile_set(tiles_dir, *set); !s)
    return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
  const auto mismatches = tile_set_border_mismatch(*set);
  if (!mismatches) return std::fprintf(stderr, "%s\n", mismatches.error().to_string().c_str()), 1;
  std::printf("%zu tiles (%lld elements cross edges), border mismatches %lld -> %s\n", set->tiles.size(),
              static_cast<long long>(set->crossing_elements), static_cast<long long>(*mismatches), tiles_dir.c_str());
  // the set laid out 4 x 4 with gaps, in complete_tile_index order
  tri_mesh layout;
  const double w = set->tile_size, gap = 0.15 * w;
  for (std::size_t i = 0; i < set->tiles.size(); ++i)
    layout.append(set->tiles[i], vec3{double(i % 4) * (w + gap), double(3 - i / 4) * (w + gap), 0});
  if (auto s = write_mesh_preview(dir + "/tileset_" + kind + ".png", layout,
                                  {.width = 800, .height = 640, .elevation_degrees = 70}, pool);
      !s)
    return 1;
  // a plane of 5 x 4 tiles by a hash colouring
  const auto hash = hash_coloring::create(set->horizontal_colors, set->vertical_colors, 5);
  if (!hash) return std::fprintf(stderr, "%s\n", hash.error().to_string().c_str()), 1;
  const auto coloring = hash->window(0, 0, 5, 4);
  if (!coloring) return std::fprintf(stderr, "%s\n", coloring.error().to_string().c_str()), 1;
  const auto plane = tile_geometric_plane(*set, *coloring, 5, 4, pool);
  if (!plane) return std::fprintf(stderr, "%s\n", plane.error().to_string().c_str()), 1;
  const auto rep = check_geometric_texture(*plane, {0, 0, 5 * w, 4 * w});
  if (!rep) return std::fprintf(stderr, "%s\n", rep.error().to_string().c_str()), 1;
  std::printf(
      "plane: %lld vertices, %lld elements; open edges inside %lld, non-manifold %lld, intersecting pairs %lld\n",
      static_cast<long long>(plane->num_vertices()), static_cast<long long>(rep->elements),
      static_cast<long long>(rep->open_edges_inside), static_cast<long long>(rep->nonmanifold_edges),
      static_cast<long long>(rep->intersecting_pairs));
  if (auto s = write_obj(dir + "/plane_" + kind + ".obj", *plane); !s) return 1;
  mesh_preview_options view{.width = 900, .height = 640, .elevation_degrees = 55};
  if (auto s = write_mesh_preview(dir + "/plane_" + kind + ".png", *plane, view, pool); !s) return 1;
  view.grid_spacing = w;
  if (auto s = write_mesh_preview(dir + "/plane_" + kind + "_borders.png", *plane, view, pool); !s) return 1;
  std::printf("wrote %s/tileset_%s.png, plane_%s.obj, plane_%s.png, plane_%s_borders.png\n", dir.c_str(), kind.c_str(),
              kind.c_str(), kind.c_str(), kind.c_str());
  return 0;
}
