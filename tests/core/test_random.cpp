#include <tessera/core/executor.hpp>
#include <tessera/core/random.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include <catch2/catch.hpp>

using tessera::counter_rng;
using tessera::index_t;

namespace {
__extension__ typedef unsigned __int128 uint128;  // GCC/Clang extension, for the oracle only
enum class decision { place = 1, rotate = 2 };
// Chi-square statistic of `samples` draws of below(n) keyed by the sample index.
double chi_square(const counter_rng& rng, std::uint64_t n, int samples) {
  std::vector<int> count(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < samples; ++i) ++count[static_cast<std::size_t>(rng.below(n, i))];
  const double expected = double(samples) / double(n);
  double chi = 0;
  for (int c : count) chi += (c - expected) * (c - expected) / expected;
  return chi;
}
}  // namespace

static_assert(tessera::stream_id("a") != tessera::stream_id("b"));
static_assert(counter_rng(1).bits(5) == counter_rng(1).bits(5));  // usable at compile time
static_assert(std::uniform_random_bit_generator<tessera::random_sequence>);

TEST_CASE("random: SplitMix64 finalizer matches the reference", "[random]") {
  // first output of the reference splitmix64 generator seeded with 0
  REQUIRE(tessera::mix64(0x9e3779b97f4a7c15ULL) == 0xe220a8397b1dcdafULL);
  REQUIRE(tessera::mix64(0) == 0);
}

TEST_CASE("random: values are fixed functions of (seed, stream, keys)", "[random]") {
  // Pinned values: changing them changes every algorithm's output for a given seed.
  const counter_rng rng(42, tessera::stream_id("test.stream"));
  REQUIRE(tessera::stream_id("test.stream") == 0x3c5b12c3cf6011d8ULL);
  REQUIRE(rng.bits() == 0x4d8d02df4d384900ULL);
  REQUIRE(rng.bits(7) == 0xaa2f2c9ef6967816ULL);
  REQUIRE(rng.bits(3, -4) == 0x89c1023d84a36db6ULL);
  REQUIRE(rng.below(1000, 1, 2, 3) == 255);
  REQUIRE(rng.uniform(5) == 0.22686291993981367);
  auto seq = rng.sequence(9);
  REQUIRE(seq() == 0xbccf03f061115b51ULL);
  REQUIRE(seq() == 0x5b5239951e542d2aULL);
  REQUIRE(rng.substream(2).bits(1) == 0x1e18153d3a5d0e43ULL);
}

TEST_CASE("random: independent of call order and thread count", "[random]") {
  const counter_rng rng(7, tessera::stream_id("order"));
  const index_t n = 5000;
  std::vector<std::uint64_t> forward(static_cast<std::size_t>(n)), backward(forward.size()), pooled(forward.size());
  for (index_t i = 0; i < n; ++i) forward[static_cast<std::size_t>(i)] = rng.bits(i, i % 7);
  for (index_t i = n; i-- > 0;) backward[static_cast<std::size_t>(i)] = rng.bits(i, i % 7);
  tessera::thread_pool_executor pool(3);
  pool.parallel_for(0, n, [&](index_t i) { pooled[static_cast<std::size_t>(i)] = rng.bits(i, i % 7); });
  REQUIRE(forward == backward);
  REQUIRE(forward == pooled);
  // drawing other values in between changes nothing
  (void)rng.bits(123);
  REQUIRE(rng.bits(0, 0) == forward[0]);
}

TEST_CASE("random: seeds, streams, keys and key order all matter", "[random]") {
  std::set<std::uint64_t> values;
  for (std::uint64_t seed = 0; seed < 4; ++seed)
    for (std::uint64_t stream = 0; stream < 4; ++stream)
      for (int k = 0; k < 4; ++k) values.insert(counter_rng(seed, stream).bits(k));
  REQUIRE(values.size() == 64);
  const counter_rng rng(1);
  REQUIRE(rng.bits(1, 2) != rng.bits(2, 1));
  REQUIRE(rng.bits(1) != rng.bits(1, 0));
  REQUIRE(rng.bits() != rng.bits(0));
  REQUIRE(rng.substream(3).bits(1) != rng.bits(1));
  REQUIRE(rng.substream(3).bits(1) == counter_rng(1).substream(3).bits(1));
  // signed keys are taken modulo 2^64; enums by value
  REQUIRE(rng.bits(-1) == rng.bits(std::numeric_limits<std::uint64_t>::max()));
  REQUIRE(rng.bits(std::int8_t{5}) == rng.bits(std::uint64_t{5}));
  REQUIRE(rng.bits(decision::rotate) == rng.bits(2));
  REQUIRE(rng.bits(decision::place) != rng.bits(decision::rotate));
}

