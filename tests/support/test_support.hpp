// tests/support/test_support.hpp: small helpers several test files share (one definition each, so that
// the test files of a folder can be compiled together as one unity batch).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <tessera/core/status.hpp>
#include <tessera/image/exemplars.hpp>

namespace tessera_test {

using tessera::index_t;

/// Whether the status' message contains `text`.
inline bool mentions(const tessera::status& s, const std::string& text) {
  return s.message().find(text) != std::string::npos;
}

/// Distance of two hues in degrees, around the circle (0..180).
inline double hue_distance(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

/// A square procedural exemplar.
template <class T = std::uint8_t, int C = 3>
tessera::image_buffer<T, C> exemplar(tessera::exemplar_kind kind, index_t size, std::uint64_t seed = 1) {
  return tessera::make_exemplar<T, C>(kind, {.width = size, .height = size, .seed = seed}).value();
}

/// The w x h window of `src` at (x0, y0), copied.
template <class T, int C>
tessera::image_buffer<T, C> crop(const tessera::image_buffer<T, C>& src, index_t x0, index_t y0, index_t w, index_t h) {
  tessera::image_buffer<T, C> out(w, h);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) out.write(x, y, src.read(x0 + x, y0 + y));
  return out;
}

/// A member-style user image of 16-bit RGB in a vector of arrays (the Image concept without an
/// adapter): `px` holds w x h pixels row by row.
struct user_image {
  index_t w = 0, h = 0;
  std::vector<std::array<std::uint16_t, 3>> px;
  index_t width() const { return w; }
  index_t height() const { return h; }
  std::array<std::uint16_t, 3> read(index_t x, index_t y) const { return px[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, const std::array<std::uint16_t, 3>& p) {
    px[static_cast<std::size_t>(y * w + x)] = p;
  }
};

}  // namespace tessera_test
