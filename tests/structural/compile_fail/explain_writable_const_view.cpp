// expect: tessera::WritableImage: the type cannot be written
#include <cstdint>
#include <tessera/core/explain.hpp>
#include <tessera/core/image_view.hpp>
int main() { tessera::explain_writable_image<tessera::image_view<const std::uint8_t, 3>>(); }
