// tessera/terrain/render_anchored_frame.hpp: the frame of a ground-anchored terrain_session
// (terrain_session.hpp): the visible faces rasterized (render/triangle_rasterizer.hpp) and
// depth-tested, each pixel coloured from the exemplar pyramid at its face's level scale and its
// PERSPECTIVE-correct texture coordinates (the texture lies on the ground), a level change being
// blended over the session's blend_frames, and colours blended across the seams between
// placements (§2.3 step 3 of paper 003 on the ground): within `feather` exemplar texels of a side
// whose neighbour has other coordinates, the neighbour's mapping (its affine map extended across
// the edge) is mixed in with a weight falling from 1/2 at the edge to 0.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"
#include "../render/triangle_rasterizer.hpp"
#include "build_exemplar_pyramid.hpp"
#include "detail/tolerances.hpp"
#include "detail/visibility.hpp"
#include "render_terrain_frame.hpp"
#include "terrain_session.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of render_anchored_frame.
struct render_anchored_options {
  terrain_shading shading = terrain_shading::texture;  ///< texture, scale_field (level) or regions (placement)
  double feather = 2.0;  ///< seam blend width in exemplar texels (level 0) on each side, 0 to 64
  /// Unit RGBA where no triangle is.
  std::array<float, 4> background = {0.62f, 0.74f, 0.88f, 1.0f};
  std::array<double, 3> sun = {0, 0, 0};  ///< flat Lambert light direction; zero: unlit
  /// Light on faces turned away from the sun, in [0, 1].
  double ambient = 0.35;
  /// Rasterizer tile side in pixels.
  index_t tile_size = 64;
};

namespace detail {
/// Exemplar coordinates at world point p (in face n's plane, extended) from face n's corner coordinates.
inline vec2 anchored_extend(const terrain_mesh& mesh, const anchored_atlas& atlas, std::int32_t n, const vec3& p) {
  const auto& fv = mesh.faces[to_size(n)];
  const vec3 a = mesh.position(fv[0]), e1 = mesh.position(fv[1]) - a, e2 = mesh.position(fv[2]) - a;
  const vec3 nn = cross(e1, e2);
  const double d = dot(nn, nn);
  const auto& t = atlas.uv[to_size(n)];
  if (!(d > 0)) return {t[0], t[1]};
  const vec3 q = p - a;
  const double b1 = dot(cross(q, e2), nn) / d, b2 = dot(cross(e1, q), nn) / d;
  return {t[0] + b1 * (t[2] - t[0]) + b2 * (t[4] - t[0]), t[1] + b1 * (t[3] - t[1]) + b2 * (t[5] - t[1])};
}
}  // namespace detail

