// tessera/image/detail/patch_render.hpp: the pixel work of patch synthesis. Every output row is a
// list of spans precomputed per cell row: copies of exemplar row segments (memcpy) between overlaps,
// and feathered blends (paper 002 §2: linear weights by the distance to the overlap border, integer
// fixed point for uint8 and uint16) or seam cuts inside the overlaps. Rows where two cell rows overlap
// combine two such rows. Internal.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../../core/config.hpp"
#include "../../core/image_buffer.hpp"
#include "patch_plan.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Fixed-point feather weights: uint8 blends in 8 fractional bits, uint16 in 15, float in float.
template <class T>
using blend_weight = std::conditional_t<std::is_same_v<T, std::uint8_t>, std::uint16_t,
                                        std::conditional_t<std::is_same_v<T, std::uint16_t>, std::uint32_t, float>>;
template <class T>
inline constexpr blend_weight<T> weight_one = std::is_same_v<T, std::uint8_t>    ? 256
                                              : std::is_same_v<T, std::uint16_t> ? 32768
                                                                                 : 1;

/// Weight in [0, 1] of the second (right or bottom) patch at overlap position t in [0, v) for a blend
/// band of `band` pixels (1 <= band <= v) centred in the overlap: 0 before the band, (t - s + 1/2) / band
/// inside it (s = (v - band) / 2, its first position), 1 after. band = v is the paper's linear weights by
/// the distance to the overlap border (§2, "feathering"); a narrower band is ours (docs: narrow feathering).
inline double feather_fraction(index_t t, index_t v, index_t band) noexcept {
  const index_t s = (v - band) / 2;
  if (t < s) return 0.0;
  if (t >= s + band) return 1.0;
  return (static_cast<double>(t - s) + 0.5) / static_cast<double>(band);
}

/// feather_fraction in the blend's fixed point (8 fractional bits for uint8, 15 for uint16) or float.
template <class T>
blend_weight<T> feather_weight(index_t t, index_t v, index_t band) {
  const double u = feather_fraction(t, v, band);
  if constexpr (std::is_same_v<T, float>)
    return static_cast<float>(u);
  else
    return static_cast<blend_weight<T>>(u * static_cast<double>(weight_one<T>) + 0.5);
}

/// dst[i] = a[i] (1 - w[i]) + b[i] w[i], rounded, for i in [0, N): a fixed trip count the compiler
/// turns into one or two vector operations.
template <class T, index_t N>
inline void blend_fixed(T* dst, const T* a, const T* b, const blend_weight<T>* w) noexcept {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, std::uint8_t> && N == 16) {
    // 16 channel values: widen to 16 bits, a (256 - w) + b w + 128, >> 8, narrow
    const __m128i zero = _mm_setzero_si128(), half = _mm_set1_epi16(128), one = _mm_set1_epi16(256);
    const __m128i va = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a));
    const __m128i vb = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b));
    const __m128i wlo = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w));
    const __m128i whi = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w + 8));
    auto mix = [&](__m128i x, __m128i y, __m128i wy) {
      const __m128i wx = _mm_sub_epi16(one, wy);
      return _mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(_mm_mullo_epi16(x, wx), _mm_mullo_epi16(y, wy)), half), 8);
    };
    const __m128i lo = mix(_mm_unpacklo_epi8(va, zero), _mm_unpacklo_epi8(vb, zero), wlo);
    const __m128i hi = mix(_mm_unpackhi_epi8(va, zero), _mm_unpackhi_epi8(vb, zero), whi);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst), _mm_packus_epi16(lo, hi));
    return;
  }
#endif
  for (index_t i = 0; i < N; ++i) {
    if constexpr (std::is_same_v<T, std::uint8_t>)
      dst[i] = static_cast<std::uint8_t>((static_cast<std::uint16_t>(a[i] * (256 - w[i]) + b[i] * w[i] + 128)) >> 8);
    else if constexpr (std::is_same_v<T, std::uint16_t>)
      dst[i] = static_cast<std::uint16_t>(
          (std::uint32_t{a[i]} * (32768u - w[i]) + std::uint32_t{b[i]} * w[i] + 16384u) >> 15);
    else
      dst[i] = a[i] * (1.0f - w[i]) + b[i] * w[i];
  }
}

