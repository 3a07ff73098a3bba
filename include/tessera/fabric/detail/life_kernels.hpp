// tessera/fabric/detail/life_kernels.hpp: one synchronous generation of the game-of-life lightness
// rule over a toroidal float lightness field. Internal: no stability promise.
//
// A band of rows is processed with a rolling window of three rows padded by one wrapped value at
// each end, so the neighbourhood loop has no wrap tests and the compiler vectorizes it: it classifies
// every pixel (brighten / darken / keep) and records the two ends of its interpolation. A second,
// scalar loop draws r only for the pixels whose rule fired.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/random.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// The rule with its thresholds resolved (see life_perturbation_options).
struct life_rule {
  int live = 3;  // K: brighten when the live count is K (or >= K)
  bool live_exact = true;
  int dead = 6;      // N: darken when the dead count is >= N
  int crowding = 0;  // darken when the live count is >= this (0 = off)
  bool by_threshold = false;
  float threshold = 0.5f;
};

/// The 32-bit integer hash "lowbias32" (C. Wellons, hash-prospector): a bijection with good
/// avalanche, two multiplies that vectorize (SSE2 and up).
constexpr std::uint32_t life_hash32(std::uint32_t v) noexcept {
  v ^= v >> 16;
  v *= 0x7feb352dU;
  v ^= v >> 15;
  v *= 0x846ca68bU;
  v ^= v >> 16;
  return v;
}

/// r in [0, 1) for pixel (x, y) of a generation, counter-based: depends only on (seed, generation,
/// y, x), never on the order of evaluation.
///   row key  k = low 32 bits of mix64(rng.bits(generation) + (y + 1) golden + (x >> 32) golden'),
///   r = (life_hash32(k + x mod 2^32) >> 8) / 2^24  (24 bits, exact in float).
/// The row key is one SplitMix64 mix per row; each pixel then costs one 32-bit hash, which the
/// integer kernel computes four or eight pixels at a time.
class life_random {
 public:
  life_random(const counter_rng& rng, std::uint64_t generation) noexcept : key_(rng.bits(generation)) {}
  /// The key of row y for columns x with x >> 32 == x_high.
  [[nodiscard]] std::uint32_t row_key(index_t y, std::uint64_t x_high = 0) const noexcept {
    return static_cast<std::uint32_t>(
        mix64(key_ + (static_cast<std::uint64_t>(y) + 1) * 0x9e3779b97f4a7c15ULL + x_high * 0xd1b54a32d192ed03ULL));
  }
  /// The 24 bits of r from a row key and the low 32 bits of x.
  [[nodiscard]] static std::uint32_t bits24(std::uint32_t row_key, std::uint32_t x_low) noexcept {
    return life_hash32(row_key + x_low) >> 8;
  }
  /// r for pixel (x, y).
  [[nodiscard]] float operator()(index_t y, index_t x) const noexcept {
    const auto ux = static_cast<std::uint64_t>(x);
    return static_cast<float>(bits24(row_key(y, ux >> 32), static_cast<std::uint32_t>(ux))) * 0x1.0p-24f;
  }

 private:
  std::uint64_t key_;
};

/// Copies row `src` (w values) into `dst` (w + 2 values) with one wrapped value at each end.
inline void pad_row(const float* src, index_t w, float* dst) noexcept {
  dst[0] = src[w - 1];
  std::memcpy(dst + 1, src, sizeof(float) * to_size(w));
  dst[w + 1] = src[0];
}

inline std::uint32_t life_mask(bool b) noexcept { return 0u - static_cast<std::uint32_t>(b); }
/// m ? a : b for an all-ones / all-zeros mask, on the bits (vectorizes without float control flow).
inline float life_select(std::uint32_t m, float a, float b) noexcept {
  return std::bit_cast<float>((std::bit_cast<std::uint32_t>(a) & m) | (std::bit_cast<std::uint32_t>(b) & ~m));
}

