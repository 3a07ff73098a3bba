// A consumer's use of tessera::openmesh: an OpenMesh mesh through tessera and back.
#include <tessera/adapters/openmesh.hpp>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstdio>

int main() {
  OpenMesh::TriMesh_ArrayKernelT<> m;
  m.add_face(m.add_vertex({0, 0, 0}), m.add_vertex({1, 0, 0}), m.add_vertex({0, 1, 0}));
  auto tm = tessera::to_tri_mesh(m);
  if (!tm) return std::fprintf(stderr, "%s\n", tm.error().to_string().c_str()), 1;
  auto back = tessera::to_openmesh(*tm);
  if (!back || back->n_faces() != 1) return std::fprintf(stderr, "to_openmesh failed\n"), 1;
  std::printf("consumer: OpenMesh triangle through tessera and back\n");
  return 0;
}
