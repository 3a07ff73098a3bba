// tessera/fabric/detail/life_int_kernels.hpp: the first generation of the game-of-life lightness
// rule on 8- and 16-bit images, in integers. Internal: no stability promise.
//
// For integer channels the HLS lightness of a pixel is L = q / (2 M) with q = max + min of its
// channels (grey: q = 2 v) and M the channel maximum, so q is an exact integer and the first
// generation needs no float until a rule fires:
//
//   * one pass per row turns pixels into q (a compact plane of 16-bit lanes for 8-bit images,
//     32-bit for 16-bit), with one wrapped value at each end;
//   * the classification adds the 8 neighbours of each pixel in those lanes. A neighbour is stored
//     as q + 2^S (S = 12 for 8-bit, 20 for 16-bit), so one masked sum over the brighter neighbours
//     holds both their count (the bits from S up) and the sum of their q (the bits below S): two
//     compares, two ands and two adds per neighbour, and the loop vectorizes (8 pixels per SSE2
//     vector for 8-bit images);
//   * only the pixels whose rule fires draw r and are relit, straight from their own channels.
//
// The result is the rule of life_perturbation.hpp with exact neighbour statistics: L_bright is
// sum / count of the integers q, rounded once to float.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <emmintrin.h>
#endif

#include "../../core/config.hpp"
#include "life_kernels.hpp"

// the classification's rows and outputs never alias; saying so lets compilers vectorize it
#if defined(__GNUC__) || defined(__clang__) || defined(_MSC_VER)
#define TESSERA_LIFE_RESTRICT __restrict
#else
#define TESSERA_LIFE_RESTRICT
#endif

// On x86 with GCC or Clang, when the build does not already target AVX2, the two vectorized loops
// (classification and fired-pixel arithmetic) are also compiled for AVX2 and chosen at run time:
// twice as many lanes. Both versions do the same integer and IEEE float operations lane by lane
// (no FMA), so the output does not depend on the machine.
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__)) && !defined(__AVX2__)
#define TESSERA_LIFE_AVX2 1
#define TESSERA_LIFE_INLINE __attribute__((always_inline)) inline
#else
#define TESSERA_LIFE_INLINE inline
#endif

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// The lanes of the integer generation for a channel type: `value` holds q + 2^S (signed, so that
/// SSE2 compares it in one instruction), `sum` the sum of 8 of them (unsigned, wrapping into the
/// top bit: the count of summed neighbours sits in the bits from S up, the sum of their q below).
template <class T>
struct life_lane;
template <>
struct life_lane<std::uint8_t> {
  using value = std::int16_t;
  using sum = std::uint16_t;
  static constexpr int shift = 12;  // 8 (510 + 2^12) < 2^16 and 8 * 510 < 2^12
};
template <>
struct life_lane<std::uint16_t> {
  using value = std::int32_t;
  using sum = std::uint32_t;
  static constexpr int shift = 20;  // 8 (131070 + 2^20) < 2^32 and 8 * 131070 < 2^20
};

/// Whether the SSE2 paths below are compiled (every x86-64 target); elsewhere the portable loops run.
#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
inline constexpr bool life_simd = true;
#define TESSERA_LIFE_SSE2 1
#else
inline constexpr bool life_simd = false;
#endif

/// Writes q + 2^S of row `p` (w pixels of C channels) to padded[1..w], wrapping one value at each
/// end. Simd = true takes RGBA8 four pixels at a time (byte max / min across each pixel's lanes);
/// the result is the same.
template <class T, int C, bool Simd = life_simd>
void life_q_row(const T* p, index_t w, typename life_lane<T>::value* padded) noexcept {
  using V = typename life_lane<T>::value;
  constexpr V tag = V{1} << life_lane<T>::shift;
  V* out = padded + 1;
  index_t x = 0;
#if defined(TESSERA_LIFE_SSE2)
  if constexpr (Simd && C == 4 && std::is_same_v<T, std::uint8_t>) {  // 8 pixels per step
    const __m128i low_byte = _mm_set1_epi32(0xff), tagged = _mm_set1_epi32(static_cast<int>(tag));
    auto q4 = [&](const T* px) {  // byte 0 of each 32-bit pixel: max / min over r, g, b
      const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(px));
      const __m128i g = _mm_srli_epi32(v, 8), b = _mm_srli_epi32(v, 16);
      const __m128i mx = _mm_max_epu8(_mm_max_epu8(v, g), b), mn = _mm_min_epu8(_mm_min_epu8(v, g), b);
      return _mm_add_epi32(_mm_add_epi32(_mm_and_si128(mx, low_byte), _mm_and_si128(mn, low_byte)), tagged);
    };
    for (; x + 8 <= w; x += 8) {  // q + tag <= 4606: the signed pack does not saturate
      _mm_prefetch(reinterpret_cast<const char*>(p + x * 4) + 4096, _MM_HINT_T0);  // hides the read of the image
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + x), _mm_packs_epi32(q4(p + x * 4), q4(p + x * 4 + 16)));
    }
  }
