// prepare_terrain_mesh (paper 003's per-mesh preparation) over OpenMesh meshes through
// tessera/adapters/openmesh.hpp: the same adjacency as from a tri_mesh, and the adapter's checks.
#include <tessera/adapters/openmesh.hpp>
#include <tessera/terrain/assign_scale_field.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/prepare_terrain_mesh.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/synthesize_triangles.hpp>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace {
struct TerrainTraits : OpenMesh::DefaultTraits {  // double positions, as an engine's terrain would keep them
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TerrainOM = OpenMesh::TriMesh_ArrayKernelT<TerrainTraits>;

std::array<std::int32_t, 3> sorted(std::array<std::int32_t, 3> a) {
  std::sort(a.begin(), a.end());
  return a;
}
}  // namespace

TEST_CASE("prepare_terrain_mesh: an OpenMesh terrain gives the same faces and adjacency as the tri_mesh it came from") {
  const auto tm = tessera::make_terrain({.cells_x = 9, .cells_y = 7, .seed = 3}).value();
  auto om = tessera::to_openmesh<TerrainOM>(tm);
  REQUIRE(om.ok());
  const auto a = tessera::prepare_terrain_mesh(tm).value();
  const auto b = tessera::prepare_terrain_mesh(*om, "openmesh terrain").value();
  REQUIRE(b.positions == a.positions);
  REQUIRE(b.num_faces() == a.num_faces());
  REQUIRE(b.interior_edges == a.interior_edges);
  REQUIRE(b.boundary_edges == a.boundary_edges);
  REQUIRE(b.nonmanifold_edges == 0);
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    // OpenMesh may start a face at another corner: same vertices, and the neighbour across each
    // side (named by its two vertices) is the same face
    REQUIRE(sorted(b.faces[f]) == sorted(a.faces[f]));
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t u = b.faces[f][k], v = b.faces[f][(k + 1) % 3];
      for (std::size_t j = 0; j < 3; ++j) {
        const std::int32_t p = a.faces[f][j], q = a.faces[f][(j + 1) % 3];
        if ((p == u && q == v) || (p == v && q == u)) REQUIRE(b.neighbors[f][k] == a.neighbors[f][j]);
      }
    }
  }
  // and the per-frame pipeline runs on it
  const auto cam =
      tessera::make_camera_preset(tessera::camera_preset::oblique, tessera::bounding_box(b), 96, 64).value();
  const auto proj = tessera::project_mesh(b, cam).value();
  REQUIRE(proj.num_visible() == b.num_faces());
  const auto field = tessera::assign_scale_field(b, proj).value();
  REQUIRE(field.max_level_jump <= 1);
  const auto syn = tessera::synthesize_triangles(b, proj, field, 64, 64).value();
  REQUIRE(static_cast<std::size_t>(syn.visible) == b.faces.size());
  REQUIRE(syn.shared_edges == b.interior_edges);
}

TEST_CASE("prepare_terrain_mesh: OpenMesh meshes with deleted elements or polygons are refused") {
  auto om = tessera::to_openmesh<TerrainOM>(tessera::make_terrain({.cells_x = 3, .cells_y = 3}).value()).value();
  om.request_face_status();
  om.request_edge_status();
  om.request_vertex_status();
  om.delete_face(om.face_handle(4), false);
  const auto r = tessera::prepare_terrain_mesh(om, "scan");
  REQUIRE_FALSE(r);
  REQUIRE(r.error().message().find("garbage_collection()") != std::string::npos);
  om.garbage_collection();
  const auto ok = tessera::prepare_terrain_mesh(om).value();
  REQUIRE(ok.num_faces() == 17);
  REQUIRE(tessera::validate_terrain_mesh(ok));

  OpenMesh::PolyMesh_ArrayKernelT<> quad;
  std::vector<OpenMesh::PolyMesh_ArrayKernelT<>::VertexHandle> v;
  for (int i = 0; i < 4; ++i)
    v.push_back(quad.add_vertex({static_cast<float>(i & 1), static_cast<float>(i >> 1), 0.0f}));
  quad.add_face(std::vector<OpenMesh::PolyMesh_ArrayKernelT<>::VertexHandle>{v[0], v[1], v[3], v[2]});
  REQUIRE_FALSE(tessera::prepare_terrain_mesh(quad));
}
