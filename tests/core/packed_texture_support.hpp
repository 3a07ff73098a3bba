// An engine-style texture for the tests of the contiguous-memory fast path (core/image_rows.hpp):
// RGBA8 packed in a uint32 (R in the low byte), adapted through image_traits, with (Contiguous =
// true) or without the image_traits::view that exposes its texels as rows of memory.
#pragma once

#include <tessera/core/image.hpp>
#include <tessera/core/image_view.hpp>

#include <bit>
#include <cstdint>
#include <vector>

namespace test_support {
template <bool Contiguous>
struct packed_rgba8 {
  tessera::index_t w = 0, h = 0;
  std::vector<std::uint32_t> texels;
  tessera::index_t view_width_error = 0;  // makes view() lie about its width (to test the check)
  static packed_rgba8 make(tessera::index_t width, tessera::index_t height, std::uint32_t fill = 0) {
    packed_rgba8 t;
    t.w = width;
    t.h = height;
    t.texels.assign(std::size_t(width * height), fill);
    return t;
  }
};
using packed_texture = packed_rgba8<true>;        // with the fast path
using packed_texture_slow = packed_rgba8<false>;  // every pixel through image_traits::write
}  // namespace test_support

// R in the low byte of a uint32 is R first in memory on little-endian machines (every tessera target).
static_assert(std::endian::native == std::endian::little);

template <bool Contiguous>
struct tessera::image_traits<test_support::packed_rgba8<Contiguous>> {
  using texture = test_support::packed_rgba8<Contiguous>;
  using rgba8 = tessera::pixel<std::uint8_t, 4>;
  static index_t width(const texture& t) { return t.w; }
  static index_t height(const texture& t) { return t.h; }
  static rgba8 read(const texture& t, index_t x, index_t y) {
    const std::uint32_t v = t.texels[std::size_t(y * t.w + x)];
    return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
  }
  static void write(texture& t, index_t x, index_t y, const rgba8& p) {
    t.texels[std::size_t(y * t.w + x)] =
        std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
  }
  static tessera::image_view<std::uint8_t, 4> view(texture& t) requires Contiguous {
    return {reinterpret_cast<std::uint8_t*>(t.texels.data()), t.w - t.view_width_error, t.h};
  }
};
