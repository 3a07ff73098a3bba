// Tests for tessera/adapters/glm.hpp: glm vectors as pixels and as positions / uvs, through an image
// and a mesh type of a user's own built on glm, and bad input through them.
#include <tessera/adapters/glm.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/image/exemplars.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/gtc/type_precision.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using tessera::index_t;

namespace {

// An engine texture storing glm::u8vec4 (RGBA8), member style.
struct glm_texture {
  int w = 0, h = 0;
  std::vector<glm::u8vec4> texels;
  glm_texture(int width, int height) : w(width), h(height), texels(static_cast<std::size_t>(width * height)) {}
  int width() const { return w; }
  int height() const { return h; }
  glm::u8vec4 read(index_t x, index_t y) const { return texels[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, const glm::u8vec4& p) { texels[static_cast<std::size_t>(y * w + x)] = p; }
};

// A small engine mesh on glm: positions, triangles as glm::uvec3, optional per-corner uvs.
template <class Position = glm::vec3>
struct glm_mesh {
  std::vector<Position> positions;
  std::vector<glm::uvec3> triangles;
  std::vector<glm::vec2> corner_uvs;  // empty or 3 per triangle
  std::size_t num_vertices() const { return positions.size(); }
  std::size_t num_faces() const { return triangles.size(); }
  unsigned face_vertex(index_t f, int k) const { return triangles[static_cast<std::size_t>(f)][k]; }
  const Position& position(index_t v) const { return positions[static_cast<std::size_t>(v)]; }
  bool has_uvs() const { return !corner_uvs.empty(); }
  const glm::vec2& corner_uv(index_t f, int k) const { return corner_uvs[static_cast<std::size_t>(3 * f + k)]; }
};

// A unit quad (two triangles) plus a separate triangle: 7 vertices, 3 faces, 2 components.
glm_mesh<> quad_and_triangle() {
  glm_mesh<> m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {3, 0, 1}, {4, 0, 1}, {3, 1, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
  m.corner_uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {0, 1}};
  return m;
}

}  // namespace

TEST_CASE("glm: vectors are pixels and convert like std::array pixels") {
  STATIC_REQUIRE(tessera::Pixel<glm::u8vec4>);
  STATIC_REQUIRE(tessera::Pixel<glm::vec3>);
  STATIC_REQUIRE(tessera::Pixel<glm::u16vec2>);
  STATIC_REQUIRE(tessera::Pixel<glm::vec<1, float>>);
  STATIC_REQUIRE_FALSE(tessera::Pixel<glm::dvec3>);  // double channels
  STATIC_REQUIRE_FALSE(tessera::Pixel<glm::ivec4>);  // int channels

  const glm::u8vec4 p(200, 0, 255, 128);
  CHECK(tessera::convert_pixel<glm::u8vec4>(p) == p);
  const auto f = tessera::convert_pixel<glm::vec4>(p);
  CHECK(f.x == Approx(200.0f / 255.0f));
  CHECK(f.w == Approx(128.0f / 255.0f));
  const auto rgb16 = tessera::convert_pixel<glm::u16vec3>(p);  // alpha dropped
  CHECK(rgb16 == glm::u16vec3(51400, 0, 65535));
  const auto grey = tessera::convert_pixel<glm::vec<1, float>>(glm::vec3(1, 1, 1));
  CHECK(grey.x == Approx(1.0f));
  CHECK(tessera::convert_pixel<tessera::pixel<std::uint8_t, 4>>(glm::vec3(0, 0.5f, 1)) ==
        tessera::pixel<std::uint8_t, 4>{0, 128, 255, 255});
}

TEST_CASE("glm: an engine texture of glm::u8vec4 goes through copy_image and to_buffer") {
  STATIC_REQUIRE(tessera::WritableImage<glm_texture>);
  auto ex = tessera::make_exemplar<float, 3>(tessera::exemplar_kind::cells, {.width = 20, .height = 12});
  REQUIRE(ex.ok());
  glm_texture tex(20, 12);
  REQUIRE(tessera::copy_image(*ex, tex).ok());
  CHECK(tex.read(3, 4).a == 255);  // opaque alpha added
  CHECK(tex.read(3, 4).r == tessera::unit_to_channel<std::uint8_t>(ex->read(3, 4)[0]));
  auto back = tessera::to_buffer<std::uint8_t, 4>(tex);
  REQUIRE(back.ok());
  CHECK(back->read(19, 11)[1] == tex.read(19, 11).g);
  glm_texture other(12, 20);
  CHECK(tessera::copy_image(tex, other).code() == tessera::status_code::invalid_argument);
}

TEST_CASE("glm: vectors are positions and uvs, a glm mesh runs the core mesh functions") {
  CHECK(tessera::to_vec3(glm::dvec3(1, 2, 3)) == tessera::vec3{1, 2, 3});
  CHECK(tessera::to_vec3(glm::vec2(1, 2)) == tessera::vec3{1, 2, 0});  // no read past the vector
  CHECK(tessera::to_vec2(glm::vec4(5, 6, 7, 8)) == tessera::vec2{5, 6});

  const auto m = quad_and_triangle();
  STATIC_REQUIRE(tessera::UVMesh<glm_mesh<>>);
  REQUIRE(tessera::validate_mesh(m).ok());
  auto tm = tessera::to_tri_mesh(m);
  REQUIRE(tm.ok());
  CHECK(tm->positions[4] == tessera::vec3{3, 0, 1});
  REQUIRE(tm->has_uvs());
  CHECK(tm->uvs[1][2] == tessera::vec2{0, 1});
  const auto comp = tessera::connected_components(m);
  CHECK(comp.count == 2);
  CHECK(comp.vertex_component[6] == 1);
  CHECK(tessera::boundary_edges(m).size() == 7);  // 4 around the quad, 3 around the triangle
  const auto n = tessera::face_normals(m);
  CHECK(n[0] == tessera::vec3{0, 0, 1});
  CHECK(tessera::bounding_box(m).max == tessera::vec3{4, 1, 1});

  // 2D positions (glm::vec2) lie in z = 0.
  glm_mesh<glm::vec2> flat;
  flat.positions = {{0, 0}, {2, 0}, {0, 2}};
  flat.triangles = {{0, 1, 2}};
  REQUIRE(tessera::validate_mesh(flat).ok());
  CHECK(tessera::face_area(flat, 0) == Approx(2.0));
  CHECK(tessera::bounding_box(flat).max == tessera::vec3{2, 2, 0});
}

TEST_CASE("glm: NaN positions, NaN uvs and out-of-range indices are reported") {
  auto m = quad_and_triangle();
  m.positions[2].y = std::numeric_limits<float>::quiet_NaN();
  auto s = tessera::validate_mesh(m, "glm mesh");
  CHECK(s.code() == tessera::status_code::invalid_argument);
  CHECK(s.message().find("glm mesh: vertex 2") != std::string::npos);

  m = quad_and_triangle();
  m.corner_uvs[4].x = std::numeric_limits<float>::infinity();
  s = tessera::validate_mesh(m);
  CHECK(s.message().find("face 1 corner 1") != std::string::npos);

  m = quad_and_triangle();
  m.triangles[2].z = 7;
  s = tessera::validate_mesh(m);
  CHECK(s.code() == tessera::status_code::out_of_range);
  CHECK(s.message().find("refers to vertex 7") != std::string::npos);
  CHECK_FALSE(tessera::to_tri_mesh(m).ok());
}