/// dst[i] = a[i] (1 - w[i]) + b[i] w[i], rounded; per-element weights. Overlap strips are short, so
/// the span is covered by 16-byte chunks, the last one overlapping its predecessor (recomputing a few
/// values is harmless: dst never aliases a or b).
template <class T>
inline void blend_span(T* dst, const T* a, const T* b, const blend_weight<T>* w, index_t n) noexcept {
  constexpr index_t chunk = 16 / static_cast<index_t>(sizeof(T));
  if (n < chunk) {
    for (index_t i = 0; i < n; ++i) blend_fixed<T, 1>(dst + i, a + i, b + i, w + i);
    return;
  }
  index_t i = 0;
  for (; i + chunk <= n; i += chunk) blend_fixed<T, chunk>(dst + i, a + i, b + i, w + i);
  if (i < n) blend_fixed<T, chunk>(dst + n - chunk, a + n - chunk, b + n - chunk, w + n - chunk);
}

/// memcpy for the short runs of a patch row: inline 16-byte moves (the last overlapping) instead of a
/// library call per run; long runs go to std::memcpy.
inline void copy_span_bytes(unsigned char* d, const unsigned char* s, std::size_t n) noexcept {
  if (n > 256) {
    std::memcpy(d, s, n);
  } else if (n >= 16) {
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) std::memcpy(d + i, s + i, 16);
    if (i < n) std::memcpy(d + n - 16, s + n - 16, 16);
  } else if (n >= 8) {
    std::memcpy(d, s, 8);
    std::memcpy(d + n - 8, s + n - 8, 8);
  } else {
    for (std::size_t i = 0; i < n; ++i) d[i] = s[i];
  }
}
template <class T>
inline void copy_span(T* dst, const T* src, index_t n) noexcept {
  copy_span_bytes(reinterpret_cast<unsigned char*>(dst), reinterpret_cast<const unsigned char*>(src),
                  to_size(n) * sizeof(T));
}

/// dst[i] = a[i] (1 - w) + b[i] w, rounded; one weight.
template <class T>
inline void blend_span_const(T* dst, const T* a, const T* b, blend_weight<T> w, index_t n) noexcept {
  if constexpr (std::is_same_v<T, std::uint8_t>) {
    const auto wa = static_cast<std::uint16_t>(256 - w);
    for (index_t i = 0; i < n; ++i)
      dst[i] = static_cast<std::uint8_t>((static_cast<std::uint16_t>(a[i] * wa + b[i] * w + 128)) >> 8);
  } else if constexpr (std::is_same_v<T, std::uint16_t>) {
    for (index_t i = 0; i < n; ++i)
      dst[i] =
          static_cast<std::uint16_t>((std::uint32_t{a[i]} * (32768u - w) + std::uint32_t{b[i]} * w + 16384u) >> 15);
  } else {
    const float wa = 1.0f - w;
    for (index_t i = 0; i < n; ++i) dst[i] = a[i] * wa + b[i] * w;
  }
}

/// A run of one output row: a copy from one patch, or an overlap between the patch of cell `cell - 1`
/// (source a) and of cell `cell` (source b).
struct row_span {
  index_t dst = 0;   ///< first channel value in the output row
  index_t len = 0;   ///< channel values
  index_t a = 0;     ///< exemplar channel-value offset of the first source at patch row 0
  index_t b = -1;    ///< second source for overlaps, -1 for copies
  index_t lx = 0;    ///< local column of the first pixel in cell `cell`
  index_t cell = 0;  ///< plan cell of the (right) patch
};

/// Renders rows of a plan from an exemplar of any pixel type (the model's or an aligned map of the
/// same size). Spans are computed once per call, per cell row.
template <class T, int C>
class plan_renderer {
 public:
  plan_renderer(const patch_plan& p, const image_buffer<T, C>& ex) : p_(p), ex_(ex), stride_(ex.width() * C) {
    spans_.resize(to_size(p.ncy));
    for (index_t cj = 0; cj < p.ncy; ++cj) {
      auto& row = spans_[to_size(cj)];
      index_t x = 0, i = floor_div(p.ox, p.pw), lx = p.ox - i * p.pw;
      while (x < p.w) {
        const index_t ci = i - p.ci0;
        const index_t c = p.cell(ci, cj);
        row_span s;
        s.dst = x * C;
        s.lx = lx;
        s.cell = c;
        index_t n;
        if (lx < p.v) {
          const index_t l = p.cell(ci - 1, cj);
          n = std::min(p.v - lx, p.w - x);
          s.a = offset(l, p.pw + lx);
          s.b = offset(c, lx);
        } else {
          n = std::min(p.pw - lx, p.w - x);
          s.a = offset(c, lx);
        }
        s.len = n * C;
        row.push_back(s);
        x += n;
        lx += n;
        if (lx == p.pw) {
          lx = 0;
          ++i;
        }
      }
    }
    weights_.resize(to_size(p.v * C));
    for (index_t t = 0; t < p.v; ++t)
      for (int c = 0; c < C; ++c) weights_[to_size(t * C + c)] = feather_weight<T>(t, p.v, p.band);
  }

