// tessera/surface/polycube_tiling.hpp: Wang tiles on a polycube surface, paper 000 §4 (after Fu & Leung
// 2005): every grid edge of the quad layout gets a colour from the colour set of the axis it runs along
// (parallel edges share one set, §3.1 Fig. 2), and every quad the three-axis tile of its face whose four
// edge colours match (geometry/geometric_wang_tiles.hpp). The result, per quad a tile and the map from
// tile-local into quad-local coordinates, is what the shell map places the tiles' geometry with.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/vec.hpp"
#include "../geometry/geometric_wang_tiles.hpp"
#include "../tiling/axis_tile_set.hpp"
#include "polycube_map.hpp"
#include "quad_layout.hpp"

TESSERA_NAMESPACE_BEGIN

/// The TileColoring side (0 north, 1 east, 2 south, 3 west, in the quad's (u, v) frame, north = +v) of
/// quad side k (polycube_quad: side k joins corner k to k + 1): 0 -> south, 1 -> east, 2 -> north,
/// 3 -> west. Its own inverse.
constexpr int quad_tile_side(int k) noexcept { return k % 2 == 0 ? 2 - k : k; }

/// Colours of a quad layout's grid edges, and per quad its four sides' colours in the quad's (u, v)
/// frame. Models TileColoring over the quads (face = quad).
struct polycube_coloring {
  /// {nX, nY, nZ}: an edge along axis a has a colour in [0, n_a).
  axis_color_counts axis_colors = {0, 0, 0};
  /// Per grid edge (quad_layout::edges order), its colour.
  std::vector<int> edge_colors;
  /// Per quad, [north, east, south, west] (quad sides 2, 1, 0, 3).
  std::vector<std::array<int, 4>> quad_colors;

  /// Number of quads.
  [[nodiscard]] index_t num_faces() const noexcept { return static_cast<index_t>(quad_colors.size()); }
  /// The largest of nX, nY, nZ: a quad's north and south sides run along its face's first in-plane
  /// axis, which differs from face to face, so no single count describes a side (tile_polycube checks
  /// every colour against its own axis).
  [[nodiscard]] int num_colors(int) const noexcept {
    return std::max({axis_colors[0], axis_colors[1], axis_colors[2]});
  }
  /// The colour of side `side` (0 north ... 3 west) of quad `quad`.
  [[nodiscard]] int edge_color(index_t quad, int side) const noexcept {
    return quad_colors[detail::to_size(quad)][detail::to_size(side)];
  }
};

namespace detail {
// A three-axis tile's face frame is its quads' frame (tiling/axis_tile_set.hpp = quad_layout.hpp).
static_assert(cube_face_axes(0) == quad_plane_axes(polycube_label::pos_x) &&
              cube_face_axes(1) == quad_plane_axes(polycube_label::neg_x) &&
              cube_face_axes(2) == quad_plane_axes(polycube_label::pos_y) &&
              cube_face_axes(3) == quad_plane_axes(polycube_label::neg_y) &&
              cube_face_axes(4) == quad_plane_axes(polycube_label::pos_z) &&
              cube_face_axes(5) == quad_plane_axes(polycube_label::neg_z));
/// Checks what the tiling reads of a quad layout: quads on existing charts, side k of each quad naming
/// an existing grid edge that runs along the face's first (k even) or second (k odd) in-plane axis and
/// lists the quad among its two.
inline status check_layout_for_tiling(const polycube_map& map) {
  const auto& L = map.layout;
  if (L.quads.empty()) return status::invalid_argument("polycube tiling: the map has no quads (no quad layout)");
  const auto ne = static_cast<index_t>(L.edges.size());
  for (std::size_t q = 0; q < L.quads.size(); ++q) {
    const auto& quad = L.quads[q];
    if (quad.chart < 0 || to_size(quad.chart) >= map.charts.size())
      return status::invalid_argument(cat("polycube tiling: quad ", q, " lies on chart ", quad.chart, ", outside [0, ",
                                          map.charts.size(), ") (a layout of another map?)"));
    const auto ax = quad_plane_axes(map.charts[to_size(quad.chart)].label);
    for (int k = 0; k < 4; ++k) {
      const index_t e = quad.edges[to_size(k)];
      if (e < 0 || e >= ne)
        return status::invalid_argument(
            cat("polycube tiling: quad ", q, " side ", k, " names grid edge ", e, ", outside [0, ", ne, ")"));
      const auto& g = L.edges[to_size(e)];
      if (g.axis != ax[to_size(k % 2)] ||
          (g.quads[0] != static_cast<index_t>(q) && g.quads[1] != static_cast<index_t>(q)))
        return status::invalid_argument(cat("polycube tiling: quad ", q, " side ", k, " and grid edge ", e,
                                            " disagree (axis or quads): the layout does not belong to this map"));
    }
  }
  return {};
}
}  // namespace detail

