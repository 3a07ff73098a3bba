// tessera/render/triangle_rasterizer.hpp: a small, exact triangle rasterizer for previews, frame
// renderers and tests (terrain frames, shaded mesh previews). It produces fragments; what a
// fragment becomes (a colour, an id in a visibility buffer) is the caller's business.
//
//   Screen space: pixel (i, j) covers [i, i+1) x [j, j+1), x to the right, y DOWN (row 0 at the
//   top, like images), and is sampled at its centre (i + 0.5, j + 0.5).
//   Coverage: vertices snap to 1/256 pixel and 64-bit integer edge functions decide coverage, with
//   the top-left fill rule: a centre exactly on an edge belongs to the triangle whose interior lies
//   below a horizontal edge or right of a non-horizontal one. Triangles that share an edge (same
//   vertex positions) cover every pixel centre on it exactly once, with no gaps, whatever the order
//   of vertices or triangles.
//   Attributes: `fragment::bary` are the weights of the caller's three corners, perspective-correct
//   when the vertices carry 1/w (screen-linear when every inv_w is equal); depth is interpolated
//   linearly in screen space, as hardware does with window z; `fragment::w` is the interpolated
//   clip w (the view depth for a perspective camera: a depth with even precision).
//   Clipping: fragments are produced only inside the caller's `pixel_rect` (viewport or scissor).
//   Coordinates beyond +-2^20 pixels are clipped to that guard band first. Clip-space input
//   (projection * view * position) is clipped against the near and far planes, so triangles passing
//   behind the eye rasterize correctly; fragments of clipped pieces still report weights of the
//   original corners.
//   Parallelism: rasterize_triangles() bins triangles into square tiles and rasterizes the tiles in
//   parallel through an Executor. Each pixel belongs to one tile and each tile draws its triangles
//   in index order on one thread, so every pixel sees its fragments in triangle order: results are
//   identical for any executor and thread count, and per-pixel state (depth_buffer) needs no lock.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/status.hpp"
#include "detail/raster_kernel.hpp"

TESSERA_NAMESPACE_BEGIN

/// A screen-space vertex: pixel position (y down), depth, and 1/w of its clip-space vertex (leave 1
/// for screen-linear interpolation). inv_w must be positive and finite.
struct raster_vertex {
  /// Pixel position (y down).
  double x = 0, y = 0;
  /// Depth, interpolated into fragment::depth.
  double z = 0;
  /// 1 / w of the clip-space vertex (1: screen-linear interpolation).
  double inv_w = 1;
};
/// Three screen-space vertices.
using raster_triangle = std::array<raster_vertex, 3>;

/// A vertex in homogeneous clip space (projection * view * position, OpenGL/GLM conventions).
struct clip_vertex {
  /// Homogeneous clip-space coordinates.
  double x = 0, y = 0, z = 0, w = 1;
};
/// Three clip-space vertices.
using clip_triangle = std::array<clip_vertex, 3>;

/// Depth range of clip space: OpenGL/GLM default (-w <= z <= w) or Direct3D/Vulkan (0 <= z <= w,
/// GLM_FORCE_DEPTH_ZERO_TO_ONE). Window depth is [0, 1] either way, 0 at the near plane.
enum class clip_depth { negative_one_to_one, zero_to_one };

/// Maps normalized device coordinates to pixels: NDC (-1, +1) is the viewport's top-left corner
/// (x, y), NDC (+1, -1) its bottom-right corner (x + width, y + height).
struct raster_viewport {
  /// The viewport rectangle in pixels.
  double x = 0, y = 0, width = 0, height = 0;
  /// The clip-space depth range of the input.
  clip_depth depth = clip_depth::negative_one_to_one;
};

/// A half-open rectangle of pixels [x0, x1) x [y0, y1).
struct pixel_rect {
  /// Corners: [x0, x1) x [y0, y1).
  index_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  /// x1 - x0.
  [[nodiscard]] constexpr index_t width() const noexcept { return x1 - x0; }
  /// y1 - y0.
  [[nodiscard]] constexpr index_t height() const noexcept { return y1 - y0; }
  /// True when it holds no pixel.
  [[nodiscard]] constexpr bool empty() const noexcept { return x1 <= x0 || y1 <= y0; }
};

