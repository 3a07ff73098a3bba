// tessera/fabric/cat_map.hpp: Arnold's cat map on N x N images (eq. 1-4 of paper 001).
//
// One step moves pixel (x, y) to A (x, y) mod N with A = [1 1; 1 2] (eq. 2), carrying its colour
// along (eq. 3-4); iterating turns stripes into the diagonal, regular patterns of woven fabric, and
// returns to the original image after cat_map_period(N) steps. tessera gives:
//
//   cat_map_step(in, out)        one step exactly as the paper iterates it (the reference);
//   cat_map(in, out, n)          n steps (any n, negative = inverse) in a single pass: A^n mod N by
//                                binary exponentiation, then one gather whose cost does not depend
//                                on n (see detail/cat_map_kernels.hpp);
//   cat_map_options::family      the family [1 a; b ab+1]: more fabrics from one source image.
//
// Non-square images are rejected unless the options ask for the largest centred square or for square
// tiles; pixels outside the mapped squares are copied unchanged.
//
//   tessera::image_buffer<std::uint8_t, 3> fabric(400, 400);
//   auto s = tessera::cat_map(source, fabric, 60);          // the paper's flannel, figure 4
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/image_view.hpp"
#include "../core/status.hpp"
#include "cat_map_period.hpp"
#include "detail/cat_map_kernels.hpp"
#include "detail/number_theory.hpp"
#include "detail/square_regions.hpp"

TESSERA_NAMESPACE_BEGIN

/// What the cat map does with an image that is not square.
enum class non_square_mode {
  reject,           ///< return invalid_argument (default)
  centered_square,  ///< map the largest centred square, copy the rest unchanged
  square_tiles      ///< map each tile_size x tile_size tile on its own, copy any remainder unchanged
};

/// How the kernel is organized; the output is identical for every choice.
enum class cat_map_strategy {
  automatic,  ///< direct when the square fits in a typical L2 (<= 1 MiB), separable otherwise
  direct,     ///< one gather pass
  separable   ///< row and column permutation passes (cache-friendly for large images)
};

/// Options of the cat-map functions of this header.
struct cat_map_options {
  cat_map_family family = {};  ///< [1 a; b ab+1]; a = b = 1 is the paper's map
  /// What to do with a non-square image (reject by default).
  non_square_mode non_square = non_square_mode::reject;
  index_t tile_size = 0;  ///< square_tiles: tile side; 0 = gcd(width, height)
  /// How the map is computed (automatic picks one).
  cat_map_strategy strategy = cat_map_strategy::automatic;
};

namespace detail {

inline constexpr index_t cat_direct_bytes = index_t{1024} * 1024;

/// The squares the cat map works on, or a status naming the problem.
inline result<std::vector<square_region>> cat_regions(index_t w, index_t h, const cat_map_options& o,
                                                      const char* what) {
  std::vector<square_region> regions;
  if (w == h) {
    regions.push_back({0, 0, w});
    return regions;
  }
  switch (o.non_square) {
    case non_square_mode::reject:
      return status::invalid_argument(cat(what, ": the image is ", w, " x ", h,
                                          " but the cat map needs a square image; set options.non_square to "
                                          "centered_square or square_tiles"));
    case non_square_mode::centered_square: {
      const index_t n = std::min(w, h);
      regions.push_back({(w - n) / 2, (h - n) / 2, n});
      return regions;
    }
    case non_square_mode::square_tiles: {
      const index_t t = o.tile_size == 0 ? std::gcd(w, h) : o.tile_size;
      if (t < 1 || t > std::min(w, h))
        return status::invalid_argument(cat(what, ": options.tile_size must be 0 (gcd of the sides) or in [1, ",
                                            std::min(w, h), "] for a ", w, " x ", h, " image, got ", o.tile_size));
      for (index_t y = 0; y + t <= h; y += t)
        for (index_t x = 0; x + t <= w; x += t) regions.push_back({x, y, t});
      return regions;
    }
  }
  return status::invalid_argument(
      cat(what, ": options.non_square has an unknown value ", static_cast<int>(o.non_square)));
}

/// Validates, then runs kernel(src_square, dst_square) on every region, on tessera's own memory when
/// both images are packed views/buffers of one format, else through a buffer of the output's format.
template <Image I, WritableImage O, class Kernel>
status run_cat_regions(const I& in, O& out, const cat_map_options& o, const char* what, Kernel&& kernel) {
  if (auto s = validate_image(in, "input"); !s) return status(s.code(), cat(what, ": ", s.message()));
  if (auto s = validate_image(out, "output"); !s) return status(s.code(), cat(what, ": ", s.message()));
  if (auto s = validate_same_size(in, "input", out, "output"); !s)
    return status(s.code(), cat(what, ": ", s.message()));
  if (auto s =
          validate_enum(o.non_square, {"reject", "centered_square", "square_tiles"}, cat(what, ": options.non_square"));
      !s)
    return s;
  if (auto s = validate_enum(o.strategy, {"automatic", "direct", "separable"}, cat(what, ": options.strategy")); !s)
    return s;
  auto regions = cat_regions(width_of(in), height_of(in), o, what);
  if (!regions) return regions.error();
  using T = channel_t<O>;
  constexpr int C = channels_v<O>;
  auto run = [&](image_view<const T, C> src, image_view<T, C> dst) {
    index_t covered = 0;
    for (const square_region& r : *regions) covered += r.side * r.side;
    if (covered != src.width() * src.height()) copy_view<T, C>(src, dst);
    for (const square_region& r : *regions)
      kernel(src.subview(r.x, r.y, r.side, r.side), dst.subview(r.x, r.y, r.side, r.side));
  };
  if constexpr (raw_image_v<I> && raw_image_v<O> && std::is_same_v<channel_t<I>, T> && channels_v<I> == C) {
    image_view<const T, C> src = const_view_of(in);
    const image_view<T, C> dst = mutable_view_of(out);
    if (views_overlap(src, dst)) {  // in place (or any overlap): read from a copy
      auto copy = image_buffer<T, C>::create(src.width(), src.height());
      if (!copy) return status(copy.error().code(), cat(what, ": ", copy.error().message()));
      copy_view<T, C>(src, copy->view());
      run(copy->cview(), dst);
    } else {
      run(src, dst);
    }
    return {};
  } else {
    auto src = to_buffer<T, C>(in, "input");
    if (!src) return src.error();
    auto dst = image_buffer<T, C>::create(src->width(), src->height());
    if (!dst) return status(dst.error().code(), cat(what, ": ", dst.error().message()));
    run(src->cview(), dst->view());
    return copy_image(*dst, out);
  }
}

}  // namespace detail

