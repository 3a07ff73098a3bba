#include <tessera/core/tri_mesh.hpp>
#include <tessera/core/mesh_topology.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include "../support/test_support.hpp"

using tessera_test::mentions;

using tessera::index_t;
using tessera::status_code;
using tessera::tri_mesh;
using tessera::vec2;
using tessera::vec3;

namespace {
// A unit right tetrahedron with outward-facing counter-clockwise faces.
tri_mesh tetrahedron() {
  tri_mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}
}  // namespace

static_assert(tessera::Mesh<tri_mesh> && tessera::UVMesh<tri_mesh>);

// A mesh type from a library whose namespace has Boost.Graph-style free functions of the same names
// (CGAL, BGL adaptors): tessera must not pick those up through argument-dependent lookup.
namespace graphlib {
struct surface {
  std::vector<tessera::vec3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
};
inline int num_vertices(const surface&) { return -99; }  // a different meaning: must never be called
inline int num_faces(const surface&) { return -99; }
inline bool has_uvs(const surface&) { return true; }
}  // namespace graphlib
template <>
struct tessera::mesh_traits<graphlib::surface> {
  static index_t num_vertices(const graphlib::surface& s) { return static_cast<index_t>(s.pts.size()); }
  static index_t num_faces(const graphlib::surface&) { return 1; }
  static index_t face_vertex(const graphlib::surface&, index_t, int k) { return k; }
  static const vec3& position(const graphlib::surface& s, index_t v) { return s.pts[static_cast<std::size_t>(v)]; }
};

TEST_CASE("tri_mesh: building and appending", "[tri_mesh]") {
  tri_mesh m;
  REQUIRE(m.add_vertex({0, 0, 0}) == 0);
  REQUIRE(m.add_vertex({1, 0, 0}) == 1);
  REQUIRE(m.add_vertex({0, 1, 0}) == 2);
  REQUIRE(m.add_face(0, 1, 2) == 0);
  REQUIRE_FALSE(m.has_uvs());
  REQUIRE(tessera::validate_mesh(m).ok());

  tri_mesh a = tetrahedron();
  a.append(m, {10, 0, 0});
  REQUIRE(a.num_vertices() == 7);
  REQUIRE(a.num_faces() == 5);
  REQUIRE(a.faces[4] == std::array<index_t, 3>{4, 5, 6});
  REQUIRE(a.positions[5] == vec3{11, 0, 0});
  REQUIRE(tessera::validate_mesh(a).ok());

  // uvs survive an append only when both sides have them (or the target has no faces yet)
  tri_mesh u;
  u.add_vertex({0, 0, 0});
  u.add_vertex({1, 0, 0});
  u.add_vertex({0, 1, 0});
  u.add_face(0, 1, 2, {vec2{0, 0}, vec2{1, 0}, vec2{0, 1}});
  REQUIRE(u.has_uvs());
  tri_mesh empty;
  empty.append(u);
  REQUIRE(empty.uvs.size() == 1);
  empty.append(u);
  REQUIRE(empty.uvs.size() == 2);
  REQUIRE(tessera::validate_mesh(empty).ok());
  tri_mesh points_only;
  points_only.add_vertex({7, 7, 7});
  empty.append(points_only);  // no faces: the uvs stay
  REQUIRE(empty.uvs.size() == 2);
  REQUIRE(tessera::validate_mesh(empty).ok());
  empty.append(m);  // m has faces without uvs: the result has none
  REQUIRE_FALSE(empty.has_uvs());
  REQUIRE(tessera::validate_mesh(empty).ok());
  REQUIRE(empty.num_faces() == 3);
  REQUIRE(empty.num_vertices() == 10);
}

