// tessera/surface/map_wang_tiles_to_surface.hpp: image Wang tiles on a closed surface (Fu & Leung
// 2005, paper 000's ref. [5]; paper 000 §4): the base mesh of a polycube map is split along the quad
// borders so that every face lies in exactly one quad, and every face corner gets a texture
// coordinate into a three-axis Wang atlas (image/axis_wang_atlas.hpp) from its position in its quad
// and the tile the quad was given (surface/polycube_tiling.hpp). Rendered with that atlas the surface
// shows no tile seams: on either side of a quad border the bilinear samples agree, also around polycube
// edges and corners (the atlas' padding is what lies across the border, see axis_wang_tiles.hpp).
//
// The split works in each face's chart plane, in grid units (polycube position / tile_size, with each
// vertex's coordinate along a chart's axis set to that chart's integer plane, so chart borders and
// grid lines are exact): the triangle is clipped against every grid cell it overlaps (Sutherland-
// Hodgman). A point where a base edge crosses a grid plane is computed once per edge (from its
// lower-index end), so the faces on both sides of the edge, in one chart or on two charts meeting at
// a polycube edge, share it bit for bit and the split mesh stays closed; a grid point inside a face
// is exact. Pieces with more than three corners are fanned from their first corner, or, when that
// would give a degenerate triangle (three corners on one line), from an added centre point.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "../image/axis_wang_atlas.hpp"
#include "../image/axis_wang_tiles.hpp"
#include "../tiling/axis_tile_set.hpp"
#include "polycube_map.hpp"
#include "polycube_tiling.hpp"
#include "quad_layout.hpp"

TESSERA_NAMESPACE_BEGIN

/// Gives every quad of `map` the tile of the three-axis image set `set` whose face is the quad's label
/// and whose edge colours match `coloring` (as assign_polycube_tiles does for geometric sets; the
/// placement's tile_to_quad maps tile pixels (x, y, 0) to (u, v, 0) = (x, y, 0) / tile_size, y
/// measured upwards). Errors: those of assign_polycube_tiles, and an empty set.
template <Channel T, int C, TileColoring Col>
result<polycube_tiling> assign_polycube_tiles(const polycube_map& map, const axis_wang_tile_set<T, C>& set,
                                              const Col& coloring) {
  if (set.size() == 0) return status::invalid_argument("assign_polycube_tiles: the image tile set is empty");
  return detail::assign_axis_tiles(
      map, set.axis_colors(), set.size(), [&](index_t t) { return set.tile_info(t); },
      static_cast<double>(set.tile_size()), coloring, "assign_polycube_tiles");
}

/// Colours `map`'s grid edges with the image set's colour counts (color_polycube_edges, keyed by
/// `seed`) and assigns the tiles: a pure function of (map, set, seed), whatever the executor.
template <Channel T, int C, Executor E = serial_executor>
result<polycube_tiling> tile_polycube(const polycube_map& map, const axis_wang_tile_set<T, C>& set, std::uint64_t seed,
                                      E&& exec = {}) {
  if (set.size() == 0) return status::invalid_argument("tile_polycube: the image tile set is empty");
  auto coloring = color_polycube_edges(map, set.axis_colors(), seed, exec);
  if (!coloring) return coloring.error();
  return assign_polycube_tiles(map, set, *coloring);
}

/// The base mesh split along quad borders, with texture coordinates into the atlas.
struct wang_surface_mesh {
  /// Positions in base-mesh units: the base vertices first (same order), then the new ones; faces
  /// counter-clockwise as the base's; `uvs`: per corner, atlas coordinates in [0, 1]² with v upwards
  /// (OBJ convention: atlas texel (x, y), y downwards, is (x / W, 1 − y / H)).
  tri_mesh mesh;
  /// Per face: the quad it lies in.
  std::vector<index_t> face_quad;
  /// Per face: the base face it is a piece of.
  std::vector<index_t> face_origin;
  /// Per face corner: its (u, v) in its face's quad, [0, 1]² (u from corner 0 to 1, v from 0 to 3).
  std::vector<std::array<vec2, 3>> quad_uv;
  /// New vertices on base edges (where a grid plane crosses them), inside faces (grid points) and
  /// added centres.
  index_t edge_vertices = 0, grid_vertices = 0, centre_vertices = 0;
  /// Base faces cut by at least one quad border.
  index_t split_faces = 0;
};

