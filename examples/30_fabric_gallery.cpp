// Example 30: the pictures of docs/fabric.md, from paper 001 ("computer generation of fabric
// textures"): the orbit of a source image under the cat map (like the paper's figures 3-5), the
// generalized family [1 a; b ab+1], source layouts, the presets and perturbed tweeds.
//
//   example_30_fabric_gallery [OUTPUT_DIR]      (default: the current directory)
#include <cstdio>
#include <string>
#include <vector>

#include <tessera/core/image_buffer.hpp>
#include <tessera/fabric/cat_map.hpp>
#include <tessera/fabric/make_fabric.hpp>
#include <tessera/fabric/source_image.hpp>
#include <tessera/io/png.hpp>

using tessera::index_t;
using rgb8 = tessera::image_buffer<std::uint8_t, 3>;

namespace {

std::string g_dir = ".";

// Lays out the top-left `crop` x `crop` corner of each image in a grid with 4-pixel white gaps.
rgb8 grid(const std::vector<rgb8>& images, int cols, index_t crop) {
  const int rows = (static_cast<int>(images.size()) + cols - 1) / cols;
  rgb8 out(cols * (crop + 4) - 4, rows * (crop + 4) - 4, {255, 255, 255});
  for (std::size_t k = 0; k < images.size(); ++k)
    for (index_t y = 0; y < crop; ++y)
      for (index_t x = 0; x < crop; ++x)
        out.write(static_cast<index_t>(k % static_cast<std::size_t>(cols)) * (crop + 4) + x,
                  static_cast<index_t>(k / static_cast<std::size_t>(cols)) * (crop + 4) + y,
                  images[k].read(x % images[k].width(), y % images[k].height()));
  return out;
}

bool save(const std::string& name, const rgb8& img) {
  const std::string path = g_dir + "/" + name;
  if (auto s = tessera::write_png(path, img); !s) {
    std::fprintf(stderr, "%s\n", s.to_string().c_str());
    return false;
  }
  std::printf("wrote %s\n", path.c_str());
  return true;
}

bool check(const tessera::status& s) {
  if (!s) std::fprintf(stderr, "%s\n", s.to_string().c_str());
  return s.ok();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) g_dir = argv[1];
  const index_t n = 400;  // the paper's image size; the period is 300
  tessera::thread_pool_executor pool;
  const tessera::palette black_white = {{{0, 0, 0}, 0.75}, {{1, 1, 1}, 0.25}};

  // 1. The orbit of a 75 % black / 25 % white block source (figure 3) under the cat map:
  //    31 steps give twill (figure 5), 60 flannel (figure 4); step 300 is the source again.
  rgb8 source(n, n);
  if (!check(tessera::make_source_image(source, black_white, {.layout = tessera::source_layout::blocks, .seed = 1})))
    return 1;
  std::vector<rgb8> orbit;
  for (std::int64_t steps : {0, 1, 2, 5, 31, 60, 150, 300}) {
    auto f = tessera::cat_map(source, steps, {}, pool);
    if (!f) return check(f.error()), 1;
    orbit.push_back(std::move(*f));
  }
  if (!save("orbit.png", grid(orbit, 4, 200))) return 1;
  if (!save("orbit_full.png", grid({orbit[4], orbit[5]}, 2, 400))) return 1;

  // 2. The family [1 a; b ab+1]: other fabrics from the same source, 31 steps each.
  std::vector<rgb8> family;
  for (tessera::cat_map_family f : {tessera::cat_map_family{1, 1}, {1, 2}, {2, 1}, {3, 5}}) {
    auto img = tessera::cat_map(source, 31, {.family = f}, pool);
    if (!img) return check(img.error()), 1;
    family.push_back(std::move(*img));
  }
  if (!save("family.png", grid(family, 4, 200))) return 1;

  // 3. Source layouts (§1.3): stripes, blocks, cells of a three-tone palette, and 31 steps of each.
  const tessera::palette denim = {
      {{0.10f, 0.16f, 0.32f}, 0.6}, {{0.55f, 0.62f, 0.75f}, 0.25}, {{0.93f, 0.92f, 0.88f}, 0.15}};
  std::vector<rgb8> layouts, mapped;
  for (auto layout : {tessera::source_layout::stripes, tessera::source_layout::blocks, tessera::source_layout::cells}) {
    rgb8 img(n, n);
    if (!check(tessera::make_source_image(img, denim, {.layout = layout, .feature_size = 36, .seed = 3}))) return 1;
    auto stepped = tessera::cat_map(img, 31, {}, pool);
    if (!check(stepped.error())) return 1;
    mapped.push_back(std::move(*stepped));
    layouts.push_back(std::move(img));
  }
  for (auto& m : mapped) layouts.push_back(std::move(m));
  if (!save("sources.png", grid(layouts, 3, 200))) return 1;

  // 4. The presets: flannel, twill, linen (from a photo-like exemplar), tweed.
  std::vector<rgb8> presets;
  for (tessera::fabric_preset p : tessera::all_fabric_presets) {
    rgb8 img(n, n);
    if (!check(tessera::make_fabric(p, img, {}, pool))) return 1;
    presets.push_back(std::move(img));
  }
  if (!save("presets.png", grid(presets, 4, 200))) return 1;
  auto photo = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, {.width = n, .height = n});
  if (!photo) return check(photo.error()), 1;
  if (!save("linen.png", grid({*photo, presets[2]}, 2, 256))) return 1;

  // 5. Tweeds: a cat-mapped wool fabric perturbed for 0, 1, 3 and 8 generations, and a grey tweed.
  auto recipe = tessera::fabric_preset_recipe(tessera::fabric_preset::tweed);
  std::vector<rgb8> tweeds;
  for (int generations : {0, 1, 3, 8}) {
    rgb8 img(n, n);
    recipe.options.perturbation.generations = generations;
    if (!check(tessera::make_fabric(recipe.tones, recipe.source, img, recipe.options, pool))) return 1;
    tweeds.push_back(std::move(img));
  }
  if (!save("tweed_generations.png", grid(tweeds, 4, 160))) return 1;
  const tessera::palette grey = {{{0.15f, 0.15f, 0.17f}, 0.45},
                                 {{0.45f, 0.45f, 0.47f}, 0.30},
                                 {{0.85f, 0.84f, 0.80f}, 0.20},
                                 {{0.20f, 0.30f, 0.50f}, 0.05}};
  std::vector<rgb8> coats;
  for (int generations : {0, 3}) {
    rgb8 img(n, n);
    if (!check(tessera::make_fabric(grey, {.layout = tessera::source_layout::blocks}, img,
                                    {.iterations = 45, .perturbation = {.generations = generations}}, pool)))
      return 1;
    coats.push_back(std::move(img));
  }
  if (!save("tweed_grey.png", grid(coats, 2, 256))) return 1;

  // 6. Any size: a 400 x 400 twill tiled over 1000 x 300 without seams (the cat map lives on a torus).
  rgb8 wide(1000, 300);
  if (!check(tessera::make_fabric(tessera::fabric_preset::twill, wide, {.tile_size = 400}, pool))) return 1;
  if (!save("tiled.png", wide)) return 1;
  return 0;
}
