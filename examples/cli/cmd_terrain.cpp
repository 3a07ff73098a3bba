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
#include <tessera/terrain/export_session_uvs.hpp>
#include <tessera/terrain/render_anchored_frame.hpp>
#include <tessera/terrain/terrain_session.hpp>
#include <tessera/terrain/texture_stretch.hpp>

#include <cstring>
#include <filesystem>
#include <sstream>

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

/// The cameras of --path FILE: one per line, `ex ey ez tx ty tz fov` (blank lines and lines
/// starting with # skipped); errors name the file, the line and the problem.
result<std::vector<tessera::terrain_camera>> read_camera_path(const std::string& path, const tessera::aabb& bounds,
                                                              index_t w, index_t h) {
  auto text = tessera::read_file(path);
  if (!text) return text.error();
  std::vector<tessera::terrain_camera> cams;
  std::istringstream in(*text);
  std::string line;
  const double diag = std::max(tessera::norm(bounds.extent()), 1e-9);
  for (int n = 1; std::getline(in, line); ++n) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ls(line);
    std::vector<double> v;
    std::string tok;
    while (ls >> tok) {
      char* end = nullptr;
      const double x = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != 0)
        return status::invalid_argument("--path " + path + " line " + std::to_string(n) + ": '" + tok +
                                        "' is not a number");
      v.push_back(x);
    }
    if (v.size() != 7)
      return status::invalid_argument("--path " + path + " line " + std::to_string(n) +
                                      ": expected 7 numbers (ex ey ez " + "tx ty tz fov), got " +
                                      std::to_string(v.size()));
    for (const double x : v)
      if (!std::isfinite(x))
        return status::invalid_argument("--path " + path + " line " + std::to_string(n) + ": numbers must be finite");
    tessera::look_at_camera l;
    l.eye = {v[0], v[1], v[2]};
    l.target = {v[3], v[4], v[5]};
    l.fov_y_degrees = v[6];
    l.near = std::max(1e-4 * diag, 1e-9);
    l.far = 2 * (tessera::norm(l.eye - bounds.center()) + diag);
    auto cam = tessera::make_camera(l, w, h);
    if (!cam)
      return status::invalid_argument("--path " + path + " line " + std::to_string(n) + ": " + cam.error().message());
    cams.push_back(*cam);
  }
  if (cams.empty()) return status::invalid_argument("--path " + path + ": no camera in the file");
  return cams;
}

// The terrain: --mesh FILE, or a generated relief of --grid cells with height --height.
result<tessera::terrain_mesh> load_terrain_mesh(const cli::arguments& args, long long grid, double relief,
                                                tessera::thread_pool_executor& pool) {
  result<tessera::tri_mesh> source =
      args.has("--mesh")
          ? tessera::read_mesh(args.str("--mesh"))
          : tessera::make_terrain({.cells_x = grid, .cells_y = grid, .height = relief, .seed = args.seed()}, pool);
  if (!source) return source.error();
  return tessera::prepare_terrain_mesh(*source, args.has("--mesh") ? args.str("--mesh") : "terrain");
}

/// Faces visible in both buffers (same level) with bit-identical corner coordinates, over faces visible in both.
double stable_fraction(const tessera::terrain_uv_buffer& a, const tessera::terrain_uv_buffer& b) {
  std::size_t common = 0, same = 0;
  for (std::size_t f = 0; f < a.state.size() && f < b.state.size(); ++f) {
    if (a.state[f] == 0 || b.state[f] == 0) continue;
    ++common;
    same += a.level[f] == b.level[f] && std::memcmp(a.corner_uv[f].data(), b.corner_uv[f].data(), 24) == 0 ? 1 : 0;
  }
  return common > 0 ? static_cast<double>(same) / static_cast<double>(common) : 1.0;
}

