// build_polycube_map (surface/build_polycube_map.hpp) over OpenMesh meshes through
// tessera/adapters/openmesh.hpp: the same polycube as from the tri_mesh the OpenMesh mesh came from,
// and the input checks on an open OpenMesh mesh.
#include <tessera/adapters/openmesh.hpp>
#include <tessera/surface/build_polycube_map.hpp>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <catch2/catch.hpp>

#include <string>

#include "../surface/shapes.hpp"

namespace {
struct PolycubeTraits : OpenMesh::DefaultTraits {  // double positions: the same input as the tri_mesh
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolycubeOM = OpenMesh::TriMesh_ArrayKernelT<PolycubeTraits>;
}  // namespace

TEST_CASE("polycube: an OpenMesh sphere and torus give the polycube of the tri_mesh they came from") {
  for (const auto& tm : {shapes::sphere(8), shapes::torus(2, 0.7, 48, 16)}) {
    auto om = tessera::to_openmesh<PolycubeOM>(tm);
    REQUIRE(om.ok());
    tessera::polycube_options o;
    o.tiles_across = 6;
    const auto a = tessera::build_polycube_map(tm, o);
    const auto b = tessera::build_polycube_map(*om, o);
    INFO(a.error().to_string() << " / " << b.error().to_string());
    REQUIRE(a);
    REQUIRE(b);
    CHECK(b->charts.size() == a->charts.size());
    CHECK(b->corners.size() == a->corners.size());
    CHECK(b->layout.quads.size() == a->layout.quads.size());
    REQUIRE(b->polycube.size() == a->polycube.size());
    for (std::size_t v = 0; v < a->polycube.size(); ++v) CHECK(distance(a->polycube[v], b->polycube[v]) < 1e-6);
  }
}

TEST_CASE("polycube: an open OpenMesh mesh is refused with a status") {
  auto tm = shapes::voxel_surface(shapes::cube(), 2);
  tm.faces.pop_back();
  auto om = tessera::to_openmesh<PolycubeOM>(tm);
  REQUIRE(om.ok());
  const auto r = tessera::build_polycube_map(*om);
  REQUIRE(!r);
  CHECK(r.error().message().find("not closed") != std::string::npos);
}