/// One covered pixel: `bary[k]` weighs the caller's corner k (sum 1); `depth` is the interpolated
/// z (window depth in [0, 1] for clip-space input); `w` the interpolated clip w (1 / interpolated
/// inv_w).
struct fragment {
  /// The pixel.
  index_t x = 0, y = 0;
  /// Weights of the caller's three corners (sum 1).
  std::array<double, 3> bary{};
  /// Interpolated depth.
  double depth = 0;
  /// Interpolated clip w.
  double w = 1;
};

/// Which triangles to skip, by orientation as seen on the screen (row 0 at the top). A triangle
/// that is counter-clockwise in OpenGL's NDC looks counter-clockwise on screen too.
enum class face_culling { none, cull_clockwise, cull_counter_clockwise };

/// Largest pixel coordinate a pixel_rect or viewport may reach.
inline constexpr index_t max_raster_coordinate = index_t{1} << 19;

/// Checks a pixel rectangle: 0 <= x0 <= x1 <= 2^19, same for y.
inline status validate_pixel_rect(const pixel_rect& r, std::string_view what = "pixel_rect") {
  if (r.x0 < 0 || r.y0 < 0 || r.x1 < r.x0 || r.y1 < r.y0 || r.x1 > max_raster_coordinate ||
      r.y1 > max_raster_coordinate)
    return status::invalid_argument(detail::cat(what, ": [", r.x0, ", ", r.x1, ") x [", r.y0, ", ", r.y1,
                                                ") must satisfy 0 <= x0 <= x1 <= 2^19 and 0 <= y0 <= y1 <= 2^19"));
  return {};
}

/// Checks a viewport: finite, positive size, within +-2^19 pixels.
inline status validate_raster_viewport(const raster_viewport& v, std::string_view what = "viewport") {
  const double lim = static_cast<double>(max_raster_coordinate);
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && v.width > 0 && v.height > 0 && v.x >= -lim && v.y >= -lim &&
        v.x + v.width <= lim && v.y + v.height <= lim))
    return status::invalid_argument(detail::cat(what, ": origin (", v.x, ", ", v.y, ") size ", v.width, " x ", v.height,
                                                " must be finite, positive and within 2^19 pixels"));
  return validate_enum(v.depth, {"negative_one_to_one", "zero_to_one"}, detail::cat(what, ": depth"));
}

/// Checks a face_culling value (one of its three enumerators).
inline status validate_face_culling(face_culling c, std::string_view what = "culling") {
  return validate_enum(c, {"none", "cull_clockwise", "cull_counter_clockwise"}, what);
}

namespace detail::raster {
inline int keep_orientation(face_culling c) noexcept {
  // the kernel's sign is the cross product in y-down coordinates: positive is clockwise on screen
  return c == face_culling::cull_clockwise ? -1 : c == face_culling::cull_counter_clockwise ? 1 : 0;
}
inline std::array<std::array<double, 4>, 3> pack(const raster_triangle& t) noexcept {
  return {{{t[0].x, t[0].y, t[0].z, t[0].inv_w},
           {t[1].x, t[1].y, t[1].z, t[1].inv_w},
           {t[2].x, t[2].y, t[2].z, t[2].inv_w}}};
}
inline std::array<std::array<double, 4>, 3> pack(const clip_triangle& t) noexcept {
  return {{{t[0].x, t[0].y, t[0].z, t[0].w}, {t[1].x, t[1].y, t[1].z, t[1].w}, {t[2].x, t[2].y, t[2].z, t[2].w}}};
}
inline bool make_polygon(const raster_triangle& t, const raster_viewport&, polygon& p) {
  return screen_polygon(pack(t), p);
}
inline bool make_polygon(const clip_triangle& t, const raster_viewport& vp, polygon& p) {
  return clip_polygon_to_screen(pack(t), {vp.x, vp.y, vp.width, vp.height}, vp.depth == clip_depth::zero_to_one, p);
}
template <class F>
void draw(const polygon& p, face_culling culling, const pixel_rect& r, F&& fn) {
  draw_polygon(p, keep_orientation(culling), r.x0, r.y0, r.x1, r.y1, [&](const covered& c) {
    const fragment f{static_cast<index_t>(c.x), static_cast<index_t>(c.y), c.bary, c.depth, c.w};
    fn(f);
  });
}
}  // namespace detail::raster

