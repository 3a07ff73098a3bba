// tessera/core/tile_coloring.hpp: the vocabulary of Wang tile colourings. A colouring assigns a
// colour to each side of each face (a grid cell of a tiled plane, or a quad of a polycube). Sides are
// numbered 0 north, 1 east, 2 south, 3 west. North and south sides are horizontal edges and draw from
// `num_colors(north)` colours; east and west sides are vertical edges with `num_colors(east)` colours.
//
// Grid convention (used by every grid colouring in tessera): face = row * cols + col, row 0 at the
// top, rows growing southwards (like image y), columns growing eastwards (like image x). So the north
// side of (col, row) touches the south side of (col, row - 1), and its east side the west side of
// (col + 1, row).
#pragma once

#include <array>
#include <concepts>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "config.hpp"
#include "status.hpp"

TESSERA_NAMESPACE_BEGIN

/// Side numbers, usable wherever an int side is expected.
inline constexpr int side_north = 0;
/// Side index of the east edge.
inline constexpr int side_east = 1;
/// Side index of the south edge.
inline constexpr int side_south = 2;
/// Side index of the west edge.
inline constexpr int side_west = 3;

/// "north", "east", "south" or "west" for side 0 to 3 (anything else: "invalid side"), for messages.
constexpr std::string_view side_name(int side) noexcept {
  constexpr std::string_view names[] = {"north", "east", "south", "west"};
  return side >= 0 && side < 4 ? names[side] : "invalid side";
}
/// The side facing `side` across an edge (north <-> south, east <-> west).
constexpr int opposite_side(int side) noexcept { return (side + 2) & 3; }
/// True for north and south (horizontal edges).
constexpr bool is_horizontal_side(int side) noexcept { return (side & 1) == 0; }

/// A colouring of the sides of `num_faces()` faces.
template <class C>
concept TileColoring = requires(const C& c, index_t face, int side) {
  { c.num_faces() } -> std::convertible_to<index_t>;
  { c.num_colors(side) } -> std::convertible_to<int>;
  { c.edge_color(face, side) } -> std::convertible_to<int>;
};

/// A colouring stored explicitly, four colours per face in side order [north, east, south, west].
struct stored_tile_coloring {
  int horizontal_colors = 1;  ///< colours of north/south sides
  int vertical_colors = 1;    ///< colours of east/west sides
  /// colors[face][side]: the edge colours of every face.
  std::vector<std::array<int, 4>> colors;

  /// Number of faces.
  [[nodiscard]] index_t num_faces() const noexcept { return static_cast<index_t>(colors.size()); }
  /// Colours of this side's edges (horizontal for north/south, vertical for east/west).
  [[nodiscard]] int num_colors(int side) const noexcept {
    return is_horizontal_side(side) ? horizontal_colors : vertical_colors;
  }
  /// Colour of edge `side` of `face`.
  [[nodiscard]] int edge_color(index_t face, int side) const noexcept {
    return colors[detail::to_size(face)][detail::to_size(side)];
  }
};

/// Copies any colouring into a stored one (a negative face count is treated as zero).
template <TileColoring C>
stored_tile_coloring store_coloring(const C& c) {
  stored_tile_coloring s{static_cast<int>(c.num_colors(side_north)), static_cast<int>(c.num_colors(side_east)), {}};
  if (c.num_faces() <= 0) return s;
  s.colors.resize(detail::to_size(c.num_faces()));
  for (index_t f = 0; f < c.num_faces(); ++f)
    for (int side = 0; side < 4; ++side)
      s.colors[detail::to_size(f)][detail::to_size(side)] = static_cast<int>(c.edge_color(f, side));
  return s;
}