namespace detail {
/// A point of the split: its grid-unit polycube position and its base position.
struct wang_split_point {
  vec3 grid;
  vec3 base;
};
/// Base edge (lo, hi), lo < hi, and where it crosses grid planes: the distinct points, sorted by
/// parameter from lo, and which point each crossed plane gives (planes crossed at one grid point share
/// it).
struct wang_split_edge {
  index_t lo = 0, hi = 0;
  struct crossing {
    int axis = 0;
    std::int64_t plane = 0;
    std::size_t point = 0;
  };
  std::vector<wang_split_point> points;
  std::vector<crossing> crossings;
};
/// Coordinates within this many grid units of an integer are moved onto it: vertices (and edge
/// crossings) a rounding error away from a grid line would otherwise leave pieces too thin to orient.
inline constexpr double wang_grid_snap = 1e-6;
inline double snap_to_grid(double g) noexcept {
  const double r = std::round(g);
  return std::abs(g - r) < wang_grid_snap ? r : g;
}
/// A corner of a clip polygon: its 2D chart coordinates and what it is. kind 0: a vertex id (base
/// vertex or edge crossing, global); 1: the grid point (gx, gy) of the chart plane.
struct wang_clip_corner {
  vec2 q;
  int kind = 0;
  index_t id = 0;
  std::int64_t gx = 0, gy = 0;
  /// Support of the polygon side from this corner to the next: a base edge (edge >= 0), or the grid
  /// line (line_axis, line_value) of the chart plane (edge = -1).
  index_t edge = -1;
  int line_axis = 0;
  std::int64_t line_value = 0;
};
/// A piece's corner before global numbering: kind 0 vertex id; 1 grid point (key); 2 the centre of
/// polygon `id` of its face.
struct wang_piece_corner {
  int kind = 0;
  index_t id = 0;
  grid_point g{};
  vec2 q;  // chart coordinates
};
struct wang_piece {
  index_t quad = -1;
  std::array<wang_piece_corner, 3> c;
};
}  // namespace detail