/// Rasterizes one screen-space triangle: calls `fn(const fragment&)` for each pixel of `clip` whose
/// centre it covers (top-left rule), row by row. A triangle with a non-finite value, a non-positive
/// inv_w, zero area after snapping, or culled by `culling` produces nothing. Errors: invalid `clip`.
/// O(covered pixels + rows). Thread-safe: no shared state.
template <class F>
status rasterize_triangle(const raster_triangle& tri, const pixel_rect& clip, F&& fn,
                          face_culling culling = face_culling::none) {
  if (auto s = validate_pixel_rect(clip, "clip"); !s) return s;
  if (auto s = validate_face_culling(culling); !s) return s;
  detail::raster::polygon p;
  if (detail::raster::make_polygon(tri, {}, p)) detail::raster::draw(p, culling, clip, fn);
  return {};
}

/// Rasterizes one clip-space triangle (projection * view * position): clips it against the near and
/// far planes, maps it through `viewport` and draws the pieces inside `clip` (usually the viewport's
/// pixels). Fragments carry perspective-correct weights of the given corners and window depth in
/// [0, 1]. Errors: invalid viewport or clip. Thread-safe.
template <class F>
status rasterize_clip_triangle(const clip_triangle& tri, const raster_viewport& viewport, const pixel_rect& clip,
                               F&& fn, face_culling culling = face_culling::none) {
  if (auto s = validate_raster_viewport(viewport); !s) return s;
  if (auto s = validate_pixel_rect(clip, "clip"); !s) return s;
  if (auto s = validate_face_culling(culling); !s) return s;
  detail::raster::polygon p;
  if (detail::raster::make_polygon(tri, viewport, p)) detail::raster::draw(p, culling, clip, fn);
  return {};
}

/// Options of the batch rasterizers.
struct rasterize_options {
  index_t tile_size = 64;  ///< tile side in pixels (8 to 4096); grown automatically past 2^16 tiles
  /// Which triangles to skip by orientation.
  face_culling culling = face_culling::none;
};

