// tessera/core/image_checks.hpp: validation of image sizes shared by views, buffers and algorithms.
// Each check returns a status whose message names the parameter (`what`) and the offending values.
#pragma once

#include <cstdint>
#include <limits>
#include <string_view>

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

/// Checks any Image: positive size, no overflow.
template <Image I>
status validate_image(const I& img, std::string_view what) {
  return validate_image_extent(width_of(img), height_of(img), channels_v<I>, what);
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
