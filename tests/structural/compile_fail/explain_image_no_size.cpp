// expect: tessera::Image: the type has no width\(\)/height\(\)
#include <tessera/core/explain.hpp>
struct texture {
  float read(tessera::index_t, tessera::index_t) const { return 0; }
};
int main() { tessera::explain_image<texture>(); }
