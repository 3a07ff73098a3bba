// Code blocks of docs/wang_tiles.md that are not cut from an example, compiled and run
// (tests/structural/snippets.cmake keeps the page identical to the regions between the markers).
#include <catch2/catch.hpp>
#include <cstdint>

#include <tessera/core/executor.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>

TEST_CASE("docs: wang_tiles.md streaming windows of the endless plane") {
  using rgb8 = tessera::image_buffer<std::uint8_t, 3>;
  tessera::thread_pool_executor pool(2);
  const auto exemplar =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, {.width = 96, .height = 96});
  REQUIRE(exemplar);
  const auto set =
      tessera::build_wang_tiles(*exemplar, {.tile_size = 32, .horizontal_colors = 2, .vertical_colors = 2}, pool);
  REQUIRE(set);
  rgb8 first(96, 96);
  auto fail = [](const tessera::status&) { return 1; };
  const int failed = [&] {
    // [snippet:wang_streaming]
    // The infinite hash colouring goes straight to compose_tiles (a PlaneTileColoring): any window
    // of the endless plane, at any pixel origin (negative too), in any order, always the same pixels.
    auto plane = tessera::hash_coloring::for_set(set->edges(), /*seed=*/5);
    if (!plane) return fail(plane.error());
    rgb8 window(96, 96);
    for (tessera::index_t y0 : {-96, 0, 96}) {  // e.g. the texture-cache pages a moving camera needs
      if (auto s = tessera::compose_tiles(*set, *plane, window, {.x = 1000, .y = y0}, pool); !s) return fail(s);
      // ... upload `window` ...
    }
    // A finite grid of it instead (for a GridTileColoring API): window() returns a result too.
    auto grid = plane->window(/*col=*/-4, /*row=*/-4, /*cols=*/8, /*rows=*/8);
    if (!grid) return fail(grid.error());
    // [/snippet]
    // the last page equals a fresh composition of the same window, and the grid is 8 x 8
    if (auto s = tessera::compose_tiles(*set, *plane, first, {.x = 1000, .y = 96}); !s) return fail(s);
    CHECK(first == window);
    CHECK(grid->num_faces() == 64);
    return 0;
  }();
  CHECK(failed == 0);
}