/// Colours every grid edge of `map`'s quad layout (paper 000 §4: parallel edges draw from the colour set
/// of their axis): edge e along axis a gets a colour in [0, n_a) drawn by a counter RNG keyed by the
/// edge's identity (its axis and grid origin, which also fix its id), so the colouring depends on the
/// polycube's geometry and `seed` only, never on traversal order or threads. Edges are coloured in
/// parallel through `exec`. Errors: colour counts outside [1, 4096] (naming the axis), an empty or
/// inconsistent layout. O(quads).
template <Executor E = serial_executor>
result<polycube_coloring> color_polycube_edges(const polycube_map& map, const axis_color_counts& colors,
                                               std::uint64_t seed, E&& exec = {}) {
  if (auto s = validate_axis_color_counts(colors); !s)
    return status(s.code(), detail::cat("color_polycube_edges: ", s.message()));
  if (auto s = detail::check_layout_for_tiling(map); !s) return s;
  const auto& L = map.layout;
  polycube_coloring out;
  out.axis_colors = colors;
  out.edge_colors.resize(L.edges.size());
  const counter_rng rng(seed, stream_id("surface.polycube.edge_colors"));
  exec.parallel_for(0, static_cast<index_t>(L.edges.size()), [&](index_t e) {
    const grid_edge& g = L.edges[detail::to_size(e)];
    out.edge_colors[detail::to_size(e)] = static_cast<int>(rng.below(
        static_cast<std::uint64_t>(colors[detail::to_size(g.axis)]), g.axis, g.origin[0], g.origin[1], g.origin[2]));
  });
  out.quad_colors.resize(L.quads.size());
  for (std::size_t q = 0; q < L.quads.size(); ++q)
    for (int k = 0; k < 4; ++k)
      out.quad_colors[q][detail::to_size(quad_tile_side(k))] =
          out.edge_colors[detail::to_size(L.quads[q].edges[detail::to_size(k)])];
  return out;
}

/// Where one quad's tile goes: the interface between the tile assignment and the shell map.
///
/// Quad-local coordinates (u, v, h) of quad q: the polycube point of (u, v) in [0, 1]² is
/// corners[0] + u (corners[1] - corners[0]) + v (corners[3] - corners[0]) (grid units; times
/// map.tile_size for mesh units; u along the face's first in-plane axis, v along its second, both
/// towards +axis), and h is the height along the quad's outward normal (its chart label direction), in
/// quad sides (h = 0.1 is a tenth of the quad's side above the surface). (u, v, outward) is a
/// right-handed frame, and polycube_projector::inverse(q, u, v) takes (u, v) back to the base surface.
///
/// Tile-local coordinates (x, y, z): a tile's own mesh coordinates, [0, w_T]² × [0, height] in
/// tile-set units (geometric_tile_set::tile_size = w_T), its south side on y = 0, east on x = w_T.
struct quad_tile_placement {
  /// Index of the tile in the tile set.
  index_t tile = -1;
  /// The face the quad looks to (its chart's label): which side of its plane the tile faces.
  polycube_label face = polycube_label::pos_x;
  /// The affine map tile-local (x, y, z) -> quad-local (u, v, h): row r gives
  /// m[r][0] x + m[r][1] y + m[r][2] z + m[r][3]. A rotation or flip of the tile in its quad would show
  /// in the 2 x 2 (u, v) block; for tessera's three-axis sets it is always the identity scaled by 1 / w_T
  /// (h = z / w_T too): each face's tiles are built in that face's quad frame, which is why the set
  /// holds separate tiles for the two sides of a plane (docs/geometry.md, "Three-axis sets").
  std::array<std::array<double, 4>, 3> tile_to_quad{};
  /// tile_to_quad applied to a tile-local point.
  [[nodiscard]] vec3 to_quad(vec3 p) const noexcept {
    vec3 r;
    for (int i = 0; i < 3; ++i) {
      const auto& m = tile_to_quad[detail::to_size(i)];
      r[i] = m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3];
    }
    return r;
  }
};

