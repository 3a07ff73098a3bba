// expect: channel type must be std::uint8_t, std::uint16_t or float
#include <tessera/core/explain.hpp>
struct height_field {
  int width() const { return 1; }
  int height() const { return 1; }
  double read(tessera::index_t, tessera::index_t) const { return 0; }
};
int main() { tessera::explain_image<height_field>(); }
