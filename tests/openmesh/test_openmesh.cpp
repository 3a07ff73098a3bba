// Tests for tessera/adapters/openmesh.hpp: OpenMesh TriMesh / PolyMesh as tessera meshes (index
// order, uvs, core functions), validate_openmesh on quads and deleted elements, and to_openmesh.
#include <tessera/adapters/openmesh.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using tessera::index_t;
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

namespace {

// A user's own mesh class derived from an OpenMesh mesh, with double positions.
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
struct EngineMesh : OpenMesh::TriMesh_ArrayKernelT<DoubleTraits> {};

// A closed cube of 12 triangles (8 vertices), optionally shifted.
template <class M>
void add_cube(M& m, double shift = 0.0) {
  std::vector<typename M::VertexHandle> v;
  for (int i = 0; i < 8; ++i) v.push_back(m.add_vertex(typename M::Point(shift + (i & 1), (i >> 1) & 1, (i >> 2) & 1)));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.add_face(v[q[0]], v[q[1]], v[q[2]]);
    m.add_face(v[q[0]], v[q[2]], v[q[3]]);
  }
}

PolyMesh quad_cube() {
  PolyMesh m;
  std::vector<PolyMesh::VertexHandle> v;
  for (int i = 0; i < 8; ++i) v.push_back(m.add_vertex(PolyMesh::Point(i & 1, (i >> 1) & 1, (i >> 2) & 1)));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) m.add_face(std::vector<PolyMesh::VertexHandle>{v[q[0]], v[q[1]], v[q[2]], v[q[3]]});
  return m;
}

}  // namespace

TEST_CASE("TriMesh, PolyMesh and derived meshes model Mesh and UVMesh") {
  STATIC_REQUIRE(tessera::Mesh<TriMesh>);
  STATIC_REQUIRE(tessera::UVMesh<TriMesh>);
  STATIC_REQUIRE(tessera::Mesh<PolyMesh>);
  STATIC_REQUIRE(tessera::Mesh<EngineMesh>);
}

TEST_CASE("face_vertex follows OpenMesh's own face-vertex order") {
  TriMesh m;
  add_cube(m);
  REQUIRE(tessera::num_faces(m) == 12);
  for (auto f : m.faces()) {
    int k = 0;
    for (auto v : m.fv_range(f)) CHECK(tessera::face_vertex(m, f.idx(), k++) == v.idx());
  }
  // add_face(a, b, c) keeps corner order: corner 0 is a.
  CHECK(tessera::face_vertex(m, 0, 0) == 0);
  CHECK(tessera::face_vertex(m, 0, 1) == 2);
  CHECK(tessera::face_vertex(m, 0, 2) == 3);
  CHECK(tessera::vertex_position(m, 7) == tessera::vec3{1, 1, 1});
}

TEST_CASE("core functions run through the adapter and agree with OpenMesh") {
  EngineMesh m;
  add_cube(m);
  add_cube(m, 3.0);
  REQUIRE(tessera::validate_mesh(m).ok());
  auto tm = tessera::to_tri_mesh(m);
  REQUIRE(tm.ok());
  CHECK(tm->num_vertices() == 16);
  CHECK(tm->num_faces() == 24);
  const auto comp = tessera::connected_components(m);
  CHECK(comp.count == 2);
  CHECK(comp.face_component[11] == 0);
  CHECK(comp.face_component[12] == 1);
  CHECK(tessera::face_adjacency(m).boundary_edges == 0);
  CHECK(tessera::bounding_box(m).max == tessera::vec3{4, 1, 1});

  // Face normals match OpenMesh's own.
  m.request_face_normals();
  m.update_face_normals();
  const auto n = tessera::face_normals(m);
  for (auto f : m.faces()) {
    const auto& on = m.normal(f);
    CHECK(n[static_cast<std::size_t>(f.idx())].x == Approx(on[0]).margin(1e-12));
    CHECK(n[static_cast<std::size_t>(f.idx())].y == Approx(on[1]).margin(1e-12));
    CHECK(n[static_cast<std::size_t>(f.idx())].z == Approx(on[2]).margin(1e-12));
  }
}

TEST_CASE("per-corner uvs come from halfedge or vertex texcoords") {
  TriMesh m;
  const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0});
  m.add_face(a, b, c);
  CHECK_FALSE(tessera::mesh_traits<TriMesh>::has_uvs(m));

  m.request_vertex_texcoords2D();
  m.set_texcoord2D(b, {0.5f, 0.25f});
  auto tm = tessera::to_tri_mesh(m);
  REQUIRE(tm.ok());
  REQUIRE(tm->has_uvs());
  CHECK(tm->uvs[0][1] == tessera::vec2{0.5, 0.25});

  m.request_halfedge_texcoords2D();  // per corner takes precedence
  for (auto h : m.fh_range(m.face_handle(0)))
    m.set_texcoord2D(h, {static_cast<float>(m.to_vertex_handle(h).idx()), 1.0f});
  tm = tessera::to_tri_mesh(m);
  REQUIRE(tm.ok());
  CHECK(tm->uvs[0][2] == tessera::vec2{2, 1});

  m.set_texcoord2D(m.halfedge_handle(m.face_handle(0)), {std::numeric_limits<float>::quiet_NaN(), 0.0f});
  CHECK(tessera::validate_mesh(m).message().find("non-finite uv") != std::string::npos);
}

