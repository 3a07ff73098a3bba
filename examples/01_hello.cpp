// 01_hello: the smallest tessera program. Pixels that belong to the caller (here a std::vector, in an
// engine a locked texture or a staging buffer) are viewed in place and tessera works on them through
// the Image concept: no copy into a tessera type, no conversion by hand.
// Usage: example_01_hello [OUTPUT_DIR]   (writes OUTPUT_DIR/01_hello.png)
// [snippet:hello]
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  // The caller's pixels: 96 x 64 RGBA, 8 bits per channel, rows packed.
  std::vector<std::uint8_t> pixels(96 * 64 * 4);
  auto view = tessera::make_image_view<4>(pixels.data(), 96, 64);  // checks size, stride, null
  if (!view) return std::fprintf(stderr, "%s\n", view.error().to_string().c_str()), 1;

  // Fill them with a procedural exemplar (float RGB, converted to RGBA8 on the way) ...
  auto bricks = tessera::make_exemplar<float, 3>(tessera::exemplar_kind::bricks, {.width = 96, .height = 64});
  if (!bricks) return std::fprintf(stderr, "%s\n", bricks.error().to_string().c_str()), 1;
  if (auto s = tessera::copy_image(*bricks, *view); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;

  // ... and save the caller's pixels: any Image can be written.
  const std::string path = dir + "/01_hello.png";
  if (auto s = tessera::write_png(path, *view); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
  std::printf("wrote %s (%td x %td RGBA8)\n", path.c_str(), view->width(), view->height());
  return 0;
}
// [/snippet]
