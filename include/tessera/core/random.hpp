// tessera/core/random.hpp: counter-based randomness. A random value is a pure function of
// (seed, stream, keys...), so results never depend on loop order, thread count or how work is split
// into windows. Key every decision by what it decides (cell coordinates, tile index, generation and
// pixel), never by how many numbers were drawn before it.
//
//   tessera::counter_rng rng(seed, tessera::stream_id("patch.distribute"));
//   auto patch = rng.below(num_patches, cell_x, cell_y);
#pragma once

#include <cstdint>
#include <string_view>
#include <type_traits>

#include "config.hpp"

TESSERA_NAMESPACE_BEGIN

/// SplitMix64 finalizer (Stafford variant 13): a bijective 64-bit mixer with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z ^= z >> 30;
  z *= 0xbf58476d1ce4e5b9ULL;
  z ^= z >> 27;
  z *= 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return z;
}

/// A stable 64-bit id for a stream name (FNV-1a, then mixed), computed at compile time.
constexpr std::uint64_t stream_id(std::string_view name) noexcept {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char ch : name) {
    h ^= static_cast<unsigned char>(ch);
    h *= 0x100000001b3ULL;
  }
  return mix64(h);
}

/// Hashes a seed and any number of integer or enum keys (signed keys are taken modulo 2^64, so -1
/// and 2^64 - 1 are the same key). The order of keys matters: (a, b) and (b, a) differ.
template <class... Keys>
constexpr std::uint64_t hash_keys(std::uint64_t seed, Keys... keys) noexcept {
  static_assert(((std::is_integral_v<Keys> || std::is_enum_v<Keys>)&&...),
                "random keys must be integers or enums (convert coordinates to integer cells first)");
  std::uint64_t h = mix64(seed ^ 0x6a09e667f3bcc909ULL);
  ((h = mix64(h ^ mix64(static_cast<std::uint64_t>(keys) + 0x9e3779b97f4a7c15ULL))), ...);
  return h;
}

/// Turns 64 random bits into a double in [0, 1) with 53 bits of precision.
constexpr double bits_to_unit(std::uint64_t bits) noexcept { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

/// Maps 64 random bits to [0, n) by a multiply-high (Lemire; bias below n / 2^64, no rejection loop
/// so the result stays a pure function of the bits). n must be > 0; n == 0 yields 0.
constexpr std::uint64_t bits_below(std::uint64_t bits, std::uint64_t n) noexcept {
  // high 64 bits of the 128-bit product bits * n, portably from 32-bit halves
  const std::uint64_t a_lo = bits & 0xffffffffULL, a_hi = bits >> 32;
  const std::uint64_t b_lo = n & 0xffffffffULL, b_hi = n >> 32;
  const std::uint64_t lo_lo = a_lo * b_lo, hi_lo = a_hi * b_lo, lo_hi = a_lo * b_hi, hi_hi = a_hi * b_hi;
  const std::uint64_t cross = (lo_lo >> 32) + (hi_lo & 0xffffffffULL) + lo_hi;
  return hi_hi + (hi_lo >> 32) + (cross >> 32);
}

/// A sequence of draws from one key, for decisions that need several numbers (draw i is
/// hash(base, i)). Models UniformRandomBitGenerator; prefer below()/uniform() over std::
/// distributions, whose output differs between standard libraries.
class random_sequence {
 public:
  /// 64-bit draws.
  using result_type = std::uint64_t;
  /// The sequence whose draws hash `base` with a counter.
  constexpr explicit random_sequence(std::uint64_t base) noexcept : base_(base) {}
  /// Smallest draw: 0.
  static constexpr result_type min() noexcept { return 0; }
  /// Largest draw: 2^64 - 1.
  static constexpr result_type max() noexcept { return ~result_type{0}; }
  constexpr result_type operator()() noexcept { return mix64(base_ ^ mix64(++counter_)); }
  constexpr double uniform() noexcept { return bits_to_unit((*this)()); }
  constexpr std::uint64_t below(std::uint64_t n) noexcept { return bits_below((*this)(), n); }

 private:
  std::uint64_t base_;
  std::uint64_t counter_ = 0;
};

/// Random values as pure functions of (seed, stream, keys...).
class counter_rng {
 public:
  /// A generator for this seed and stream (e.g. stream_id("name")).
  constexpr explicit counter_rng(std::uint64_t seed, std::uint64_t stream = 0) noexcept
      : base_(hash_keys(seed, stream)) {}

  /// 64 random bits for these keys.
  template <class... Keys>
  [[nodiscard]] constexpr std::uint64_t bits(Keys... keys) const noexcept {
    return hash_keys(base_, keys...);
  }
  /// A double in [0, 1).
  template <class... Keys>
  [[nodiscard]] constexpr double uniform(Keys... keys) const noexcept {
    return bits_to_unit(bits(keys...));
  }
  /// An integer in [0, n); n must be > 0.
  template <class... Keys>
  [[nodiscard]] constexpr std::uint64_t below(std::uint64_t n, Keys... keys) const noexcept {
    return bits_below(bits(keys...), n);
  }
  /// A sequence of draws keyed by these keys.
  template <class... Keys>
  [[nodiscard]] constexpr random_sequence sequence(Keys... keys) const noexcept {
    return random_sequence(bits(keys...));
  }
  /// An independent generator for a sub-stream.
  [[nodiscard]] constexpr counter_rng substream(std::uint64_t stream) const noexcept {
    return counter_rng(base_, stream);
  }

 private:
  std::uint64_t base_;
};

TESSERA_NAMESPACE_END
