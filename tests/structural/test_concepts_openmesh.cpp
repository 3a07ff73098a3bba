// Concept checks for the OpenMesh adapter (built only when OpenMesh is found).
#include <tessera/adapters/openmesh.hpp>
#include <tessera/core/explain.hpp>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <catch2/catch.hpp>

namespace {
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
struct DerivedMesh : OpenMesh::TriMesh_ArrayKernelT<DoubleTraits> {};
}  // namespace

static_assert(tessera::UVMesh<OpenMesh::TriMesh_ArrayKernelT<>>);
static_assert(tessera::UVMesh<OpenMesh::PolyMesh_ArrayKernelT<>>);
static_assert(tessera::UVMesh<DerivedMesh>);
static_assert(tessera::Point<OpenMesh::Vec3f> && tessera::Point<OpenMesh::Vec2d>);
static_assert(!tessera::Mesh<OpenMesh::Vec3f>);
static_assert(!tessera::Image<OpenMesh::TriMesh_ArrayKernelT<>>);

TEST_CASE("explain_mesh compiles to nothing for OpenMesh meshes") {
  tessera::explain_mesh<OpenMesh::TriMesh_ArrayKernelT<>>();
  tessera::explain_mesh<OpenMesh::PolyMesh_ArrayKernelT<>>();
  tessera::explain_mesh<DerivedMesh>();
  CHECK(tessera::to_vec3(OpenMesh::Vec2f(1, 2)) == tessera::vec3{1, 2, 0});
}
