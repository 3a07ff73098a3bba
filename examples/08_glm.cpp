// 08_glm: an engine built on GLM. Its texture stores glm::u8vec4 texels and its mesh glm::vec3
// positions, glm::uvec3 triangles and glm::vec2 corner uvs; with tessera/adapters/glm.hpp both
// model tessera's concepts member style, with nothing else to write.
// Usage: example_08_glm [OUTPUT_DIR]   (writes 08_glm_uv_layout.png and 08_glm_crate.obj)
#include <tessera/adapters/glm.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/png.hpp>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdio>
#include <string>
#include <vector>

// [snippet:glm-types]
struct GlmTexture {
  int w, h;
  std::vector<glm::u8vec4> texels;
  int width() const { return w; }
  int height() const { return h; }
  glm::u8vec4 read(std::ptrdiff_t x, std::ptrdiff_t y) const { return texels[std::size_t(y * w + x)]; }
  void write(std::ptrdiff_t x, std::ptrdiff_t y, const glm::u8vec4& t) { texels[std::size_t(y * w + x)] = t; }
};

struct GlmMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;
  std::vector<glm::vec2> uvs;  // three per triangle
  std::size_t num_vertices() const { return positions.size(); }
  std::size_t num_faces() const { return triangles.size(); }
  unsigned face_vertex(std::ptrdiff_t f, int k) const { return triangles[std::size_t(f)][k]; }
  const glm::vec3& position(std::ptrdiff_t v) const { return positions[std::size_t(v)]; }
  bool has_uvs() const { return !uvs.empty(); }
  const glm::vec2& corner_uv(std::ptrdiff_t f, int k) const { return uvs[std::size_t(3 * f + k)]; }
};

static_assert(tessera::WritableImage<GlmTexture> && tessera::UVMesh<GlmMesh>);
// [/snippet]

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

// A box of 12 triangles with its faces unwrapped into a 3 x 2 grid of uv cells.
GlmMesh make_box(glm::vec3 lo, glm::vec3 hi) {
  GlmMesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
  const unsigned quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int q = 0; q < 6; ++q) {
    const glm::vec2 o(float(q % 3) / 3.0f, float(q / 3) / 2.0f), s(1.0f / 3.0f, 0.5f);
    const glm::vec2 c[4] = {o + s * glm::vec2(0.1f, 0.1f), o + s * glm::vec2(0.9f, 0.1f), o + s * glm::vec2(0.9f, 0.9f),
                            o + s * glm::vec2(0.1f, 0.9f)};
    m.triangles.emplace_back(quads[q][0], quads[q][1], quads[q][2]);
    m.triangles.emplace_back(quads[q][0], quads[q][2], quads[q][3]);
    m.uvs.insert(m.uvs.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
  }
  return m;
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";

  // [snippet:glm-use]
  GlmTexture texture{192, 128, std::vector<glm::u8vec4>(192 * 128)};
  auto dots = tessera::make_exemplar<float, 3>(tessera::exemplar_kind::dots, {.width = 192, .height = 128});
  if (!dots) return fail(dots.error());
  if (auto s = tessera::copy_image(*dots, texture); !s) return fail(s);  // float RGB -> glm::u8vec4

  GlmMesh crate = make_box({0, 0, 0}, {1, 1, 1});
  if (auto s = tessera::validate_mesh(crate, "crate"); !s) return fail(s);  // positions, indices and uvs
  auto crate_mesh = tessera::to_tri_mesh(crate);                            // glm -> tessera, uvs included
  const auto normals = tessera::face_normals(crate);
  // [/snippet]
  if (!crate_mesh) return fail(crate_mesh.error());
  std::printf("crate: %td vertices, %td faces, %td components, closed: %s, uvs: %s\n", crate_mesh->num_vertices(),
              crate_mesh->num_faces(), tessera::connected_components(crate).count,
              tessera::boundary_edges(crate).empty() ? "yes" : "no", crate_mesh->has_uvs() ? "yes" : "no");
  std::printf("face 0 normal (%g, %g, %g)\n", normals[0].x, normals[0].y, normals[0].z);

  // Show the uv layout on top of the texture: draw each triangle's uv edges into the glm texture.
  for (std::ptrdiff_t f = 0; f < crate_mesh->num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const tessera::vec2 a = crate_mesh->uvs[std::size_t(f)][std::size_t(k)];
      const tessera::vec2 b = crate_mesh->uvs[std::size_t(f)][std::size_t((k + 1) % 3)];
      for (int i = 0; i <= 200; ++i) {
        const double t = i / 200.0;
        const auto x = std::ptrdiff_t((a.x + (b.x - a.x) * t) * (texture.w - 1));
        const auto y = std::ptrdiff_t((a.y + (b.y - a.y) * t) * (texture.h - 1));
        texture.write(x, y, glm::u8vec4(20, 40, 200, 255));
      }
    }
  const std::string path = dir + "/08_glm_uv_layout.png";
  if (auto s = tessera::write_png(path, texture); !s) return fail(s);

  const std::string obj_path = dir + "/08_glm_crate.obj";
  if (auto s = tessera::write_mesh(obj_path, crate); !s) return fail(s);  // positions, faces and uvs

  // A bad index in the glm mesh is reported by name.
  crate.triangles[4].y = 42;
  std::printf("bad index: %s\n", tessera::validate_mesh(crate, "crate").to_string().c_str());
  std::printf("wrote %s\nwrote %s\n", path.c_str(), obj_path.c_str());
  return 0;
}
