// Example 51: mesh quilting (paper 000 §3.3, after Zhou et al. 2006) grows a larger geometric texture
// from a small exemplar. Writes the quilted mesh and a preview.
// Mesh quilting is the subject of US patent US7800627B2; judge for yourself whether it concerns you.
//   example_51_mesh_quilt [OUT_DIR]
#include <cstdio>
#include <string>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/obj.hpp>

int main(int argc, char** argv) {
  using namespace tessera;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const auto exemplar = make_stone_exemplar({.size = 6, .seed = 2});
  if (!exemplar) return std::fprintf(stderr, "%s\n", exemplar.error().to_string().c_str()), 1;
  const auto prepared = prepare_quilt_exemplar(*exemplar);  // keep and reuse for many quilts
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().to_string().c_str()), 1;
  thread_pool_executor pool;
  const auto quilt = mesh_quilt(*prepared, 16, 12, {.seed = 7}, pool);
  if (!quilt) return std::fprintf(stderr, "%s\n", quilt.error().to_string().c_str()), 1;
  const auto report = check_geometric_texture(quilt->mesh);
  if (!report) return std::fprintf(stderr, "%s\n", report.error().to_string().c_str()), 1;
  std::printf(
      "quilted %zu elements (%lld merged, %lld dropped); open edges %lld, non-manifold %lld, intersecting pairs %lld\n",
      quilt->elements.size(), static_cast<long long>(quilt->stats.elements_merged),
      static_cast<long long>(quilt->stats.elements_dropped), static_cast<long long>(report->open_edges_inside),
      static_cast<long long>(report->nonmanifold_edges), static_cast<long long>(report->intersecting_pairs));
  const std::string obj = dir + "/quilt_stones.obj", png = dir + "/quilt_stones.png",
                    ex_png = dir + "/quilt_stones_exemplar.png";
  if (auto s = write_obj(obj, quilt->mesh); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
  if (auto s = write_mesh_preview(png, quilt->mesh, {.width = 800, .height = 520}, pool); !s) return 1;
  if (auto s = write_mesh_preview(ex_png, *exemplar, {.width = 400, .height = 320}, pool); !s) return 1;
  std::printf("wrote %s, %s and %s\n", obj.c_str(), png.c_str(), ex_png.c_str());
  return 0;
}
