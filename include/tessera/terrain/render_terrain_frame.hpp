// tessera/terrain/render_terrain_frame.hpp: the synthesized frame a person looks at (paper 003,
// figure 1): the visible triangles rasterized (render/triangle_rasterizer.hpp), depth-tested, each
// pixel coloured from the exemplar pyramid at its triangle's scale and texture coordinates
// (uv = pixel centre + the triangle's offset), and colours blended across synthesis seams (§2.3
// step 3, see detail/seam_feather.hpp). Two diagnostic shadings show the scale field (colour-coded
// scale) and the synthesis regions (one colour per placement).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "assign_scale_field.hpp"
#include "build_exemplar_pyramid.hpp"
#include "detail/seam_feather.hpp"
#include "detail/tolerances.hpp"
#include "detail/visibility.hpp"
#include "prepare_terrain_mesh.hpp"
#include "project_mesh.hpp"
#include "synthesize_triangles.hpp"

TESSERA_NAMESPACE_BEGIN

/// What render_terrain_frame draws.
enum class terrain_shading {
  texture,      ///< the synthesized texture
  scale_field,  ///< each triangle's scale: yellow (1, near) through green and blue to purple (min_scale)
  regions,      ///< one colour per synthesis placement; seams are where colours change
};

/// Options of render_terrain_frame.
struct render_terrain_options {
  /// texture, scale_field or regions.
  terrain_shading shading = terrain_shading::texture;
  double feather = 3.0;  ///< blend width in pixels on each side of a seam (0: none), 0 to 64
  std::array<float, 4> background = {0.62f, 0.74f, 0.88f, 1.0f};  ///< unit RGBA where no triangle is
  std::array<double, 3> sun = {0, 0, 0};  ///< direction towards a light for flat Lambert shading; zero: unlit
  double ambient = 0.35;                  ///< light on faces turned away from the sun, in [0, 1]
  index_t tile_size = 64;                 ///< rasterizer tile
  /// Progress callback and cancellation token.
  tessera::progress progress = {};
};

namespace detail {
/// A perceptual ramp (viridis-like): 0 yellow, 1 purple.
inline pixel<float, 3> scale_colour(double t) {
  static constexpr float ramp[6][3] = {{0.99f, 0.91f, 0.14f}, {0.48f, 0.82f, 0.32f}, {0.13f, 0.66f, 0.52f},
                                       {0.16f, 0.47f, 0.56f}, {0.25f, 0.27f, 0.53f}, {0.27f, 0.00f, 0.33f}};
  const double x = std::clamp(t, 0.0, 1.0) * 5;
  const int i = std::min(4, static_cast<int>(x));
  const auto f = static_cast<float>(x - i);
  return {ramp[i][0] + f * (ramp[i + 1][0] - ramp[i][0]), ramp[i][1] + f * (ramp[i + 1][1] - ramp[i][1]),
          ramp[i][2] + f * (ramp[i + 1][2] - ramp[i][2])};
}
inline pixel<float, 3> region_colour(std::int32_t r) {
  const counter_rng rng(0x7e55e7a, 0);
  return {static_cast<float>(0.25 + 0.7 * rng.uniform(r, 0)), static_cast<float>(0.25 + 0.7 * rng.uniform(r, 1)),
          static_cast<float>(0.25 + 0.7 * rng.uniform(r, 2))};
}
/// Checks that the field, the synthesis and the pyramid belong to this projection before any
/// pixel is drawn: check_visible_geometry, then every visible face has a level
/// in [0, levels), a finite scale in [field.min_scale, 1] and a placement with a finite offset;
/// the field's min_scale is not below the pyramid's. O(visible faces), in parallel chunks whose
/// first failure (in visible order) is reported.
template <Channel T, int C, class E>
status check_frame_inputs(const terrain_mesh& mesh, const screen_projection& proj, const scale_field& field,
                          const triangle_synthesis& syn, const exemplar_pyramid<T, C>& pyramid, E& exec) {
  if (auto s = check_visible_geometry(mesh, proj, "render_terrain_frame", exec); !s) return s;
  const auto nf = to_size(mesh.num_faces());
  if (field.level.size() != nf || field.scale.size() != nf || syn.region.size() != nf || syn.offset.size() != nf)
    return status::invalid_argument(detail::cat("render_terrain_frame: the scale field (", field.level.size(),
                                                " faces) and synthesis (", syn.region.size(),
                                                " faces) must belong to the mesh (", nf, " faces)"));
  if (pyramid.num_levels() == 0) return status::invalid_argument("render_terrain_frame: the exemplar pyramid is empty");
  if (!(field.min_scale > 0 && field.min_scale >= pyramid.min_scale() * (1 - detail::scale_match_slack)))
    return status::invalid_argument(detail::cat("render_terrain_frame: the scale field reaches scale ", field.min_scale,
                                                " but the exemplar pyramid only ", pyramid.min_scale(),
                                                ": build both with the same min_scale"));
  const index_t nvis = proj.num_visible();
  constexpr index_t block = 16384;
  const index_t chunks = (nvis + block - 1) / block;
  std::vector<index_t> bad(to_size(chunks), -1);
  const float lo = static_cast<float>(field.min_scale) * (1 - detail::float_scale_slack);
  exec.parallel_for(0, chunks, [&](index_t c) {
    for (index_t i = c * block; i < std::min(nvis, (c + 1) * block); ++i) {
      const auto fi = to_size(proj.visible[to_size(i)]);
      const float s = field.scale[fi];
      if (!(field.level[fi] >= 0 && field.level[fi] < field.levels && s >= lo && s <= 1 && syn.region[fi] >= 0 &&
            is_finite(syn.offset[fi]))) {
        bad[to_size(c)] = i;
        return;
      }
    }
  });
  for (const index_t i : bad) {
    if (i < 0) continue;
    const std::int32_t f = proj.visible[to_size(i)];
    const auto fi = to_size(f);
    return status::invalid_argument(
        detail::cat("render_terrain_frame: visible face ", f, " has level ", field.level[fi], " of ", field.levels,
                    ", scale ", field.scale[fi], " (field min_scale ", field.min_scale, "), region ", syn.region[fi],
                    ", offset (", syn.offset[fi].x, ", ", syn.offset[fi].y,
                    "): the field and the synthesis must come from this projection and mesh"));
  }
  return {};
}
}  // namespace detail