/// Applies `steps` iterations of the cat map (eq. 3 of paper 001; the family [1 a; b ab+1] of
/// options.family) to `in`, writing `out`: out(A^n p mod N) = in(p). Negative `steps` apply the
/// inverse map, so cat_map(cat_map(img, n), -n) == img. The n-th matrix power is computed mod N in
/// O(log |n|) (cat_map_jump_matrix), then the pixels move in one gather whose cost is independent of
/// n: a single pass for squares of at most 1 MiB, else two (rarely three) cache-friendly row and
/// column permutation passes. `in` and `out` may be the same image.
/// Parameters: in, out (same size; out's pixel format is used, converting with convert_pixel);
/// steps (any int64); options (family, non-square handling, strategy); exec (parallel over rows or
/// column strips; output identical for every executor).
/// Errors: invalid_argument for an empty input, mismatched sizes, a non-square image with
/// non_square = reject, or a tile_size out of range; size_overflow for oversized images.
/// Complexity: O(W H) time, O(W H) extra memory only when converting formats or mapping in place.
/// Thread safety: reads `in`, writes `out`; no shared state.
template <Image I, WritableImage O, Executor E = serial_executor>
[[nodiscard]] status cat_map(const I& in, O& out, std::int64_t steps, const cat_map_options& options = {},
                             E&& exec = {}) {
  return detail::run_cat_regions(in, out, options, "cat_map", [&](auto src, auto dst) {
    using V = decltype(dst);
    using T = typename V::value_type;
    const auto n = static_cast<detail::u64>(src.width());
    // gather matrix: out(p') = in(M^-1 p') with M = A^steps; the inverse of [p q; r s] (det 1) is [s -q; -r p]
    const cat_map_matrix m = *cat_map_jump_matrix(static_cast<std::int64_t>(n), steps, options.family);
    const detail::mat2 g{m[3], (n - m[1]) % n, (n - m[2]) % n, m[0]};
    const index_t direct = options.strategy == cat_map_strategy::direct      ? index_t{-1}
                           : options.strategy == cat_map_strategy::separable ? index_t{0}
                                                                             : detail::cat_direct_bytes;
    detail::apply_gather<T, V::channels>(src, dst, g, direct, exec);
  });
}

/// Convenience form: returns the mapped image in a new buffer of the input's pixel format.
/// Same behaviour, parameters and errors as the form above.
template <Image I, Executor E = serial_executor>
[[nodiscard]] result<image_buffer<channel_t<I>, channels_v<I>>> cat_map(const I& in, std::int64_t steps,
                                                                        const cat_map_options& options = {},
                                                                        E&& exec = {}) {
  if (auto s = validate_image(in, "input"); !s) return status(s.code(), detail::cat("cat_map: ", s.message()));
  auto out = image_buffer<channel_t<I>, channels_v<I>>::create(width_of(in), height_of(in));
  if (!out) return status(out.error().code(), detail::cat("cat_map: ", out.error().message()));
  if (auto s = cat_map(in, *out, steps, options, exec); !s) return s;
  return out;
}

/// One step of the cat map exactly as paper 001 iterates it (eq. 2-4): every pixel (x, y) of `in` is
/// moved to (x + a y, b x + (ab+1) y) mod N in `out` (a = b = 1: [1 1; 1 2]). This is the reference
/// cat_map is tested against, and the baseline of its benchmark. Same options, errors and
/// guarantees as cat_map; `in` and `out` may be the same image. Complexity O(W H). Thread-safe as
/// cat_map.
template <Image I, WritableImage O, Executor E = serial_executor>
[[nodiscard]] status cat_map_step(const I& in, O& out, const cat_map_options& options = {}, E&& exec = {}) {
  return detail::run_cat_regions(in, out, options, "cat_map_step", [&](auto src, auto dst) {
    using V = decltype(dst);
    const auto n = static_cast<detail::u64>(src.width());
    detail::scatter_step<typename V::value_type, V::channels>(src, dst, detail::reduce_signed(options.family.a, n),
                                                              detail::reduce_signed(options.family.b, n), exec);
  });
}

TESSERA_NAMESPACE_END
