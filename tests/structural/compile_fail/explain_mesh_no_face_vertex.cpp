// expect: the type has no face_vertex\(f, k\)
#include <tessera/core/explain.hpp>
struct mesh {
  int num_vertices() const { return 0; }
  int num_faces() const { return 0; }
};
int main() { tessera::explain_mesh<mesh>(); }