/// Classifies one row from three padded rows: fire[x] != 0 where the rule fires with a neighbour to
/// move towards, and then L' = lo[x] + (hi[x] - lo[x]) r (brighten: lo = L, hi = L_bright; darken:
/// lo = L_dim, hi = L). Written with integer masks and bit selects, no float branches, so compilers
/// vectorize it even under strict IEEE semantics.
template <bool ByThreshold>
void life_classify(const float* up, const float* mid, const float* down, index_t w, const life_rule& rule, float* lo,
                   float* hi, std::int32_t* fire) {
  const std::int32_t live_k = rule.live, dead_n = rule.dead, crowd = rule.crowding > 0 ? rule.crowding : 100;
  const float threshold = rule.threshold;
  const std::uint32_t exact = life_mask(rule.live_exact);
  for (index_t x = 0; x < w; ++x) {
    const float l = mid[x + 1];
    float sb = 0, sd = 0;
    std::int32_t nb = 0, nd = 0, na = 0;
    auto add = [&](float v) {
      const std::uint32_t gt = life_mask(v > l), lt = life_mask(v < l), bits = std::bit_cast<std::uint32_t>(v);
      sb += std::bit_cast<float>(bits & gt);
      sd += std::bit_cast<float>(bits & lt);
      nb -= static_cast<std::int32_t>(gt);
      nd -= static_cast<std::int32_t>(lt);
      na += static_cast<std::int32_t>(v > threshold);
    };
    add(up[x]);
    add(up[x + 1]);
    add(up[x + 2]);
    add(mid[x]);
    add(mid[x + 2]);
    add(down[x]);
    add(down[x + 1]);
    add(down[x + 2]);
    const std::int32_t live = ByThreshold ? na : nb;
    const std::int32_t dead = ByThreshold ? 8 - na : nd;
    const std::uint32_t darken = life_mask(dead >= dead_n) | life_mask(live >= crowd);
    const std::uint32_t lives = (life_mask(live == live_k) & exact) | (life_mask(live >= live_k) & ~exact);
    const std::uint32_t brighten = ~darken & lives;
    const float l_bright = sb / static_cast<float>(nb + static_cast<std::int32_t>(nb == 0));
    const float l_dim = sd / static_cast<float>(nd + static_cast<std::int32_t>(nd == 0));
    lo[x] = life_select(darken, l_dim, l);
    hi[x] = life_select(darken, l, l_bright);
    fire[x] = static_cast<std::int32_t>((darken & life_mask(nd > 0)) | (brighten & life_mask(nb > 0)));
  }
}

/// Scratch of one band task: three padded rows, the classification of one row, its new lightness
/// and the list of pixels whose rule fired.
struct life_scratch {
  std::vector<float> rows, lo, hi, next;
  std::vector<std::int32_t> fire;
  std::vector<index_t> fired;
  explicit life_scratch(index_t w)
      : rows(to_size(3 * (w + 2))), lo(to_size(w)), hi(lo.size()), next(lo.size()), fire(lo.size()), fired(lo.size()) {}
};

/// Runs one generation on rows [y0, y1) of a W x H toroidal lightness field whose row y is written,
/// padded, by fill(y, dst) (from a float field, or straight from the image for the first
/// generation), calling emit(y, old_row, next_row, fired, n_fired) for each row with its lightness
/// before and after and the n_fired columns whose lightness may have changed (all others keep
/// theirs exactly).
template <class Fill, class Emit>
void life_band(index_t w, index_t h, index_t y0, index_t y1, const life_rule& rule, const life_random& random,
               life_scratch& s, Fill&& fill, Emit&& emit) {
  float* ring[3] = {s.rows.data(), s.rows.data() + (w + 2), s.rows.data() + 2 * (w + 2)};
  fill((y0 + h - 1) % h, ring[0]);
  fill(y0, ring[1]);
  for (index_t y = y0; y < y1; ++y) {
    fill((y + 1) % h, ring[2]);
    if (rule.by_threshold)
      life_classify<true>(ring[0], ring[1], ring[2], w, rule, s.lo.data(), s.hi.data(), s.fire.data());
    else
      life_classify<false>(ring[0], ring[1], ring[2], w, rule, s.lo.data(), s.hi.data(), s.fire.data());
    // compact the fired columns without branches, then update only those
    index_t n = 0;
    for (index_t x = 0; x < w; ++x) {
      s.fired[to_size(n)] = x;
      n += s.fire[to_size(x)] != 0;
    }
    std::memcpy(s.next.data(), ring[1] + 1, sizeof(float) * to_size(w));
    const std::uint32_t key = random.row_key(y);
    const bool narrow = static_cast<std::uint64_t>(w) <= (std::uint64_t{1} << 32);  // one row key per row
    for (index_t k = 0; k < n; ++k) {
      const index_t x = s.fired[to_size(k)];
      const float r = narrow ? static_cast<float>(life_random::bits24(key, static_cast<std::uint32_t>(x))) * 0x1.0p-24f
                             : random(y, x);
      const auto xs = to_size(x);
      s.next[xs] = s.lo[xs] + (s.hi[xs] - s.lo[xs]) * r;
    }
    emit(y, static_cast<const float*>(ring[1] + 1), static_cast<const float*>(s.next.data()),
         static_cast<const index_t*>(s.fired.data()), n);
    std::rotate(ring, ring + 1, ring + 3);
  }
}

}  // namespace detail
TESSERA_NAMESPACE_END
