// tessera/surface/quad_layout.hpp: the quad layout of a polycube (types in polycube_map.hpp): every chart
// plane cut into tile-size squares, the grid edges they share with stable ids, and each quad's
// neighbour across each side, also around convex and concave polycube edges. Paper 000 §4 puts one Wang
// tile on each square; the grid edges' axes are its three colour classes (nX, nY, nZ).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "detail/tolerances.hpp"
#include "polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// Barycentric slack of the quad-centre-in-face test, so a centre on a face edge is found in a face.
inline constexpr double quad_centre_bary_slack = 1e-9;
/// A chart's area (in tiles) and its count of whole grid squares may differ by this fraction (of the
/// area, at least 1) before the chart's boundary counts as off the tile grid.
inline constexpr double chart_area_tolerance = 1e-6;

/// In-plane axes of a label: side 0 of its quads runs along the first, side 1 along the second, so that
/// the quad corners run counter-clockwise seen from the label direction.
constexpr std::array<int, 2> quad_plane_axes(polycube_label l) noexcept {
  const int a = label_axis(l);
  return label_sign(l) > 0 ? std::array<int, 2>{(a + 1) % 3, (a + 2) % 3}
                           : std::array<int, 2>{(a + 2) % 3, (a + 1) % 3};
}
inline bool point_in_triangle_2d(vec2 p, vec2 a, vec2 b, vec2 c) noexcept {
  const double d = cross(b - a, c - a);
  if (d == 0) return false;
  const double s = cross(b - a, p - a) / d, t = cross(p - a, c - a) / d;
  const double e = quad_centre_bary_slack;
  return s >= -e && t >= -e && s + t <= 1 + e;
}
}  // namespace detail