namespace detail::raster {
template <class Tri, class Get, class F, class E>
status rasterize_batch(index_t count, const raster_viewport& vp, const pixel_rect& clip, Get& get, F& fn,
                       const rasterize_options& opts, E& exec) {
  if (count < 0 || count > std::numeric_limits<std::int32_t>::max())
    return status::invalid_argument(detail::cat("count must be 0 to 2^31 - 1, got ", count));
  if (opts.tile_size < 8 || opts.tile_size > 4096)
    return status::invalid_argument(detail::cat("tile_size must be 8 to 4096, got ", opts.tile_size));
  if (auto s = validate_face_culling(opts.culling, "options.culling"); !s) return s;
  if (count == 0 || clip.empty()) return {};
  index_t ts = opts.tile_size;
  while (((clip.width() + ts - 1) / ts) * ((clip.height() + ts - 1) / ts) > (index_t{1} << 16)) ts *= 2;
  const index_t tx = (clip.width() + ts - 1) / ts, ty = (clip.height() + ts - 1) / ts, tiles = tx * ty;
  // 1. tile range of every triangle (parallel), 2. per-chunk counts, 3. bins in index order.
  std::vector<std::array<std::int32_t, 4>> range(to_size(count));
  const index_t chunks = std::min<index_t>(64, (count + 4095) / 4096), per = (count + chunks - 1) / chunks;
  std::vector<std::int32_t> counts(to_size(chunks * tiles), 0);
  exec.parallel_for(0, chunks, [&](index_t c) {
    std::int32_t* cnt = counts.data() + c * tiles;
    for (index_t i = c * per; i < std::min(count, (c + 1) * per); ++i) {
      auto& r = range[to_size(i)];
      r = {0, 0, -1, -1};
      Tri t{};
      polygon p;
      if (!get(i, t) || !make_polygon(t, vp, p) || p.n < 3) continue;
      const auto b = polygon_bounds(p);
      const std::int64_t x0 = std::max<std::int64_t>(b[0], clip.x0), y0 = std::max<std::int64_t>(b[1], clip.y0);
      const std::int64_t x1 = std::min<std::int64_t>(b[2], clip.x1), y1 = std::min<std::int64_t>(b[3], clip.y1);
      if (x0 >= x1 || y0 >= y1) continue;
      r = {static_cast<std::int32_t>((x0 - clip.x0) / ts), static_cast<std::int32_t>((y0 - clip.y0) / ts),
           static_cast<std::int32_t>((x1 - 1 - clip.x0) / ts), static_cast<std::int32_t>((y1 - 1 - clip.y0) / ts)};
      for (std::int32_t yy = r[1]; yy <= r[3]; ++yy)
        for (std::int32_t xx = r[0]; xx <= r[2]; ++xx) ++cnt[yy * tx + xx];
    }
  });
  std::vector<index_t> start(to_size(tiles + 1), 0), cursor(to_size(chunks * tiles));
  index_t total = 0;
  for (index_t t = 0; t < tiles; ++t) {
    start[to_size(t)] = total;
    for (index_t c = 0; c < chunks; ++c) {
      cursor[to_size(c * tiles + t)] = total;
      total += counts[to_size(c * tiles + t)];
    }
  }
  start[to_size(tiles)] = total;
  std::vector<std::int32_t> bins(to_size(total));
  exec.parallel_for(0, chunks, [&](index_t c) {
    index_t* cur = cursor.data() + c * tiles;
    for (index_t i = c * per; i < std::min(count, (c + 1) * per); ++i) {
      const auto& r = range[to_size(i)];
      for (std::int32_t yy = r[1]; yy <= r[3]; ++yy)
        for (std::int32_t xx = r[0]; xx <= r[2]; ++xx)
          bins[to_size(cur[yy * tx + xx]++)] = static_cast<std::int32_t>(i);
    }
  });
  exec.parallel_for(0, tiles, [&](index_t t) {
    const pixel_rect tile{clip.x0 + (t % tx) * ts, clip.y0 + (t / tx) * ts,
                          std::min(clip.x1, clip.x0 + (t % tx + 1) * ts),
                          std::min(clip.y1, clip.y0 + (t / tx + 1) * ts)};
    for (index_t k = start[to_size(t)]; k < start[to_size(t + 1)]; ++k) {
      const index_t i = bins[to_size(k)];
      Tri tri{};
      polygon p;
      if (!get(i, tri) || !make_polygon(tri, vp, p)) continue;
      draw(p, opts.culling, tile, [&](const fragment& f) { fn(i, f); });
    }
  });
  return {};
}
}  // namespace detail::raster

/// Rasterizes `count` screen-space triangles inside `clip`. `triangle(i, raster_triangle& out)`
/// fills triangle i and returns false to skip it; it is called more than once per triangle (binning,
/// then per tile) and from several threads, so it must be a pure read. `fn(index_t i, const
/// fragment&)` is called from several threads, but each pixel's fragments come from one thread in
/// increasing i, so per-pixel state needs no synchronization and the result is the same for every
/// executor. Errors: invalid clip, count or tile_size. Work: O(count + covered pixels); memory:
/// 16 bytes per triangle plus 4 per (triangle, tile) pair.
template <class Get, class F, Executor E = serial_executor>
status rasterize_triangles(index_t count, const pixel_rect& clip, Get&& triangle, F&& fn,
                           const rasterize_options& opts = {}, E&& exec = {}) {
  if (auto s = validate_pixel_rect(clip, "clip"); !s) return s;
  return detail::raster::rasterize_batch<raster_triangle>(count, raster_viewport{}, clip, triangle, fn, opts, exec);
}

