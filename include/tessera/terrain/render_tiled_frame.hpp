// tessera/terrain/render_tiled_frame.hpp: the baseline paper 003 improves on (§1.1): plain tiled
// texture mapping. The exemplar is repeated over the ground plane (u = x / repeat, v = y / repeat in
// exemplar widths; z is up), rendered with perspective-correct coordinates and trilinear mipmapping,
// as a game engine would. It shows the two defects the paper fixes: repetition (the same exemplar
// every `repeat` world units) and stretching on steep slopes (the planar mapping ignores height).
// Also the same-frame baseline for measuring what synthesis costs over the naive method.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/status.hpp"
#include "detail/resample.hpp"
#include "detail/tolerances.hpp"
#include "detail/visibility.hpp"
#include "prepare_terrain_mesh.hpp"
#include "project_mesh.hpp"

TESSERA_NAMESPACE_BEGIN

template <Channel T, int C>
class tiled_texture;
/// Builds the mipmap chain of any Image. Errors: an invalid exemplar. O(width * height), rows in
/// parallel through `exec`.
template <Image I, Executor E = serial_executor>
result<tiled_texture<channel_t<I>, channels_v<I>>> prepare_tiled_texture(const I& exemplar, E&& exec = {});

/// An exemplar prepared for repeated (wrap-around) sampling: a mipmap chain of halved levels down to
/// 1 x 1, each low-pass resampled from the exemplar. Read-only after preparation.
template <Channel T, int C>
class tiled_texture {
 public:
  /// Width of level 0 (the exemplar).
  [[nodiscard]] index_t width() const noexcept { return levels_.empty() ? 0 : levels_[0].width(); }
  /// Height of level 0.
  [[nodiscard]] index_t height() const noexcept { return levels_.empty() ? 0 : levels_[0].height(); }
  /// Number of mipmap levels.
  [[nodiscard]] index_t num_levels() const noexcept { return static_cast<index_t>(levels_.size()); }
  /// Mipmap level k (0: the exemplar).
  [[nodiscard]] const image_buffer<T, C>& level(index_t k) const noexcept { return levels_[detail::to_size(k)]; }

  /// Trilinear sample at texel coordinates (u, v) of level 0, wrapping around, at level of detail
  /// `lod` (0 = full resolution). Unit float channels. Thread-safe.
  [[nodiscard]] std::array<float, C> sample(double u, double v, double lod) const noexcept {
    lod = std::clamp(lod, 0.0, static_cast<double>(num_levels() - 1));
    const auto k = static_cast<index_t>(lod);
    const double f = lod - static_cast<double>(k);
    std::array<float, C> a = bilinear(k, u, v);
    if (f > detail::single_level_snap && k + 1 < num_levels()) {
      const std::array<float, C> b = bilinear(k + 1, u, v);
      for (std::size_t c = 0; c < detail::to_size(C); ++c) a[c] += static_cast<float>(f) * (b[c] - a[c]);
    }
    return a;
  }

 private:
  template <Image I, Executor E>
  friend result<tiled_texture<channel_t<I>, channels_v<I>>> prepare_tiled_texture(const I& exemplar, E&& exec);
  std::vector<image_buffer<T, C>> levels_;  ///< level k is about width / 2^k x height / 2^k

  [[nodiscard]] std::array<float, C> bilinear(index_t k, double u, double v) const noexcept {
    const image_buffer<T, C>& img = levels_[detail::to_size(k)];
    return detail::bilinear_sample(img, u * static_cast<double>(img.width()) / static_cast<double>(width()) - 0.5,
                                   v * static_cast<double>(img.height()) / static_cast<double>(height()) - 0.5,
                                   detail::wrap_index{});
  }
};

/// Prepares `exemplar` for tiled rendering: the mipmap chain, levels resampled in parallel through `exec`.
template <Image I, Executor E>
result<tiled_texture<channel_t<I>, channels_v<I>>> prepare_tiled_texture(const I& exemplar, E&& exec) {
  using T = channel_t<I>;
  constexpr int C = channels_v<I>;
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  auto buf = to_buffer(exemplar, "exemplar");
  if (!buf) return buf.error();
  tiled_texture<T, C> t;
  std::vector<float> src(detail::to_size(buf->width() * buf->height() * C));
  for (std::size_t i = 0; i < src.size(); ++i) src[i] = channel_to_unit(buf->data()[i]);
  const index_t w0 = buf->width(), h0 = buf->height();
  t.levels_.push_back(std::move(*buf));
  auto rows = [&](index_t n, auto&& body) { exec.parallel_for(0, n, body); };
  for (index_t w = w0, h = h0; w > 1 || h > 1;) {
    w = std::max<index_t>(1, w / 2);
    h = std::max<index_t>(1, h / 2);
    const std::vector<float> r = detail::resample_image(src.data(), w0, h0, C, w, h, rows);
    image_buffer<T, C> lv(w, h);
    for (std::size_t i = 0; i < r.size(); ++i) lv.data()[i] = unit_to_channel<T>(r[i]);
    t.levels_.push_back(std::move(lv));
  }
  return t;
}

/// Options of render_tiled_frame.
struct render_tiled_options {
  /// World units per exemplar repeat along x and y; 0 = automatic: one texel per pixel at the
  /// nearest fully projected face (the density of a scale-1 synthesized frame).
  double repeat = 0;
  bool mipmaps = true;  ///< trilinear mipmapping (false: level 0 only, which aliases in the distance)
  /// Unit RGBA where no triangle is.
  std::array<float, 4> background = {0.62f, 0.74f, 0.88f, 1.0f};
  std::array<double, 3> sun = {0, 0, 0};  ///< direction towards a light for flat Lambert shading; zero: unlit
  double ambient = 0.35;                  ///< light on faces turned away from the sun, in [0, 1]
  /// Rasterizer tile side in pixels.
  index_t tile_size = 64;
};

