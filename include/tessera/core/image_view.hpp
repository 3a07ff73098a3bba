// tessera/core/image_view.hpp: a non-owning view over a raw pixel buffer (like Eigen::Map or
// std::span): data pointer, width, height and row stride, C interleaved channels of T per pixel.
// `image_view<const T, C>` reads only; `image_view<T, C>` also writes. Constness is shallow, as for
// std::span: copying a view never copies pixels.
#pragma once

#include <array>
#include <string_view>
#include <type_traits>

#include "config.hpp"
#include "image.hpp"
#include "image_checks.hpp"
#include "status.hpp"

TESSERA_NAMESPACE_BEGIN

/// Non-owning view of `height` rows of `width` pixels, C interleaved channels of T each, rows
/// `stride` channel values apart. Models Image (and WritableImage when T is not const). Build it with
/// make_image_view(), which validates the size, stride and pointer; the constructor does not (like
/// std::span). Pixel reads and writes are by value; the view never owns or copies the pixels.
template <class T, int C>
class image_view {
 public:
  /// The channel type without const.
  using value_type = std::remove_const_t<T>;
  /// The pixel type, C channels of value_type.
  using pixel_type = pixel<value_type, C>;
  static_assert(Channel<value_type>, "image_view channels must be uint8_t, uint16_t or float");
  static_assert(C >= 1 && C <= max_channels, "image_view channel count must be 1 to 4");
  /// The channel count C.
  static constexpr int channels = C;

  image_view() = default;
  /// Unchecked: use make_image_view() to validate caller-supplied buffers. `stride` counts channel
  /// values (not bytes) from one row to the next; 0 means tightly packed (width * C). A view built
  /// here with null data or a short stride is refused by every entry point (validate(), below).
  image_view(T* data, index_t width, index_t height, index_t stride = 0) noexcept
      : data_(data), width_(width), height_(height), stride_(stride == 0 ? width * C : stride) {}

  /// A read-only view converts implicitly from a writable one.
  operator image_view<const value_type, C>() const noexcept  // NOLINT(google-explicit-constructor)
      requires(!std::is_const_v<T>) {
    return {data_, width_, height_, stride_};
  }

  /// Width in pixels.
  [[nodiscard]] index_t width() const noexcept { return width_; }
  /// Height in pixels.
  [[nodiscard]] index_t height() const noexcept { return height_; }
  /// Channel values from one row to the next.
  [[nodiscard]] index_t stride() const noexcept { return stride_; }
  /// True when width or height is 0.
  [[nodiscard]] bool empty() const noexcept { return width_ == 0 || height_ == 0; }
  /// The first channel value of row 0.
  [[nodiscard]] T* data() const noexcept { return data_; }
  /// The first channel value of row y.
  [[nodiscard]] T* row(index_t y) const noexcept { return data_ + y * stride_; }
  /// The first channel value of pixel (x, y).
  [[nodiscard]] T* pixel_ptr(index_t x, index_t y) const noexcept { return data_ + y * stride_ + x * C; }

  /// The image_traits validate hook (run by validate_image at every entry point): refuses what the
  /// unchecked constructor let through: negative sizes, null data with a non-empty size, a stride
  /// shorter than a row of width * C channel values, or rows whose span overflows.
  [[nodiscard]] status validate(std::string_view what) const {
    if (width_ < 0 || height_ < 0)
      return status::invalid_argument(detail::cat(what, ": image_view has a negative size ", width_, " x ", height_));
    if (width_ == 0 || height_ == 0) return {};  // reported as empty by validate_image_extent
    if (data_ == nullptr)
      return status::invalid_argument(
          detail::cat(what, ": image_view data is null for a ", width_, " x ", height_, " image"));
    if (width_ > max_image_elements / C || stride_ < width_ * C)
      return status::invalid_argument(
          detail::cat(what, ": image_view stride ", stride_, " is smaller than width * channels = ", width_, " * ", C));
    if (stride_ > max_image_elements / height_)
      return status::size_overflow(detail::cat(what, ": image_view stride ", stride_, " x height ", height_,
                                               " exceeds the supported maximum of ", max_image_elements));
    return {};
  }

  /// Pixel (x, y); asserts it is inside.
  [[nodiscard]] pixel_type read(index_t x, index_t y) const noexcept {
    TESSERA_ASSERT(x >= 0 && x < width_ && y >= 0 && y < height_);
    const T* p = pixel_ptr(x, y);
    pixel_type out;
    for (int c = 0; c < C; ++c) out[detail::to_size(c)] = p[c];
    return out;
  }
  /// Sets pixel (x, y); asserts it is inside. Writable views only.
  void write(index_t x, index_t y, const pixel_type& v) const noexcept requires(!std::is_const_v<T>) {
    TESSERA_ASSERT(x >= 0 && x < width_ && y >= 0 && y < height_);
    T* p = pixel_ptr(x, y);
    for (int c = 0; c < C; ++c) p[c] = v[detail::to_size(c)];
  }

  /// The sub-rectangle [x, x + w) x [y, y + h); unchecked (asserts).
  [[nodiscard]] image_view subview(index_t x, index_t y, index_t w, index_t h) const noexcept {
    TESSERA_ASSERT(x >= 0 && y >= 0 && w >= 0 && h >= 0 && x + w <= width_ && y + h <= height_);
    return {pixel_ptr(x, y), w, h, stride_};
  }

 private:
  T* data_ = nullptr;
  index_t width_ = 0;
  index_t height_ = 0;
  index_t stride_ = 0;
};

/// Validates a caller's buffer and returns a view over it: positive sizes, `stride` (in channel
/// values; 0 = packed) at least width * C, non-null data, and a byte count that does not overflow.
template <int C, class T>
result<image_view<T, C>> make_image_view(T* data, index_t width, index_t height, index_t stride = 0) {
  if (auto s = validate_image_extent(width, height, C, "image_view"); !s) return s;
  const index_t row = width * C;
  if (stride == 0) stride = row;
  if (stride < row)
    return status::invalid_argument(detail::cat("image_view: stride ", stride, " is smaller than width * channels = ",
                                                row, " (stride counts channel values, not bytes)"));
  if (stride > max_image_elements / height)
    return status::size_overflow(detail::cat("image_view: stride ", stride, " x height ", height, " overflows"));
  if (data == nullptr)
    return status::invalid_argument(detail::cat("image_view: data is null for a ", width, " x ", height, " image"));
  return image_view<T, C>(data, width, height, stride);
}

TESSERA_NAMESPACE_END
