// tessera/core/image_checks.hpp: validation of image sizes shared by views, buffers and algorithms.
// Each check returns a status whose message names the parameter (`what`) and the offending values.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>

#include "config.hpp"
#include "image.hpp"
#include "status.hpp"

TESSERA_NAMESPACE_BEGIN

/// Largest number of channel values one image may hold (keeps every index product in range and
/// byte counts representable on 64-bit hosts).
/// 2^40 on 64-bit hosts; on 32-bit hosts small enough that bytes of 4-byte channels fit in size_t.
inline constexpr index_t max_image_elements =
    sizeof(index_t) >= 8 ? static_cast<index_t>(std::int64_t{1} << 40) : std::numeric_limits<index_t>::max() / 8;

/// Checks that width x height x channels is a valid, non-empty image extent whose element count and
/// byte count do not overflow. `what` names the image in the message ("exemplar", "output", ...).
inline status validate_image_extent(index_t width, index_t height, int channels, std::string_view what) {
  if (width <= 0 || height <= 0)
    return status::invalid_argument(
        detail::cat(what, ": width and height must be positive, got ", width, " x ", height));
  if (channels < 1 || channels > max_channels)
    return status::invalid_argument(detail::cat(what, ": channel count must be 1 to 4, got ", channels));
  if (width > max_image_elements / height || width * height > max_image_elements / channels)
    return status::size_overflow(detail::cat(what, ": ", width, " x ", height, " x ", channels,
                                             " channel values exceed the supported maximum of ", max_image_elements));
  return {};
}

/// Checks any Image: first the type's own `image_traits<I>::validate(img, what)` hook when it has one
/// (image_view: null data, a stride shorter than a row; see core/image.hpp), then positive size and no
/// overflow. Every entry point runs it on its input and output images.
template <Image I>
status validate_image(const I& img, std::string_view what) {
  if constexpr (requires { image_traits<I>::validate(img, what); }) {
    if (status s = image_traits<I>::validate(img, what); !s) return s;
  }
  return validate_image_extent(width_of(img), height_of(img), channels_v<I>, what);
}

/// Checks that every channel of a float image is finite: NaN or infinite values would make distances,
/// errors, means and spectra NaN. Other channel types always pass (without reading a pixel). Names the
/// image (`what`), the first bad pixel, its channel and value. O(pixels); run it after validate_image.
template <Image I>
status validate_finite_pixels(const I& img, std::string_view what) {
  if constexpr (std::is_floating_point_v<channel_t<I>>) {
    using P = pixel_t<I>;
    const index_t w = width_of(img), h = height_of(img);
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x) {
        const P px = image_traits<I>::read(img, x, y);
        for (int c = 0; c < channels_v<I>; ++c) {
          const auto v = pixel_traits<P>::get(px, c);
          if (!std::isfinite(v))
            return status::invalid_argument(detail::cat(what, ": pixel (", x, ", ", y, ") channel ", c, " is ", v,
                                                        "; pixel values must be finite (no NaN or infinity)"));
        }
      }
  }
  return {};
}

/// Checks that two images have the same size (aligned maps, masks).
template <Image A, Image B>
status validate_same_size(const A& a, std::string_view what_a, const B& b, std::string_view what_b) {
  if (width_of(a) != width_of(b) || height_of(a) != height_of(b))
    return status::invalid_argument(detail::cat(what_b, " is ", width_of(b), " x ", height_of(b), " but ", what_a,
                                                " is ", width_of(a), " x ", height_of(a), "; they must match"));
  return {};
}

TESSERA_NAMESPACE_END
