// The code blocks of docs/geometry.md, compiled (tests/structural/snippets.cmake keeps the page
// identical to the regions between the snippet markers). The exemplar block runs; the quilting and
// tile-set blocks take tens of seconds, so they are hidden tests: tests_geometry "[docs-slow]".
#include <catch2/catch.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/quilt_exemplar.hpp>
#include <tessera/geometry/texture_quality.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/io/geometric_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>

TEST_CASE("docs: geometry.md exemplars") {
  // [snippet:geometry_exemplars]
  auto rings = tessera::make_ring_exemplar({.size = 8, .spacing = 1.6});  // loose tori
  auto mail = tessera::make_ring_exemplar({.size = 5, .minor_radius = 0.08, .chain_mail = true});
  auto stones = tessera::make_stone_exemplar({.coverage = 0.55, .subdivisions = 2, .seed = 7});
  auto weave = tessera::make_weave_exemplar({.spacing = 1.0, .segments_per_spacing = 8});
  // [/snippet]
  CHECK(rings);
  CHECK(mail);
  CHECK(stones);
  CHECK(weave);
}

TEST_CASE("docs: geometry.md quilting and geometric Wang tiles", "[.][docs-slow]") {
  auto stones = tessera::make_stone_exemplar({.coverage = 0.55, .subdivisions = 2, .seed = 7});
  REQUIRE(stones);
  // [snippet:geometry_quilt]
  auto ex = tessera::prepare_quilt_exemplar(*stones);  // rejects open / non-manifold input
  tessera::thread_pool_executor pool;
  auto q = tessera::mesh_quilt(*ex, 16.0, 12.0, {.seed = 7}, pool);  // q->mesh, q->elements, q->stats
  // [/snippet]
  REQUIRE(q);
  // [snippet:geometry_quality]
  auto quality = tessera::compare_texture_quality(*stones, q->mesh, {0, 0, 16, 12});  // exemplar, output, domain
  // quality->density_ratio, coverage_ratio, partial_excess, empty_cell_excess, nn_outside_excess;
  // with {.tile_size = w} as the options, band_ratio and corner_ratio of a tiled plane
  // [/snippet]
  REQUIRE(quality);
  auto hash = tessera::hash_coloring::create(2, 2, /*seed=*/3);
  REQUIRE(hash);
  auto window = hash->window(0, 0, 8, 6);
  REQUIRE(window);
  const auto& coloring = *window;
  // [snippet:geometry_wang]
  tessera::geometric_wang_options o;
  o.horizontal_colors = o.vertical_colors = 2;  // complete set: 2² · 2² = 16 tiles
  o.tile_size = 6.4;                            // w_T; edge_height h_E defaults to 1.5 x element size
  auto set = tessera::build_geometric_wang_tiles(*ex, o, pool);
  if (auto s = tessera::save_geometric_tile_set("tiles", *set); !s) FAIL(s.to_string());  // tiles/tile_<i>.obj + .json
  auto plane = tessera::tile_geometric_plane(*set, coloring, 8, 6, pool);                 // any TileColoring
  // [/snippet]
  CHECK(plane);
}
