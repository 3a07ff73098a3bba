// Any window of an infinite texture, and aligned maps from one model (paper 002 synthesis; every
// random choice keyed by (seed, cell coordinates)).
//
// A terrain streamer renders 128 x 128 tiles on demand, anywhere in the plane; tiles rendered
// separately and out of order match a single large render bit for bit. The same decisions drive an
// albedo (8-bit RGB), a height map (16-bit grey) and a normal map (float RGB), and a source map says
// where in the exemplar every pixel comes from.
//
// Writes 11_tiles.png (16 separately rendered tiles, their borders marked), 11_albedo.png,
// 11_height.png, 11_normal.png and 11_source.png into the output directory.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include <tessera/core/executor.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/io/png.hpp>

namespace {

using tessera::index_t;

int fail(const tessera::status& s) {
  std::fprintf(stderr, "11_infinite_texture: %s\n", s.to_string().c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::thread_pool_executor pool;

  // exemplar maps: albedo from the procedural rock, height = its grey value, normals from the height
  auto albedo = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::rock, {.width = 128, .height = 128});
  if (!albedo) return fail(albedo.error());
  tessera::image_buffer<std::uint16_t, 1> height(128, 128);
  if (auto s = tessera::copy_image(*albedo, height); !s) return fail(s);
  tessera::image_buffer<float, 3> normal(128, 128);
  for (index_t y = 0; y < 128; ++y)
    for (index_t x = 0; x < 128; ++x) {
      auto h = [&](index_t u, index_t v) {
        return tessera::channel_to_unit(height.read(std::clamp<index_t>(u, 0, 127), std::clamp<index_t>(v, 0, 127))[0]);
      };
      const double dx = 4.0 * (h(x + 1, y) - h(x - 1, y)), dy = 4.0 * (h(x, y + 1) - h(x, y - 1)),
                   len = std::sqrt(dx * dx + dy * dy + 1);
      normal.write(x, y,
                   {static_cast<float>(0.5 - 0.5 * dx / len), static_cast<float>(0.5 - 0.5 * dy / len),
                    static_cast<float>(0.5 + 0.5 / len)});
    }

  // [snippet:patch_synthesis]
  auto model = tessera::build_patch_model(*albedo, {}, pool);
  if (!model) return fail(model.error());
  const tessera::texture_offset far_away{-1'000'000'000, 123'456'789};  // anywhere in the plane
  const tessera::patch_synthesis_options opts{.origin = far_away, .seed = 42};

  // one 512 x 512 render, then the same region as 16 tiles rendered separately, last tile first
  tessera::image_buffer<std::uint8_t, 3> whole(512, 512), tiles(512, 512);
  if (auto s = tessera::synthesize(*model, whole, opts, pool); !s) return fail(s.error());
  for (int t = 15; t >= 0; --t) {
    const index_t tx = (t % 4) * 128, ty = (t / 4) * 128;
    tessera::image_buffer<std::uint8_t, 3> tile(128, 128);
    auto o = opts;
    o.origin = {far_away.x + tx, far_away.y + ty};
    if (auto s = tessera::synthesize(*model, tile, o); !s) return fail(s.error());
    for (index_t y = 0; y < 128; ++y)
      for (index_t x = 0; x < 128; ++x) tiles.write(tx + x, ty + y, tile.read(x, y));
  }
  // [/snippet]
  const bool identical = tiles == whole;
  std::printf("16 tiles rendered separately %s the single 512 x 512 render\n",
              identical ? "are bit-identical to" : "DIFFER from");
  for (index_t i = 0; i < 512; ++i)
    for (index_t k = 128; k < 512; k += 128) {  // mark the tile borders (one pixel, for the picture only)
      tiles.write(k, i, {255, 255, 255});
      tiles.write(i, k, {255, 255, 255});
    }
  if (auto s = tessera::write_png(dir + "/11_tiles.png", tiles); !s) return fail(s);

  // aligned maps: the same cells and weights, other pixel types
  // [snippet:patch_aligned]
  tessera::image_buffer<std::uint16_t, 1> out_height(256, 256);
  tessera::image_buffer<float, 3> out_normal(256, 256);
  tessera::image_buffer<std::uint8_t, 3> out_albedo(256, 256);
  tessera::image_buffer<std::uint16_t, 2> source(256, 256);
  if (auto s = tessera::synthesize(*model, out_albedo, opts, pool); !s) return fail(s.error());
  if (auto s = tessera::synthesize_aligned(*model, height, out_height, opts, pool); !s) return fail(s.error());
  if (auto s = tessera::synthesize_aligned(*model, normal, out_normal, opts, pool); !s) return fail(s.error());
  if (auto s = tessera::synthesize_source_map(*model, source, opts, pool); !s) return fail(s.error());
  // [/snippet]
  tessera::image_buffer<std::uint8_t, 3> shown(256, 256);  // source map: red = exemplar x, green = exemplar y
  for (index_t y = 0; y < 256; ++y)
    for (index_t x = 0; x < 256; ++x) {
      const auto c = source.read(x, y);
      shown.write(x, y, {static_cast<std::uint8_t>(c[0] * 2), static_cast<std::uint8_t>(c[1] * 2), 64});
    }
  if (auto s = tessera::write_png(dir + "/11_albedo.png", out_albedo); !s) return fail(s);
  if (auto s = tessera::write_png(dir + "/11_height.png", out_height); !s) return fail(s);
  if (auto s = tessera::write_png(dir + "/11_normal.png", out_normal); !s) return fail(s);
  if (auto s = tessera::write_png(dir + "/11_source.png", shown); !s) return fail(s);
  std::printf("wrote %s/11_tiles.png, 11_albedo.png, 11_height.png, 11_normal.png, 11_source.png\n", dir.c_str());
  return identical ? 0 : 1;
}