TEST_CASE("tri_mesh: validate_mesh reports each problem", "[tri_mesh]") {
  REQUIRE(tessera::validate_mesh(tetrahedron()).ok());
  REQUIRE(tessera::validate_mesh(tri_mesh{}).ok());  // empty is valid

  tri_mesh m = tetrahedron();
  m.faces[2][1] = 4;
  auto s = tessera::validate_mesh(m, "shell");
  REQUIRE(s.code() == status_code::out_of_range);
  REQUIRE(s.message() == "shell: face 2 corner 1 refers to vertex 4 but the mesh has 4 vertices");
  m.faces[2][1] = -1;
  REQUIRE(tessera::validate_mesh(m).code() == status_code::out_of_range);

  m = tetrahedron();
  m.faces[3] = {1, 2, 1};
  s = tessera::validate_mesh(m);
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(mentions(s, "face 3 is degenerate"));

  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()}) {
    m = tetrahedron();
    m.positions[2].z = bad;
    s = tessera::validate_mesh(m);
    REQUIRE(s.code() == status_code::invalid_argument);
    REQUIRE(mentions(s, "vertex 2 has a non-finite position"));
  }

  m = tetrahedron();
  m.uvs.resize(3);  // fewer uv triples than faces
  s = tessera::validate_mesh(m);
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(mentions(s, "3 uv triples for 4 faces"));
  m.uvs.resize(4);
  REQUIRE(tessera::validate_mesh(m).ok());
  m.uvs[1][2].y = std::numeric_limits<double>::quiet_NaN();
  s = tessera::validate_mesh(m);
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(mentions(s, "face 1 corner 2 has a non-finite uv"));
  REQUIRE(tessera::to_tri_mesh(m).error().code() == status_code::invalid_argument);

  // zero-area faces with distinct vertices are accepted
  tri_mesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  flat.faces = {{0, 1, 2}};
  REQUIRE(tessera::validate_mesh(flat).ok());
}

TEST_CASE("tri_mesh: normals, areas and bounding box", "[tri_mesh]") {
  const tri_mesh m = tetrahedron();
  const auto fn = tessera::face_normals(m);
  REQUIRE(fn[0] == vec3{0, 0, -1});
  REQUIRE(fn[1] == vec3{0, -1, 0});
  REQUIRE(fn[2] == vec3{-1, 0, 0});
  const double s = 1 / std::sqrt(3.0);
  REQUIRE(fn[3].x == Approx(s));
  REQUIRE(fn[3].y == Approx(s));
  REQUIRE(fn[3].z == Approx(s));
  REQUIRE(tessera::face_area(m, 0) == 0.5);
  REQUIRE(tessera::face_area(m, 3) == Approx(std::sqrt(3.0) / 2));
  REQUIRE(tessera::face_area_normal(m, 0) == vec3{0, 0, -1});
  const auto corners = tessera::face_corners(m, 1);
  REQUIRE(corners[2] == vec3{0, 0, 1});

  // vertex normals point outwards: the apex (1,0,0) averages the -z, -y and slanted faces
  const auto vn = tessera::vertex_normals(m);
  for (index_t v = 0; v < 4; ++v) {
    REQUIRE(tessera::norm(vn[static_cast<std::size_t>(v)]) == Approx(1.0));
    REQUIRE(tessera::dot(vn[static_cast<std::size_t>(v)],
                         m.positions[static_cast<std::size_t>(v)] - vec3{0.25, 0.25, 0.25}) > 0);
  }

  const auto box = tessera::bounding_box(m);
  REQUIRE(box.min == vec3{0, 0, 0});
  REQUIRE(box.max == vec3{1, 1, 1});
  REQUIRE(tessera::bounding_box(tri_mesh{}).empty());

  // a zero-area face has a zero normal; an unused vertex a zero vertex normal
  tri_mesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
  flat.faces = {{0, 1, 2}};
  REQUIRE(tessera::face_normals(flat)[0] == vec3{});
  REQUIRE(tessera::vertex_normals(flat)[3] == vec3{});
}

TEST_CASE("tri_mesh: same-named free functions in a mesh type's namespace are not used", "[tri_mesh]") {
  const graphlib::surface s;
  REQUIRE(tessera::validate_mesh(s).ok());
  const auto t = tessera::to_tri_mesh(s);
  REQUIRE(t->num_vertices() == 3);
  REQUIRE(t->num_faces() == 1);
  REQUIRE_FALSE(t->has_uvs());
  REQUIRE(tessera::vertex_normals(s).size() == 3);
  REQUIRE(tessera::bounding_box(s).max == vec3{1, 1, 0});
  REQUIRE(tessera::face_adjacency(s).boundary_edges == 3);
  REQUIRE(tessera::connected_components(s).count == 1);
}
