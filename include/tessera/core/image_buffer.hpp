// tessera/core/image_buffer.hpp: an owning image of C interleaved channels of T, rows packed.
// This is what algorithms use internally; callers may use it too. Models WritableImage.
// Also: copying any Image into a buffer and a buffer out into any WritableImage, which is how
// algorithms convert at their entry points (kernels are instantiated per channel type and count,
// not per user type).
#pragma once

#include <array>
#include <new>
#include <vector>

#include "config.hpp"
#include "image.hpp"
#include "image_checks.hpp"
#include "image_rows.hpp"
#include "image_view.hpp"
#include "status.hpp"

TESSERA_NAMESPACE_BEGIN

/// Owning image of width x height pixels, C interleaved channels of T (uint8_t, uint16_t or float),
/// rows packed. What algorithms convert caller images into; models Image and WritableImage. Copyable
/// and movable like a std::vector; view() gives an image_view of it.
template <class T, int C>
class image_buffer {
 public:
  /// The channel type T.
  using value_type = T;
  /// The pixel type, C channels of T.
  using pixel_type = pixel<T, C>;
  static_assert(Channel<T>, "image_buffer channels must be uint8_t, uint16_t or float");
  static_assert(C >= 1 && C <= max_channels, "image_buffer channel count must be 1 to 4");
  /// The channel count C.
  static constexpr int channels = C;

  image_buffer() = default;
  /// A width x height image filled with `fill`. A size that is not positive or whose byte count
  /// overflows gives an empty 0 x 0 image (never a throw or a huge allocation); use create() when the
  /// size comes from a caller and the reason matters.
  image_buffer(index_t width, index_t height, const pixel_type& fill = {}) {
    if (!validate_image_extent(width, height, C, "image_buffer").ok()) return;
    width_ = width;
    height_ = height;
    data_.resize(detail::to_size(width * height * C));
    for (index_t i = 0; i < width * height; ++i)
      for (int c = 0; c < C; ++c) data_[detail::to_size(i * C + c)] = fill[detail::to_size(c)];
  }

  /// Validated construction: a status when the size is not positive or overflows, and (in builds
  /// with exceptions) size_overflow when the system cannot allocate it.
  static result<image_buffer> create(index_t width, index_t height, const pixel_type& fill = {}) {
    if (auto s = validate_image_extent(width, height, C, "image_buffer"); !s) return s;
#if TESSERA_HAS_EXCEPTIONS
    try {
      return image_buffer(width, height, fill);
    } catch (const std::bad_alloc&) {
      return status::size_overflow(
          detail::cat("image_buffer: cannot allocate ", width, " x ", height, " x ", C, " x ", sizeof(T), " bytes"));
    }
#else
    return image_buffer(width, height, fill);
#endif
  }

  /// Width in pixels.
  [[nodiscard]] index_t width() const noexcept { return width_; }
  /// Height in pixels.
  [[nodiscard]] index_t height() const noexcept { return height_; }
  /// Channel values from one row to the next: width * C (rows are packed).
  [[nodiscard]] index_t stride() const noexcept { return width_ * C; }
  /// True when the buffer holds no pixel.
  [[nodiscard]] bool empty() const noexcept { return data_.empty(); }
  /// The first channel value of row 0.
  [[nodiscard]] T* data() noexcept { return data_.data(); }
  /// The first channel value of row 0 (read-only).
  [[nodiscard]] const T* data() const noexcept { return data_.data(); }
  /// The first channel value of row y.
  [[nodiscard]] T* row(index_t y) noexcept { return data_.data() + y * width_ * C; }
  /// The first channel value of row y (read-only).
  [[nodiscard]] const T* row(index_t y) const noexcept { return data_.data() + y * width_ * C; }
  /// The first channel value of pixel (x, y).
  [[nodiscard]] T* pixel_ptr(index_t x, index_t y) noexcept { return row(y) + x * C; }
  /// The first channel value of pixel (x, y) (read-only).
  [[nodiscard]] const T* pixel_ptr(index_t x, index_t y) const noexcept { return row(y) + x * C; }
  /// Bytes of pixel storage.
  [[nodiscard]] std::size_t size_bytes() const noexcept { return data_.size() * sizeof(T); }

  /// Pixel (x, y); asserts it is inside.
  [[nodiscard]] pixel_type read(index_t x, index_t y) const noexcept { return cview().read(x, y); }
  /// Sets pixel (x, y); asserts it is inside.
  void write(index_t x, index_t y, const pixel_type& v) noexcept { view().write(x, y, v); }

  /// A writable view of the whole buffer.
  [[nodiscard]] image_view<T, C> view() noexcept { return {data_.data(), width_, height_, width_ * C}; }
  /// A read-only view of the whole buffer.
  [[nodiscard]] image_view<const T, C> view() const noexcept { return cview(); }
  /// A read-only view of the whole buffer.
  [[nodiscard]] image_view<const T, C> cview() const noexcept { return {data_.data(), width_, height_, width_ * C}; }

  /// Same size and same channel values.
  friend bool operator==(const image_buffer& a, const image_buffer& b) noexcept {
    return a.width_ == b.width_ && a.height_ == b.height_ && a.data_ == b.data_;
  }

 private:
  std::vector<T> data_;
  index_t width_ = 0;
  index_t height_ = 0;
};

/// Copies any Image into an owning buffer of pixel type (T, C), converting pixels with
/// convert_pixel. Fails on an empty or overflowing image, one its type's validate hook refuses, or
/// (size_overflow) when the copy cannot be allocated.
template <Channel T, int C, Image I>
result<image_buffer<T, C>> to_buffer(const I& img, std::string_view what = "image") {
  if (auto s = validate_image(img, what); !s) return s;
  const index_t w = width_of(img), h = height_of(img);
  auto created = image_buffer<T, C>::create(w, h);
  if (!created) return status(created.error().code(), detail::cat(what, ": ", created.error().message()));
  image_buffer<T, C>& out = *created;
  for (index_t y = 0; y < h; ++y) {
    T* dst = out.row(y);
    for (index_t x = 0; x < w; ++x) {
      const auto p = convert_pixel<pixel<T, C>>(image_traits<I>::read(img, x, y));
      for (int c = 0; c < C; ++c) dst[x * C + c] = p[detail::to_size(c)];
    }
  }
  return created;
}

/// Copies any Image into a buffer of its own channel type and count.
template <Image I>
result<image_buffer<channel_t<I>, channels_v<I>>> to_buffer(const I& img, std::string_view what = "image") {
  return to_buffer<channel_t<I>, channels_v<I>>(img, what);
}

/// Copies `src` into `dst` pixel by pixel, converting pixel types. The sizes must match. A
/// ContiguousImage destination (core/image_rows.hpp) is written through its view.
template <Image S, WritableImage D>
status copy_image(const S& src, D& dst) {
  if (auto s = validate_image(src, "source"); !s) return s;
  if (auto s = validate_image(dst, "destination"); !s) return s;
  if (auto s = validate_same_size(src, "source", dst, "destination"); !s) return s;
  if constexpr (ContiguousImage<D>) {  // adapted destination over rows of memory: write its view
    auto view = detail::checked_contiguous_view(dst, "copy_image: destination");
    if (!view) return view.error();
    return copy_image(src, *view);
  }
  const index_t w = width_of(src), h = height_of(src);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x)
      image_traits<D>::write(dst, x, y, convert_pixel<pixel_t<D>>(image_traits<S>::read(src, x, y)));
  return {};
}

TESSERA_NAMESPACE_END