/// A polycube surface covered by Wang tiles: one placement per quad of the map's layout, in quad order.
struct polycube_tiling {
  /// Per quad, its tile and the tile-local to quad-local map.
  std::vector<quad_tile_placement> quads;
  /// w_T of the tile set (tile-local units of a tile side).
  double tile_size = 0;
  /// How many different tiles the quads use.
  index_t tiles_used = 0;
};

namespace detail {
/// assign_polycube_tiles over any three-axis set: `count` tiles, tile t being `tile_info(t)` (an
/// axis_tile), `tile_size` the side w_T of a tile in tile-local units. `name` starts messages.
template <TileColoring C, class Info>
result<polycube_tiling> assign_axis_tiles(const polycube_map& map, const axis_color_counts& n, index_t count,
                                          Info&& tile_info, double tile_size, const C& coloring,
                                          std::string_view name) {
  if (auto s = validate_axis_color_counts(n); !s) return status(s.code(), detail::cat(name, ": ", s.message()));
  if (auto s = detail::check_layout_for_tiling(map); !s) return s;
  const auto& L = map.layout;
  if (coloring.num_faces() != static_cast<index_t>(L.quads.size()))
    return status::invalid_argument(detail::cat(name, ": the colouring has ", coloring.num_faces(),
                                                " faces, the layout ", L.quads.size(), " quads"));
  // the tile of every (face, edges), by its index in the complete set: the set may be in any order
  std::vector<index_t> lookup(detail::to_size(axis_tile_count(n)), -1);
  for (index_t t = 0; t < count; ++t) {
    const axis_tile at = tile_info(t);
    if (auto s = validate_axis_tile(at, n); !s)
      return status(s.code(), detail::cat(name, ": tile ", t, ": ", s.message()));
    auto& slot = lookup[detail::to_size(axis_tile_index(at, n))];
    if (slot < 0) slot = t;
  }
  // colours: in range of their axis, and the same from both quads of every grid edge
  std::vector<int> edge_color(L.edges.size(), -1);
  for (std::size_t q = 0; q < L.quads.size(); ++q)
    for (int k = 0; k < 4; ++k) {
      const auto& g = L.edges[detail::to_size(L.quads[q].edges[detail::to_size(k)])];
      const int c = static_cast<int>(coloring.edge_color(static_cast<index_t>(q), quad_tile_side(k)));
      if (c < 0 || c >= n[detail::to_size(g.axis)])
        return status::out_of_range(detail::cat(name, ": quad ", q, " ", side_name(quad_tile_side(k)), " side (along ",
                                                "XYZ"[g.axis], ") has colour ", c, ", outside [0, ",
                                                n[detail::to_size(g.axis)], ")"));
      int& e = edge_color[detail::to_size(L.quads[q].edges[detail::to_size(k)])];
      if (e >= 0 && e != c)
        return status::invalid_argument(detail::cat(name, ": the two quads of grid edge ",
                                                    L.quads[q].edges[detail::to_size(k)], " give it colours ", e,
                                                    " and ", c));
      e = c;
    }
  polycube_tiling out;
  out.tile_size = tile_size;
  const double scale = 1.0 / tile_size;
  out.quads.resize(L.quads.size());
  std::vector<char> used(detail::to_size(count), 0);
  for (std::size_t q = 0; q < L.quads.size(); ++q) {
    const polycube_label face = map.charts[detail::to_size(L.quads[q].chart)].label;
    axis_tile want{static_cast<int>(face), {}};
    want.edges = {coloring.edge_color(static_cast<index_t>(q), side_north),
                  coloring.edge_color(static_cast<index_t>(q), side_east),
                  coloring.edge_color(static_cast<index_t>(q), side_south),
                  coloring.edge_color(static_cast<index_t>(q), side_west)};
    const index_t t = lookup[detail::to_size(axis_tile_index(want, n))];
    if (t < 0)
      return status::invalid_argument(detail::cat(
          name, ": quad ", q, " (face ", cube_face_name(want.face), ") needs edges [", want.edges.north, ", ",
          want.edges.east, ", ", want.edges.south, ", ", want.edges.west, "], which no tile of the set has"));
    auto& p = out.quads[q];
    p.tile = t;
    p.face = face;
    // the tile's frame is the quad's frame (same face): (u, v, h) = (x, y, z) / w_T
    p.tile_to_quad = {{{scale, 0, 0, 0}, {0, scale, 0, 0}, {0, 0, scale, 0}}};
    out.tiles_used += used[detail::to_size(t)] ? 0 : 1;
    used[detail::to_size(t)] = 1;
  }
  return out;
}
}  // namespace detail

