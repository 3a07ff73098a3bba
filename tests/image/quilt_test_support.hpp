// Helpers shared by the quilting and Wang tile tests (not a test file itself).
#pragma once

#include <tessera/core/image_buffer.hpp>
#include <tessera/image/exemplars.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace quilt_test {

using tessera::index_t;

/// A member-style, writable user image: 16-bit RGB in a vector of arrays.
struct user_rgb16 {
  index_t w = 0, h = 0;
  std::vector<std::array<std::uint16_t, 3>> px;
  user_rgb16(index_t width, index_t height) : w(width), h(height), px(static_cast<std::size_t>(width * height)) {}
  index_t width() const { return w; }
  index_t height() const { return h; }
  std::array<std::uint16_t, 3> read(index_t x, index_t y) const { return px[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, const std::array<std::uint16_t, 3>& p) {
    px[static_cast<std::size_t>(y * w + x)] = p;
  }
};

/// A user image of any claimed size holding no pixels (reads are constant, writes ignored): lets
/// tests ask for sizes beyond the library's caps without allocating them.
struct huge_rgb8 {
  index_t w = 0, h = 0;
  index_t width() const { return w; }
  index_t height() const { return h; }
  std::array<std::uint8_t, 3> read(index_t, index_t) const { return {1, 2, 3}; }
  void write(index_t, index_t, const std::array<std::uint8_t, 3>&) {}
};

template <class T = std::uint8_t, int C = 3>
tessera::image_buffer<T, C> exemplar(tessera::exemplar_kind kind, index_t size, std::uint64_t seed = 1) {
  return tessera::make_exemplar<T, C>(kind, {.width = size, .height = size, .seed = seed}).value();
}

/// Mean absolute channel difference (unit range) between horizontally / vertically adjacent pixels.
template <class T, int C>
double mean_gradient(const tessera::image_buffer<T, C>& img) {
  double s = 0;
  index_t n = 0;
  for (index_t y = 0; y < img.height(); ++y)
    for (index_t x = 0; x < img.width(); ++x)
      for (int d = 0; d < 2; ++d) {
        const index_t x2 = x + (d == 0), y2 = y + (d == 1);
        if (x2 >= img.width() || y2 >= img.height()) continue;
        for (int c = 0; c < C; ++c)
          s += std::abs(tessera::channel_to_unit(img.pixel_ptr(x, y)[c]) -
                        tessera::channel_to_unit(img.pixel_ptr(x2, y2)[c]));
        n += C;
      }
  return s / static_cast<double>(n);
}

}  // namespace quilt_test
