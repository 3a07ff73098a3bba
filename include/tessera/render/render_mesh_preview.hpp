// tessera/render/render_mesh_preview.hpp: a shaded preview of a triangle mesh as an RGB image, from
// a chosen view: orthographic camera at an azimuth and elevation around the mesh's bounding box,
// smooth Lambert shading with two lights, optional per-element tint and an optional overlay of the
// tile grid of a tiled plane. Built on render/triangle_rasterizer.hpp (exact coverage, depth buffer,
// deterministic parallel tiles). Used by the docs and the `tessera render` command; io/mesh_preview.hpp
// writes it as a PNG.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "triangle_rasterizer.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of render_mesh_preview.
struct mesh_preview_options {
  /// Image width in pixels.
  index_t width = 800;
  /// Image height in pixels.
  index_t height = 600;
  double azimuth_degrees = -60;   ///< camera direction around +Z, 0 = looking along +Y from the south
  double elevation_degrees = 45;  ///< 90 = straight down (top view)
  double margin = 0.04;           ///< empty border, fraction of the image size
  /// Unit RGB of the mesh.
  std::array<float, 3> color{0.80f, 0.74f, 0.64f};
  /// Unit RGB of the background.
  std::array<float, 3> background{1.0f, 1.0f, 1.0f};
  bool tint_elements = true;  ///< vary the colour slightly per connected component
  /// Darken the pixels within about a pixel of a triangle's edge (shows a mesh's triangles).
  bool wireframe = false;
  /// Overlay the grid lines x = k * grid_spacing, y = k * grid_spacing (k integer) on the base plane
  /// z = grid_height over the mesh's XY bounds: tile borders of a tiled plane. 0 = no grid.
  double grid_spacing = 0;
  /// z of the grid's plane.
  double grid_height = 0;
  /// Unit RGB of the grid lines.
  std::array<float, 3> grid_color{0.85f, 0.15f, 0.10f};
  /// Grid line width in pixels.
  int grid_line_width = 2;
};

namespace detail {
/// Floor of the mesh's extent along each view axis, so a flat (or single-point) mesh still gets a
/// finite scale and depth instead of a division by zero.
inline constexpr double preview_min_extent = 1e-12;

inline std::array<float, 3> tint(std::array<float, 3> c, index_t id) {
  const std::uint64_t h = mix64(static_cast<std::uint64_t>(id) + 0x1234567ULL);
  const float k = 0.85f + 0.3f * static_cast<float>((h >> 11) & 0xff) / 255.0f;
  const float hue = 0.06f * (static_cast<float>((h >> 23) & 0xff) / 255.0f - 0.5f);
  return {std::min(1.0f, c[0] * k * (1 + hue)), std::min(1.0f, c[1] * k), std::min(1.0f, c[2] * k * (1 - hue))};
}
}  // namespace detail

