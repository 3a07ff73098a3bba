// An engine's translation unit: patch synthesis, Wang tiles, terrain and geometric Wang tiles in one
// .cpp, RGBA8 textures and a thread pool, as issue 19 measured it. Prints one FNV-1a digest per
// output, so a build linking tessera::compiled can be compared with the header-only build
// (tests/consumer/compiled) and timed by scripts/compile-time.sh --engine (docs/compile_once.md).
// Usage: four_families [--quick]; exit status 0 when every step succeeded.
#include <tessera/core/executor.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/terrain/assign_scale_field.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/prepare_terrain_mesh.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/render_terrain_frame.hpp>
#include <tessera/terrain/synthesize_triangles.hpp>
#include <tessera/terrain/terrain_camera.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace {

using rgba8 = tessera::image_buffer<std::uint8_t, 4>;

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t h = 14695981039346656037ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

std::uint64_t digest(const rgba8& img) {
  std::uint64_t h = 14695981039346656037ull;
  for (tessera::index_t y = 0; y < img.height(); ++y)
    for (tessera::index_t x = 0; x < img.width(); ++x) {
      const auto p = img.read(x, y);
      for (int c = 0; c < 4; ++c) h = fnv1a(&p[c], 1, h);
    }
  return h;
}

std::uint64_t digest(const tessera::tri_mesh& m) {
  std::uint64_t h = 14695981039346656037ull;
  for (const auto& p : m.positions) {
    const double xyz[3] = {p.x, p.y, p.z};
    h = fnv1a(xyz, sizeof xyz, h);
  }
  for (const auto& f : m.faces) h = fnv1a(f.data(), sizeof f, h);
  return h;
}

int fail(const char* step, const tessera::status& s) {
  std::fprintf(stderr, "four_families: %s: %s\n", step, s.to_string().c_str());
  return 1;
}

}  // namespace

int main() {
  tessera::thread_pool_executor pool(2);
  auto exemplar =
      tessera::make_exemplar<std::uint8_t, 4>(tessera::exemplar_kind::cells, {.width = 96, .height = 96, .seed = 3});
  if (!exemplar) return fail("exemplar", exemplar.error());

  // patch synthesis
  auto model = tessera::build_patch_model(*exemplar, {.patch_width = 24, .patch_height = 24, .overlap = 6}, pool);
  if (!model) return fail("build_patch_model", model.error());
  rgba8 patches(160, 128);
  if (auto s = tessera::synthesize(*model, patches, {.seed = 7}, pool); !s) return fail("synthesize", s.error());
  std::printf("patch synthesis %016llx\n", static_cast<unsigned long long>(digest(patches)));

  // Wang tiles, composed from the infinite hash colouring
  auto set =
      tessera::build_wang_tiles(*exemplar, {.tile_size = 32, .horizontal_colors = 2, .vertical_colors = 2}, pool);
  if (!set) return fail("build_wang_tiles", set.error());
  auto hash = tessera::hash_coloring::for_set(set->edges(), 5);
  if (!hash) return fail("hash_coloring", hash.error());
  rgba8 plane(200, 120);
  if (auto s = tessera::compose_tiles(*set, *hash, plane, {.x = -40, .y = 17}, pool); !s)
    return fail("compose_tiles", s);
  std::printf("wang tiles      %016llx\n", static_cast<unsigned long long>(digest(plane)));

  // terrain: one frame
  auto source = tessera::make_terrain({.cells_x = 24, .cells_y = 24}, pool);
  if (!source) return fail("make_terrain", source.error());
  auto mesh = tessera::prepare_terrain_mesh(*source);
  if (!mesh) return fail("prepare_terrain_mesh", mesh.error());
  auto pyramid = tessera::build_exemplar_pyramid(*exemplar, {.min_scale = 0.5}, pool);
  if (!pyramid) return fail("build_exemplar_pyramid", pyramid.error());
  auto camera = tessera::make_camera({.eye = {0, -60, 30}, .target = {0, 0, 0}}, 160, 90);
  if (!camera) return fail("make_camera", camera.error());
  tessera::screen_projection proj;
  tessera::scale_field field;
  tessera::triangle_synthesis syn;
  if (auto s = tessera::project_mesh(*mesh, *camera, proj, {}, pool); !s) return fail("project_mesh", s);
  if (auto s = tessera::assign_scale_field(*mesh, proj, {.min_scale = 0.5, .max_levels = pyramid->num_levels()}, field,
                                           pool);
      !s)
    return fail("assign_scale_field", s);
  if (auto s = tessera::synthesize_triangles(*mesh, proj, field, exemplar->width(), exemplar->height(), {.seed = 7},
                                             syn, pool);
      !s)
    return fail("synthesize_triangles", s);
  rgba8 frame(160, 90);
  if (auto s = tessera::render_terrain_frame(*mesh, proj, field, syn, *pyramid, frame, {}, pool); !s)
    return fail("render_terrain_frame", s);
  std::printf("terrain frame   %016llx\n", static_cast<unsigned long long>(digest(frame)));

  // geometric Wang tiles: a 3 x 2 plane
  auto rings = tessera::make_ring_exemplar();
  if (!rings) return fail("make_ring_exemplar", rings.error());
  auto prepared = tessera::prepare_quilt_exemplar(*rings);
  if (!prepared) return fail("prepare_quilt_exemplar", prepared.error());
  tessera::geometric_wang_options o;
  o.tile_size = 6.4;
  o.quilt.seed = 3;
  auto geo = tessera::build_geometric_wang_tiles(*prepared, o, pool);
  if (!geo) return fail("build_geometric_wang_tiles", geo.error());
  auto geo_hash = tessera::hash_coloring::create(geo->horizontal_colors, geo->vertical_colors, 5);
  if (!geo_hash) return fail("hash_coloring", geo_hash.error());
  auto window = geo_hash->window(0, 0, 3, 2);
  if (!window) return fail("window", window.error());
  auto geo_plane = tessera::tile_geometric_plane(*geo, *window, 3, 2, pool);
  if (!geo_plane) return fail("tile_geometric_plane", geo_plane.error());
  std::printf("geometric plane %016llx\n", static_cast<unsigned long long>(digest(*geo_plane)));
  return 0;
}