/// --anchor ground and/or --path: one frame per camera, ground-anchored (terrain_session) or the
/// paper's screen-space pipeline, with --frames-out DIR and one --stats line per frame.
int run_terrain_frames(const cli::arguments& args) {
  auto fail = [&](const status& s) { return cli::fail(args, s); };
  const std::string anchor = args.str("--anchor", "screen");
  if (anchor != "ground" && anchor != "screen")
    return fail(status::invalid_argument("--anchor expects ground or screen, got '" + anchor + "'"));
  if (!args.has("--out") && !args.has("--frames-out"))
    return fail(status::invalid_argument("missing required option --out or --frames-out"));
  if (!args.has("--exemplar")) return fail(status::invalid_argument("missing required option --exemplar"));
  if (args.has("--mesh") && args.has("--grid"))
    return fail(status::invalid_argument("give --mesh or --grid, not both"));
  auto vp = args.has("--viewport") ? args.size("--viewport", tessera::max_viewport_side, index_t{1} << 26)
                                   : result<std::pair<index_t, index_t>>(std::pair<index_t, index_t>{960, 540});
  if (!vp) return fail(vp.error());
  auto min_scale = args.number("--min-scale", 0.5);
  auto levels = args.integer("--levels", 0, 0, 4096);
  auto feather = args.number("--feather", anchor == "ground" ? 2.0 : 3.0, 0, 64);
  auto grid = args.integer("--grid", 128, 1, max_grid);
  auto relief = args.number("--height", 14.0, 0, 1e6);
  // ground anchoring: the largest texture stretch a face may end with, and the relaxation rounds
  auto max_stretch = args.number("--max-stretch", 1.3, 1, 2);
  auto relax = args.integer("--relax", 3, 0, 64);
  for (const status* s : {&min_scale.error(), &levels.error(), &feather.error(), &grid.error(), &relief.error(),
                          &max_stretch.error(), &relax.error()})
    if (!s->ok()) return fail(*s);
  if (anchor != "ground" && (args.has("--max-stretch") || args.has("--relax")))
    return fail(status::invalid_argument("--max-stretch and --relax apply to --anchor ground only"));
  if (!(*min_scale > 0 && *min_scale <= 1))
    return fail(status::invalid_argument("--min-scale must be in (0, 1], got " + args.str("--min-scale")));
  tessera::thread_pool_executor pool(args.threads());
  auto exemplar = cli::load_image_source<std::uint8_t, 3>(args, "--exemplar", 256);
  if (!exemplar) return fail(exemplar.error());
  auto mesh = load_terrain_mesh(args, *grid, *relief, pool);
  if (!mesh) return fail(mesh.error());
  const tessera::aabb bounds = tessera::bounding_box(*mesh);
  std::vector<tessera::terrain_camera> cams;
  if (args.has("--path")) {
    auto c = read_camera_path(args.str("--path"), bounds, vp->first, vp->second);
    if (!c) return fail(c.error());
    cams = std::move(*c);
  } else {
    auto c = make_cli_camera(args, bounds, vp->first, vp->second);
    if (!c) return fail(c.error());
    cams.push_back(*c);
  }
  std::string dir;
  if (args.has("--frames-out")) {
    dir = args.str("--frames-out");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return fail(status::io_error("--frames-out " + dir + ": " + ec.message()));
  }
  auto pyramid = tessera::build_exemplar_pyramid(*exemplar, {.min_scale = *min_scale, .levels = *levels}, pool);
  if (!pyramid) return fail(pyramid.error());
  result<tessera::terrain_session> session = status::invalid_argument("unused");
  if (anchor == "ground") {
    tessera::terrain_session_options so{.synthesis = {.seed = args.seed()}, .min_scale = *min_scale};
    so.synthesis.relax_iterations = static_cast<int>(*relax);
    if (args.has("--max-stretch")) {  // the final bound, with or without the relaxation
      so.synthesis.max_stretch = *max_stretch;
      so.synthesis.relaxed_max_stretch = *max_stretch;
    }
    session = tessera::make_terrain_session(*mesh, exemplar->width(), exemplar->height(), so);
    if (!session) return fail(session.error());
    // level 0 (no pre-filter) up to where one texel covers one pixel of the first camera: focal
    // length in pixels / texels per unit (at least the smallest near distance allowed)
    const double focal = 0.5 * static_cast<double>(vp->second) * cams[0].projection[1][1];
    so.near_distance = std::max(session->near_distance(), focal / session->regions().texels_per_unit);
    session = tessera::make_terrain_session(*mesh, exemplar->width(), exemplar->height(), so);
    if (!session) return fail(session.error());
  }
  tessera::screen_projection proj;
  tessera::scale_field field;
  tessera::triangle_synthesis syn;
  tessera::terrain_uv_buffer prev;
  rgb_image frame(vp->first, vp->second);
  for (std::size_t i = 0; i < cams.size(); ++i) {
    status error;
    result<tessera::terrain_uv_buffer> uv = status::invalid_argument("unused");
    index_t visible = 0, resynthesized = 0;
    double continuous = 1;
    int jump = 0;
    tessera::stretch_summary stretch;  // ground-anchored frames: the stretch of the faces in view
    const double ms = cli::time_ms([&] {
      if (anchor == "ground") {
        error = session->update(*mesh, cams[i], pool);
      } else {
        error = tessera::project_mesh(*mesh, cams[i], proj, {}, pool);
        if (error.ok())
          error = tessera::assign_scale_field(
              *mesh, proj, {.min_scale = *min_scale, .max_levels = pyramid->num_levels()}, field, pool);
        if (error.ok())
          error = tessera::synthesize_triangles(*mesh, proj, field, exemplar->width(), exemplar->height(),
                                                {.seed = args.seed()}, syn, pool);
      }
    });
    if (!error) return fail(status(error.code(), "frame " + std::to_string(i) + ": " + error.message()));
    if (anchor == "ground") {
      const auto& st = session->stats();
      if (!st.warning.ok()) std::fprintf(stderr, "tessera terrain: warning: %s\n", st.warning.message().c_str());
      visible = st.visible, resynthesized = st.resynthesized, continuous = st.continuous_fraction;
      jump = st.max_level_jump;
      if (args.stats()) {
        // the stretch (texture_stretch.hpp) of every face in view, in level-0 texels
        std::vector<double> values;
        for (const std::int32_t f : session->projection().visible) {
          const auto fi = static_cast<std::size_t>(f);
          const double scale = session->level_scale(session->level()[fi]);
          std::array<float, 6> t = session->corner_uv()[fi];
          for (float& c : t) c = static_cast<float>(c / scale);
          values.push_back(tessera::face_stretch(*mesh, f, t, session->regions().texels_per_unit));
        }
        stretch = tessera::summarize_stretch(values);
      }
      uv = tessera::export_session_uvs(*session);
      error = tessera::render_anchored_frame(*mesh, *session, *pyramid, frame, {.feather = *feather}, pool);
    } else {
      if (proj.num_visible() == 0)
        std::fprintf(stderr, "tessera terrain: warning: frame %zu: no triangle is visible from this camera\n", i);
      visible = proj.num_visible(), resynthesized = visible, continuous = syn.continuous_fraction;
      jump = field.max_level_jump;
      uv = tessera::export_corner_uvs(*mesh, proj, field, syn);
      error = tessera::render_terrain_frame(*mesh, proj, field, syn, *pyramid, frame, {.feather = *feather}, pool);
    }
    if (!uv) return fail(uv.error());
    if (!error) return fail(error);
    if (!dir.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04zu", i);
      const std::filesystem::path base = std::filesystem::path(dir) / name;
      if (auto s = tessera::write_png(base.string() + ".png", frame); !s) return fail(s);
      if (auto s = tessera::write_terrain_uv_file(base.string() + ".tsuv", *uv); !s) return fail(s);
    }
    if (args.stats()) {
      cli::json_line line;
      line.add("frame", static_cast<index_t>(i))
          .add("frame_ms", ms)
          .add("visible", visible)
          .add("resynthesized", resynthesized)
          .add("stable_faces", i == 0 ? 0.0 : stable_fraction(prev, *uv))
          .add("continuous_edges", continuous)
          .add("max_level_jump", jump);
      if (anchor == "ground")
        line.add("stretch_median", stretch.median).add("stretch_p95", stretch.p95).add("stretch_max", stretch.max);
      line.print();
    }
    prev = std::move(*uv);
  }
  if (args.has("--out"))
    if (auto s = tessera::write_png(args.str("--out"), frame); !s) return fail(s);
  return 0;
}

