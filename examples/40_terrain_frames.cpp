// Example 40: real-time texture synthesis of terrain frames (paper 003), next to plain tiled
// texture mapping of the same frames. Writes the pictures of docs/terrain.md:
//   exemplars.png                         the grass, sand and rock exemplars
//   {grass,sand,rock}_synthesized.png     scale field + triangle synthesis + seam feathering
//   {grass,sand,rock}_tiled.png           the same frame, exemplar repeated over the ground plane
//   scale_field.png, scale_field_continuous.png   the per-triangle scale, yellow (1) to purple (min)
//   regions.png                           one colour per synthesis placement
//   seams_hard.png, seams_feathered.png   a magnified corner without and with seam blending
//
// usage: example_40_terrain_frames [output directory, default "."]
#include <cstdint>
#include <cstdio>
#include <string>

#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>
#include <tessera/terrain/assign_scale_field.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/prepare_terrain_mesh.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/render_terrain_frame.hpp>
#include <tessera/terrain/render_tiled_frame.hpp>
#include <tessera/terrain/synthesize_triangles.hpp>
#include <tessera/terrain/terrain_camera.hpp>

namespace {

using tessera::index_t;
using frame_t = tessera::image_buffer<std::uint8_t, 3>;
constexpr index_t width = 640, height = 360;
constexpr std::array<double, 3> sun = {0.45, -0.35, 0.8};

int check(const tessera::status& s) {
  if (!s) std::fprintf(stderr, "example 40: %s\n", s.to_string().c_str());
  return s ? 0 : 1;
}

struct scene_spec {
  const char* name;
  tessera::exemplar_kind kind;
  tessera::terrain_options terrain;
  tessera::look_at_camera camera;
};

int render_scene(const scene_spec& spec, const std::string& dir, tessera::thread_pool_executor& pool,
                 bool diagnostics) {
  const auto source = tessera::make_terrain(spec.terrain, pool);
  if (!source) return check(source.error());
  const auto exemplar = tessera::make_exemplar<std::uint8_t, 3>(spec.kind, {.width = 256, .height = 256});
  if (!exemplar) return check(exemplar.error());

  const tessera::look_at_camera& look = spec.camera;  // eye, target, up, fov_y_degrees, near, far

  // [snippet:terrain_pipeline]
  // once per mesh and per exemplar: adjacency, the finely spaced exemplar pyramid
  auto prepared = tessera::prepare_terrain_mesh(*source);
  if (!prepared) return check(prepared.error());
  auto levels = tessera::build_exemplar_pyramid(*exemplar, {.min_scale = 0.5}, pool);
  if (!levels) return check(levels.error());
  const auto& mesh = *prepared;
  const auto& pyramid = *levels;
  auto camera = tessera::make_camera(look, width, height);  // a look_at_camera -> matrices + viewport
  if (!camera) return check(camera.error());                // eye == target, fov outside (0, 180), ...

  // every frame: project (§2.1), scale field (§2.2), triangle synthesis (§2.3), render
  tessera::screen_projection proj;
  tessera::scale_field field;
  tessera::triangle_synthesis syn;
  if (auto s = tessera::project_mesh(mesh, *camera, proj, {}, pool); !s) return check(s);
  if (auto s =
          tessera::assign_scale_field(mesh, proj, {.min_scale = 0.5, .max_levels = pyramid.num_levels()}, field, pool);
      !s)
    return check(s);
  if (auto s = tessera::synthesize_triangles(mesh, proj, field, exemplar->width(), exemplar->height(), {.seed = 7}, syn,
                                             pool);
      !s)
    return check(s);
  if (!syn.warning.ok()) std::fprintf(stderr, "warning: %s\n", syn.warning.message().c_str());
  tessera::image_buffer<std::uint8_t, 3> frame(width, height);  // or any WritableImage of the viewport's size
  if (auto s = tessera::render_terrain_frame(mesh, proj, field, syn, pyramid, frame, {.sun = sun}, pool); !s)
    return check(s);
  // [/snippet]

  const std::string synthesized = dir + "/" + spec.name + "_synthesized.png",
                    tiled_path = dir + "/" + spec.name + "_tiled.png";
  if (check(tessera::write_png(synthesized, frame))) return 1;
  const auto tiled = tessera::prepare_tiled_texture(*exemplar, pool);
  if (!tiled) return check(tiled.error());
  if (check(tessera::render_tiled_frame(mesh, proj, *tiled, frame, {.sun = sun}, pool))) return 1;
  if (check(tessera::write_png(tiled_path, frame))) return 1;
  std::printf("%-6s %7td visible triangles, %3td levels (max jump %d), %4td restarts, %.1f %% continuous edges\n",
              spec.name, proj.num_visible(), field.levels, field.max_level_jump, syn.restarts,
              100 * syn.continuous_fraction);
  std::printf("  wrote %s\n  wrote %s\n", synthesized.c_str(), tiled_path.c_str());
  if (!diagnostics) return 0;

  auto write = [&](const char* file, const tessera::render_terrain_options& o) {
    if (check(tessera::render_terrain_frame(mesh, proj, field, syn, pyramid, frame, o, pool))) return 1;
    const std::string path = dir + "/" + file;
    if (check(tessera::write_png(path, frame))) return 1;
    std::printf("  wrote %s\n", path.c_str());
    return 0;
  };
  if (write("scale_field.png", {.shading = tessera::terrain_shading::scale_field, .sun = sun})) return 1;
  if (write("regions.png", {.shading = tessera::terrain_shading::regions, .sun = sun})) return 1;
  // seam blending, magnified: a 160 x 90 corner at 3x
  for (double feather : {0.0, 3.0}) {
    if (check(tessera::render_terrain_frame(mesh, proj, field, syn, pyramid, frame, {.feather = feather}, pool)))
      return 1;
    frame_t zoom(480, 270);
    for (index_t y = 0; y < 270; ++y)
      for (index_t x = 0; x < 480; ++x) zoom.write(x, y, frame.read(240 + x / 3, 250 + y / 3));
    const std::string path = dir + (feather > 0 ? "/seams_feathered.png" : "/seams_hard.png");
    if (check(tessera::write_png(path, zoom))) return 1;
    std::printf("  wrote %s\n", path.c_str());
  }
  // the continuous variant of the scale field
  if (check(tessera::assign_scale_field(
          mesh, proj, {.min_scale = 0.5, .max_levels = pyramid.num_levels(), .mode = tessera::scale_mode::continuous},
          field, pool)))
    return 1;
  return write("scale_field_continuous.png", {.shading = tessera::terrain_shading::scale_field, .sun = sun});
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::thread_pool_executor pool;

  frame_t strip(3 * 256 + 2 * 8, 256, {255, 255, 255});
  int i = 0;
  for (auto kind : {tessera::exemplar_kind::grass, tessera::exemplar_kind::sand, tessera::exemplar_kind::rock}) {
    const auto e = tessera::make_exemplar<std::uint8_t, 3>(kind, {.width = 256, .height = 256});
    if (!e) return check(e.error());
    for (index_t y = 0; y < 256; ++y)
      for (index_t x = 0; x < 256; ++x) strip.write(i * 264 + x, y, e->read(x, y));
    ++i;
  }
  if (check(tessera::write_png(dir + "/exemplars.png", strip))) return 1;
  std::printf("wrote %s/exemplars.png\n", dir.c_str());

  // the paper's figure: a low, grazing view over a wide, gently rolling grass plane
  const scene_spec grass{"grass",
                         tessera::exemplar_kind::grass,
                         {.cells_x = 160, .cells_y = 160, .size_x = 200, .size_y = 200, .height = 6, .seed = 3},
                         {.eye = {0, -96, 9}, .target = {0, 60, 0}, .fov_y_degrees = 50, .near = 0.05, .far = 600}};
  // dunes seen from a little higher
  const scene_spec sand{
      "sand",
      tessera::exemplar_kind::sand,
      {.cells_x = 160, .cells_y = 160, .size_x = 160, .size_y = 160, .height = 12, .feature_size = 0.3, .seed = 5},
      {.eye = {-70, -70, 22}, .target = {20, 20, 0}, .fov_y_degrees = 50, .near = 0.05, .far = 600}};
  // steep mountains: the tiled frame stretches on the slopes
  const scene_spec rock{
      "rock",
      tessera::exemplar_kind::rock,
      {.cells_x = 160, .cells_y = 160, .size_x = 100, .size_y = 100, .height = 40, .feature_size = 0.45, .seed = 2},
      {.eye = {-15, -105, 62}, .target = {0, 5, 6}, .fov_y_degrees = 45, .near = 0.05, .far = 600}};
  if (render_scene(grass, dir, pool, true) || render_scene(sand, dir, pool, false) ||
      render_scene(rock, dir, pool, false))
    return 1;
  return 0;
}
