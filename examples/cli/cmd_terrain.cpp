// tessera terrain: real-time texture synthesis of a large terrain scene (paper 003): project a
// mesh, assign the per-triangle scale field, synthesize texture coordinates triangle by triangle
// and render the frame; optionally the plain tiled frame and the colour-coded scale field next to
// it, and the per-triangle texture coordinates an engine would use.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <tessera/io/mesh_file.hpp>
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
#include <tessera/terrain/export_corner_uvs.hpp>
#include <tessera/io/terrain_uv_file.hpp>

#include "cli.hpp"
#include "image_source.hpp"

namespace {

using tessera::index_t;
using tessera::result;
using tessera::status;
using rgb_image = tessera::image_buffer<std::uint8_t, 3>;

result<tessera::vec3> vec_option(const cli::arguments& args, const char* name) {
  auto v = args.numbers(name, 3);
  if (!v) return v.error();
  return tessera::vec3{(*v)[0], (*v)[1], (*v)[2]};
}

result<tessera::terrain_camera> make_cli_camera(const cli::arguments& args, const tessera::aabb& bounds, index_t w,
                                                index_t h) {
  auto preset = tessera::parse_camera_preset(args.str("--camera", "grazing"));
  if (!preset) return preset.error();
  auto look = tessera::camera_preset_look_at(*preset, bounds);
  if (!look) return look.error();
  if (args.has("--eye")) {
    auto e = vec_option(args, "--eye");
    if (!e) return e.error();
    look->eye = *e;
  }
  if (args.has("--target")) {
    auto t = vec_option(args, "--target");
    if (!t) return t.error();
    look->target = *t;
  }
  if (args.has("--up")) {
    auto u = vec_option(args, "--up");
    if (!u) return u.error();
    look->up = *u;
  }
  auto fov = args.number("--fov", look->fov_y_degrees);
  if (!fov) return fov.error();
  look->fov_y_degrees = *fov;
  // near and far planes fitted to the scene seen from this eye
  const double diag = std::max(tessera::norm(bounds.extent()), 1e-9);
  look->near = std::max(1e-4 * diag, 1e-9);
  look->far = 2 * (tessera::norm(look->eye - bounds.center()) + diag);
  return tessera::make_camera(*look, w, h);
}

/// Largest --grid: 4096 x 4096 cells are 33.5 M triangles (about 3 GB through the pipeline).
constexpr long long max_grid = 4096;

int run_terrain(const cli::arguments& args) {
  auto fail = [&](const status& s) { return cli::fail(args, s); };
  const auto out_path = args.required("--out");
  if (!out_path) return fail(out_path.error());
  if (!args.has("--exemplar")) return fail(status::invalid_argument("missing required option --exemplar"));
  if (args.has("--mesh") && args.has("--grid"))
    return fail(status::invalid_argument("give --mesh or --grid, not both"));
  auto vp = args.has("--viewport") ? args.size("--viewport", tessera::max_viewport_side, index_t{1} << 26)
                                   : result<std::pair<index_t, index_t>>(std::pair<index_t, index_t>{960, 540});
  if (!vp) return fail(vp.error());
  auto min_scale = args.number("--min-scale", 0.5);
  auto levels = args.integer("--levels", 0, 0, 4096);
  auto feather = args.number("--feather", 3.0, 0, 64);
  auto grid = args.integer("--grid", 128, 1, max_grid);
  auto relief = args.number("--height", 14.0, 0, 1e6);
  for (const status* s : {&min_scale.error(), &levels.error(), &feather.error(), &grid.error(), &relief.error()})
    if (!s->ok()) return fail(*s);
  const std::string mode = args.str("--mode", "stepped"), placement = args.str("--placement", "away");
  const std::string continuation = args.str("--continuation", "oldest"), restart = args.str("--restart", "wait");
  if (restart != "wait" && restart != "immediate")
    return fail(status::invalid_argument("--restart expects wait or immediate, got '" + restart + "'"));
  const std::string keep_axis = args.str("--keep-axis", "yes");
  if (keep_axis != "yes" && keep_axis != "no")
    return fail(status::invalid_argument("--keep-axis expects yes or no, got '" + keep_axis + "'"));
  if (continuation != "oldest" && continuation != "first")
    return fail(status::invalid_argument("--continuation expects oldest or first, got '" + continuation + "'"));
  if (mode != "stepped" && mode != "continuous")
    return fail(status::invalid_argument("--mode expects stepped or continuous, got '" + mode + "'"));
  if (placement != "away" && placement != "uniform")
    return fail(status::invalid_argument("--placement expects away or uniform, got '" + placement + "'"));

  tessera::thread_pool_executor pool(args.threads());
  auto exemplar = cli::load_image_source<std::uint8_t, 3>(args, "--exemplar", 256);
  if (!exemplar) return fail(exemplar.error());
  result<tessera::tri_mesh> source =
      args.has("--mesh")
          ? tessera::read_mesh(args.str("--mesh"))
          : tessera::make_terrain({.cells_x = *grid, .cells_y = *grid, .height = *relief, .seed = args.seed()}, pool);
  if (!source) return fail(source.error());
  auto mesh = tessera::prepare_terrain_mesh(*source, args.has("--mesh") ? args.str("--mesh") : "terrain");
  if (!mesh) return fail(mesh.error());
  auto camera = make_cli_camera(args, tessera::bounding_box(*mesh), vp->first, vp->second);
  if (!camera) return fail(camera.error());
  if (!(*min_scale > 0 && *min_scale <= 1))
    return fail(status::invalid_argument("--min-scale must be in (0, 1], got " + args.str("--min-scale")));
  auto pyramid = tessera::build_exemplar_pyramid(*exemplar, {.min_scale = *min_scale, .levels = *levels}, pool);
  if (!pyramid) return fail(pyramid.error());

  tessera::screen_projection proj;
  tessera::scale_field field;
  tessera::triangle_synthesis syn;
  if (auto s = tessera::project_mesh(*mesh, *camera, proj, {}, pool); !s) return fail(s);
  const tessera::scale_field_options field_opts{
      .min_scale = *min_scale,
      .max_levels = pyramid->num_levels(),
      .mode = mode == "continuous" ? tessera::scale_mode::continuous : tessera::scale_mode::stepped};
  status error;
  const double field_ms = cli::median_ms(args.repeat(), [&] {
    if (error.ok()) error = tessera::assign_scale_field(*mesh, proj, field_opts, field, pool);
  });
  if (!error) return fail(error);
  const tessera::triangle_synthesis_options syn_opts{
      .seed = args.seed(),
      .placement = placement == "uniform" ? tessera::placement_strategy::uniform
                                          : tessera::placement_strategy::away_from_neighbors,
      .continuation = continuation == "first" ? tessera::continuation_rule::first_neighbor
                                              : tessera::continuation_rule::oldest_placement,
      .defer_restarts = restart == "wait",
      .keep_fitting_axis = keep_axis == "yes"};
  const double syn_ms = cli::median_ms(args.repeat(), [&] {
    if (error.ok())
      error = tessera::synthesize_triangles(*mesh, proj, field, exemplar->width(), exemplar->height(), syn_opts, syn);
  });
  if (!error) return fail(error);
  if (!syn.warning.ok()) std::fprintf(stderr, "tessera terrain: warning: %s\n", syn.warning.message().c_str());
  if (proj.num_visible() == 0)
    std::fprintf(stderr, "tessera terrain: warning: no triangle is visible from this camera\n");

  rgb_image frame(vp->first, vp->second);
  const auto shading = args.str("--shading", "texture");
  tessera::render_terrain_options render_opts{.feather = *feather};
  tessera::render_tiled_options tiled_opts;
  if (args.has("--sun")) {
    auto sun = vec_option(args, "--sun");
    if (!sun) return fail(sun.error());
    render_opts.sun = tiled_opts.sun = {sun->x, sun->y, sun->z};
  }
  if (shading == "scale")
    render_opts.shading = tessera::terrain_shading::scale_field;
  else if (shading == "regions")
    render_opts.shading = tessera::terrain_shading::regions;
  else if (shading != "texture")
    return fail(status::invalid_argument("--shading expects texture, scale or regions, got '" + shading + "'"));
  const double render_ms = cli::median_ms(args.repeat(), [&] {
    if (error.ok()) error = tessera::render_terrain_frame(*mesh, proj, field, syn, *pyramid, frame, render_opts, pool);
  });
  if (!error) return fail(error);
  if (auto s = tessera::write_png(*out_path, frame); !s) return fail(s);
  if (args.has("--scale-out")) {
    render_opts.shading = tessera::terrain_shading::scale_field;
    if (auto s = tessera::render_terrain_frame(*mesh, proj, field, syn, *pyramid, frame, render_opts, pool); !s)
      return fail(s);
    if (auto s = tessera::write_png(args.str("--scale-out"), frame); !s) return fail(s);
  }
  if (args.has("--tiled-out")) {
    auto tex = tessera::prepare_tiled_texture(*exemplar, pool);
    if (!tex) return fail(tex.error());
    if (auto s = tessera::render_tiled_frame(*mesh, proj, *tex, frame, tiled_opts, pool); !s) return fail(s);
    if (auto s = tessera::write_png(args.str("--tiled-out"), frame); !s) return fail(s);
  }
  if (args.has("--uv-out")) {
    auto uv = tessera::export_corner_uvs(*mesh, proj, field, syn);
    if (!uv) return fail(uv.error());
    if (auto s = tessera::write_terrain_uv_file(args.str("--uv-out"), *uv); !s) return fail(s);
  }
  if (args.stats())
    cli::json_line()
        .add("triangles", mesh->num_faces())
        .add("visible", proj.num_visible())
        .add("levels", field.levels)
        .add("max_level_jump", field.max_level_jump)
        .add("restarts", syn.restarts)
        .add("continuous_edges", syn.continuous_fraction)
        .add("scale_field_ms", field_ms)
        .add("synthesis_ms", syn_ms)
        .add("render_ms", render_ms)
        .print();
  return 0;
}

std::vector<cli::option_spec> terrain_options() {
  std::vector<cli::option_spec> o = {
      {"--exemplar", "E",
       "exemplar PNG, or a procedural kind: grass, sand, rock, bricks, cells, weave, dots (required)"},
      cli::exemplar_size_option(256),
      {"--mesh", "M.obj",
       "terrain mesh (.obj, .off or .ply; polygons are fan-triangulated); default: a procedural heightfield"},
      {"--grid", "N",
       "procedural heightfield of N x N cells, 2 N^2 triangles, N in 1..4096 (default 128; --seed picks the relief)"},
      {"--height", "H", "relief of the procedural heightfield on its 100 x 100 extent (default 14; 0 = a flat plane)"},
      {"--camera", "P", "view preset grazing, oblique or overview (default grazing); --eye/--target/--fov override it"},
      {"--eye", "x,y,z", "eye position (z is up)"},
      {"--target", "x,y,z", "point looked at"},
      {"--up", "x,y,z", "up vector (default 0,0,1)"},
      {"--fov", "DEG", "vertical field of view in (0, 180) degrees (preset default)"},
      {"--viewport", "WxH", "frame size in pixels (default 960x540)"},
      {"--min-scale", "s", "smallest texture scale, in (0, 1] (default 0.5)"},
      {"--levels", "N", "exemplar pyramid levels (default 0: steps of at most 0.008 in scale)"},
      {"--mode", "M", "scale field: stepped (the paper) or continuous (default stepped)"},
      {"--placement", "P",
       "restart placement: away (from synthesized neighbours) or uniform (the paper) (default away)"},
      {"--continuation", "R",
       "which synthesized neighbour's coordinates to continue: oldest (placement) or first (in side "
       "order, the paper read literally) (default oldest)"},
      {"--restart", "R",
       "a face that fits no neighbour's coordinates: wait (once, for neighbours synthesized later) or immediate "
       "(a new placement at once, the paper) (default wait)"},
      {"--keep-axis", "yes|no",
       "a new placement keeps the offset along an axis where a neighbouring placement still fits (default "
       "yes; no: both axes at random, the paper)"},
      {"--feather", "PX", "seam blending width in pixels (default 3; 0 = none)"},
      {"--shading", "S", "frame shading: texture, scale or regions (default texture)"},
      {"--sun", "x,y,z", "direction towards a light: flat Lambert shading of the frames (default: unlit)"},
      {"--out", "F.png", "the synthesized frame (required)"},
      {"--scale-out", "F.png", "also write the colour-coded scale field (yellow: scale 1, purple: min-scale)"},
      {"--tiled-out", "F.png", "also write the same frame with plain tiled texture mapping"},
      {"--uv-out", "F.bin",
       "per-triangle texture coordinates for an engine (TSUV version 3, little-endian: 40-byte header, then per "
       "face 6 f32 corner uv, 2 f32 offset, i32 level, f32 scale, u32 state; see docs/terrain.md)"},
  };
  for (auto& c : cli::common_options()) o.push_back(c);
  return o;
}

const cli::registrar terrain_registrar{{
    "terrain",
    "real-time texture synthesis of a terrain frame (scale field + triangle synthesis, paper 003)",
    "tessera terrain --exemplar E.png [--mesh M.obj | --grid N --seed S] [--eye x,y,z --target x,y,z --fov DEG] "
    "[--viewport WxH] [--min-scale s] --out frame.png [--uv-out uv.bin] [--stats]",
    terrain_options(),
    run_terrain,
}};

}  // namespace