/// Renders the current frame of `session` (over `mesh`, the session's mesh) into `out` (any
/// WritableImage of the viewport's size). Errors: no frame yet or a failed last update, `out` of
/// another size, a mesh other than the session's (sizes), an empty pyramid or one of another
/// exemplar size, a pyramid whose min_scale is above the session's, feather outside [0, 64],
/// ambient outside [0, 1]. O(V + visible faces + pixels) (it projects the vertices with the
/// session's camera()), parallel through `exec`; bit-identical for any executor.
template <Channel T, int C, WritableImage O, Executor E = serial_executor>
status render_anchored_frame(const terrain_mesh& mesh, const terrain_session& session,
                             const exemplar_pyramid<T, C>& pyramid, O& out, const render_anchored_options& opts = {},
                             E&& exec = {}) {
  const screen_projection& proj = session.projection();
  if (session.frame() < 0 || proj.state.size() != detail::to_size(mesh.num_faces()) ||
      session.level().size() != detail::to_size(mesh.num_faces()))
    return status::invalid_argument("render_anchored_frame: the session has no frame of this mesh (call update)");
  if (width_of(out) != proj.width || height_of(out) != proj.height)
    return status::invalid_argument(detail::cat("output is ", width_of(out), " x ", height_of(out),
                                                " but the viewport is ", proj.width, " x ", proj.height));
  if (!(opts.feather >= 0 && opts.feather <= 64))
    return status::invalid_argument(detail::cat("feather must be 0 to 64 texels, got ", opts.feather));
  if (!(opts.ambient >= 0 && opts.ambient <= 1) || !is_finite(vec3{opts.sun[0], opts.sun[1], opts.sun[2]}))
    return status::invalid_argument(
        detail::cat("ambient must be in [0, 1] and sun finite, got ambient ", opts.ambient));
  if (pyramid.num_levels() == 0 || pyramid.width() != session.exemplar_width() ||
      pyramid.height() != session.exemplar_height())
    return status::invalid_argument(detail::cat("render_anchored_frame: the pyramid (", pyramid.width(), " x ",
                                                pyramid.height(), ", ", pyramid.num_levels(),
                                                " levels) must be of the session's exemplar (",
                                                session.exemplar_width(), " x ", session.exemplar_height(), ")"));
  if (pyramid.min_scale() > session.options().min_scale * (1 + detail::scale_match_slack))
    return status::invalid_argument(detail::cat("render_anchored_frame: the session reaches scale ",
                                                session.options().min_scale, " but the pyramid only ",
                                                pyramid.min_scale()));
  if (auto s = detail::check_terrain_mesh_sizes(mesh); !s) return s;
  if (auto s = detail::check_visible_entries(mesh, proj, "render_anchored_frame", exec); !s) return s;
  const index_t w = proj.width, h = proj.height;
  // the session does not project vertices: clip coordinates of the camera of its frame
  const glm::dmat4 m = session.camera().projection * session.camera().view;
  const index_t nv = mesh.num_vertices();
  std::vector<std::array<double, 4>> clip(detail::to_size(nv));
  constexpr index_t vblock = 16384;
  exec.parallel_for(0, (nv + vblock - 1) / vblock, [&](index_t b) {
    for (index_t v = b * vblock; v < std::min(nv, (b + 1) * vblock); ++v) {
      const vec3& p = mesh.positions[detail::to_size(v)];
      const glm::dvec4 c = m * glm::dvec4(p.x, p.y, p.z, 1.0);
      clip[detail::to_size(v)] = {c.x, c.y, c.z, c.w};
    }
  });
  std::vector<std::int32_t> face(detail::to_size(w * h), -1);
  std::vector<float> depth(face.size(), std::numeric_limits<float>::infinity());
  std::vector<std::array<float, 2>> bary(face.size());
  const raster_viewport vp{0, 0, static_cast<double>(w), static_cast<double>(h), proj.depth};
  if (auto s = rasterize_clip_triangles(
          proj.num_visible(), vp, pixel_rect{0, 0, w, h},
          [&](index_t i, clip_triangle& t) {
            const auto& fv = mesh.faces[detail::to_size(proj.visible[detail::to_size(i)])];
            for (std::size_t k = 0; k < 3; ++k) {
              const auto& c = clip[detail::to_size(fv[k])];
              t[k] = {c[0], c[1], c[2], c[3]};
            }
            return true;
          },
          [&](index_t i, const fragment& f) {
            const auto p = detail::to_size(f.y * w + f.x);
            if (!(static_cast<float>(f.w) < depth[p])) return;
            depth[p] = static_cast<float>(f.w);
            face[p] = proj.visible[detail::to_size(i)];
            bary[p] = {static_cast<float>(f.bary[0]), static_cast<float>(f.bary[1])};
          },
          rasterize_options{.tile_size = opts.tile_size}, exec);
      !s)
    return s;
  const std::vector<float> light = detail::face_light(mesh, proj, opts.sun, opts.ambient, exec);
  const anchored_atlas& atlas = session.atlas();
  const double cx = 0.5 * static_cast<double>(pyramid.width()), cy = 0.5 * static_cast<double>(pyramid.height());
  const double top = std::max<index_t>(1, session.levels() - 1);
  auto sample = [&](double s, vec2 uv) { return pyramid.sample(s, (uv.x + cx) * s, (uv.y + cy) * s); };
  image_buffer<float, C> frame(w, h);
  const auto bg = convert_pixel<pixel<float, C>>(
      pixel<float, 4>{opts.background[0], opts.background[1], opts.background[2], opts.background[3]});
  exec.parallel_for(0, h, [&](index_t y) {
    for (index_t x = 0; x < w; ++x) {
      const auto p = detail::to_size(y * w + x);
      const std::int32_t f = face[p];
      pixel<float, C> c = bg;
      if (f >= 0) {
        const auto fi = detail::to_size(f);
        const auto& t = atlas.uv[fi];
        const double b[3] = {bary[p][0], bary[p][1], 1.0 - bary[p][0] - bary[p][1]};
        const vec2 uv{b[0] * t[0] + b[1] * t[2] + b[2] * t[4], b[0] * t[1] + b[1] * t[3] + b[2] * t[5]};
        const std::int32_t l = session.level()[fi];
        if (opts.shading == terrain_shading::scale_field) {
          c = convert_pixel<pixel<float, C>>(detail::scale_colour(static_cast<double>(l) / top));
        } else if (opts.shading == terrain_shading::regions) {
          c = convert_pixel<pixel<float, C>>(
              detail::region_colour(session.regions().region[fi] * 4096 + atlas.patch[fi]));
        } else {
          const double s = session.level_scale(l);
          c = sample(s, uv);
          const float wgt = session.blend_weight(f);
          if (wgt < 1) {
            const auto o = sample(session.level_scale(session.blend_from(f)), uv);
            for (std::size_t k = 0; k < detail::to_size(C); ++k) c[k] = o[k] + wgt * (c[k] - o[k]);
          }
          if (opts.feather > 0) {
            // the nearest seam side within the feather: mix in the neighbour's mapping
            const auto& fv = mesh.faces[fi];
            for (std::size_t k = 0; k < 3; ++k) {
              const std::int32_t n = mesh.neighbors[fi][k];
              if (n < 0 || atlas.patch[detail::to_size(n)] < 0) continue;
              if (((atlas.seam[fi] >> k) & 1) == 0) continue;
              // distance to side k in texels: the opposite corner's weight times its height over the side
              const std::size_t opp = (k + 2) % 3;
              const vec2 a{t[2 * k], t[2 * k + 1]}, bb{t[2 * ((k + 1) % 3)], t[2 * ((k + 1) % 3) + 1]},
                  o{t[2 * opp], t[2 * opp + 1]};
              const double len = norm(bb - a);
              const double height = len > 0 ? std::abs(cross(bb - a, o - a)) / len : 0;
              const double dist = b[opp] * height;
              if (!(dist < opts.feather)) continue;
              const vec3 wp = mesh.position(fv[0]) * b[0] + mesh.position(fv[1]) * b[1] + mesh.position(fv[2]) * b[2];
              const auto other = sample(s, detail::anchored_extend(mesh, atlas, n, wp));
              const auto mix = static_cast<float>(0.5 * (1 - dist / opts.feather));
              for (std::size_t q = 0; q < detail::to_size(C); ++q) c[q] += mix * (other[q] - c[q]);
              break;
            }
          }
        }
        if (!light.empty()) detail::apply_light(c, light[fi]);
      }
      float* dst = frame.pixel_ptr(x, y);
      for (std::size_t k = 0; k < detail::to_size(C); ++k) dst[k] = c[k];
    }
  });
  return copy_image(frame, out);
}

TESSERA_NAMESPACE_END
