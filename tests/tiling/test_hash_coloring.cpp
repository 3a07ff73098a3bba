#include <tessera/tiling/hash_coloring.hpp>

#include <tessera/core/tile_coloring.hpp>

#include <limits>
#include <map>

#include <catch2/catch.hpp>

using tessera::hash_coloring;
using tessera::index_t;
using tessera::tile_set_edges;

static_assert(tessera::TileColoring<tessera::hash_coloring_window>);

TEST_CASE("hash colouring: neighbours agree everywhere, windows are views of the plane", "[tiling]") {
  for (int m : {1, 2, 3}) {
    const int nh = m == 3 ? 3 : 2, nv = m == 3 ? 6 : 4;
    auto plane = hash_coloring::create(nh, nv, 99, m);
    REQUIRE(plane.ok());
    auto w = plane->window(-7, -3, 17, 11);  // negative origins are part of the plane too
    REQUIRE(w.ok());
    REQUIRE(tessera::check_grid_coloring(*w, 17, 11).ok());
    auto subset = tile_set_edges::modular_subset(nh, nv, m);
    REQUIRE(tessera::check_coloring_against_set(*w, *subset).ok());
    // O(1) random access: a far-away window agrees with direct queries and with an overlapping window
    auto far = plane->window(1'000'000'000, -2'000'000'000, 5, 5);
    auto overlap = plane->window(-5, -2, 4, 4);
    for (index_t r = 0; r < 5; ++r)
      for (index_t c = 0; c < 5; ++c)
        for (int s = 0; s < 4; ++s)
          REQUIRE(far->edge_color_at(c, r, s) == plane->edge_color_at(1'000'000'000 + c, -2'000'000'000 + r, s));
    for (index_t r = 0; r < 4; ++r)
      for (index_t c = 0; c < 4; ++c) REQUIRE(overlap->edges_at(c, r) == w->edges_at(c + 2, r + 1));
    // the extreme cells of the index range are defined too (coordinates wrap as hash keys): a window
    // straddling both ends of the index range is a consistent grid colouring of the set, agrees cell
    // by cell with the plane at the wrapped coordinates, and is not degenerate
    const index_t top = std::numeric_limits<index_t>::max(), bottom = std::numeric_limits<index_t>::min();
    auto edge = plane->window(top - 3, top - 2, 8, 6);  // columns top-3 .. bottom+4, rows top-2 .. bottom+3
    REQUIRE(edge.ok());
    REQUIRE(tessera::check_grid_coloring(*edge, 8, 6).ok());
    REQUIRE(tessera::check_coloring_against_set(*edge, *subset).ok());
    std::map<index_t, int> seen;
    for (index_t r = 0; r < 6; ++r)
      for (index_t c = 0; c < 8; ++c) {
        const index_t pc = c <= 3 ? top - 3 + c : bottom + (c - 4), pr = r <= 2 ? top - 2 + r : bottom + (r - 3);
        REQUIRE(edge->edges_at(c, r) == plane->edges_at(pc, pr));
        ++seen[tessera::complete_tile_index(edge->edges_at(c, r), nh, nv)];
      }
    REQUIRE(seen.size() > 4u);
  }
}

TEST_CASE("hash colouring: colours are uniform and the seed matters", "[tiling]") {
  for (int m : {1, 2}) {
    auto plane = hash_coloring::create(2, 2, 5, m);
    std::map<index_t, int> tiles;
    for (index_t r = 0; r < 64; ++r)
      for (index_t c = 0; c < 64; ++c) ++tiles[tessera::complete_tile_index(plane->edges_at(c, r), 2, 2)];
    REQUIRE(tiles.size() == (m == 1 ? 16u : 8u));
    for (auto& [t, n] : tiles) REQUIRE(n > 4096 / static_cast<int>(tiles.size()) / 2);
  }
  auto a = hash_coloring::create(2, 2, 1), b = hash_coloring::create(2, 2, 2);
  int differ = 0;
  for (index_t c = 0; c < 100; ++c) differ += a->edge_color_at(c, 0, 0) != b->edge_color_at(c, 0, 0);
  REQUIRE(differ > 20);
}

TEST_CASE("hash colouring: constrained to a set, periodic variant", "[tiling]") {
  auto cohen = tile_set_edges::modular_subset(2, 2, 2);
  auto plane = hash_coloring::for_set(*cohen, 3);
  REQUIRE(plane.ok());
  REQUIRE(plane->modulus() == 2);
  auto periodic = plane->with_period(3, 5);
  REQUIRE(periodic.ok());
  for (index_t r = -10; r < 10; ++r)
    for (index_t c = -10; c < 10; ++c) REQUIRE(periodic->edges_at(c, r) == periodic->edges_at(c + 3, r - 5));
  auto torus = periodic->window(0, 0, 3, 5);
  REQUIRE(tessera::check_grid_coloring(*torus, 3, 5, /*toroidal=*/true).ok());
  REQUIRE(tessera::check_coloring_against_set(*torus, *cohen).ok());
}

TEST_CASE("hash colouring: bad input", "[tiling]") {
  REQUIRE_FALSE(hash_coloring::create(0, 2).ok());
  REQUIRE(hash_coloring::create(2, 3, 1, 2).error().code() == tessera::status_code::invalid_argument);
  REQUIRE_FALSE(hash_coloring::create(2, 2, 1, 0).ok());
  auto gappy = tile_set_edges::create(2, 2, {{0, 0, 0, 0}, {1, 1, 1, 1}});
  auto s = hash_coloring::for_set(*gappy, 1);
  REQUIRE(s.error().code() == tessera::status_code::unsupported);
  REQUIRE_THAT(s.error().message(), Catch::Contains("scanline"));
  auto plane = hash_coloring::create(2, 2);
  REQUIRE_FALSE(plane->window(0, 0, 0, 3).ok());
  REQUIRE_FALSE(plane->with_period(0, 3).ok());
  REQUIRE(plane->window(0, 0, index_t{1} << 20, index_t{1} << 13).error().code() ==
          tessera::status_code::size_overflow);
}
