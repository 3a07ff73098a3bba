// Example 32: a fabric texture for an engine in a few lines (paper 001): design a source from main
// tones, weave it with the cat map, roughen it with the game-of-life perturbation, and tile the
// periodic result over any texture size without seams.
//
//   example_32_fabric_texture [OUTPUT_DIR]      (writes fabric_texture.png; default: the current directory)
#include <cstdio>
#include <string>

#include <tessera/fabric/make_fabric.hpp>
#include <tessera/fabric/tone_proportions.hpp>
#include <tessera/io/png.hpp>

int main(int argc, char** argv) {
  const std::string path = std::string(argc > 1 ? argv[1] : ".") + "/fabric_texture.png";
  // [snippet:fabric_texture]
  // main tones of a heather-green tweed, as relative weights
  auto tones = tessera::parse_palette("#1f3324:5,#4f6b3f:3,#b8b08a:1.5,#7a2e22:0.5");
  if (!tones) return std::fprintf(stderr, "%s\n", tones.error().to_string().c_str()), 1;
  tessera::image_buffer<std::uint8_t, 4> texture(1024, 512);  // an RGBA engine texture
  tessera::thread_pool_executor pool;
  const tessera::fabric_options options{.iterations = 45,
                                        .perturbation = {.generations = 3, .seed = 7},
                                        .tile_size = 512};  // weave 512 x 512, tile it twice
  if (auto s =
          tessera::make_fabric(*tones, {.layout = tessera::source_layout::blocks, .seed = 7}, texture, options, pool);
      !s)
    return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
  // [/snippet]
  if (auto s = tessera::write_png(path, texture); !s) return std::fprintf(stderr, "%s\n", s.to_string().c_str()), 1;
  // the weave only rearranges pixels and the perturbation only changes lightness, so the main tones stay
  const auto shares = tessera::dominant_tones(texture, 4);
  if (!shares) return std::fprintf(stderr, "%s\n", shares.error().to_string().c_str()), 1;
  std::printf("wrote %s; dominant tones:", path.c_str());
  for (const auto& t : *shares)
    std::printf(" #%02x%02x%02x %.0f%%", static_cast<int>(t.color[0] * 255 + 0.5f),
                static_cast<int>(t.color[1] * 255 + 0.5f), static_cast<int>(t.color[2] * 255 + 0.5f),
                100 * t.proportion);
  std::printf("\n");
  return 0;
}