TEST_CASE("random: uniform lies in 0 <= u < 1 and is roughly uniform", "[random]") {
  REQUIRE(tessera::bits_to_unit(0) == 0.0);
  REQUIRE(tessera::bits_to_unit(~std::uint64_t{0}) < 1.0);
  const counter_rng rng(3, tessera::stream_id("uniform"));
  double lo = 1, hi = 0, sum = 0;
  std::vector<int> bins(10, 0);
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform(i);
    lo = std::min(lo, u);
    hi = std::max(hi, u);
    sum += u;
    ++bins[static_cast<std::size_t>(u * 10)];
  }
  REQUIRE(lo >= 0.0);
  REQUIRE(hi < 1.0);
  REQUIRE(sum / n == Approx(0.5).margin(0.005));
  double chi = 0;
  for (int b : bins) chi += (b - n / 10.0) * (b - n / 10.0) / (n / 10.0);
  REQUIRE(chi < 27.88);  // chi-square, 9 degrees of freedom, p = 0.001
}

TEST_CASE("random: below(n) is in range and passes a chi-square test", "[random]") {
  const counter_rng rng(11, tessera::stream_id("below"));
  for (int i = 0; i < 10000; ++i) {
    REQUIRE(rng.below(1, i) == 0);
    REQUIRE(rng.below(3, i) < 3);
    REQUIRE(rng.below(std::numeric_limits<std::uint64_t>::max(), i) < std::numeric_limits<std::uint64_t>::max());
  }
  // critical values at p = 0.001: df 1 -> 10.83, df 6 -> 22.46, df 9 -> 27.88, df 99 -> 148.2, df 999 -> 1143
  REQUIRE(chi_square(rng, 2, 20000) < 10.83);
  REQUIRE(chi_square(rng.substream(1), 7, 70000) < 22.46);
  REQUIRE(chi_square(rng.substream(2), 10, 100000) < 27.88);
  REQUIRE(chi_square(rng.substream(3), 100, 100000) < 148.2);
  REQUIRE(chi_square(rng.substream(4), 1000, 200000) < 1143.0);
}

TEST_CASE("random: bits_below equals the 128-bit multiply-high", "[random]") {
  tessera::random_sequence seq(99);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t bits = seq(), n = (i % 3 == 0) ? seq() : seq() >> (i % 64);
    const auto expected = static_cast<std::uint64_t>((static_cast<uint128>(bits) * n) >> 64);
    REQUIRE(tessera::bits_below(bits, n) == expected);
  }
  REQUIRE(tessera::bits_below(~std::uint64_t{0}, ~std::uint64_t{0}) == ~std::uint64_t{0} - 1);
  REQUIRE(tessera::bits_below(12345, 0) == 0);
}

TEST_CASE("random: sequences draw distinct values and work with std algorithms", "[random]") {
  auto a = counter_rng(5).sequence(1, 2);
  auto b = counter_rng(5).sequence(1, 2);
  std::set<std::uint64_t> seen;
  for (int i = 0; i < 1000; ++i) {
    const auto v = a();
    REQUIRE(v == b());
    seen.insert(v);
  }
  REQUIRE(seen.size() == 1000);
  for (int i = 0; i < 1000; ++i) {
    const double u = a.uniform();
    REQUIRE((u >= 0 && u < 1));
    REQUIRE(a.below(6) < 6);
  }
  std::vector<int> v(20);
  std::iota(v.begin(), v.end(), 0);
  std::vector<int> w = v;
  auto s1 = counter_rng(8).sequence(0);
  auto s2 = counter_rng(8).sequence(0);
  std::shuffle(v.begin(), v.end(), s1);
  std::shuffle(w.begin(), w.end(), s2);
  REQUIRE(v == w);  // same library, same keys, same permutation
}