/// Cuts the polycube surface of `map` (its polycube positions, face charts, chart labels and planes,
/// tile_size; the other fields are not read) into quads: a tile-grid square of a chart's plane is a quad
/// when its centre lies in one of the chart's faces. Quads are numbered chart by chart, row by row.
/// Checks that the quads cover the polycube area exactly and that every grid edge is shared by exactly
/// two quads traversing it in opposite directions (a closed, consistently oriented quad surface).
/// Errors: size_overflow when the chart rectangles exceed `max_cells` squares in all; not_converged
/// naming the chart or grid edge where the layout is not a closed quad surface. O(F + quads log quads).
inline result<quad_layout> build_quad_layout(const polycube_map& map, std::int64_t max_cells = std::int64_t{1} << 26) {
  quad_layout out;
  const double t = map.tile_size;
  const std::size_t nc = map.charts.size();
  out.chart_grids.resize(nc);
  std::vector<double> chart_area(nc, 0.0);
  std::int64_t cells = 0;
  std::vector<std::array<double, 4>> box(nc, {1e300, 1e300, -1e300, -1e300});
  for (std::size_t f = 0; f < map.base.faces.size(); ++f) {
    const auto c = detail::to_size(map.face_chart[f]);
    const auto ax = detail::quad_plane_axes(map.charts[c].label);
    for (index_t v : map.base.faces[f]) {
      const vec3& p = map.polycube[detail::to_size(v)];
      box[c][0] = std::min(box[c][0], p[ax[0]] / t);
      box[c][1] = std::min(box[c][1], p[ax[1]] / t);
      box[c][2] = std::max(box[c][2], p[ax[0]] / t);
      box[c][3] = std::max(box[c][3], p[ax[1]] / t);
    }
  }
  for (std::size_t c = 0; c < nc; ++c) {
    auto& g = out.chart_grids[c];
    if (!(box[c][2] - box[c][0] < 1e15 && box[c][3] - box[c][1] < 1e15))
      return status::size_overflow(detail::cat("polycube: chart ", c, " spans too many tiles"));
    g.origin = {static_cast<std::int64_t>(std::floor(box[c][0] + detail::tile_grid_rounding)),
                static_cast<std::int64_t>(std::floor(box[c][1] + detail::tile_grid_rounding))};
    g.size = {std::max<std::int64_t>(
                  0, static_cast<std::int64_t>(std::ceil(box[c][2] - detail::tile_grid_rounding)) - g.origin[0]),
              std::max<std::int64_t>(
                  0, static_cast<std::int64_t>(std::ceil(box[c][3] - detail::tile_grid_rounding)) - g.origin[1])};
    if (g.size[0] > max_cells || g.size[1] > max_cells || g.size[0] * g.size[1] > max_cells - cells)
      return status::size_overflow(
          detail::cat("polycube: the charts' tile rectangles exceed ", max_cells, " squares; use a larger tile size"));
    cells += g.size[0] * g.size[1];
    g.quad.assign(detail::to_size(g.size[0] * g.size[1]), -1);
  }
  // mark covered squares: -2 = covered, quad ids are given below in row order
  for (std::size_t f = 0; f < map.base.faces.size(); ++f) {
    const auto c = detail::to_size(map.face_chart[f]);
    auto& g = out.chart_grids[c];
    const auto ax = detail::quad_plane_axes(map.charts[c].label);
    std::array<vec2, 3> q;
    for (int k = 0; k < 3; ++k) {
      const vec3& p = map.polycube[detail::to_size(map.base.faces[f][detail::to_size(k)])];
      q[detail::to_size(k)] = {p[ax[0]] / t - static_cast<double>(g.origin[0]),
                               p[ax[1]] / t - static_cast<double>(g.origin[1])};
    }
    chart_area[c] += 0.5 * std::abs(cross(q[1] - q[0], q[2] - q[0]));
    const double x0 = std::min({q[0].x, q[1].x, q[2].x}), x1 = std::max({q[0].x, q[1].x, q[2].x});
    const double y0 = std::min({q[0].y, q[1].y, q[2].y}), y1 = std::max({q[0].y, q[1].y, q[2].y});
    const auto i0 = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(x0 - 0.5)));
    const auto i1 = std::min<std::int64_t>(g.size[0] - 1, static_cast<std::int64_t>(std::ceil(x1 - 0.5)));
    const auto j0 = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(y0 - 0.5)));
    const auto j1 = std::min<std::int64_t>(g.size[1] - 1, static_cast<std::int64_t>(std::ceil(y1 - 0.5)));
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i)
        if (detail::point_in_triangle_2d({static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5}, q[0], q[1],
                                         q[2]))
          g.quad[detail::to_size(j * g.size[0] + i)] = -2;
  }
  struct key {
    int axis;
    grid_point origin;
    index_t quad;
    int side;
  };
  std::vector<key> keys;
  for (std::size_t c = 0; c < nc; ++c) {
    auto& g = out.chart_grids[c];
    const polycube_label l = map.charts[c].label;
    const auto ax = detail::quad_plane_axes(l);
    std::int64_t count = 0;
    for (std::int64_t j = 0; j < g.size[1]; ++j)
      for (std::int64_t i = 0; i < g.size[0]; ++i) {
        auto& slot = g.quad[detail::to_size(j * g.size[0] + i)];
        if (slot != -2) continue;
        ++count;
        slot = static_cast<index_t>(out.quads.size());
        polycube_quad q;
        q.chart = static_cast<index_t>(c);
        const std::array<std::array<std::int64_t, 2>, 4> uv{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
        for (int k = 0; k < 4; ++k) {
          grid_point p{};
          p[detail::to_size(label_axis(l))] = map.charts[c].plane;
          p[detail::to_size(ax[0])] = g.origin[0] + i + uv[detail::to_size(k)][0];
          p[detail::to_size(ax[1])] = g.origin[1] + j + uv[detail::to_size(k)][1];
          q.corners[detail::to_size(k)] = p;
        }
        for (int k = 0; k < 4; ++k) {
          const grid_point& a = q.corners[detail::to_size(k)];
          const grid_point& b = q.corners[detail::to_size((k + 1) % 4)];
          const int axis = a[0] != b[0] ? 0 : a[1] != b[1] ? 1 : 2;
          q.edge_forward[detail::to_size(k)] = b[detail::to_size(axis)] > a[detail::to_size(axis)];
          keys.push_back({axis, q.edge_forward[detail::to_size(k)] ? a : b, slot, k});
        }
        out.quads.push_back(q);
      }
    if (std::abs(static_cast<double>(count) - chart_area[c]) >
        detail::chart_area_tolerance * std::max(1.0, chart_area[c]))
      return status::not_converged(detail::cat("polycube: chart ", c, " covers ", chart_area[c], " tiles of area but ",
                                               count, " whole squares: its boundary is off the tile grid"));
  }
  std::sort(keys.begin(), keys.end(), [](const key& x, const key& y) {
    return x.axis != y.axis ? x.axis < y.axis : x.origin != y.origin ? x.origin < y.origin : x.quad < y.quad;
  });
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j].axis == keys[i].axis && keys[j].origin == keys[i].origin) ++j;
    const auto id = static_cast<index_t>(out.edges.size());
    const auto& k0 = keys[i];
    if (j - i != 2)
      return status::not_converged(detail::cat("polycube: grid edge at (", k0.origin[0], ", ", k0.origin[1], ", ",
                                               k0.origin[2], ") along ", "XYZ"[k0.axis], " is shared by ", j - i,
                                               " quads, not 2: the polycube surface is not closed there"));
    const auto& k1 = keys[i + 1];
    auto& q0 = out.quads[detail::to_size(k0.quad)];
    auto& q1 = out.quads[detail::to_size(k1.quad)];
    if (q0.edge_forward[detail::to_size(k0.side)] == q1.edge_forward[detail::to_size(k1.side)])
      return status::not_converged(detail::cat("polycube: quads ", k0.quad, " and ", k1.quad,
                                               " traverse their shared grid edge in the same direction"));
    out.edges.push_back({k0.axis, k0.origin, {k0.quad, k1.quad}});
    q0.edges[detail::to_size(k0.side)] = id;
    q1.edges[detail::to_size(k1.side)] = id;
    q0.neighbors[detail::to_size(k0.side)] = k1.quad;
    q1.neighbors[detail::to_size(k1.side)] = k0.quad;
    q0.neighbor_side[detail::to_size(k0.side)] = static_cast<std::int8_t>(k1.side);
    q1.neighbor_side[detail::to_size(k1.side)] = static_cast<std::int8_t>(k0.side);
    i = j;
  }
  return out;
}

/// The quad layout as a triangle mesh: each quad as two triangles (corners 0-1-2 and 0-2-3) over its own
/// four vertices, in mesh units, in quad order (face 2q and 2q + 1 are quad q). O(quads).
inline tri_mesh quad_layout_mesh(const polycube_map& map) {
  tri_mesh m;
  for (const auto& q : map.layout.quads) {
    const index_t b = m.num_vertices();
    for (const auto& p : q.corners)
      m.add_vertex({static_cast<double>(p[0]) * map.tile_size, static_cast<double>(p[1]) * map.tile_size,
                    static_cast<double>(p[2]) * map.tile_size});
    m.add_face(b, b + 1, b + 2);
    m.add_face(b, b + 2, b + 3);
  }
  return m;
}

TESSERA_NAMESPACE_END
