// 09_openmesh: OpenMesh meshes through tessera (link tessera::openmesh). tessera reads an OpenMesh
// TriMesh or PolyMesh in place through mesh_traits; validate_mesh tells what must be fixed first
// (quads: triangulate(); deleted elements: garbage_collection()); to_openmesh hands tessera's
// results back to OpenMesh, whose writers then save them.
// Usage: example_09_openmesh [OUTPUT_DIR]   (writes 09_openmesh.obj)
#include <OpenMesh/Core/IO/MeshIO.hh>  // OpenMesh wants its IO header before the mesh types

#include <tessera/adapters/openmesh.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

// A wavy n x n quad sheet, as a modelling tool would hand it over.
PolyMesh make_sheet(int n) {
  PolyMesh m;
  std::vector<PolyMesh::VertexHandle> v;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x)
      v.push_back(m.add_vertex(
          PolyMesh::Point(float(x), float(y), 0.3f * std::sin(0.8f * float(x)) * std::cos(0.6f * float(y)))));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x;
      m.add_face(std::vector<PolyMesh::VertexHandle>{v[a], v[a + 1], v[a + n + 2], v[a + n + 1]});
    }
  return m;
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  omlog().disable();  // keep OpenMesh's progress chatter out of the output

  // [snippet:openmesh]
  PolyMesh sheet = make_sheet(12);
  // tessera reads triangles: a quad mesh is reported, not misread.
  std::printf("quads:         %s\n", tessera::validate_mesh(sheet, "sheet").to_string().c_str());
  sheet.triangulate();

  // Deleted elements keep their indices until garbage_collection(); tessera reports them too.
  sheet.request_face_status();
  sheet.request_edge_status();
  sheet.request_vertex_status();
  sheet.delete_face(sheet.face_handle(0), /*delete_isolated_vertices=*/true);
  std::printf("deleted face:  %s\n", tessera::validate_mesh(sheet, "sheet").to_string().c_str());
  sheet.garbage_collection();
  if (auto s = tessera::validate_mesh(sheet, "sheet"); !s) return fail(s);

  // Now every tessera function reads the OpenMesh mesh in place.
  const auto box = tessera::bounding_box(sheet);
  const auto boundary = tessera::boundary_edges(sheet);
  auto triangles = tessera::to_tri_mesh(sheet);  // an owning copy for tessera's algorithms
  if (!triangles) return fail(triangles.error());
  // [/snippet]
  std::printf("sheet: %td vertices, %td triangles, %zu boundary edges, box z in [%.2f, %.2f]\n",
              tessera::num_vertices(sheet), tessera::num_faces(sheet), boundary.size(), box.min.z, box.max.z);

  // [snippet:to-openmesh]
  // A tessera result (here: the sheet plus a copy lifted above it) goes back to OpenMesh ...
  tessera::tri_mesh result = *triangles;
  result.append(*triangles, {0, 0, 2});
  auto om = tessera::to_openmesh(result);  // OpenMesh::TriMesh_ArrayKernelT<> by default
  if (!om) return fail(om.error());
  // ... and OpenMesh's own writers save it.
  const std::string path = dir + "/09_openmesh.obj";
  if (!OpenMesh::IO::write_mesh(*om, path)) return fail(tessera::status::io_error(path + ": OpenMesh cannot write"));
  // [/snippet]
  std::printf("result: %zu vertices, %zu faces, %td components\n", om->n_vertices(), om->n_faces(),
              tessera::connected_components(*om).count);
  std::printf("wrote %s\n", path.c_str());
  return 0;
}
