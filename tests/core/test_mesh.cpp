#include <tessera/core/mesh.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::vec2;
using tessera::vec3;

namespace {
struct xyz {
  float x, y, z;
};
struct xy {
  double x, y;
};
// member-style mesh with its own point type
struct member_mesh {
  std::vector<xyz> pts;
  std::vector<int> tris;
  std::size_t num_vertices() const { return pts.size(); }
  std::size_t num_faces() const { return tris.size() / 3; }
  int face_vertex(index_t f, int k) const { return tris[static_cast<std::size_t>(3 * f + k)]; }
  const xyz& position(index_t v) const { return pts[static_cast<std::size_t>(v)]; }
};
// member-style mesh with uvs
struct uv_mesh : member_mesh {
  std::vector<xy> uv;  // per corner
  bool has_uvs() const { return !uv.empty(); }
  xy corner_uv(index_t f, int k) const { return uv[static_cast<std::size_t>(3 * f + k)]; }
};
// a foreign mesh reached through a mesh_traits specialization
struct soup {
  std::vector<std::array<double, 3>> corners;  // three per triangle, no sharing
};
struct no_position_mesh {
  index_t num_vertices() const { return 0; }
  index_t num_faces() const { return 0; }
  index_t face_vertex(index_t, int) const { return 0; }
};
}  // namespace

template <>
struct tessera::mesh_traits<soup> {
  static index_t num_vertices(const soup& s) { return static_cast<index_t>(s.corners.size()); }
  static index_t num_faces(const soup& s) { return static_cast<index_t>(s.corners.size() / 3); }
  static index_t face_vertex(const soup&, index_t f, int k) { return 3 * f + k; }
  static const std::array<double, 3>& position(const soup& s, index_t v) {
    return s.corners[static_cast<std::size_t>(v)];
  }
};

static_assert(tessera::Point<xyz> && tessera::Point<xy> && tessera::Point<std::array<float, 3>> &&
              tessera::Point<vec3>);
static_assert(!tessera::Point<int> && !tessera::Point<std::vector<int>*>);
static_assert(tessera::Mesh<member_mesh> && !tessera::UVMesh<member_mesh>);
static_assert(tessera::Mesh<uv_mesh> && tessera::UVMesh<uv_mesh>);
static_assert(tessera::Mesh<soup> && !tessera::UVMesh<soup>);
static_assert(!tessera::Mesh<no_position_mesh> && !tessera::Mesh<int>);

TEST_CASE("mesh: point_traits reads any vector type", "[mesh]") {
  REQUIRE(tessera::to_vec3(xyz{1, 2, 3}) == vec3{1, 2, 3});
  REQUIRE(tessera::to_vec3(xy{1, 2}) == vec3{1, 2, 0});  // missing z reads 0
  REQUIRE(tessera::to_vec3(std::array<float, 3>{4, 5, 6}) == vec3{4, 5, 6});
  // a 2D array: z is not read past the end (this would be caught by ASan otherwise)
  const std::array<double, 2> two{7, 8};
  REQUIRE(tessera::to_vec3(two) == vec3{7, 8, 0});
  REQUIRE(tessera::to_vec2(std::array<float, 3>{1, 2, 3}) == vec2{1, 2});
  REQUIRE(tessera::to_vec2(vec3{9, 8, 7}) == vec2{9, 8});
  REQUIRE(tessera::detail::static_point_size<std::array<float, 2>>() == 2);
  REQUIRE(tessera::detail::static_point_size<vec3>() == -1);
}

TEST_CASE("mesh: traits reach member-style and specialized meshes", "[mesh]") {
  uv_mesh m;
  m.pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.tris = {0, 1, 2, 2, 1, 3};
  REQUIRE(tessera::num_vertices(m) == 4);
  REQUIRE(tessera::num_faces(m) == 2);
  REQUIRE(tessera::face_vertex(m, 1, 2) == 3);
  REQUIRE(tessera::vertex_position(m, 3) == vec3{1, 1, 0});
  REQUIRE_FALSE(tessera::has_uvs(m));
  m.uv = {{0, 0}, {1, 0}, {0, 1}, {0, 1}, {1, 0}, {1, 1}};
  REQUIRE(tessera::has_uvs(m));
  REQUIRE(tessera::corner_uv(m, 1, 2) == vec2{1, 1});
  const member_mesh& base = m;
  REQUIRE_FALSE(tessera::has_uvs(base));  // not a UVMesh: never has uvs

  soup s{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}}};
  REQUIRE(tessera::num_faces(s) == 2);
  REQUIRE(tessera::face_vertex(s, 1, 0) == 3);
  REQUIRE(tessera::vertex_position(s, 4) == vec3{6, 5, 5});
}