/// The automatic repeat of render_tiled_options (world units per exemplar width), or 0 when no face
/// is fully projected.
inline double auto_tiled_repeat(const terrain_mesh& mesh, const screen_projection& proj, index_t exemplar_width) {
  double best = std::numeric_limits<double>::infinity(), repeat = 0;
  for (const std::int32_t f : proj.visible) {
    if (proj.state[detail::to_size(f)] != static_cast<std::uint8_t>(face_visibility::inside)) continue;
    const auto& fv = mesh.faces[detail::to_size(f)];
    const vec3 a = mesh.position(fv[0]), b = mesh.position(fv[1]), c = mesh.position(fv[2]);
    const double ground = 0.5 * std::abs(cross(vec2{b.x - a.x, b.y - a.y}, vec2{c.x - a.x, c.y - a.y}));
    const vec2 p = proj.screen[detail::to_size(fv[0])], q = proj.screen[detail::to_size(fv[1])],
               r = proj.screen[detail::to_size(fv[2])];
    const double screen = 0.5 * std::abs(cross(q - p, r - p));
    const double d = norm(mesh.centroids[detail::to_size(f)] - proj.eye);
    if (screen >= 1 && ground > 0 && d < best) {
      best = d;
      repeat = static_cast<double>(exemplar_width) * std::sqrt(ground / screen);
    }
  }
  return repeat;
}

/// Renders `mesh` as projected with the exemplar tiled over the ground plane into `out` (any
/// WritableImage of the viewport's size). Errors: wrong output size, a projection not belonging to
/// `mesh` (detail::check_visible_geometry), empty texture, repeat < 0 or not finite, bad tile_size. O(visible faces + pixels), parallel through `exec` (bit-identical for
/// any executor).
template <Channel T, int C, WritableImage O, Executor E = serial_executor>
status render_tiled_frame(const terrain_mesh& mesh, const screen_projection& proj, const tiled_texture<T, C>& tex,
                          O& out, const render_tiled_options& opts = {}, E&& exec = {}) {
  if (auto s = validate_image(out, "output"); !s) return s;
  if (width_of(out) != proj.width || height_of(out) != proj.height)
    return status::invalid_argument(detail::cat("output is ", width_of(out), " x ", height_of(out),
                                                " but the viewport is ", proj.width, " x ", proj.height));
  if (tex.num_levels() == 0) return status::invalid_argument("the tiled texture is empty");
  if (!(opts.repeat >= 0) || !std::isfinite(opts.repeat))
    return status::invalid_argument(detail::cat("repeat must be >= 0 and finite, got ", opts.repeat));
  if (!(opts.ambient >= 0 && opts.ambient <= 1) || !is_finite(vec3{opts.sun[0], opts.sun[1], opts.sun[2]}))
    return status::invalid_argument(
        detail::cat("ambient must be in [0, 1] and sun finite, got ambient ", opts.ambient));
  if (auto s = detail::check_visible_geometry(mesh, proj, "render_tiled_frame", exec); !s) return s;
  double repeat = opts.repeat > 0 ? opts.repeat : auto_tiled_repeat(mesh, proj, tex.width());
  if (!(repeat > 0)) repeat = 1;
  detail::visibility_buffer vb;
  if (auto s = detail::render_visibility(mesh, proj, vb, true, opts.tile_size, exec); !s) return s;
  const std::vector<float> light = detail::face_light(mesh, proj, opts.sun, opts.ambient, exec);
  const index_t w = proj.width, h = proj.height;
  const double su = static_cast<double>(tex.width()) / repeat, sv = static_cast<double>(tex.height()) / repeat;
  const auto bg = convert_pixel<pixel<float, C>>(
      pixel<float, 4>{opts.background[0], opts.background[1], opts.background[2], opts.background[3]});
  image_buffer<float, C> frame(w, h);
  exec.parallel_for(0, h, [&](index_t y) {
    for (index_t x = 0; x < w; ++x) {
      const auto i = detail::to_size(y * w + x);
      pixel<float, C> c = bg;
      if (vb.face[i] >= 0) {
        const auto& p = vb.world[i];
        const double u = p[0] * su, v = p[1] * sv;
        double lod = 0;
        if (opts.mipmaps) {  // texel footprint from the neighbouring pixels (as a GPU's quad derivatives)
          auto footprint = [&](index_t dx, index_t dy) {
            index_t nx = x + dx, ny = y + dy;
            if (nx >= w || ny >= h || vb.face[detail::to_size(ny * w + nx)] < 0) {
              nx = x - dx;
              ny = y - dy;
            }
            if (nx < 0 || ny < 0 || vb.face[detail::to_size(ny * w + nx)] < 0) return 0.0;
            const auto& q = vb.world[detail::to_size(ny * w + nx)];
            return std::hypot(q[0] * su - u, q[1] * sv - v);
          };
          const double rho = std::max(footprint(1, 0), footprint(0, 1));
          lod = rho > 1 ? std::log2(rho) : 0.0;
        }
        c = tex.sample(u, v, lod);
        if (!light.empty()) detail::apply_light(c, light[detail::to_size(vb.face[i])]);
      }
      float* dst = frame.pixel_ptr(x, y);
      for (std::size_t k = 0; k < detail::to_size(C); ++k) dst[k] = c[k];
    }
  });
  return copy_image(frame, out);
}

TESSERA_NAMESPACE_END
