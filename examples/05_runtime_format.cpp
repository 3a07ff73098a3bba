// 05_runtime_format: textures whose format is known only at run time (a GPU format enum, a file
// header). dispatch_format turns the runtime (component type, channel count) into the compile-time
// (T, C) that tessera's kernels are instantiated for; the caller writes the work once as a generic
// lambda. Unsupported formats come back as a status, not a crash.
// Usage: example_05_runtime_format [OUTPUT_DIR]   (writes 05_format_<format>.png for four formats)
#include <tessera/core/format.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

// An engine's texture: raw storage plus a format decided at run time.
struct GpuTexture {
  std::string name;
  tessera::pixel_format format;
  std::ptrdiff_t width = 0, height = 0;
  std::unique_ptr<unsigned char[]> bytes;
};

GpuTexture make_texture(std::string name, tessera::pixel_format format, std::ptrdiff_t width, std::ptrdiff_t height) {
  const auto size = std::size_t(width * height * format.channels * tessera::channel_size(format.type));
  return {std::move(name), format, width, height, std::make_unique<unsigned char[]>(size)};
}

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  std::vector<GpuTexture> textures;
  textures.push_back(make_texture("r8", {tessera::channel_type::uint8, 1}, 64, 48));
  textures.push_back(make_texture("rg16", {tessera::channel_type::uint16, 2}, 64, 48));
  textures.push_back(make_texture("rgb32f", {tessera::channel_type::float32, 3}, 64, 48));
  textures.push_back(make_texture("rgba8", {tessera::channel_type::uint8, 4}, 64, 48));

  for (GpuTexture& t : textures) {
    // [snippet:runtime-format]
    // One generic lambda; dispatch_format instantiates it for the (T, C) matching t.format.
    auto s = tessera::dispatch_format(t.format, [&]<class T, int C>(tessera::format_tag<T, C>) -> tessera::status {
      auto view = tessera::make_image_view<C>(reinterpret_cast<T*>(t.bytes.get()), t.width, t.height);
      if (!view) return view.error();
      auto exemplar =
          tessera::make_exemplar<T, C>(tessera::exemplar_kind::grass, {.width = t.width, .height = t.height});
      if (!exemplar) return exemplar.error();
      if (auto c = tessera::copy_image(*exemplar, *view); !c) return c;  // fill the texture
      auto grey = tessera::to_buffer<float, 1>(*view);                   // read it back as float grey
      if (!grey) return grey.error();
      double mean = 0;
      for (std::ptrdiff_t y = 0; y < grey->height(); ++y)
        for (std::ptrdiff_t x = 0; x < grey->width(); ++x) mean += grey->read(x, y)[0];
      std::printf("%-7s %s x %d channels: mean grey %.3f\n", t.name.c_str(),
                  std::string(tessera::to_string(t.format.type)).c_str(), C, mean / double(t.width * t.height));
      return tessera::write_png(dir + "/05_format_" + t.name + ".png", *view);
    });
    // [/snippet]
    if (!s) return fail(s);
    std::printf("wrote %s/05_format_%s.png\n", dir.c_str(), t.name.c_str());
  }

  // A format tessera does not handle is reported, not crashed on.
  const tessera::pixel_format bc7{tessera::channel_type::uint8, 5};
  const auto s = tessera::dispatch_format(bc7, []<class T, int C>(tessera::format_tag<T, C>) {});
  std::printf("5-channel format: %s\n", s.to_string().c_str());
  return 0;
}