/// Checks that colour counts are positive and every side's colour lies in [0, num_colors(side)).
/// O(faces).
template <TileColoring C>
status check_color_ranges(const C& c) {
  if (c.num_faces() < 0)
    return status::invalid_argument(detail::cat("tile colouring: negative face count ", c.num_faces()));
  for (int side = 0; side < 2; ++side)
    if (c.num_colors(side) < 1)
      return status::invalid_argument(detail::cat("tile colouring: ", side == 0 ? "horizontal" : "vertical",
                                                  " edges need at least one colour, got ", c.num_colors(side)));
  for (index_t f = 0; f < c.num_faces(); ++f)
    for (int side = 0; side < 4; ++side) {
      const int col = c.edge_color(f, side);
      if (col < 0 || col >= c.num_colors(side))
        return status::out_of_range(detail::cat("tile colouring: face ", f, " side ", side, " has colour ", col,
                                                ", outside [0, ", c.num_colors(side), ")"));
    }
  return {};
}

/// Checks colour ranges and that every pair of touching sides carries the same colour.
/// `neighbor(face, side)` returns the (face, side) across that edge, or std::nullopt on a border.
/// A neighbour outside [0, num_faces()) x [0, 4) is reported as out_of_range. O(faces).
template <TileColoring C, class Neighbor>
status check_coloring(const C& c, Neighbor&& neighbor) {
  if (auto s = check_color_ranges(c); !s) return s;
  const index_t nf = c.num_faces();
  for (index_t f = 0; f < nf; ++f)
    for (int side = 0; side < 4; ++side) {
      const std::optional<std::pair<index_t, int>> other = neighbor(f, side);
      if (!other) continue;
      if (other->first < 0 || other->first >= nf || other->second < 0 || other->second > 3)
        return status::out_of_range(detail::cat("tile colouring: the neighbour of face ", f, " side ", side,
                                                " is face ", other->first, " side ", other->second, ", outside [0, ",
                                                nf, ") x [0, 4)"));
      const int a = c.edge_color(f, side), b = c.edge_color(other->first, other->second);
      if (a != b)
        return status::invalid_argument(detail::cat("tile colouring: face ", f, " side ", side, " has colour ", a,
                                                    " but the touching face ", other->first, " side ", other->second,
                                                    " has colour ", b));
    }
  return {};
}

/// Neighbours on a cols x rows grid (see the convention above); `toroidal` wraps both directions.
/// Precondition: cols > 0, rows > 0, 0 <= face < cols * rows, 0 <= side < 4.
struct grid_neighbors {
  /// Grid size in cells.
  index_t cols = 0, rows = 0;
  /// True when the grid wraps around (a torus).
  bool toroidal = false;
  /// The neighbour across edge `side` of `face` and its side facing back, or none at the border.
  std::optional<std::pair<index_t, int>> operator()(index_t face, int side) const {
    index_t col = face % cols, row = face / cols;
    static constexpr int dx[4] = {0, 1, 0, -1}, dy[4] = {-1, 0, 1, 0};
    col += dx[side];
    row += dy[side];
    if (toroidal) {
      col = (col + cols) % cols;
      row = (row + rows) % rows;
    } else if (col < 0 || col >= cols || row < 0 || row >= rows) {
      return std::nullopt;
    }
    return std::pair<index_t, int>{row * cols + col, opposite_side(side)};
  }
};

/// check_coloring for a colouring of a cols x rows grid; also checks that it has cols * rows faces.
template <TileColoring C>
status check_grid_coloring(const C& c, index_t cols, index_t rows, bool toroidal = false) {
  if (cols <= 0 || rows <= 0)
    return status::invalid_argument(detail::cat("tile colouring: grid must be positive, got ", cols, " x ", rows));
  if (cols > std::numeric_limits<index_t>::max() / rows)
    return status::size_overflow(
        detail::cat("tile colouring: a ", cols, " x ", rows, " grid overflows the index type"));
  if (c.num_faces() != cols * rows)
    return status::invalid_argument(detail::cat("tile colouring: has ", c.num_faces(), " faces, a ", cols, " x ", rows,
                                                " grid needs ", cols * rows));
  return check_coloring(c, grid_neighbors{cols, rows, toroidal});
}

TESSERA_NAMESPACE_END
