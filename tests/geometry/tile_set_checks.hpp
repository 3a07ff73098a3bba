// Checks every tile of a geometric Wang tile set must pass, shared by the planar and three-axis tests.
#pragma once

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>

#include <catch2/catch.hpp>

/// Every tile inside its square, closed except on the border, manifold, without intersections, and
/// with nothing on a corner.
inline void require_valid_tiles(const tessera::geometric_tile_set& set) {
  for (const auto& tile : set.tiles) {
    const auto rep = tessera::check_geometric_texture(tile, {0, 0, set.tile_size, set.tile_size});
    REQUIRE(rep.ok());
    REQUIRE(rep->open_edges_inside == 0);
    REQUIRE(rep->nonmanifold_edges == 0);
    REQUIRE(rep->intersecting_pairs == 0);
    REQUIRE(tessera::tile_border_vertices(tile, set.tile_size).ok());  // nothing on a corner, nothing outside
  }
}