#endif
  for (; x < w; ++x) {
    const T* px = p + x * C;
    if constexpr (C <= 2) {
      out[x] = static_cast<V>(2 * V{px[0]} + tag);
    } else {
      const V r = px[0], g = px[1], b = px[2];
      out[x] = static_cast<V>(std::max(r, std::max(g, b)) + std::min(r, std::min(g, b)) + tag);
    }
  }
  padded[0] = padded[w];
  padded[w + 1] = padded[1];
}

/// The rule resolved for integer lanes: q_threshold is the largest q that is not "above" the
/// threshold (q > threshold 2M  <=>  q > floor(threshold 2M)); crowd > 8 turns crowding off.
template <class V>
struct life_int_rule {
  V live, dead, crowd, q_threshold;
  bool exact, by_threshold;
};

/// Classifies one row from three padded rows of tagged q: kind[x] = 1 (brighten), 2 (darken) or
/// 0 (keep; also when the rule fires with no neighbour to move towards), and toward[x] the tagged
/// sum over the brighter neighbours (kind 1) or the dimmer ones (otherwise). Masks and selects
/// only, with signed compares, so it vectorizes well (8 pixels per SSE2 vector for 8-bit images).
template <class V, class U, int S, bool ByThreshold, bool Exact>
TESSERA_LIFE_INLINE void life_int_classify(const V* TESSERA_LIFE_RESTRICT up, const V* TESSERA_LIFE_RESTRICT mid,
                                           const V* TESSERA_LIFE_RESTRICT down, index_t w, const life_int_rule<V>& rule,
                                           U* TESSERA_LIFE_RESTRICT toward, U* TESSERA_LIFE_RESTRICT kind) noexcept {
  const V live_k = rule.live, dead_n = rule.dead, crowd = rule.crowd;
  const V qt = static_cast<V>(rule.q_threshold + (V{1} << S));
  auto mask = [](bool b) { return static_cast<U>(0 - static_cast<U>(b)); };
  for (index_t x = 0; x < w; ++x) {
    const V c = mid[x + 1];
    const V around[8] = {up[x], up[x + 1], up[x + 2], mid[x], mid[x + 2], down[x], down[x + 1], down[x + 2]};
    U sb = 0, sd = 0;
    V na = 0;
    for (const V v : around) {
      sb = static_cast<U>(sb + (v > c ? static_cast<U>(v) : U{0}));
      sd = static_cast<U>(sd + (v < c ? static_cast<U>(v) : U{0}));
      if constexpr (ByThreshold) na = static_cast<V>(na + (v > qt));
    }
    const auto nb = static_cast<V>(sb >> S), nd = static_cast<V>(sd >> S);
    const V live = ByThreshold ? na : nb;
    const V dead = ByThreshold ? static_cast<V>(8 - na) : nd;
    const U darken = mask(dead >= dead_n) | mask(live >= crowd);
    const U lives = Exact ? mask(live == live_k) : mask(live >= live_k);
    const U brighten = static_cast<U>(lives & ~darken & mask(nb > 0));
    toward[x] = static_cast<U>((sb & brighten) | (sd & ~brighten));
    kind[x] = static_cast<U>((brighten & 1u) | (darken & mask(nd > 0) & 2u));
  }
}

/// For each byte mask of 8 lanes: the positions of its set bits, in order, and how many there are.
struct life_compact_table {
  std::uint8_t at[256][8] = {};
  std::uint8_t count[256] = {};
  constexpr life_compact_table() {
    for (int m = 0; m < 256; ++m)
      for (int b = 0; b < 8; ++b)
        if (m >> b & 1) at[m][count[m]++] = static_cast<std::uint8_t>(b);
  }
};
inline constexpr life_compact_table life_compact_lanes{};

