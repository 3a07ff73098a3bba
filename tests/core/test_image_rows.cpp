#include <tessera/core/image_rows.hpp>

#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_view.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

using tessera::index_t;

namespace {
// An engine-style texture: RGBA8 packed in uint32 (R in the low byte), adapted through image_traits.
struct packed_texture {
  index_t w = 0, h = 0;
  std::vector<std::uint32_t> texels;
  index_t view_width_error = 0;  // makes view() lie about its size (to test the check)
};
// The same type without the view: the generic path.
struct packed_texture_slow : packed_texture {};

template <class Tex>
struct packed_traits {
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
}  // namespace

// RGBA8 in a uint32 with R in the low byte is R, G, B, A in memory on little-endian machines (all
// tessera targets); a big-endian engine would view its texels as A, B, G, R instead.
static_assert(std::endian::native == std::endian::little);
template <>
struct tessera::image_traits<packed_texture> : packed_traits<packed_texture> {
  static tessera::image_view<std::uint8_t, 4> view(packed_texture& t) {
    return {reinterpret_cast<std::uint8_t*>(t.texels.data()), t.w - t.view_width_error, t.h};
  }
};
template <>
struct tessera::image_traits<packed_texture_slow> : packed_traits<packed_texture_slow> {};

static_assert(tessera::WritableImage<packed_texture>);
static_assert(tessera::WritableImage<packed_texture_slow>);
static_assert(!tessera::ContiguousImage<packed_texture_slow>);
static_assert(!tessera::ContiguousImage<tessera::image_view<std::uint8_t, 4>>);  // already a view
static_assert(!tessera::ContiguousImage<tessera::image_view<const std::uint8_t, 4>>);

TEST_CASE("image_rows: a texture whose traits expose a view is a ContiguousImage", "[image_rows]") {
  {
    STATIC_REQUIRE(tessera::ContiguousImage<packed_texture>);
    packed_texture t{3, 2, std::vector<std::uint32_t>(6)};
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
      packed_texture fast{w, h, std::vector<std::uint32_t>(std::size_t(w * h))};
      packed_texture_slow slow;
      slow.w = w;
      slow.h = h;
      slow.texels.assign(std::size_t(w * h), 0);
      REQUIRE(tessera::copy_image(src, fast).ok());
      REQUIRE(tessera::copy_image(src, slow).ok());
      REQUIRE(fast.texels == slow.texels);
    }
}

TEST_CASE("image_rows: a view whose size differs from the image is refused before writing", "[image_rows]") {
  {
    packed_texture t{4, 4, std::vector<std::uint32_t>(16, 0x12345678u)};
    t.view_width_error = 1;
    tessera::image_buffer<std::uint8_t, 4> src(4, 4);
    const auto s = tessera::copy_image(src, t);
    REQUIRE(s.code() == tessera::status_code::invalid_argument);
    REQUIRE(s.message().find("3 x 4 view of a 4 x 4 image") != std::string::npos);
    for (auto v : t.texels) REQUIRE(v == 0x12345678u);
  }
}
