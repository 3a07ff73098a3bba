#include <tessera/core/image_rows.hpp>

#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_view.hpp>

#include <catch2/catch.hpp>

#include "packed_texture_support.hpp"

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

using tessera::index_t;

using test_support::packed_texture;
using test_support::packed_texture_slow;

static_assert(tessera::WritableImage<packed_texture>);
static_assert(tessera::WritableImage<packed_texture_slow>);
static_assert(!tessera::ContiguousImage<packed_texture_slow>);
static_assert(!tessera::ContiguousImage<tessera::image_view<std::uint8_t, 4>>);  // already a view
static_assert(!tessera::ContiguousImage<tessera::image_view<const std::uint8_t, 4>>);

TEST_CASE("image_rows: a texture whose traits expose a view is a ContiguousImage", "[image_rows]") {
  {
    STATIC_REQUIRE(tessera::ContiguousImage<packed_texture>);
    auto t = packed_texture::make(3, 2);
    auto v = tessera::contiguous_view(t);
    REQUIRE(v.width() == 3);
    v.write(1, 1, {10, 20, 30, 40});
    REQUIRE(t.texels[4] == (10u | 20u << 8 | 30u << 16 | 40u << 24));
    REQUIRE(tessera::image_traits<packed_texture>::read(t, 1, 1) == tessera::pixel<std::uint8_t, 4>{10, 20, 30, 40});
  }
}

TEST_CASE("image_rows: copy_image writes a ContiguousImage through its view, same pixels as the generic path",
          "[image_rows]") {
  // property-style over a few sizes and source formats
  for (index_t w : {1, 7, 33})
    for (index_t h : {1, 5}) {
      tessera::image_buffer<float, 3> src(w, h);
      for (index_t y = 0; y < h; ++y)
        for (index_t x = 0; x < w; ++x)
          src.write(x, y, {float(x) / float(w), float(y) / float(h), float((x * 7 + y * 3) % 11) / 10.0f});
      auto fast = packed_texture::make(w, h);
      auto slow = packed_texture_slow::make(w, h);
      REQUIRE(tessera::copy_image(src, fast).ok());
      REQUIRE(tessera::copy_image(src, slow).ok());
      REQUIRE(fast.texels == slow.texels);
    }
}

TEST_CASE("image_rows: a view whose size differs from the image is refused before writing", "[image_rows]") {
  {
    auto t = packed_texture::make(4, 4, 0x12345678u);
    t.view_width_error = 1;
    tessera::image_buffer<std::uint8_t, 4> src(4, 4);
    const auto s = tessera::copy_image(src, t);
    REQUIRE(s.code() == tessera::status_code::invalid_argument);
    REQUIRE(s.message().find("3 x 4 view of a 4 x 4 image") != std::string::npos);
    for (auto v : t.texels) REQUIRE(v == 0x12345678u);
  }
}