  /// Writes output row y (0-based in the window) to dst (w * C values); tmp is scratch of the same size.
  void render(index_t y, T* dst, T* tmp) const {
    const index_t Y = p_.oy + y, j = floor_div(Y, p_.ph), ly = Y - j * p_.ph, cj = j - p_.cj0;
    if (ly >= p_.v) {
      cell_row(cj, ly, dst);
      return;
    }
    cell_row(cj - 1, ly + p_.ph, tmp);  // the row above overlaps this one
    cell_row(cj, ly, dst);
    if (!p_.cut) {
      blend_span_const(dst, tmp, dst, weights_[to_size(ly * C)], p_.w * C);
      return;
    }
    // seam cut across the rows: above the horizontal seam the upper patches win. In an overlap corner
    // the lower row's vertical seam says which column's horizontal seam applies.
    for (const row_span& s : spans_[to_size(cj)]) {
      const index_t n = s.len / C;
      const std::uint8_t* right = p_.hseam[to_size(s.cell)];
      const std::uint8_t* left = s.b >= 0 ? p_.hseam[to_size(s.cell - 1)] : nullptr;
      const index_t vcut = s.b >= 0 ? p_.vseam[to_size(s.cell)][ly] : 0;
      for (index_t k = 0; k < n; ++k) {
        const index_t t = s.lx + k;
        const bool from_left = s.b >= 0 && t < vcut;
        const index_t hcut = from_left ? left[t + p_.pw] : right[t];
        if (ly < hcut) std::memcpy(dst + s.dst + k * C, tmp + s.dst + k * C, sizeof(T) * C);
      }
    }
  }

 private:
  [[nodiscard]] index_t offset(index_t cell, index_t lx) const {
    return p_.sy[to_size(cell)] * stride_ + (p_.sx[to_size(cell)] + lx) * C;
  }

  /// One row of cell row cj at patch row r (0 <= r < ph + v), all columns of the window.
  void cell_row(index_t cj, index_t r, T* dst) const {
    const T* base = ex_.data() + r * stride_;
    for (const row_span& s : spans_[to_size(cj)]) {
      if (s.b < 0) {
        copy_span(dst + s.dst, base + s.a, s.len);
      } else if (!p_.cut) {
        blend_span(dst + s.dst, base + s.a, base + s.b, weights_.data() + s.lx * C, s.len);
      } else {
        const index_t cut = p_.vseam[to_size(s.cell)][r];
        const index_t split = std::clamp<index_t>(cut - s.lx, 0, s.len / C) * C;
        copy_span(dst + s.dst, base + s.a, split);
        copy_span(dst + s.dst + split, base + s.b + split, s.len - split);
      }
    }
  }

  const patch_plan& p_;
  const image_buffer<T, C>& ex_;
  index_t stride_;
  std::vector<std::vector<row_span>> spans_;
  std::vector<blend_weight<T>> weights_;
};

/// Exemplar coordinates of the patch pixel that dominates output pixel (x, y) of the window: the
/// larger feather weight (the second patch from the overlap's middle on), or the side of the seam.
inline void source_of(const patch_plan& p, index_t x, index_t y, index_t& sx, index_t& sy) {
  const index_t X = p.ox + x, Y = p.oy + y;
  const index_t i = floor_div(X, p.pw), j = floor_div(Y, p.ph), lx = X - i * p.pw, ly = Y - j * p.ph;
  const index_t ci = i - p.ci0, cj = j - p.cj0;
  auto right_wins = [&](index_t cell_row, index_t r) {  // column choice in cell row cell_row at patch row r
    if (lx >= p.v) return true;
    if (!p.cut) return feather_fraction(lx, p.v, p.band) >= 0.5;
    return lx >= p.vseam[to_size(p.cell(ci, cell_row))][r];
  };
  bool lower = true;
  if (ly < p.v) {
    if (!p.cut) {
      lower = feather_fraction(ly, p.v, p.band) >= 0.5;
    } else {
      const bool right = right_wins(cj, ly);
      const std::uint8_t* h = p.hseam[to_size(p.cell(right ? ci : ci - 1, cj))];
      lower = ly >= h[right ? lx : lx + p.pw];
    }
  }
  const index_t row = lower ? cj : cj - 1, r = lower ? ly : ly + p.ph;
  const bool right = right_wins(row, r);
  const auto c = to_size(p.cell(right ? ci : ci - 1, row));
  sx = p.sx[c] + (right ? lx : lx + p.pw);
  sy = p.sy[c] + r;
}

}  // namespace detail
TESSERA_NAMESPACE_END