/// Writes the columns x < w with kind[x] != 0 to fired[0..n), in order, and returns n. fired must
/// hold w + 8 entries (the SSE2 path writes 8 at a time). Simd = false is the portable loop.
template <class U, bool Simd = life_simd>
std::size_t life_compact(const U* kind, index_t w, std::uint32_t* fired) noexcept {
  std::size_t n = 0;
  index_t x = 0;
#if defined(TESSERA_LIFE_SSE2)
  if constexpr (Simd && std::is_same_v<U, std::uint16_t>) {
    const __m128i zero = _mm_setzero_si128();
    for (; x + 8 <= w; x += 8) {
      const __m128i k = _mm_loadu_si128(reinterpret_cast<const __m128i*>(kind + x));
      const __m128i none = _mm_packs_epi16(_mm_cmpeq_epi16(k, zero), zero);
      const auto m = to_size(~_mm_movemask_epi8(none) & 0xff);
      const __m128i at =
          _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(life_compact_lanes.at[m])), zero);
      const __m128i first = _mm_set1_epi32(static_cast<int>(x));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(fired + n), _mm_add_epi32(_mm_unpacklo_epi16(at, zero), first));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(fired + n + 4), _mm_add_epi32(_mm_unpackhi_epi16(at, zero), first));
      n += life_compact_lanes.count[m];
    }
  }
#endif
  for (; x < w; ++x) {  // without branches: a fired column advances n
    fired[n] = static_cast<std::uint32_t>(x);
    n += kind[x] != 0;
  }
  return n;
}

/// Scratch of one band task of the integer generation: three padded rows of q, the classification
/// of one row, and per fired pixel (structure of arrays) its column, tagged sum, q, r, new
/// lightness and relighting factors.
template <class T>
struct life_int_scratch {
  using V = typename life_lane<T>::value;
  using U = typename life_lane<T>::sum;
  std::vector<V> rows;
  std::vector<U> toward, kind;
  std::vector<std::uint32_t> fired, sum, q, up;
  std::vector<float> lq, k, base;
  explicit life_int_scratch(index_t w)
      : rows(to_size(3 * (w + 2))),
        toward(to_size(w)),
        kind(toward.size()),
        fired(toward.size() + 8),
        sum(toward.size()),
        q(toward.size()),
        up(toward.size()),
        lq(toward.size()),
        k(toward.size()),
        base(toward.size()) {}
};

/// The per-pixel arithmetic of the fired pixels, over structure-of-arrays scratch so that it
/// vectorizes: L_bright or L_dim as sum / count of the integers q (eq. of §1.3 of paper 001:
/// L' = L + (L_bright - L) r or L' = L_dim + (L - L_dim) r), then the relighting factors of
/// life_int_relight: c' = base + c k.
template <class T>
TESSERA_LIFE_INLINE void life_int_fired(std::size_t n, std::uint32_t row_key, life_int_scratch<T>& s) noexcept {
  constexpr int S = life_lane<T>::shift;
  constexpr std::uint32_t low = (std::uint32_t{1} << S) - 1;
  constexpr float top = static_cast<float>(std::numeric_limits<T>::max());
  const std::uint32_t* TESSERA_LIFE_RESTRICT sum = s.sum.data();
  const std::uint32_t* TESSERA_LIFE_RESTRICT qv = s.q.data();
  const std::uint32_t* TESSERA_LIFE_RESTRICT up = s.up.data();
  const std::uint32_t* TESSERA_LIFE_RESTRICT fired = s.fired.data();
  float* TESSERA_LIFE_RESTRICT lq = s.lq.data();
  float* TESSERA_LIFE_RESTRICT kk = s.k.data();
  float* TESSERA_LIFE_RESTRICT base = s.base.data();
  constexpr std::int32_t m = std::numeric_limits<T>::max();
  // integer compares and float arithmetic without compares: compilers vectorize this even under
  // -ftrapping-math (a float compare may trap, so they would keep it as a branch)
  for (std::size_t i = 0; i < n; ++i) {
    const float mean = static_cast<float>(static_cast<std::int32_t>(sum[i] & low)) /
                       static_cast<float>(static_cast<std::int32_t>(sum[i] >> S));
    const auto qi = static_cast<std::int32_t>(qv[i]);
    const auto q = static_cast<float>(qi);
    const auto bits = static_cast<std::int32_t>(life_random::bits24(row_key, fired[i]));
    const float r = static_cast<float>(bits) * 0x1.0p-24f;
    const float lo = life_select(up[i], q, mean), hi = life_select(up[i], mean, q);
    const float l = lo + (hi - lo) * r;
    const std::int32_t d = qi - m, span_old = m - (d < 0 ? -d : d);  // 2M times 1 - |2L - 1|
    const float span_new = top - std::abs(l - top);
    const float k =
        life_select(life_mask(span_old > 0), span_new / static_cast<float>(span_old > 1 ? span_old : 1), 0.0f);
    lq[i] = l;
    kk[i] = k;
    base[i] = (l - q * k) * 0.5f + 0.5f;
  }
}