/// Renders a shaded preview of any valid Mesh. Errors: invalid mesh (validate_mesh), a mesh without
/// faces, an image size outside 1 to 8192 pixels a side, non-finite angles, a negative or non-finite
/// grid spacing, a grid finer than 4096 lines over the mesh, a grid line width outside 1 to 64.
/// O(F + pixels); rasterization runs through `exec` (same image for every executor).
namespace detail {
/// 0.35 for a pixel within 0.75 pixels of an edge of its triangle (screen vertices sv, face fc,
/// barycentrics b: the distance to the edge opposite corner i is b_i times twice the area over that
/// edge's length), else 1.
inline float wire_factor(const std::vector<raster_vertex>& sv, const std::array<index_t, 3>& fc,
                         const std::array<float, 3>& b) {
  const raster_vertex& p0 = sv[to_size(fc[0])];
  const raster_vertex& p1 = sv[to_size(fc[1])];
  const raster_vertex& p2 = sv[to_size(fc[2])];
  const double area2 = std::abs((p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y));
  const raster_vertex* q[3] = {&p0, &p1, &p2};
  for (int i = 0; i < 3; ++i) {
    const raster_vertex& a = *q[(i + 1) % 3];
    const raster_vertex& c = *q[(i + 2) % 3];
    const double len = std::hypot(c.x - a.x, c.y - a.y);
    if (len > 0 && b[to_size(i)] * area2 / len < 0.75) return 0.35f;
  }
  return 1.0f;
}
/// render_mesh_preview with the unit RGB of face fi at barycentrics b given by surface(m, fi, b) (or
/// the options' colour and tint when `surface` is null).
template <Mesh M, Executor E, class Surface>
result<image_buffer<std::uint8_t, 3>> render_preview_with(const M& mesh, const mesh_preview_options& o, E&& exec,
                                                          const Surface* surface) {
  if (o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192)
    return status::invalid_argument(
        detail::cat("render_mesh_preview: image size must be 1 to 8192 a side, got ", o.width, " x ", o.height));
  if (!std::isfinite(o.azimuth_degrees) || !std::isfinite(o.elevation_degrees) || !(o.margin >= 0 && o.margin < 0.5))
    return status::invalid_argument("render_mesh_preview: angles must be finite and margin in [0, 0.5)");
  if (!(o.grid_spacing >= 0) || !std::isfinite(o.grid_spacing) || !std::isfinite(o.grid_height))
    return status::invalid_argument(detail::cat("render_mesh_preview: grid_spacing must be finite and >= 0, got ",
                                                o.grid_spacing, " (grid_height ", o.grid_height, ")"));
  if (o.grid_line_width < 1 || o.grid_line_width > 64)
    return status::invalid_argument(
        detail::cat("render_mesh_preview: grid_line_width must be 1 to 64, got ", o.grid_line_width));
  auto tm = to_tri_mesh(mesh, "render_mesh_preview: mesh");
  if (!tm) return tm.error();
  const tri_mesh& m = *tm;
  if (m.faces.empty()) return status::invalid_argument("render_mesh_preview: mesh has no faces");
  // camera frame: forward f points from the eye into the scene
  const double az = o.azimuth_degrees * std::numbers::pi / 180, el = o.elevation_degrees * std::numbers::pi / 180;
  const vec3 f = normalized(vec3{std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), -std::sin(el)});
  vec3 r = normalized(cross(f, vec3{0, 0, 1}));
  if (squared_norm(r) == 0) r = {1, 0, 0};
  const vec3 u = cross(r, f);
  const aabb box = bounding_box(m);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, z0 = 1e300, z1 = -1e300;
  for (const vec3& p : m.positions) {
    x0 = std::min(x0, dot(p, r));
    x1 = std::max(x1, dot(p, r));
    y0 = std::min(y0, dot(p, u));
    y1 = std::max(y1, dot(p, u));
    z0 = std::min(z0, dot(p, f));
    z1 = std::max(z1, dot(p, f));
  }
  const double mw = o.width * (1 - 2 * o.margin), mh = o.height * (1 - 2 * o.margin);
  const double scale =
      std::min(mw / std::max(x1 - x0, detail::preview_min_extent), mh / std::max(y1 - y0, detail::preview_min_extent));
  const double ox = 0.5 * (o.width - scale * (x1 - x0)), oy = 0.5 * (o.height - scale * (y1 - y0));
  auto project = [&](vec3 p) {
    return raster_vertex{ox + (dot(p, r) - x0) * scale, oy + (y1 - dot(p, u)) * scale,
                         (dot(p, f) - z0) / std::max(z1 - z0, detail::preview_min_extent) * 0.98 + 0.01, 1.0};
  };
  std::vector<raster_vertex> sv(m.positions.size());
  for (std::size_t v = 0; v < sv.size(); ++v) sv[v] = project(m.positions[v]);
  const std::vector<vec3> vn = vertex_normals(m);
  auto depth = depth_buffer::create(o.width, o.height);
  if (!depth) return depth.error();
  std::vector<std::int32_t> face_at(detail::to_size(o.width * o.height), -1);
  std::vector<std::array<float, 3>> bary_at(face_at.size());
  const auto st = rasterize_triangles(
      m.num_faces(), depth->rect(),
      [&](index_t i, raster_triangle& t) {
        const auto& fc = m.faces[detail::to_size(i)];
        t = {sv[detail::to_size(fc[0])], sv[detail::to_size(fc[1])], sv[detail::to_size(fc[2])]};
        return true;
      },
      [&](index_t i, const fragment& fr) {
        if (!depth->test_and_set(fr.x, fr.y, fr.depth)) return;
        const auto px = detail::to_size(fr.y * o.width + fr.x);
        face_at[px] = static_cast<std::int32_t>(i);
        bary_at[px] = {float(fr.bary[0]), float(fr.bary[1]), float(fr.bary[2])};
      },
      {}, exec);
  if (!st) return st;
  std::vector<index_t> comp;
  if (o.tint_elements && surface == nullptr) comp = connected_components(m).face_component;
  const vec3 l1 = normalized(vec3{-0.4, -0.5, 0.75}), l2 = normalized(vec3{0.6, 0.3, 0.4});
  image_buffer<std::uint8_t, 3> img(o.width, o.height);
  auto to8 = [](float v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
  for (index_t y = 0; y < o.height; ++y)
    for (index_t x = 0; x < o.width; ++x) {
      const auto px = detail::to_size(y * o.width + x);
      std::uint8_t* out = img.pixel_ptr(x, y);
      const std::int32_t fi = face_at[px];
      if (fi < 0) {
        for (int c = 0; c < 3; ++c) out[c] = to8(o.background[detail::to_size(c)]);
        continue;
      }
      const auto& fc = m.faces[detail::to_size(fi)];
      vec3 n = normalized(vn[detail::to_size(fc[0])] * bary_at[px][0] + vn[detail::to_size(fc[1])] * bary_at[px][1] +
                          vn[detail::to_size(fc[2])] * bary_at[px][2]);
      if (dot(n, f) > 0) n = -n;  // back faces lit like front faces
      const double shade = 0.28 + 0.62 * std::max(0.0, dot(n, l1)) + 0.25 * std::max(0.0, dot(n, l2));
      std::array<float, 3> col = o.color;
      if (surface != nullptr)
        col = (*surface)(m, fi, bary_at[px]);
      else if (o.tint_elements)
        col = detail::tint(o.color, comp[detail::to_size(fi)]);
      const float edge = o.wireframe ? detail::wire_factor(sv, fc, bary_at[px]) : 1.0f;
      for (int c = 0; c < 3; ++c) out[c] = to8(col[detail::to_size(c)] * static_cast<float>(shade) * edge);
    }
  if (o.grid_spacing > 0) {
    auto line = [&](vec3 a, vec3 b) {
      raster_vertex pa = project(a), pb = project(b);
      if (!std::isfinite(pa.x) || !std::isfinite(pa.y) || !std::isfinite(pb.x) || !std::isfinite(pb.y)) return;
      // clip to the image (plus the line width) first, Liang-Barsky: a coarse grid over a small mesh
      // projects to lines far longer than the image, and stepping along all of them would never end
      const double pad = o.grid_line_width + 1.0;
      const double dx0 = pb.x - pa.x, dy0 = pb.y - pa.y;
      double t0 = 0, t1 = 1;
      const double p[4] = {-dx0, dx0, -dy0, dy0};
      const double q[4] = {pa.x + pad, o.width + pad - pa.x, pa.y + pad, o.height + pad - pa.y};
      for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
          if (q[k] < 0) return;  // parallel to this edge and outside
          continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0)
          t0 = std::max(t0, t);
        else
          t1 = std::min(t1, t);
      }
      if (!(t0 <= t1)) return;
      pb = {pa.x + dx0 * t1, pa.y + dy0 * t1, 0, 1};
      pa = {pa.x + dx0 * t0, pa.y + dy0 * t0, 0, 1};
      // now inside the padded image: at most its diagonal long
      const double len = std::max(std::abs(pb.x - pa.x), std::abs(pb.y - pa.y));
      const auto steps = static_cast<index_t>(std::ceil(len)) + 1;
      for (index_t s = 0; s <= steps; ++s) {
        const double t = double(s) / double(steps);
        const double cx = pa.x + (pb.x - pa.x) * t, cy = pa.y + (pb.y - pa.y) * t;
        for (int dy = 0; dy < o.grid_line_width; ++dy)
          for (int dx = 0; dx < o.grid_line_width; ++dx) {
            const auto ix = static_cast<index_t>(std::floor(cx)) + dx - o.grid_line_width / 2;
            const auto iy = static_cast<index_t>(std::floor(cy)) + dy - o.grid_line_width / 2;
            if (ix < 0 || iy < 0 || ix >= o.width || iy >= o.height) continue;
            std::uint8_t* out = img.pixel_ptr(ix, iy);
            for (int c = 0; c < 3; ++c) out[c] = to8(o.grid_color[detail::to_size(c)]);
          }
      }
    };
    const double g = o.grid_spacing;
    const double gx0 = std::floor(box.min.x / g) * g, gx1 = std::ceil(box.max.x / g) * g;
    const double gy0 = std::floor(box.min.y / g) * g, gy1 = std::ceil(box.max.y / g) * g;
    if (!((gx1 - gx0) / g + (gy1 - gy0) / g <= 4096))
      return status::invalid_argument(
          detail::cat("render_mesh_preview: grid_spacing ", g, " is too fine for the mesh (more than 4096 lines)"));
    // counted loops: at coordinates far larger than g, x += g would not advance
    const auto nx = static_cast<index_t>(std::round((gx1 - gx0) / g)),
               ny = static_cast<index_t>(std::round((gy1 - gy0) / g));
    for (index_t k = 0; k <= nx; ++k) {
      const double x = gx0 + double(k) * g;
      line({x, gy0, o.grid_height}, {x, gy1, o.grid_height});
    }
    for (index_t k = 0; k <= ny; ++k) {
      const double y = gy0 + double(k) * g;
      line({gx0, y, o.grid_height}, {gx1, y, o.grid_height});
    }
  }
  return img;
}

}  // namespace detail

