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

#include "quilt_test_support.hpp"

using tessera::index_t;

namespace {
struct texture_rgba8 {
  index_t w = 0, h = 0;
  std::vector<std::uint32_t> texels;
};
struct texture_rgba8_slow : texture_rgba8 {};
template <class Tex>
struct rgba8_traits {
  using rgba8 = tessera::pixel<std::uint8_t, 4>;
  static index_t width(const Tex& t) { return t.w; }
  static index_t height(const Tex& t) { return t.h; }
  static rgba8 read(const Tex& t, index_t x, index_t y) {
    const std::uint32_t v = t.texels[std::size_t(y * t.w + x)];
    return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
  }
  static void write(Tex& t, index_t x, index_t y, const rgba8& p) {
    t.texels[std::size_t(y * t.w + x)] =
        std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
  }
};
template <class Tex>
Tex make_texture(index_t w, index_t h) {
  Tex t;
  t.w = w;
  t.h = h;
  t.texels.assign(std::size_t(w * h), 0xCDCDCDCDu);
  return t;
}
}  // namespace

static_assert(std::endian::native == std::endian::little);  // R in the low byte is R first in memory
template <>
struct tessera::image_traits<texture_rgba8> : rgba8_traits<texture_rgba8> {
  static tessera::image_view<std::uint8_t, 4> view(texture_rgba8& t) {
    return {reinterpret_cast<std::uint8_t*>(t.texels.data()), t.w, t.h};
  }
};
template <>
struct tessera::image_traits<texture_rgba8_slow> : rgba8_traits<texture_rgba8_slow> {};

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
    auto fast = make_texture<texture_rgba8>(53, 41);
    auto slow = make_texture<texture_rgba8_slow>(53, 41);
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
  auto fast = make_texture<texture_rgba8>(70, 50);
  auto slow = make_texture<texture_rgba8_slow>(70, 50);
  tessera::thread_pool_executor pool(2);
  REQUIRE(tessera::synthesize(model, fast, o, pool).ok());
  REQUIRE(tessera::synthesize(model, slow, o).ok());
  REQUIRE(fast.texels == slow.texels);
  const auto grey = quilt_test::exemplar<float, 1>(tessera::exemplar_kind::bricks, 48, 4);
  REQUIRE(tessera::synthesize_aligned(model, grey, fast, o).ok());
  REQUIRE(tessera::synthesize_aligned(model, grey, slow, o).ok());
  REQUIRE(fast.texels == slow.texels);
}
