// expect: tessera::Mesh: the type has no num_vertices\(\)/num_faces\(\)
#include <tessera/core/explain.hpp>
struct mesh {
  int face_vertex(int, int) const { return 0; }
};
int main() { tessera::explain_mesh<mesh>(); }
