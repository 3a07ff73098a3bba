// 20_image_quilting: Efros-Freeman image quilting on procedural exemplars, a seamless (toroidal)
// texture shown repeated 3 x 3 next to a plain one, and a hole filled by constrained quilting.
// Usage: example_20_image_quilting [OUTPUT_DIR]
//   writes quilt_kinds.png, seamless_3x3.png, plain_3x3.png, inpaint.png (docs/images/wang/)
#include <tessera/core/executor.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/constrained_quilt.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/quilt.hpp>
#include <tessera/io/png.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using tessera::index_t;
using rgb8 = tessera::image_buffer<std::uint8_t, 3>;

namespace {

// Places images side by side with a white gap (pictures for the docs).
rgb8 side_by_side(const std::vector<const rgb8*>& images, index_t gap = 6) {
  index_t w = 0, h = 0;
  for (const rgb8* i : images) w += i->width() + gap, h = std::max(h, i->height());
  rgb8 out(w - gap, h, {255, 255, 255});
  index_t x0 = 0;
  for (const rgb8* i : images) {
    for (index_t y = 0; y < i->height(); ++y)
      for (index_t x = 0; x < i->width(); ++x) out.write(x0 + x, y, i->read(x, y));
    x0 += i->width() + gap;
  }
  return out;
}

rgb8 repeat(const rgb8& img, int times) {
  rgb8 out(img.width() * times, img.height() * times);
  for (index_t y = 0; y < out.height(); ++y)
    for (index_t x = 0; x < out.width(); ++x) out.write(x, y, img.read(x % img.width(), y % img.height()));
  return out;
}

bool save(const std::string& path, const rgb8& img) {
  if (auto s = tessera::write_png(path, img); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), false;
  std::printf("wrote %s (%td x %td)\n", path.c_str(), img.width(), img.height());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::thread_pool_executor pool;

  // 1. Quilting: exemplar next to a larger output, for three kinds of texture.
  std::vector<rgb8> pictures;
  for (auto kind : {tessera::exemplar_kind::bricks, tessera::exemplar_kind::cells, tessera::exemplar_kind::grass}) {
    // [snippet:quilt]
    auto exemplar = tessera::make_exemplar<std::uint8_t, 3>(kind, {.width = 96, .height = 96, .seed = 2});
    if (!exemplar) return std::fprintf(stderr, "%s\n", exemplar.error().to_string().c_str()), 1;
    tessera::image_buffer<std::uint8_t, 3> out(192, 192);
    auto s = tessera::quilt(*exemplar, out, {.patch_size = 24, .overlap = 5, .seed = 7}, pool);
    // [/snippet]
    if (!s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
    pictures.push_back(*exemplar);
    pictures.push_back(out);
  }
  std::vector<const rgb8*> row;
  for (const rgb8& p : pictures) row.push_back(&p);
  if (!save(dir + "/quilt_kinds.png", side_by_side(row))) return 1;

  // 2. Seamless output: synthesized on a torus, it repeats without seams; a plain one does not.
  auto cells =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, {.width = 96, .height = 96, .seed = 5});
  rgb8 seamless(128, 128), plain(128, 128);
  // [snippet:seamless]
  auto s1 = tessera::quilt(*cells, seamless, {.patch_size = 24, .overlap = 6, .seamless = true}, pool);
  // [/snippet]
  auto s2 = tessera::quilt(*cells, plain, {.patch_size = 24, .overlap = 6}, pool);
  if (!s1 || !s2) return std::fprintf(stderr, "%s %s\n", s1.to_string().c_str(), s2.to_string().c_str()), 1;
  if (!save(dir + "/seamless_3x3.png", repeat(seamless, 3)) || !save(dir + "/plain_3x3.png", repeat(plain, 3)))
    return 1;

  // 3. Inpainting: a disc-shaped hole filled from the rest of the image; pixels outside the hole
  //    are untouched, bit for bit.
  auto wall =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::bricks, {.width = 192, .height = 192, .seed = 9});
  tessera::image_buffer<std::uint8_t, 1> mask(192, 192);
  for (index_t y = 0; y < 192; ++y)
    for (index_t x = 0; x < 192; ++x)
      if (std::hypot(double(x) - 100, double(y) - 90) < 44) mask.write(x, y, {255});
  rgb8 filled(192, 192), shown = *wall;
  // [snippet:inpaint]
  auto s3 = tessera::constrained_quilt(*wall, mask, filled, {.patch_size = 20, .overlap = 5}, pool);
  // [/snippet]
  if (!s3) return std::fprintf(stderr, "%s\n", s3.to_string().c_str()), 1;
  for (index_t y = 0; y < 192; ++y)
    for (index_t x = 0; x < 192; ++x)
      if (mask.read(x, y)[0]) shown.write(x, y, {255, 0, 255});
  return save(dir + "/inpaint.png", side_by_side({&shown, &filled})) ? 0 : 1;
}