/// Renders the synthesized frame into `out` (any WritableImage of the viewport's size; pixels are
/// converted with convert_pixel). Errors: `out` not projection.width x projection.height, a
/// projection, field or synthesis not belonging to `mesh` or to each other (a visible face without
/// a level, scale or placement, e.g. a field computed from another projection: see
/// detail::check_frame_inputs), a field reaching below the pyramid's min_scale, an empty pyramid,
/// feather outside [0, 64], bad tile_size, cancelled. A field with more levels than the pyramid
/// is accepted: its scales fall between pyramid levels, which sample() blends. Faces culled by the projection are not drawn; where nothing is drawn the background
/// shows (an empty or fully culled mesh gives a background-only frame). O(visible faces + pixels);
/// rasterization, feathering and shading run in parallel through `exec`, bit-identically for any
/// executor.
template <Channel T, int C, WritableImage O, Executor E = serial_executor>
status render_terrain_frame(const terrain_mesh& mesh, const screen_projection& proj, const scale_field& field,
                            const triangle_synthesis& syn, const exemplar_pyramid<T, C>& pyramid, O& out,
                            const render_terrain_options& opts = {}, E&& exec = {}) {
  if (auto s = validate_image(out, "output"); !s) return s;
  if (auto s = validate_enum(opts.shading, {"texture", "scale_field", "regions"}, "options.shading"); !s) return s;
  if (width_of(out) != proj.width || height_of(out) != proj.height)
    return status::invalid_argument(detail::cat("output is ", width_of(out), " x ", height_of(out),
                                                " but the viewport is ", proj.width, " x ", proj.height));
  if (!(opts.feather >= 0 && opts.feather <= 64))
    return status::invalid_argument(detail::cat("feather must be 0 to 64 pixels, got ", opts.feather));
  if (!(opts.ambient >= 0 && opts.ambient <= 1) || !is_finite(vec3{opts.sun[0], opts.sun[1], opts.sun[2]}))
    return status::invalid_argument(
        detail::cat("ambient must be in [0, 1] and sun finite, got ambient ", opts.ambient));
  if (auto s = detail::check_frame_inputs(mesh, proj, field, syn, pyramid, exec); !s) return s;
  detail::visibility_buffer vb;
  if (auto s = detail::render_visibility(mesh, proj, vb, false, opts.tile_size, exec); !s) return s;
  if (!opts.progress.report(0.4, "render terrain frame")) return status::cancelled();
  const detail::seam_feather feather(mesh, proj, field, syn, vb,
                                     opts.shading == terrain_shading::texture ? opts.feather : 0.0, exec);
  if (!opts.progress.report(0.6, "render terrain frame")) return status::cancelled();
  const std::vector<float> light = detail::face_light(mesh, proj, opts.sun, opts.ambient, exec);
  const index_t w = proj.width, h = proj.height;
  image_buffer<float, C> frame(w, h);
  const auto bg = convert_pixel<pixel<float, C>>(
      pixel<float, 4>{opts.background[0], opts.background[1], opts.background[2], opts.background[3]});
  exec.parallel_for(0, h, [&](index_t y) {
    for (index_t x = 0; x < w; ++x) {
      const std::int32_t f = vb.face[detail::to_size(y * w + x)];
      pixel<float, C> c = bg;
      if (f >= 0) {
        const auto i = detail::to_size(f);
        if (opts.shading == terrain_shading::scale_field) {
          c = convert_pixel<pixel<float, C>>(
              detail::scale_colour(field.min_scale < 1 ? (1.0 - field.scale[i]) / (1.0 - field.min_scale) : 0.0));
        } else if (opts.shading == terrain_shading::regions) {
          c = convert_pixel<pixel<float, C>>(detail::region_colour(syn.region[i]));
        } else {
          // uv from the level image's centre -> pixels of the shrunk exemplar from its corner
          const double px = static_cast<double>(x) + 0.5, py = static_cast<double>(y) + 0.5;
          const double cx = 0.5 * static_cast<double>(pyramid.width()),
                       cy = 0.5 * static_cast<double>(pyramid.height());
          const double s = field.scale[i];
          c = pyramid.sample(s, px + syn.offset[i].x + cx * s, py + syn.offset[i].y + cy * s);
          const detail::seam_partner p = feather.partner(x, y);
          if (p.face >= 0) {
            const auto j = detail::to_size(p.face);
            const double t = field.scale[j];
            const auto o = pyramid.sample(t, px + syn.offset[j].x + cx * t, py + syn.offset[j].y + cy * t);
            for (std::size_t k = 0; k < detail::to_size(C); ++k) c[k] += p.weight * (o[k] - c[k]);
          }
        }
        if (!light.empty()) detail::apply_light(c, light[i]);
      }
      float* dst = frame.pixel_ptr(x, y);
      for (std::size_t k = 0; k < detail::to_size(C); ++k) dst[k] = c[k];
    }
  });
  if (!opts.progress.report(0.95, "render terrain frame")) return status::cancelled();
  if (status s = copy_image(frame, out); !s) return s;
  return opts.progress.report(1.0, "render terrain frame") ? status{} : status::cancelled();
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_render_terrain_frame.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