/// As rasterize_triangles, for clip-space triangles (`triangle(i, clip_triangle& out)`), each
/// clipped against the near and far planes and mapped through `viewport` as in
/// rasterize_clip_triangle. Errors: invalid viewport, clip, count or tile_size.
template <class Get, class F, Executor E = serial_executor>
status rasterize_clip_triangles(index_t count, const raster_viewport& viewport, const pixel_rect& clip, Get&& triangle,
                                F&& fn, const rasterize_options& opts = {}, E&& exec = {}) {
  if (auto s = validate_raster_viewport(viewport); !s) return s;
  if (auto s = validate_pixel_rect(clip, "clip"); !s) return s;
  return detail::raster::rasterize_batch<clip_triangle>(count, viewport, clip, triangle, fn, opts, exec);
}

/// Largest depth buffer, in pixels (2^28: 1 GiB of floats, e.g. 16384 x 16384).
inline constexpr index_t max_depth_buffer_pixels = index_t{1} << 28;

/// A depth buffer: one float per pixel, cleared to +infinity; smaller is closer. Pass fragment
/// depth (window z) or fragment w (view depth, even precision). Concurrent test_and_set calls on
/// distinct pixels are safe, which is what rasterize_triangles guarantees.
class depth_buffer {
 public:
  depth_buffer() = default;
  /// A width x height buffer; invalid_argument for a non-positive size or a side beyond 2^19,
  /// size_overflow beyond max_depth_buffer_pixels (checked before allocating).
  static result<depth_buffer> create(index_t width, index_t height,
                                     float clear_value = std::numeric_limits<float>::infinity()) {
    if (width <= 0 || height <= 0 || width > max_raster_coordinate || height > max_raster_coordinate)
      return status::invalid_argument(
          detail::cat("depth_buffer: size must be 1 to 2^19 per side, got ", width, " x ", height));
    if (width * height > max_depth_buffer_pixels)
      return status::size_overflow(detail::cat("depth_buffer: ", width, " x ", height,
                                               " pixels exceed max_depth_buffer_pixels = ", max_depth_buffer_pixels));
    depth_buffer d;
    d.width_ = width;
    d.height_ = height;
    d.data_.assign(detail::to_size(width * height), clear_value);
    return d;
  }
  /// Width in pixels.
  [[nodiscard]] index_t width() const noexcept { return width_; }
  /// Height in pixels.
  [[nodiscard]] index_t height() const noexcept { return height_; }
  /// The whole buffer as a rectangle.
  [[nodiscard]] pixel_rect rect() const noexcept { return {0, 0, width_, height_}; }
  /// Sets every depth to `value` (default: +infinity, farther than anything).
  void clear(float value = std::numeric_limits<float>::infinity()) { std::fill(data_.begin(), data_.end(), value); }
  /// The stored depth of pixel (x, y); asserts it is inside.
  [[nodiscard]] float at(index_t x, index_t y) const noexcept {
    TESSERA_ASSERT(x >= 0 && x < width_ && y >= 0 && y < height_);
    return data_[detail::to_size(y * width_ + x)];
  }
  /// Passes (returns true and stores the depth) when depth is strictly smaller than the stored
  /// value; ties keep the earlier fragment, so equal-depth overlaps resolve to the lower triangle.
  bool test_and_set(index_t x, index_t y, double depth) noexcept {
    TESSERA_ASSERT(x >= 0 && x < width_ && y >= 0 && y < height_);
    float& d = data_[detail::to_size(y * width_ + x)];
    const auto v = static_cast<float>(depth);
    if (!(v < d)) return false;
    d = v;
    return true;
  }
  /// The depths, row by row.
  [[nodiscard]] const float* data() const noexcept { return data_.data(); }

 private:
  std::vector<float> data_;
  index_t width_ = 0;
  index_t height_ = 0;
};

TESSERA_NAMESPACE_END