/// Renders a shaded preview of any valid Mesh. Errors: invalid mesh (validate_mesh), a mesh without
/// faces, an image size outside 1 to 8192 pixels a side, non-finite angles, a negative or non-finite
/// grid spacing, a grid finer than 4096 lines over the mesh, a grid line width outside 1 to 64.
/// O(F + pixels); rasterization runs through `exec` (same image for every executor).
template <Mesh M, Executor E = serial_executor>
result<image_buffer<std::uint8_t, 3>> render_mesh_preview(const M& mesh, const mesh_preview_options& o = {},
                                                          E&& exec = {}) {
  using no_surface = std::array<float, 3> (*)(const tri_mesh&, index_t, const std::array<float, 3>&);
  return detail::render_preview_with(mesh, o, exec, static_cast<const no_surface*>(nullptr));
}

/// Renders a shaded preview of any valid Mesh with one unit RGB colour per face, in face order (a
/// polycube map's chart labels through polycube_label_color, a per-face measure as a heat map).
/// Components are clamped to [0, 1], non-finite ones drawn as 0. The view, lights and grid as
/// render_mesh_preview; tint_elements and color are not used. Errors: those of render_mesh_preview,
/// invalid_argument when the colour count differs from the face count. O(F + pixels).
template <Mesh M, Executor E = serial_executor>
result<image_buffer<std::uint8_t, 3>> render_face_colored_mesh_preview(
    const M& mesh, std::span<const std::array<float, 3>> face_colors, const mesh_preview_options& o = {},
    E&& exec = {}) {
  if (auto s = validate_mesh(mesh, "render_face_colored_mesh_preview: mesh"); !s) return s;
  const index_t faces = mesh_traits<M>::num_faces(mesh);
  if (static_cast<index_t>(face_colors.size()) != faces)
    return status::invalid_argument(detail::cat("render_face_colored_mesh_preview: ", face_colors.size(),
                                                " face colours for a mesh of ", faces, " faces"));
  auto surface = [&](const tri_mesh&, index_t f, const std::array<float, 3>&) {
    std::array<float, 3> c = face_colors[detail::to_size(f)];
    for (float& v : c) v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    return c;
  };
  return detail::render_preview_with(mesh, o, exec, &surface);
}