/// Gives every quad of `map` the tile of `set` (a three-axis set) whose face is the quad's label and
/// whose four edge colours equal, side by side in the quad's (u, v) frame, the colours `coloring`
/// gives the quad (TileColoring over the quads, face = quad, sides north = quad side 2, east = 1,
/// south = 0, west = 3: quad_tile_side). Any TileColoring may be passed; its num_colors is not read:
/// every colour is checked against the colours of the axis its side runs along, and the two quads of
/// each grid edge must give it the same colour. Errors (invalid_argument unless said): a planar set or
/// one whose tiles, edges and faces disagree, an empty or inconsistent layout (quads on missing charts,
/// sides naming the wrong grid edge: a layout of another map), a colouring with another number of
/// faces, a colour outside its axis' range (out_of_range, naming quad, side and axis), two quads
/// giving a grid edge different colours, a quad whose colours no tile of its face has (an incomplete
/// set). O(quads + tiles); the result depends on the inputs only.
template <TileColoring C>
result<polycube_tiling> assign_polycube_tiles(const polycube_map& map, const geometric_tile_set& set,
                                              const C& coloring) {
  if (!set.three_axis())
    return status::invalid_argument(
        "assign_polycube_tiles: the tile set is planar; polycube quads need a three-axis set "
        "(geometric_wang_options::axis_colors)");
  if (auto s = validate_axis_color_counts(set.axis_colors); !s)
    return status(s.code(), detail::cat("assign_polycube_tiles: ", s.message()));
  if (set.tiles.size() != set.edges.size() || set.faces.size() != set.tiles.size() || set.tiles.empty())
    return status::invalid_argument("assign_polycube_tiles: the set's tiles, edges and faces differ in count");
  if (!(set.tile_size > 0) || !std::isfinite(set.tile_size))
    return status::invalid_argument(detail::cat("assign_polycube_tiles: tile_size must be > 0, got ", set.tile_size));
  return detail::assign_axis_tiles(
      map, set.axis_colors, static_cast<index_t>(set.tiles.size()),
      [&](index_t t) {
        return axis_tile{set.faces[detail::to_size(t)], set.edges[detail::to_size(t)]};
      },
      set.tile_size, coloring, "assign_polycube_tiles");
}

/// Colours `map`'s grid edges with the set's colour counts (color_polycube_edges, keyed by `seed`) and
/// assigns the tiles (assign_polycube_tiles): paper 000 §4. The result is a pure function of (map, set,
/// seed), whatever the executor. Errors: those of both. O(quads + tiles).
template <Executor E = serial_executor>
result<polycube_tiling> tile_polycube(const polycube_map& map, const geometric_tile_set& set, std::uint64_t seed,
                                      E&& exec = {}) {
  if (!set.three_axis())
    return status::invalid_argument(
        "tile_polycube: the tile set is planar; polycube quads need a three-axis set "
        "(geometric_wang_options::axis_colors)");
  auto coloring = color_polycube_edges(map, set.axis_colors, seed, exec);
  if (!coloring) return coloring.error();
  return assign_polycube_tiles(map, set, *coloring);
}

TESSERA_NAMESPACE_END