/// The classification and fired-pixel loops of one build target (Avx2: compiled for AVX2).
template <class T, bool Avx2>
struct life_int_loops {
  using V = typename life_lane<T>::value;
  using U = typename life_lane<T>::sum;
  static constexpr int S = life_lane<T>::shift;
  template <bool ByThreshold, bool Exact>
  static void classify(const V* up, const V* mid, const V* down, index_t w, const life_int_rule<V>& rule, U* toward,
                       U* kind) noexcept {
    life_int_classify<V, U, S, ByThreshold, Exact>(up, mid, down, w, rule, toward, kind);
  }
  static void fired(std::size_t n, std::uint32_t row_key, life_int_scratch<T>& s) noexcept {
    life_int_fired<T>(n, row_key, s);
  }
};
#if defined(TESSERA_LIFE_AVX2)
template <class T>
struct life_int_loops<T, true> {
  using V = typename life_lane<T>::value;
  using U = typename life_lane<T>::sum;
  static constexpr int S = life_lane<T>::shift;
  template <bool ByThreshold, bool Exact>
  __attribute__((target("avx2"))) static void classify(const V* up, const V* mid, const V* down, index_t w,
                                                       const life_int_rule<V>& rule, U* toward, U* kind) noexcept {
    life_int_classify<V, U, S, ByThreshold, Exact>(up, mid, down, w, rule, toward, kind);
  }
  __attribute__((target("avx2"))) static void fired(std::size_t n, std::uint32_t row_key,
                                                    life_int_scratch<T>& s) noexcept {
    life_int_fired<T>(n, row_key, s);
  }
};
/// Whether this machine runs AVX2 (asked once).
inline bool life_has_avx2() noexcept {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}
#else
inline bool life_has_avx2() noexcept { return false; }
#endif

/// Runs the first generation on rows [y0, y1) of a W x H torus whose padded row y of tagged q is
/// written by fill(y, dst), calling emit(y, q_row, s, n) per row with the row's tagged q (padded:
/// column x at q_row[x + 1]) and the scratch holding the n columns whose rule fired (s.fired), their
/// q, new lightness (s.lq, in q units: L' = lq / 2M) and relighting factors (s.k, s.base). All
/// other columns keep their lightness exactly.
template <class T, class Fill, class Emit>
void life_int_band(index_t w, index_t h, index_t y0, index_t y1,
                   const life_int_rule<typename life_lane<T>::value>& rule, const life_random& random,
                   life_int_scratch<T>& s, Fill&& fill, Emit&& emit, bool use_avx2 = life_has_avx2()) {
  using V = typename life_lane<T>::value;
  using U = typename life_lane<T>::sum;
  constexpr int S = life_lane<T>::shift;
  constexpr V low = (V{1} << S) - 1;
  using classify_fn = void (*)(const V*, const V*, const V*, index_t, const life_int_rule<V>&, U*, U*) noexcept;
  using fired_fn = void (*)(std::size_t, std::uint32_t, life_int_scratch<T>&) noexcept;
  auto pick = [&](auto loops) -> std::pair<classify_fn, fired_fn> {
    using L = decltype(loops);
    const classify_fn c = rule.by_threshold
                              ? (rule.exact ? &L::template classify<true, true> : &L::template classify<true, false>)
                              : (rule.exact ? &L::template classify<false, true> : &L::template classify<false, false>);
    return {c, &L::fired};
  };
  const auto [classify, fired] = use_avx2 ? pick(life_int_loops<T, true>{}) : pick(life_int_loops<T, false>{});
  V* ring[3] = {s.rows.data(), s.rows.data() + (w + 2), s.rows.data() + 2 * (w + 2)};
  fill((y0 + h - 1) % h, ring[0]);
  fill(y0, ring[1]);
  for (index_t y = y0; y < y1; ++y) {
    fill((y + 1) % h, ring[2]);
    classify(ring[0], ring[1], ring[2], w, rule, s.toward.data(), s.kind.data());
    // compact the fired columns without branches, then gather what their arithmetic needs
    const std::size_t n = life_compact<U>(s.kind.data(), w, s.fired.data());
    const V* q = ring[1] + 1;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t x = s.fired[i];
      s.up[i] = life_mask(s.kind[x] == 1);
      s.sum[i] = s.toward[x];
      s.q[i] = static_cast<std::uint32_t>(q[x] & low);
    }
    fired(n, random.row_key(y), s);
    emit(y, static_cast<const V*>(ring[1]), static_cast<const life_int_scratch<T>&>(s), n);
    std::rotate(ring, ring + 1, ring + 3);
  }
}

