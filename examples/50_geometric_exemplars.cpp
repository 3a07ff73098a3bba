// Example 50: procedural geometric-texture exemplars (rings, chain mail, stones, weave), written as
// OBJ meshes with a shaded PNG preview each.
//   example_50_geometric_exemplars [OUT_DIR]
#include <cstdio>
#include <string>

#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/obj.hpp>

int main(int argc, char** argv) {
  using namespace tessera;
  const std::string dir = argc > 1 ? argv[1] : ".";
  struct item {
    const char* name;
    result<tri_mesh> mesh;
  };
  item items[] = {{"rings", make_ring_exemplar()},
                  {"chain_mail", make_ring_exemplar({.size = 5, .minor_radius = 0.08, .chain_mail = true})},
                  {"stones", make_stone_exemplar()},
                  {"weave", make_weave_exemplar()}};
  for (auto& it : items) {
    if (!it.mesh) {
      std::fprintf(stderr, "%s: %s\n", it.name, it.mesh.error().to_string().c_str());
      return 1;
    }
    const std::string obj = dir + "/exemplar_" + it.name + ".obj", png = dir + "/exemplar_" + it.name + ".png";
    if (auto s = write_obj(obj, *it.mesh); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
    if (auto s = write_mesh_preview(png, *it.mesh, {.width = 480, .height = 360}); !s)
      return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
    std::printf("%-10s %5lld vertices -> %s, %s\n", it.name, static_cast<long long>(it.mesh->num_vertices()),
                obj.c_str(), png.c_str());
  }
  return 0;
}
