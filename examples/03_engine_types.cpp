// 03_engine_types: an engine's texture and mesh classes whose names tessera cannot guess
// (GetWidth, GetTexel with packed 0xAABBGGRR texels; GetVertexCount, GetIndex, a Vec3 with X/Y/Z) are
// adapted by specializing tessera::image_traits, tessera::mesh_traits and tessera::point_traits: a
// few static functions, no change to the engine's classes. Pixels travel by value, so packed formats
// fit. Usage: example_03_engine_types [OUTPUT_DIR]
// (writes 03_engine_texture.png, 03_engine_texture_grey16.png and 03_engine_mesh.obj)
#include <tessera/core/explain.hpp>
#include <tessera/core/image.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/mesh.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/png.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

// [snippet:engine-texture]
namespace engine {  // the engine's code, untouched
class Texture2D {
 public:
  Texture2D(std::uint32_t w, std::uint32_t h) : w_(w), h_(h), texels_(std::size_t(w) * h) {}
  std::uint32_t GetWidth() const { return w_; }
  std::uint32_t GetHeight() const { return h_; }
  std::uint32_t GetTexel(std::uint32_t x, std::uint32_t y) const { return texels_[std::size_t(y) * w_ + x]; }
  void SetTexel(std::uint32_t x, std::uint32_t y, std::uint32_t abgr) { texels_[std::size_t(y) * w_ + x] = abgr; }

 private:
  std::uint32_t w_, h_;
  std::vector<std::uint32_t> texels_;
};
}  // namespace engine

// The adapter: one specialization, next to the engine's code or in the application.
template <>
struct tessera::image_traits<engine::Texture2D> {
  using rgba8 = tessera::pixel<std::uint8_t, 4>;
  static index_t width(const engine::Texture2D& t) { return t.GetWidth(); }
  static index_t height(const engine::Texture2D& t) { return t.GetHeight(); }
  static rgba8 read(const engine::Texture2D& t, index_t x, index_t y) {
    const std::uint32_t v = t.GetTexel(std::uint32_t(x), std::uint32_t(y));
    return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
  }
  static void write(engine::Texture2D& t, index_t x, index_t y, const rgba8& p) {
    t.SetTexel(std::uint32_t(x), std::uint32_t(y),
               std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24);
  }
};
// [/snippet]

// [snippet:engine-mesh]
namespace engine {  // the engine's mesh, untouched
struct Vec3 {
  float X, Y, Z;
};
class StaticMesh {
 public:
  int GetVertexCount() const { return int(vertices_.size()); }
  int GetTriangleCount() const { return int(indices_.size() / 3); }
  const Vec3& GetVertex(int i) const { return vertices_[std::size_t(i)]; }
  int GetIndex(int triangle, int corner) const { return indices_[std::size_t(3 * triangle + corner)]; }
  void AddVertex(Vec3 v) { vertices_.push_back(v); }
  void AddTriangle(int a, int b, int c) { indices_.insert(indices_.end(), {a, b, c}); }

 private:
  std::vector<Vec3> vertices_;
  std::vector<int> indices_;
};
}  // namespace engine

// The adapters: how to read a Vec3, and the four mesh functions.
template <>
struct tessera::point_traits<engine::Vec3> {
  static double get(const engine::Vec3& p, int i) { return i == 0 ? p.X : i == 1 ? p.Y : p.Z; }
};
template <>
struct tessera::mesh_traits<engine::StaticMesh> {
  static index_t num_vertices(const engine::StaticMesh& m) { return m.GetVertexCount(); }
  static index_t num_faces(const engine::StaticMesh& m) { return m.GetTriangleCount(); }
  static index_t face_vertex(const engine::StaticMesh& m, index_t f, int k) { return m.GetIndex(int(f), k); }
  static const engine::Vec3& position(const engine::StaticMesh& m, index_t v) { return m.GetVertex(int(v)); }
};
static_assert(tessera::Mesh<engine::StaticMesh>);  // or tessera::explain_mesh<engine::StaticMesh>()
// [/snippet]

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::explain_writable_image<engine::Texture2D>();  // a readable compile error if the adapter were incomplete

  engine::Texture2D texture(128, 128);
  auto cells =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, {.width = 128, .height = 128, .seed = 7});
  if (!cells) return fail(cells.error());
  if (auto s = tessera::copy_image(*cells, texture); !s) return fail(s);  // RGB8 -> packed RGBA8 (opaque)

  // Read the engine texture back through the traits: a 16-bit grey copy (Rec. 601 luma).
  auto grey16 = tessera::to_buffer<std::uint16_t, 1>(texture);
  if (!grey16) return fail(grey16.error());

  const std::string path = dir + "/03_engine_texture.png", grey_path = dir + "/03_engine_texture_grey16.png";
  if (auto s = tessera::write_png(path, texture); !s) return fail(s);       // 8-bit RGBA straight from the engine type
  if (auto s = tessera::write_png(grey_path, *grey16); !s) return fail(s);  // 16-bit grey
  std::printf("texel (5, 9) = 0x%08x\n", texture.GetTexel(5, 9));

  // A terrain tile in the engine's mesh type, displaced by the texture's grey; tessera reads it
  // through mesh_traits like any other mesh.
  engine::StaticMesh tile;
  const int n = 17;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      tile.AddVertex({float(x), float(y), 4.0f * float(grey16->read(x * 8, y * 8)[0]) / 65535.0f});
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      tile.AddTriangle(y * n + x, y * n + x + 1, (y + 1) * n + x + 1);
      tile.AddTriangle(y * n + x, (y + 1) * n + x + 1, (y + 1) * n + x);
    }
  tessera::explain_mesh<engine::StaticMesh>();
  if (auto s = tessera::validate_mesh(tile, "terrain tile"); !s) return fail(s);
  const auto box = tessera::bounding_box(tile);
  const auto normals = tessera::vertex_normals(tile);
  std::printf(
      "terrain tile: %td vertices, %td triangles, %zu boundary edges, height %.2f..%.2f, normal at centre "
      "(%.2f, %.2f, %.2f)\n",
      tessera::num_vertices(tile), tessera::num_faces(tile), tessera::boundary_edges(tile).size(), box.min.z, box.max.z,
      normals[n * n / 2].x, normals[n * n / 2].y, normals[n * n / 2].z);
  const std::string mesh_path = dir + "/03_engine_mesh.obj";
  if (auto s = tessera::write_mesh(mesh_path, tile); !s) return fail(s);  // any Mesh, through mesh_traits
  tile.AddTriangle(0, 1, 400);  // an index past the last vertex is reported, not read
  std::printf("bad index: %s\n", tessera::validate_mesh(tile, "terrain tile").to_string().c_str());
  std::printf("wrote %s\nwrote %s\nwrote %s\n", path.c_str(), grey_path.c_str(), mesh_path.c_str());
  return 0;
}