TEST_CASE("non-triangle faces are reported until the mesh is triangulated") {
  PolyMesh m = quad_cube();
  const auto s = tessera::validate_openmesh(m, "cube");
  CHECK(s.code() == tessera::status_code::invalid_argument);
  CHECK(s.message() ==
        "cube: face 0 has 4 vertices; tessera reads triangle meshes (call triangulate() on the "
        "OpenMesh mesh first)");
  // validate_mesh and to_tri_mesh run the same check, so a quad is never read as a triangle.
  CHECK(tessera::validate_mesh(m).message().find("face 0 has 4 vertices") != std::string::npos);
  CHECK_FALSE(tessera::to_tri_mesh(m).ok());

  m.triangulate();
  REQUIRE(tessera::validate_mesh(m).ok());
  auto tm = tessera::to_tri_mesh(m);
  REQUIRE(tm.ok());
  CHECK(tm->num_faces() == 12);
  CHECK(tessera::face_adjacency(*tm).boundary_edges == 0);
}

TEST_CASE("deleted elements are reported until garbage_collection()") {
  TriMesh m;
  add_cube(m);
  add_cube(m, 3.0);
  m.request_face_status();
  m.request_edge_status();
  m.request_vertex_status();
  m.delete_face(m.face_handle(15), true);
  const auto s = tessera::validate_mesh(m);
  CHECK(s.code() == tessera::status_code::invalid_argument);
  CHECK(s.message().find("garbage_collection()") != std::string::npos);
  CHECK_FALSE(tessera::to_tri_mesh(m).ok());

  m.garbage_collection();
  REQUIRE(tessera::validate_mesh(m).ok());
  CHECK(tessera::num_faces(m) == 23);
  CHECK(tessera::face_adjacency(m).boundary_edges == 3);
}

TEST_CASE("NaN positions are reported") {
  TriMesh m;
  add_cube(m);
  m.point(m.vertex_handle(3))[2] = std::numeric_limits<float>::quiet_NaN();
  const auto s = tessera::validate_mesh(m, "scan");
  CHECK(s.message().find("scan: vertex 3 has a non-finite position") != std::string::npos);
}

TEST_CASE("to_openmesh hands a tri_mesh to OpenMesh and back unchanged") {
  TriMesh src;
  add_cube(src);
  add_cube(src, 3.0);
  auto tm = tessera::to_tri_mesh(src);
  REQUIRE(tm.ok());
  tm->uvs.resize(tm->faces.size());
  for (std::size_t f = 0; f < tm->faces.size(); ++f)
    tm->uvs[f] = {tessera::vec2{0, 0}, tessera::vec2{double(f), 0}, tessera::vec2{0, 1}};

  auto om = tessera::to_openmesh(*tm);
  REQUIRE(om.ok());
  CHECK(om->n_vertices() == 16);
  CHECK(om->n_faces() == 24);
  REQUIRE(om->has_halfedge_texcoords2D());
  auto back = tessera::to_tri_mesh(*om);
  REQUIRE(back.ok());
  CHECK(back->faces == tm->faces);
  CHECK(back->positions == tm->positions);
  CHECK(back->uvs == tm->uvs);

  auto dm = tessera::to_openmesh<EngineMesh>(*tm);
  REQUIRE(dm.ok());
  CHECK(dm->point(dm->vertex_handle(9))[0] == 4.0);
}

TEST_CASE("to_openmesh reports what OpenMesh cannot hold") {
  tessera::tri_mesh fin;  // three triangles sharing edge (0, 1)
  for (int i = 0; i < 5; ++i) fin.add_vertex({double(i), double(i * i % 3), double(i % 2)});
  fin.add_face(0, 1, 2);
  fin.add_face(1, 0, 3);
  fin.add_face(0, 1, 4);
  auto r = tessera::to_openmesh(fin);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().message().find("edge (0, 1) is shared by 3 faces") != std::string::npos);

  tessera::tri_mesh flipped;  // two triangles traversing edge (0, 1) the same way
  for (int i = 0; i < 4; ++i) flipped.add_vertex({double(i & 1), double(i >> 1), 0.0});
  flipped.add_face(0, 1, 2);
  flipped.add_face(0, 1, 3);
  r = tessera::to_openmesh(flipped);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().message().find("faces 0 and 1 are inconsistently oriented") != std::string::npos);

  tessera::tri_mesh bad;
  bad.add_vertex({0, 0, 0});
  bad.add_vertex({1, 0, 0});
  bad.add_vertex({0, 1, 0});
  bad.add_face(0, 1, 5);
  r = tessera::to_openmesh(bad, "result");
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().code() == tessera::status_code::out_of_range);
  CHECK(r.error().message().find("result: face 0") != std::string::npos);
}
