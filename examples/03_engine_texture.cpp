// 03_engine_texture: an engine's texture class whose names tessera cannot guess (GetWidth, GetTexel,
// packed 0xAABBGGRR texels) is adapted by specializing tessera::image_traits: four static functions,
// no change to the engine's class. Pixels travel by value, so packed formats fit.
// Usage: example_03_engine_texture [OUTPUT_DIR]   (writes 03_engine_texture.png and _grey16.png)
#include <tessera/core/explain.hpp>
#include <tessera/core/image.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

// [snippet:engine-texture]
namespace engine {  // the engine's code, untouched
class Texture2D {
 public:
  Texture2D(std::uint32_t w, std::uint32_t h) : w_(w), h_(h), texels_(std::size_t(w) * h) {}
  std::uint32_t GetWidth() const { return w_; }
  std::uint32_t GetHeight() const { return h_; }
  std::uint32_t GetTexel(std::uint32_t x, std::uint32_t y) const { return texels_[std::size_t(y) * w_ + x]; }
  void SetTexel(std::uint32_t x, std::uint32_t y, std::uint32_t abgr) { texels_[std::size_t(y) * w_ + x] = abgr; }

 private:
  std::uint32_t w_, h_;
  std::vector<std::uint32_t> texels_;
};
}  // namespace engine

// The adapter: one specialization, next to the engine's code or in the application.
template <>
struct tessera::image_traits<engine::Texture2D> {
  using rgba8 = tessera::pixel<std::uint8_t, 4>;
  static index_t width(const engine::Texture2D& t) { return t.GetWidth(); }
  static index_t height(const engine::Texture2D& t) { return t.GetHeight(); }
  static rgba8 read(const engine::Texture2D& t, index_t x, index_t y) {
    const std::uint32_t v = t.GetTexel(std::uint32_t(x), std::uint32_t(y));
    return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
  }
  static void write(engine::Texture2D& t, index_t x, index_t y, const rgba8& p) {
    t.SetTexel(std::uint32_t(x), std::uint32_t(y),
               std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24);
  }
};
// [/snippet]

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::explain_writable_image<engine::Texture2D>();  // a readable compile error if the adapter were incomplete

  engine::Texture2D texture(128, 128);
  auto cells = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, {.width = 128, .height = 128, .seed = 7});
  if (!cells) return fail(cells.error());
  if (auto s = tessera::copy_image(*cells, texture); !s) return fail(s);  // RGB8 -> packed RGBA8 (opaque)

  // Read the engine texture back through the traits: a 16-bit grey copy (Rec. 601 luma).
  auto grey16 = tessera::to_buffer<std::uint16_t, 1>(texture);
  if (!grey16) return fail(grey16.error());

  const std::string path = dir + "/03_engine_texture.png", grey_path = dir + "/03_engine_texture_grey16.png";
  if (auto s = tessera::write_png(path, texture); !s) return fail(s);  // 8-bit RGBA straight from the engine type
  if (auto s = tessera::write_png(grey_path, *grey16); !s) return fail(s);  // 16-bit grey
  std::printf("texel (5, 9) = 0x%08x\nwrote %s\nwrote %s\n", texture.GetTexel(5, 9), path.c_str(), grey_path.c_str());
  return 0;
}
