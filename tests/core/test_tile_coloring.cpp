#include <tessera/core/tile_coloring.hpp>

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <catch2/catch.hpp>
#include "../support/test_support.hpp"

using tessera_test::mentions;

using tessera::index_t;
using tessera::status_code;
using tessera::stored_tile_coloring;

namespace {
// A procedural colouring of a cols x rows grid: horizontal edge colours from the edge's row boundary
// and column, vertical ones likewise, so touching sides always agree (a valid colouring by construction).
struct procedural {
  index_t cols, rows;
  bool torus;
  index_t num_faces() const { return cols * rows; }
  int num_colors(int side) const { return tessera::is_horizontal_side(side) ? 3 : 2; }
  int edge_color(index_t face, int side) const {
    index_t c = face % cols, r = face / cols;
    if (side == tessera::side_south) ++r;
    if (side == tessera::side_east) ++c;
    if (torus) {
      r %= rows;
      c %= cols;
    }
    const bool horizontal = tessera::is_horizontal_side(side);
    return static_cast<int>((horizontal ? (r * 7 + c * 3) : (r * 5 + c * 11)) % (horizontal ? 3 : 2));
  }
};
}  // namespace

static_assert(tessera::TileColoring<stored_tile_coloring>);
static_assert(tessera::TileColoring<procedural>);
static_assert(!tessera::TileColoring<int>);
static_assert(tessera::opposite_side(tessera::side_north) == tessera::side_south);
static_assert(tessera::opposite_side(tessera::side_west) == tessera::side_east);
static_assert(tessera::is_horizontal_side(tessera::side_south) && !tessera::is_horizontal_side(tessera::side_east));

TEST_CASE("tile_coloring: grid neighbour convention", "[tile_coloring]") {
  const tessera::grid_neighbors n{4, 3, false};
  // face = row * cols + col, row 0 at the top
  REQUIRE(n(5, tessera::side_north) == std::pair<index_t, int>{1, tessera::side_south});
  REQUIRE(n(5, tessera::side_south) == std::pair<index_t, int>{9, tessera::side_north});
  REQUIRE(n(5, tessera::side_east) == std::pair<index_t, int>{6, tessera::side_west});
  REQUIRE(n(5, tessera::side_west) == std::pair<index_t, int>{4, tessera::side_east});
  REQUIRE_FALSE(n(1, tessera::side_north).has_value());
  REQUIRE_FALSE(n(3, tessera::side_east).has_value());
  REQUIRE_FALSE(n(8, tessera::side_west).has_value());
  REQUIRE_FALSE(n(11, tessera::side_south).has_value());
  const tessera::grid_neighbors t{4, 3, true};
  REQUIRE(t(1, tessera::side_north) == std::pair<index_t, int>{9, tessera::side_south});
  REQUIRE(t(3, tessera::side_east) == std::pair<index_t, int>{0, tessera::side_west});
}

TEST_CASE("tile_coloring: valid colourings pass, stored copies agree", "[tile_coloring]") {
  const procedural p{5, 4, false};
  REQUIRE(tessera::check_grid_coloring(p, 5, 4).ok());
  const stored_tile_coloring s = tessera::store_coloring(p);
  REQUIRE(s.num_faces() == 20);
  REQUIRE(s.horizontal_colors == 3);
  REQUIRE(s.vertical_colors == 2);
  for (index_t f = 0; f < 20; ++f)
    for (int side = 0; side < 4; ++side) REQUIRE(s.edge_color(f, side) == p.edge_color(f, side));
  REQUIRE(tessera::check_grid_coloring(s, 5, 4).ok());
  REQUIRE(tessera::check_grid_coloring(procedural{5, 4, true}, 5, 4, true).ok());
  // the non-toroidal colouring does not wrap
  REQUIRE_FALSE(tessera::check_grid_coloring(p, 5, 4, true).ok());
}

TEST_CASE("tile_coloring: mismatches and bad colours are reported", "[tile_coloring]") {
  stored_tile_coloring s = tessera::store_coloring(procedural{3, 3, false});
  s.colors[4][tessera::side_east] = (s.colors[4][tessera::side_east] + 1) % 2;
  auto st = tessera::check_grid_coloring(s, 3, 3);
  REQUIRE(st.code() == status_code::invalid_argument);
  REQUIRE(mentions(st, "face 4 side 1"));
  REQUIRE(mentions(st, "face 5 side 3"));

  s = tessera::store_coloring(procedural{3, 3, false});
  s.colors[7][tessera::side_south] = 3;  // only 3 horizontal colours: 0..2
  st = tessera::check_grid_coloring(s, 3, 3);
  REQUIRE(st.code() == status_code::out_of_range);
  REQUIRE(mentions(st, "face 7 side 2 has colour 3, outside [0, 3)"));
  s.colors[7][tessera::side_south] = -1;
  REQUIRE(tessera::check_color_ranges(s).code() == status_code::out_of_range);

  s = tessera::store_coloring(procedural{3, 3, false});
  s.vertical_colors = 0;
  st = tessera::check_color_ranges(s);
  REQUIRE(st.code() == status_code::invalid_argument);
  REQUIRE(mentions(st, "vertical"));
}

TEST_CASE("tile_coloring: bad grid sizes and neighbour functions", "[tile_coloring]") {
  const stored_tile_coloring s = tessera::store_coloring(procedural{3, 2, false});
  REQUIRE(tessera::check_grid_coloring(s, 0, 6).code() == status_code::invalid_argument);
  REQUIRE(tessera::check_grid_coloring(s, 3, -2).code() == status_code::invalid_argument);
  auto st = tessera::check_grid_coloring(s, 2, 2);
  REQUIRE(st.code() == status_code::invalid_argument);
  REQUIRE(mentions(st, "has 6 faces"));
  const index_t big = std::numeric_limits<index_t>::max() / 2;
  REQUIRE(tessera::check_grid_coloring(s, big, 3).code() == status_code::size_overflow);

  // a neighbour function that points outside the colouring is caught, not followed
  auto wild = [](index_t f, int side) -> std::optional<std::pair<index_t, int>> {
    if (f == 2 && side == 1) return std::pair<index_t, int>{99, 3};
    return std::nullopt;
  };
  st = tessera::check_coloring(s, wild);
  REQUIRE(st.code() == status_code::out_of_range);
  REQUIRE(mentions(st, "face 99"));
  auto bad_side = [](index_t, int) -> std::optional<std::pair<index_t, int>> { return std::pair<index_t, int>{0, 4}; };
  REQUIRE(tessera::check_coloring(s, bad_side).code() == status_code::out_of_range);
  REQUIRE(tessera::check_coloring(stored_tile_coloring{}, wild).ok());  // no faces, nothing to check
}