/// Renders a shaded preview of a mesh with per-corner uvs, its colour read from `texture` (any Image;
/// its first three channels, or the first one three times for grey images) by bilinear filtering at
/// the interpolated uv (v upwards, OBJ convention: uv (0, 1) is the texture's top-left corner; texel
/// centres at half-integers, coordinates clamped to the texture). The view, lights and grid as
/// render_mesh_preview; tint_elements and color are not used. Errors: those of render_mesh_preview, a
/// mesh without uvs, an empty texture. O(F + pixels).
template <Mesh M, Image I, Executor E = serial_executor>
result<image_buffer<std::uint8_t, 3>> render_textured_mesh_preview(const M& mesh, const I& texture,
                                                                   const mesh_preview_options& o = {}, E&& exec = {}) {
  if (!has_uvs(mesh)) return status::invalid_argument("render_textured_mesh_preview: the mesh has no uvs");
  const index_t tw = width_of(texture), th = height_of(texture);
  if (tw < 1 || th < 1) return status::invalid_argument("render_textured_mesh_preview: the texture is empty");
  constexpr int TC = channels_v<I>;
  auto texel = [&](index_t x, index_t y) {
    const auto p = image_traits<I>::read(texture, std::clamp<index_t>(x, 0, tw - 1), std::clamp<index_t>(y, 0, th - 1));
    std::array<float, 3> c{};
    for (int k = 0; k < 3; ++k)
      c[detail::to_size(k)] = channel_to_unit(pixel_traits<pixel_t<I>>::get(p, TC >= 3 ? k : 0));
    return c;
  };
  auto surface = [&](const tri_mesh& m, index_t f, const std::array<float, 3>& b) {
    vec2 uv;
    for (int k = 0; k < 3; ++k) uv = uv + m.uvs[detail::to_size(f)][detail::to_size(k)] * b[detail::to_size(k)];
    const double x = uv.x * static_cast<double>(tw) - 0.5, y = (1 - uv.y) * static_cast<double>(th) - 0.5;
    if (!std::isfinite(x) || !std::isfinite(y)) return std::array<float, 3>{0, 0, 0};
    const double fx = std::floor(std::clamp(x, -1.0, static_cast<double>(tw))),
                 fy = std::floor(std::clamp(y, -1.0, static_cast<double>(th)));
    const auto ax = static_cast<float>(x - fx), ay = static_cast<float>(y - fy);
    const auto ix = static_cast<index_t>(fx), iy = static_cast<index_t>(fy);
    const auto c00 = texel(ix, iy), c10 = texel(ix + 1, iy), c01 = texel(ix, iy + 1), c11 = texel(ix + 1, iy + 1);
    std::array<float, 3> c{};
    for (std::size_t k = 0; k < 3; ++k)
      c[k] = (c00[k] * (1 - ax) + c10[k] * ax) * (1 - ay) + (c01[k] * (1 - ax) + c11[k] * ax) * ay;
    return c;
  };
  return detail::render_preview_with(mesh, o, exec, &surface);
}

TESSERA_NAMESPACE_END
