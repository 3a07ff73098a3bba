// compose_tiles, synthesize and synthesize_aligned into an adapted texture that exposes its memory
// (ContiguousImage, core/image_rows.hpp) give exactly the pixels of the generic per-pixel path and
// of an image_view over the same memory.
#include <tessera/core/executor.hpp>
#include <tessera/core/image_rows.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <vector>

#include "../core/packed_texture_support.hpp"
#include "quilt_test_support.hpp"

using tessera::index_t;

using texture_rgba8 = test_support::packed_texture;
using texture_rgba8_slow = test_support::packed_texture_slow;

TEST_CASE("contiguous outputs: compose_tiles into an adapted texture equals the generic path and a view",
          "[image_rows]") {
  const auto ex4 = quilt_test::exemplar<std::uint8_t, 4>(tessera::exemplar_kind::cells, 48, 3);
  const auto ex3 = quilt_test::exemplar<std::uint8_t, 3>(tessera::exemplar_kind::cells, 48, 3);
  auto set4 = tessera::build_wang_tiles(ex4, {.tile_size = 16, .seed = 2});
  auto set3 = tessera::build_wang_tiles(ex3, {.tile_size = 16, .seed = 2});  // converted on the way
  REQUIRE(set4.ok());
  REQUIRE(set3.ok());
  auto plane = tessera::hash_coloring::create(2, 2, 9);
  tessera::thread_pool_executor pool(2);
  for (const tessera::compose_options o :
       {tessera::compose_options{}, tessera::compose_options{.x = -37, .y = 5, .outline = true}}) {
    auto fast = texture_rgba8::make(53, 41, 0xCDCDCDCDu);
    auto slow = texture_rgba8_slow::make(53, 41, 0xCDCDCDCDu);
    std::vector<std::uint32_t> raw(53 * 41);
    auto view = tessera::make_image_view<4>(reinterpret_cast<std::uint8_t*>(raw.data()), 53, 41).value();
    REQUIRE(tessera::compose_tiles(*set4, *plane, fast, o, pool).ok());
    REQUIRE(tessera::compose_tiles(*set4, *plane, slow, o).ok());
    REQUIRE(tessera::compose_tiles(*set4, *plane, view, o).ok());
    REQUIRE(fast.texels == slow.texels);
    REQUIRE(fast.texels == raw);
    // a set of another format converts per pixel, still identically
    REQUIRE(tessera::compose_tiles(*set3, *plane, fast, o).ok());
    REQUIRE(tessera::compose_tiles(*set3, *plane, slow, o).ok());
    REQUIRE(fast.texels == slow.texels);
  }
}

TEST_CASE("contiguous outputs: synthesize and synthesize_aligned into an adapted texture equal the generic path",
          "[image_rows]") {
  const auto ex = quilt_test::exemplar<std::uint8_t, 4>(tessera::exemplar_kind::bricks, 48);
  const auto model = tessera::build_patch_model(ex, {.patch_width = 12, .patch_height = 12, .overlap = 4}).value();
  const tessera::patch_synthesis_options o{.origin = {-20, 33}, .seed = 5};
  auto fast = texture_rgba8::make(70, 50, 0xCDCDCDCDu);
  auto slow = texture_rgba8_slow::make(70, 50, 0xCDCDCDCDu);
  tessera::thread_pool_executor pool(2);
  REQUIRE(tessera::synthesize(model, fast, o, pool).ok());
  REQUIRE(tessera::synthesize(model, slow, o).ok());
  REQUIRE(fast.texels == slow.texels);
  const auto grey = quilt_test::exemplar<float, 1>(tessera::exemplar_kind::bricks, 48, 4);
  REQUIRE(tessera::synthesize_aligned(model, grey, fast, o).ok());
  REQUIRE(tessera::synthesize_aligned(model, grey, slow, o).ok());
  REQUIRE(fast.texels == slow.texels);
}
