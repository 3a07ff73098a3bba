// expect: the type has no read\(x, y\)
#include <tessera/core/explain.hpp>
struct texture {
  int width() const { return 1; }
  int height() const { return 1; }
};
int main() { tessera::explain_image<texture>(); }
