// tessera/tiling/axis_tile_set.hpp: the combinatorics of complete three-axis Wang tile sets, the tiles
// that cover polycube surfaces (paper 000 §3.1, §5). A polycube's edges run parallel to X, Y or Z and
// draw from nX, nY and nZ colours: only parallel edges ever meet (Fig. 2). A quad facing one of the six
// cube directions has two edges along each of its two in-plane axes, so the complete set holds, per
// face direction, every combination of those four colours:
//
//     2 (nX² nY² + nX² nZ² + nY² nZ²) tiles    (96 for two colours per axis, 6 for one)
//
// The factor 2 is the two sides of each plane (+Z and -Z both have X and Y edges): a tile is built in
// the frame of one face direction and never turned over (docs/geometry.md explains why it cannot be).
//
// Faces are numbered like surface/polycube_map.hpp's polycube_label: 0 +X, 1 -X, 2 +Y, 3 -Y, 4 +Z,
// 5 -Z (axis = face / 2, + for even faces). A face's tile frame is its quads' frame: u along the first
// in-plane axis, v along the second, the outward normal third, a right-handed frame: (Y, Z) for +X,
// (Z, Y) for -X, (Z, X) for +Y, (X, Z) for -Y, (X, Y) for +Z, (Y, X) for -Z. In that frame a tile's
// north and south sides run along u (the first axis), east and west along v (the second), and its
// edges are wang_edges as in complete_tile_set.hpp. Tiles are numbered face by face (+X first), and
// inside a face by complete_tile_index with nh = colours of the first axis, nv = of the second.
#pragma once

#include <array>
#include <string_view>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "complete_tile_set.hpp"

TESSERA_NAMESPACE_BEGIN

/// Colours of the edges parallel to X, Y and Z: {nX, nY, nZ}.
using axis_color_counts = std::array<int, 3>;

/// Number of cube faces (face directions) of a three-axis set.
inline constexpr int cube_faces = 6;

/// The in-plane axes (first, second) of cube face `face` (0..5): the tile frame's u and v axes, so that
/// (u, v, outward normal) is right-handed. Precondition: 0 <= face < 6.
constexpr std::array<int, 2> cube_face_axes(int face) noexcept {
  const int a = face / 2;
  return face % 2 == 0 ? std::array<int, 2>{(a + 1) % 3, (a + 2) % 3} : std::array<int, 2>{(a + 2) % 3, (a + 1) % 3};
}

/// The axis (0 X, 1 Y, 2 Z) a side (core/tile_coloring.hpp numbering: 0 north ... 3 west) of a tile of
/// `face` runs along: north and south the face's first axis, east and west its second.
constexpr int cube_face_side_axis(int face, int side) noexcept {
  return cube_face_axes(face)[is_horizontal_side(side) ? 0 : 1];
}

/// "+X", "-X", "+Y", "-Y", "+Z", "-Z" for faces 0..5 ("invalid face" otherwise), for messages.
constexpr std::string_view cube_face_name(int face) noexcept {
  constexpr std::string_view names[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  return face >= 0 && face < cube_faces ? names[face] : "invalid face";
}

/// Checks three colour counts: each in [1, max_wang_colors]; the message names the axis.
inline status validate_axis_color_counts(const axis_color_counts& n) {
  for (int a = 0; a < 3; ++a)
    if (n[static_cast<std::size_t>(a)] < 1 || n[static_cast<std::size_t>(a)] > max_wang_colors)
      return status::invalid_argument(detail::cat("colours of edges parallel to ", "XYZ"[a], " must be in [1, ",
                                                  max_wang_colors, "], got ", n[static_cast<std::size_t>(a)]));
  return {};
}

/// Tiles of one face in the complete set: (colours of its first axis)² · (of its second)².
/// Precondition: validate_axis_color_counts(n) is ok and 0 <= face < 6. O(1).
constexpr index_t axis_face_tile_count(int face, const axis_color_counts& n) noexcept {
  const auto ax = cube_face_axes(face);
  return complete_tile_count(n[static_cast<std::size_t>(ax[0])], n[static_cast<std::size_t>(ax[1])]);
}

/// Tiles of the complete three-axis set: 2 (nX² nY² + nX² nZ² + nY² nZ²) (paper 000 §5: 96 for two
/// colours per axis). Precondition: validate_axis_color_counts(n) is ok. O(1).
constexpr index_t axis_tile_count(const axis_color_counts& n) noexcept {
  index_t total = 0;
  for (int f = 0; f < cube_faces; ++f) total += axis_face_tile_count(f, n);
  return total;
}

/// Index of the first tile of `face`. Precondition: as axis_face_tile_count. O(1).
constexpr index_t axis_face_first_tile(int face, const axis_color_counts& n) noexcept {
  index_t first = 0;
  for (int f = 0; f < face; ++f) first += axis_face_tile_count(f, n);
  return first;
}

/// One tile of a three-axis set: the face it covers and its edge colours in that face's frame.
struct axis_tile {
  /// The cube face (0..5, polycube_label numbering).
  int face = 0;
  /// Edge colours: north/south from the face's first axis, east/west from its second.
  wang_edges edges = {};
  friend constexpr bool operator==(const axis_tile&, const axis_tile&) = default;
};

/// Checks that `t` is a tile of the complete set for `n`: face in [0, 6), colours in range of the axis
/// each side runs along.
inline status validate_axis_tile(const axis_tile& t, const axis_color_counts& n) {
  if (auto s = validate_axis_color_counts(n); !s) return s;
  if (t.face < 0 || t.face >= cube_faces)
    return status::out_of_range(detail::cat("three-axis tile: face ", t.face, " is outside [0, 6)"));
  for (int side = 0; side < 4; ++side) {
    const int axis = cube_face_side_axis(t.face, side), count = n[static_cast<std::size_t>(axis)];
    if (t.edges[side] < 0 || t.edges[side] >= count)
      return status::out_of_range(detail::cat("three-axis tile of face ", cube_face_name(t.face), ": ", side_name(side),
                                              " colour ", t.edges[side], " is outside [0, ", count,
                                              ") (the side runs along ", "XYZ"[axis], ")"));
  }
  return {};
}

/// The tile with index `tile` of the complete set (inverse of axis_tile_index).
/// Precondition: validate_axis_color_counts(n) is ok and 0 <= tile < axis_tile_count(n). O(1).
constexpr axis_tile axis_tile_at(index_t tile, const axis_color_counts& n) noexcept {
  int face = 0;
  while (face + 1 < cube_faces && tile >= axis_face_tile_count(face, n)) tile -= axis_face_tile_count(face++, n);
  const auto ax = cube_face_axes(face);
  return {face, complete_tile_edges(tile, n[static_cast<std::size_t>(ax[0])], n[static_cast<std::size_t>(ax[1])])};
}

/// The index of tile `t` in the complete set. Precondition: validate_axis_tile(t, n) is ok. O(1).
constexpr index_t axis_tile_index(const axis_tile& t, const axis_color_counts& n) noexcept {
  const auto ax = cube_face_axes(t.face);
  return axis_face_first_tile(t.face, n) +
         complete_tile_index(t.edges, n[static_cast<std::size_t>(ax[0])], n[static_cast<std::size_t>(ax[1])]);
}

TESSERA_NAMESPACE_END