int run_terrain(const cli::arguments& args) {
  if (args.has("--anchor") || args.has("--path") || args.has("--frames-out")) return run_terrain_frames(args);
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
  auto mesh = load_terrain_mesh(args, *grid, *relief, pool);
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
      {"--anchor", "A",
       "screen (the paper: texture synthesized on the screen every frame; default) or ground (anchored to the "
       "ground, incremental: terrain_session)"},
      {"--max-stretch", "S",
       "--anchor ground: no face ends with its texture stretched by more than S, 1 (congruent) to 2 (default "
       "1.3 with the relaxation, 1.55 without: a lower bound gives more seams)"},
      {"--relax", "N",
       "--anchor ground: rounds of as-rigid-as-possible relaxation round the faces the unfolding left stretched, "
       "0 to 64 (default 3; 0: none)"},
      {"--path", "FILE", "camera path, one camera per line: ex ey ez tx ty tz fov (one frame each)"},
      {"--frames-out", "DIR",
       "write DIR/frame_0000.png and DIR/frame_0000.tsuv per camera; with --anchor, --path or --frames-out, "
       "--stats prints one line per frame: frame, frame_ms, visible, resynthesized, stable_faces, "
       "continuous_edges, max_level_jump (ground: also stretch_median, stretch_p95, stretch_max of the faces in "
       "view, 1 = congruent)"},
  };
  return o;
}

const cli::registrar terrain_registrar{{
    "terrain",
    "real-time texture synthesis of a terrain frame (scale field + triangle synthesis, paper 003)",
    "tessera terrain --exemplar E.png [--mesh M.obj | --grid N --seed S] [--eye x,y,z --target x,y,z --fov DEG] "
    "[--viewport WxH] [--min-scale s] --out frame.png [--uv-out uv.bin] [--stats]; moving cameras: [--anchor "
    "ground|screen] [--path cameras.txt] [--frames-out DIR]",
    terrain_options(),
    run_terrain,
}};

}  // namespace