/// Splits `mesh` (the base of `map`) along the quad borders of `map` and gives every face corner its
/// atlas coordinates for the tiles `tiling` assigns (tile_polycube with an axis_wang_tile_set, or
/// assign_polycube_tiles with any colouring) in `atlas` (build_axis_wang_atlas of that set). See the
/// file comment for how the split keeps the mesh closed and both sides of every border exact.
///
/// - mesh: any Mesh equal to map.base (same vertices within 1e-9 of its size, same faces): the input
///   of build_polycube_map, or its refined base (map.base) when the map refined it.
/// - exec: faces are split in parallel; the result is the same for any executor.
/// Errors (invalid_argument): a mesh refused by validate_polycube_input (open, non-manifold,
/// inconsistently oriented, degenerate faces); a mesh that is not map.base (vertex or face counts,
/// a face or a position differ: a polycube of another mesh); a map without a quad layout or whose
/// layout belongs to another map; a tiling with another number of quads, naming a tile outside the
/// atlas or a tile of another face than its quad's (a set or tiling that does not fit this polycube);
/// an atlas without tiles; a vertex on two charts of one axis with different planes; a face piece
/// in a grid cell that is no quad of its chart (not_converged). O(F + pieces).
template <Mesh M, Channel T, int C, Executor E = serial_executor>
result<wang_surface_mesh> map_wang_tiles_to_surface(const M& mesh, const polycube_map& map,
                                                    const polycube_tiling& tiling, const axis_wang_atlas<T, C>& atlas,
                                                    E&& exec = {}) {
  constexpr std::string_view fn = "map_wang_tiles_to_surface";
  if (auto s = validate_polycube_input(mesh, "map_wang_tiles_to_surface: mesh"); !s) return s;
  const index_t nv = num_vertices(mesh), nf = num_faces(mesh);
  if (nv != map.base.num_vertices() || nf != map.base.num_faces() || map.polycube.size() != map.base.positions.size() ||
      map.face_chart.size() != map.base.faces.size())
    return status::invalid_argument(detail::cat(fn, ": the mesh has ", nv, " vertices and ", nf,
                                                " faces, the polycube map's base ", map.base.num_vertices(), " and ",
                                                map.base.num_faces(), ": a polycube of another mesh"));
  {
    const aabb box = bounding_box(map.base);
    const double tol = 1e-9 * std::max(1e-300, std::sqrt(squared_norm(box.extent())));
    for (index_t v = 0; v < nv; ++v)
      if (!(std::sqrt(squared_norm(vertex_position(mesh, v) - map.base.positions[detail::to_size(v)])) <= tol))
        return status::invalid_argument(
            detail::cat(fn, ": vertex ", v, " differs from the polycube map's base: a polycube of another mesh"));
    for (index_t f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k)
        if (face_vertex(mesh, f, k) != map.base.faces[detail::to_size(f)][detail::to_size(k)])
          return status::invalid_argument(
              detail::cat(fn, ": face ", f, " differs from the polycube map's base: a polycube of another mesh"));
  }
  if (auto s = detail::check_layout_for_tiling(map); !s) return s;
  if (!(map.tile_size > 0) || !std::isfinite(map.tile_size))
    return status::invalid_argument(detail::cat(fn, ": the map's tile_size must be > 0, got ", map.tile_size));
  const auto& L = map.layout;
  if (tiling.quads.size() != L.quads.size())
    return status::invalid_argument(detail::cat(fn, ": the tiling covers ", tiling.quads.size(),
                                                " quads, the layout has ", L.quads.size(),
                                                ": a tiling of another polycube"));
  if (atlas.origin.empty() || atlas.tile_size <= 0 || atlas.image.width() <= 0 || atlas.image.height() <= 0)
    return status::invalid_argument(detail::cat(fn, ": the atlas has no tiles"));
  if (auto s = validate_axis_color_counts(atlas.axis_colors); !s)
    return status(s.code(), detail::cat(fn, ": atlas: ", s.message()));
  if (static_cast<index_t>(atlas.origin.size()) != axis_tile_count(atlas.axis_colors))
    return status::invalid_argument(detail::cat(
        fn, ": the atlas holds ", atlas.origin.size(), " tiles, a complete set of ", atlas.axis_colors[0], ", ",
        atlas.axis_colors[1], ", ", atlas.axis_colors[2], " colours ", axis_tile_count(atlas.axis_colors)));
  for (std::size_t q = 0; q < L.quads.size(); ++q) {
    const index_t t = tiling.quads[q].tile;
    const polycube_label label = map.charts[detail::to_size(L.quads[q].chart)].label;
    if (t < 0 || t >= static_cast<index_t>(atlas.origin.size()))
      return status::invalid_argument(detail::cat(fn, ": quad ", q, " has tile ", t, ", outside the atlas' [0, ",
                                                  atlas.origin.size(), "): a tile set that does not fit"));
    if (axis_tile_at(t, atlas.axis_colors).face != static_cast<int>(label))
      return status::invalid_argument(detail::cat(fn, ": quad ", q, " faces ", cube_face_name(static_cast<int>(label)),
                                                  " but its tile ", t, " is a tile of face ",
                                                  cube_face_name(axis_tile_at(t, atlas.axis_colors).face),
                                                  ": a tiling of another set or polycube"));
  }
  // grid-unit positions, each coordinate along a chart's axis set to that chart's plane
  std::vector<vec3> G(detail::to_size(nv));
  for (index_t v = 0; v < nv; ++v)
    for (int a = 0; a < 3; ++a)
      G[detail::to_size(v)][a] = detail::snap_to_grid(map.polycube[detail::to_size(v)][a] / map.tile_size);
  {
    std::vector<std::array<std::int64_t, 3>> plane(detail::to_size(nv), {INT64_MIN, INT64_MIN, INT64_MIN});
    for (index_t f = 0; f < nf; ++f) {
      const auto& ch = map.charts[detail::to_size(map.face_chart[detail::to_size(f)])];
      const int a = label_axis(ch.label);
      for (index_t v : map.base.faces[detail::to_size(f)]) {
        auto& p = plane[detail::to_size(v)][detail::to_size(a)];
        if (p != INT64_MIN && p != ch.plane)
          return status::invalid_argument(detail::cat(fn, ": vertex ", v, " lies on two charts along ", "XYZ"[a],
                                                      " with planes ", p, " and ", ch.plane));
        p = ch.plane;
        G[detail::to_size(v)][a] = static_cast<double>(ch.plane);
      }
    }
  }
  // base edges and their grid-plane crossings (computed once per edge, from its lower end)
  std::vector<std::array<index_t, 3>> face_edge(detail::to_size(nf));
  std::vector<detail::wang_split_edge> edges;
  {
    std::vector<std::array<index_t, 4>> hs;  // lo, hi, face, side
    hs.reserve(detail::to_size(3 * nf));
    for (index_t f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const index_t a = map.base.faces[detail::to_size(f)][detail::to_size(k)];
        const index_t b = map.base.faces[detail::to_size(f)][detail::to_size((k + 1) % 3)];
        hs.push_back({std::min(a, b), std::max(a, b), f, k});
      }
    std::sort(hs.begin(), hs.end());
    for (std::size_t i = 0; i < hs.size(); ++i) {
      if (i == 0 || hs[i][0] != hs[i - 1][0] || hs[i][1] != hs[i - 1][1]) edges.push_back({hs[i][0], hs[i][1], {}, {}});
      face_edge[detail::to_size(hs[i][2])][detail::to_size(hs[i][3])] = static_cast<index_t>(edges.size()) - 1;
    }
  }
  exec.parallel_for(0, static_cast<index_t>(edges.size()), [&](index_t e) {
    auto& ed = edges[detail::to_size(e)];
    const vec3 a = G[detail::to_size(ed.lo)], b = G[detail::to_size(ed.hi)];
    const vec3 pa = map.base.positions[detail::to_size(ed.lo)], pb = map.base.positions[detail::to_size(ed.hi)];
    struct hit {
      double t;
      int axis;
      std::int64_t plane;
      detail::wang_split_point p;
    };
    std::vector<hit> hits;
    for (int ax = 0; ax < 3; ++ax) {
      const double lo = std::min(a[ax], b[ax]), hi = std::max(a[ax], b[ax]);
      for (auto k = static_cast<std::int64_t>(std::floor(lo)) + 1; static_cast<double>(k) < hi; ++k) {
        if (!(static_cast<double>(k) > lo)) continue;
        const double t = (static_cast<double>(k) - a[ax]) / (b[ax] - a[ax]);
        hit h{t, ax, k, {a + (b - a) * t, pa + (pb - pa) * t}};
        for (int j = 0; j < 3; ++j)  // stay within the edge's range (clipping relies on it), snapped
          h.p.grid[j] = detail::snap_to_grid(std::clamp(h.p.grid[j], std::min(a[j], b[j]), std::max(a[j], b[j])));
        h.p.grid[ax] = static_cast<double>(k);
        hits.push_back(h);
      }
    }
    std::sort(hits.begin(), hits.end(), [](const hit& x, const hit& y) {
      return x.t != y.t ? x.t < y.t : x.axis != y.axis ? x.axis < y.axis : x.plane < y.plane;
    });
    for (const hit& h : hits) {
      // planes crossed at one grid point (after snapping) give one point
      std::size_t at = ed.points.size();
      for (std::size_t j = 0; j < ed.points.size(); ++j)
        if (ed.points[j].grid == h.p.grid) at = j;
      if (at == ed.points.size()) ed.points.push_back(h.p);
      ed.crossings.push_back({h.axis, h.plane, at});
    }
  });
  std::vector<index_t> edge_first(edges.size() + 1, nv);
  for (std::size_t e = 0; e < edges.size(); ++e)
    edge_first[e + 1] = edge_first[e] + static_cast<index_t>(edges[e].points.size());
  // split every face in its chart plane
  std::vector<std::vector<detail::wang_piece>> pieces(detail::to_size(nf));
  std::vector<status> failures(detail::to_size(nf));
  exec.parallel_for(0, nf, [&](index_t f) {
    const auto& ch = map.charts[detail::to_size(map.face_chart[detail::to_size(f)])];
    const auto ax = detail::quad_plane_axes(ch.label);
    const auto& grid = L.chart_grids[detail::to_size(map.face_chart[detail::to_size(f)])];
    const auto& fv = map.base.faces[detail::to_size(f)];
    auto chart_q = [&](const vec3& g) { return vec2{g[ax[0]], g[ax[1]]}; };
    std::vector<detail::wang_clip_corner> poly(3);
    for (int k = 0; k < 3; ++k) {
      auto& c = poly[detail::to_size(k)];
      c.q = chart_q(G[detail::to_size(fv[detail::to_size(k)])]);
      c.kind = 0;
      c.id = fv[detail::to_size(k)];
      c.edge = face_edge[detail::to_size(f)][detail::to_size(k)];
    }
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& c : poly) {
      x0 = std::min(x0, c.q.x), x1 = std::max(x1, c.q.x), y0 = std::min(y0, c.q.y), y1 = std::max(y1, c.q.y);
    }
    // one clip of `in` against axis2d (0: first in-plane axis) = value, keeping the side `keep` (+1 or -1)
    auto clip = [&](const std::vector<detail::wang_clip_corner>& in, int axis2d, std::int64_t value, int keep,
                    std::vector<detail::wang_clip_corner>& out) {
      out.clear();
      const auto n = in.size();
      const double vk = static_cast<double>(value);
      for (std::size_t i = 0; i < n; ++i) {
        const auto& A = in[i];
        const auto& B = in[(i + 1) % n];
        const double dA = keep * (A.q[axis2d] - vk), dB = keep * (B.q[axis2d] - vk);
        auto on_line = [&](detail::wang_clip_corner& c) {
          c.edge = -1;
          c.line_axis = axis2d;
          c.line_value = value;
        };
        if (dA >= 0) {
          out.push_back(A);
          if (!(dB >= 0 || dA > 0)) on_line(out.back());
        }
        if ((dA < 0 && dB > 0) || (dA > 0 && dB < 0)) {
          detail::wang_clip_corner X = A;  // the side's support continues (entering)
          if (A.edge >= 0) {               // on a base edge: its crossing with this grid plane
            const auto e = detail::to_size(A.edge);
            const int axis3 = ax[detail::to_size(axis2d)];
            std::size_t j = 0;
            while (j < edges[e].crossings.size() &&
                   !(edges[e].crossings[j].axis == axis3 && edges[e].crossings[j].plane == value))
              ++j;
            if (j == edges[e].crossings.size()) {
              failures[detail::to_size(f)] = status::not_converged(
                  detail::cat(fn, ": face ", f, ": base edge ", A.edge, " crosses no grid plane ", value));
              return;
            }
            X.kind = 0;
            const std::size_t pt = edges[e].crossings[j].point;
            X.id = edge_first[e] + static_cast<index_t>(pt);
            X.q = chart_q(edges[e].points[pt].grid);
          } else {  // on a grid line: a grid point of the chart plane
            const std::int64_t other = A.line_value;
            X.kind = 1;
            X.gx = axis2d == 0 ? value : other;
            X.gy = axis2d == 0 ? other : value;
            X.q = {static_cast<double>(X.gx), static_cast<double>(X.gy)};
          }
          if (dA > 0) on_line(X);  // leaving: the next side runs along the clip line
          out.push_back(X);
        }
      }
    };
    auto& out_pieces = pieces[detail::to_size(f)];
    std::vector<detail::wang_clip_corner> p0, p1;
    index_t polygons = 0;
    const auto i0 = static_cast<std::int64_t>(std::floor(x0)), i1 = static_cast<std::int64_t>(std::ceil(x1));
    const auto j0 = static_cast<std::int64_t>(std::floor(y0)), j1 = static_cast<std::int64_t>(std::ceil(y1));
    for (std::int64_t j = j0; j < std::max(j1, j0 + 1); ++j)
      for (std::int64_t i = i0; i < std::max(i1, i0 + 1); ++i) {
        clip(poly, 0, i, 1, p0);
        clip(p0, 0, i + 1, -1, p1);
        clip(p1, 1, j, 1, p0);
        clip(p0, 1, j + 1, -1, p1);
        if (!failures[detail::to_size(f)]) return;
        if (p1.size() < 3) continue;
        double area2 = 0;
        for (std::size_t k = 0; k < p1.size(); ++k) area2 += cross(p1[k].q, p1[(k + 1) % p1.size()].q);
        if (!(area2 > 0)) continue;
        const std::int64_t ci = i - grid.origin[0], cj = j - grid.origin[1];
        const index_t quad = ci >= 0 && cj >= 0 && ci < grid.size[0] && cj < grid.size[1]
                                 ? grid.quad[detail::to_size(cj * grid.size[0] + ci)]
                                 : -1;
        if (quad < 0) {
          failures[detail::to_size(f)] = status::not_converged(
              detail::cat(fn, ": face ", f, " reaches grid cell (", i, ", ", j, ") of chart ",
                          map.face_chart[detail::to_size(f)], ", which is no quad (area ", 0.5 * area2, " tiles)"));
          return;
        }
        auto corner_of = [&](const detail::wang_clip_corner& c) {
          detail::wang_piece_corner pc;
          pc.q = c.q;
          pc.kind = c.kind;
          pc.id = c.id;
          if (c.kind == 1) {
            pc.g[detail::to_size(label_axis(ch.label))] = ch.plane;
            pc.g[detail::to_size(ax[0])] = c.gx;
            pc.g[detail::to_size(ax[1])] = c.gy;
          }
          return pc;
        };
        const std::size_t n = p1.size();
        bool collinear = false;
        for (std::size_t k = 1; k + 1 < n && n > 3; ++k)
          collinear = collinear || cross(p1[k].q - p1[0].q, p1[k + 1].q - p1[0].q) == 0;
        if (!collinear) {
          for (std::size_t k = 1; k + 1 < n; ++k)
            out_pieces.push_back({quad, {corner_of(p1[0]), corner_of(p1[k]), corner_of(p1[k + 1])}});
        } else {
          detail::wang_piece_corner centre;
          centre.kind = 2;
          centre.id = polygons;
          for (const auto& c : p1) centre.q = centre.q + c.q / static_cast<double>(n);
          for (std::size_t k = 0; k < n; ++k)
            out_pieces.push_back({quad, {centre, corner_of(p1[k]), corner_of(p1[(k + 1) % n])}});
        }
        ++polygons;
      }
  });
  for (const auto& s : failures)
    if (!s) return s;
  // number the vertices: base, edge crossings, then grid points and centres in face order
  wang_surface_mesh out;
  tri_mesh& m = out.mesh;
  m.positions.resize(detail::to_size(edge_first.back()));
  for (index_t v = 0; v < nv; ++v) m.positions[detail::to_size(v)] = map.base.positions[detail::to_size(v)];
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (std::size_t j = 0; j < edges[e].points.size(); ++j)
      m.positions[detail::to_size(edge_first[e]) + j] = edges[e].points[j].base;
  out.edge_vertices = edge_first.back() - nv;
  std::map<grid_point, index_t> grid_ids;
  const double W = static_cast<double>(atlas.image.width()), H = static_cast<double>(atlas.image.height());
  const double ts = static_cast<double>(atlas.tile_size);
  for (index_t f = 0; f < nf; ++f) {
    const auto& fp = pieces[detail::to_size(f)];
    if (fp.empty()) continue;
    const auto& fv = map.base.faces[detail::to_size(f)];
    const auto ax = detail::quad_plane_axes(map.charts[detail::to_size(map.face_chart[detail::to_size(f)])].label);
    std::array<vec2, 3> tq;
    for (int k = 0; k < 3; ++k) {
      const vec3& g = G[detail::to_size(fv[detail::to_size(k)])];
      tq[detail::to_size(k)] = {g[ax[0]], g[ax[1]]};
    }
    auto base_at = [&](vec2 q) {  // barycentric in the face's chart triangle
      const double d = cross(tq[1] - tq[0], tq[2] - tq[0]);
      const double b1 = cross(q - tq[0], tq[2] - tq[0]) / d, b2 = cross(tq[1] - tq[0], q - tq[0]) / d;
      const vec3& p0 = map.base.positions[detail::to_size(fv[0])];
      return p0 + (map.base.positions[detail::to_size(fv[1])] - p0) * b1 +
             (map.base.positions[detail::to_size(fv[2])] - p0) * b2;
    };
    out.split_faces += fp.size() > 1 ? 1 : 0;
    index_t centre_id = -1, centre_of = -1;  // the latest centre and its polygon
    for (const auto& piece : fp) {
      std::array<index_t, 3> ids{};
      for (int k = 0; k < 3; ++k) {
        const auto& c = piece.c[detail::to_size(k)];
        if (c.kind == 0) {
          ids[detail::to_size(k)] = c.id;
        } else if (c.kind == 1) {
          auto [it, fresh] = grid_ids.emplace(c.g, m.num_vertices());
          if (fresh) {
            m.positions.push_back(base_at(c.q));
            ++out.grid_vertices;
          }
          ids[detail::to_size(k)] = it->second;
        } else {
          if (centre_of != c.id) {
            centre_of = c.id;
            centre_id = m.num_vertices();
            m.positions.push_back(base_at(c.q));
            ++out.centre_vertices;
          }
          ids[detail::to_size(k)] = centre_id;
        }
      }
      const auto& Q = L.quads[detail::to_size(piece.quad)];
      const index_t tile = tiling.quads[detail::to_size(piece.quad)].tile;
      std::array<vec2, 3> uv{}, quv{};
      for (int k = 0; k < 3; ++k) {
        const vec2 q = piece.c[detail::to_size(k)].q;
        const vec2 local{q.x - static_cast<double>(Q.corners[0][detail::to_size(ax[0])]),
                         q.y - static_cast<double>(Q.corners[0][detail::to_size(ax[1])])};
        quv[detail::to_size(k)] = local;
        const vec2 tx = atlas.texel(tile, local.x * ts, (1 - local.y) * ts);
        uv[detail::to_size(k)] = {tx.x / W, 1 - tx.y / H};
      }
      m.add_face(ids[0], ids[1], ids[2], uv);
      out.face_quad.push_back(piece.quad);
      out.face_origin.push_back(f);
      out.quad_uv.push_back(quv);
    }
  }
  return out;
}

TESSERA_NAMESPACE_END