/// Writes pixel `in` relit by c' = base + c k (life_int_fired) to `out`, rounded to nearest and
/// clamped; alpha is copied. Grey images have no chroma: their value is the new lightness.
template <class T, int C>
inline void life_int_relight(const T* in, T* out, float lq, float k, float base) noexcept {
  constexpr float top = static_cast<float>(std::numeric_limits<T>::max());
  if constexpr (C <= 2) {
    out[0] = static_cast<T>(std::min(std::max(lq * 0.5f + 0.5f, 0.0f), top));
  } else {
    for (int c = 0; c < 3; ++c)  // min / max, not branches: compilers emit minss / maxss
      out[c] = static_cast<T>(std::min(std::max(static_cast<float>(in[c]) * k + base, 0.0f), top));
  }
  if constexpr (C == 2 || C == 4) out[C - 1] = in[C - 1];
}

/// Relights the n fired pixels of one row (s.fired, s.lq, s.k, s.base) from `in` into `out`. A
/// pixel whose lightness did not change relights to itself (k = 1, base = 1/2). Simd = true takes
/// RGBA8 pixels four at a time, one channel per vector; the result is the same.
template <class T, int C, bool Simd = life_simd>
void life_int_relight_row(const T* in, T* out, const life_int_scratch<T>& s, std::size_t n) noexcept {
  std::size_t i = 0;
#if defined(TESSERA_LIFE_SSE2)
  if constexpr (Simd && C == 4 && std::is_same_v<T, std::uint8_t>) {
    const __m128i byte = _mm_set1_epi32(0xff), alpha = _mm_set1_epi32(static_cast<int>(0xff000000u));
    const __m128 zero = _mm_setzero_ps(), top = _mm_set1_ps(255.0f);
    auto word = [&](std::size_t x) {
      std::uint32_t v;
      std::memcpy(&v, in + x * 4, sizeof v);
      return static_cast<int>(v);
    };
    for (; i + 4 <= n; i += 4) {
      const std::uint32_t* x = s.fired.data() + i;
      const __m128i p = _mm_set_epi32(word(x[3]), word(x[2]), word(x[1]), word(x[0]));
      const __m128 k = _mm_loadu_ps(s.k.data() + i), base = _mm_loadu_ps(s.base.data() + i);
      auto channel = [&](int shift) {  // c' = min(max(c k + base, 0), 255), truncated
        const __m128 c = _mm_cvtepi32_ps(_mm_and_si128(_mm_srli_epi32(p, shift), byte));
        return _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(_mm_add_ps(_mm_mul_ps(c, k), base), zero), top));
      };
      const __m128i rgba = _mm_or_si128(_mm_or_si128(channel(0), _mm_slli_epi32(channel(8), 8)),
                                        _mm_or_si128(_mm_slli_epi32(channel(16), 16), _mm_and_si128(p, alpha)));
      std::uint32_t words[4];
      _mm_storeu_si128(reinterpret_cast<__m128i*>(words), rgba);
      for (int j = 0; j < 4; ++j) std::memcpy(out + to_size(x[j]) * 4, words + j, sizeof(std::uint32_t));
    }
  }
#endif
  for (; i < n; ++i) {
    const std::size_t x = s.fired[i];
    life_int_relight<T, C>(in + x * C, out + x * C, s.lq[i], s.k[i], s.base[i]);
  }
}

}  // namespace detail
TESSERA_NAMESPACE_END

#undef TESSERA_LIFE_RESTRICT
#undef TESSERA_LIFE_SSE2
#undef TESSERA_LIFE_AVX2
#undef TESSERA_LIFE_INLINE
