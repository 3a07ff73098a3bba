// A 96-tile three-axis ring set (two colours per axis, small rings crossing the tile edges), built once
// and shared by the polycube tiling and surface mapping tests.
#pragma once

#include <catch2/catch.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>

inline const tessera::geometric_tile_set& ring_tile_set() {
  using namespace tessera;
  static const geometric_tile_set set = [] {
    auto ex = prepare_quilt_exemplar(
        *make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 12, .tube_segments = 5, .seed = 3}));
    geometric_wang_options o;
    o.axis_colors = {2, 2, 2};
    o.tile_size = 4.0;
    o.quilt.seed = 11;
    thread_pool_executor pool(2);
    auto r = build_geometric_wang_tiles(*ex, o, pool);
    REQUIRE(r.ok());
    return std::move(*r);
  }();
  return set;
}
