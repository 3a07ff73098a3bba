// Shared helpers for the fabric tests: a member-style user image type and deterministic random images.
#pragma once

#include <tessera/core/image.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/random.hpp>

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace fabric_test {

using tessera::index_t;

/// An engine-style RGB float texture reached through members only (not a tessera type).
struct user_texture {
  index_t w = 0, h = 0;
  std::vector<std::array<float, 3>> texels;
  user_texture(index_t width, index_t height) : w(width), h(height), texels(static_cast<std::size_t>(width * height)) {}
  index_t width() const { return w; }
  index_t height() const { return h; }
  std::array<float, 3> read(index_t x, index_t y) const { return texels[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, const std::array<float, 3>& p) { texels[static_cast<std::size_t>(y * w + x)] = p; }
  friend bool operator==(const user_texture&, const user_texture&) = default;
};

/// Fills every channel of a buffer with seeded random values (uniform over the channel's range).
template <class T, int C>
tessera::image_buffer<T, C> random_image(index_t w, index_t h, std::uint64_t seed) {
  tessera::image_buffer<T, C> img(w, h);
  const tessera::counter_rng rng(seed);
  for (index_t i = 0; i < w * h * C; ++i) {
    if constexpr (std::is_floating_point_v<T>)
      img.data()[i] = static_cast<T>(rng.uniform(i));
    else
      img.data()[i] = static_cast<T>(rng.bits(i));
  }
  return img;
}

inline user_texture random_user_texture(index_t w, index_t h, std::uint64_t seed) {
  user_texture t(w, h);
  const tessera::counter_rng rng(seed);
  for (std::size_t i = 0; i < t.texels.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) t.texels[i][c] = static_cast<float>(rng.uniform(i, c));
  return t;
}

}  // namespace fabric_test
