#include <tessera/fabric/cat_map_period.hpp>

#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

using tessera::cat_map_family;
using tessera::cat_map_period;
namespace td = tessera::detail;

namespace {
// Order of [1 a; b ab+1] mod n by multiplying until the identity: the brute-force oracle.
std::uint64_t brute_order(std::int64_t n, cat_map_family f) {
  const auto m = static_cast<std::uint64_t>(n);
  const td::mat2 a = td::family_matrix(f, m), id = td::mat_identity(m);
  td::mat2 x = a;
  std::uint64_t k = 1;
  while (!(x == id)) {
    x = td::mat_mul(x, a, m);
    ++k;
  }
  return k;
}
td::mat2 jump(std::int64_t n, std::int64_t steps, cat_map_family f = {}) {
  const auto m = *tessera::cat_map_jump_matrix(n, steps, f);
  return {m[0], m[1], m[2], m[3]};
}
// A^p = I and A^(p/q) != I for every prime q | p: p is exactly the order.
void require_exact_order(std::int64_t n, std::uint64_t p, cat_map_family f = {}) {
  const td::mat2 id = td::mat_identity(static_cast<std::uint64_t>(n));
  REQUIRE(jump(n, static_cast<std::int64_t>(p), f) == id);
  for (const auto& q : td::factorize(p)) REQUIRE_FALSE(jump(n, static_cast<std::int64_t>(p / q.p), f) == id);
}
}  // namespace

TEST_CASE("cat_map_period equals the brute-force order for every N <= 2000", "[cat_map_period]") {
  for (std::int64_t n = 1; n <= 2000; ++n) {
    const auto p = cat_map_period(n);
    REQUIRE(p.ok());
    INFO("N = " << n);
    REQUIRE(*p == brute_order(n, {}));
  }
}

TEST_CASE("cat_map_period of the generalized family [1 a, b ab+1] equals brute force", "[cat_map_period]") {
  for (std::int64_t a : {-3, 0, 2, 3, 7})
    for (std::int64_t b : {-1, 1, 2, 5})
      for (std::int64_t n = 1; n <= 300; ++n) {
        INFO("a = " << a << ", b = " << b << ", N = " << n);
        REQUIRE(*cat_map_period(n, {a, b}) == brute_order(n, {a, b}));
      }
}

TEST_CASE("cat_map_period: known values", "[cat_map_period]") {
  CHECK(*cat_map_period(1) == 1);
  CHECK(*cat_map_period(2) == 3);
  CHECK(*cat_map_period(5) == 10);     // p = 5 divides the discriminant 5
  CHECK(*cat_map_period(400) == 300);  // the paper's 400 x 400 images
  CHECK(*cat_map_period(4096) == 3072);
  // half the Pisano period for N > 2: pi(10) = 60, pi(100) = 300
  CHECK(*cat_map_period(10) == 30);
  CHECK(*cat_map_period(100) == 150);
}

TEST_CASE("cat_map_period is exact for large N up to 10^12 and beyond", "[cat_map_period]") {
  const std::vector<std::int64_t> ns = {
      1000000000000LL,      // 2^12 5^12
      999999999989LL,       // prime, 5 a non-residue or residue
      999983LL * 999979LL,  // two primes near 10^6
      1099511627776LL,      // 2^40
      762939453125LL,       // 5^17
      999961LL * 999961LL,  // a prime squared
      600851475143LL,       // 71 839 1471 6857
      123456789012LL,
      4611686018427387847LL,  // 2^62 - 57, near the limit
  };
  for (std::int64_t n : ns) {
    INFO("N = " << n);
    const auto p = cat_map_period(n);
    REQUIRE(p.ok());
    require_exact_order(n, *p);
  }
  require_exact_order(999999999989LL, *cat_map_period(999999999989LL, {3, 4}), {3, 4});
}

TEST_CASE("cat_map_jump_matrix: powers, inverses and the paper's matrix", "[cat_map_period]") {
  const auto one = *tessera::cat_map_jump_matrix(400, 1);
  CHECK(one == tessera::cat_map_matrix{1, 1, 1, 2});
  CHECK(*tessera::cat_map_jump_matrix(400, 0) == tessera::cat_map_matrix{1, 0, 0, 1});
  for (std::int64_t n : {7, 400, 1000003}) {
    const auto m = static_cast<std::uint64_t>(n);
    for (std::int64_t s : std::vector<std::int64_t>{1, 5, 31, 60, 1000, INT64_MAX, INT64_MIN + 1}) {
      CHECK(td::mat_mul(jump(n, s), jump(n, -s), m) == td::mat_identity(m));
      if (s != INT64_MAX) CHECK(td::mat_mul(jump(n, s), jump(n, 1), m) == jump(n, s + 1));
    }
    CHECK(td::mat_mul(jump(n, INT64_MIN), jump(n, INT64_MAX), m) == jump(n, -1));
  }
}

TEST_CASE("cat_map_period and cat_map_jump_matrix reject bad N", "[cat_map_period]") {
  for (std::int64_t n : {std::int64_t{0}, std::int64_t{-5}, (std::int64_t{1} << 62) + 1, INT64_MAX}) {
    const auto p = cat_map_period(n);
    REQUIRE_FALSE(p.ok());
    CHECK(p.error().code() == tessera::status_code::invalid_argument);
    CHECK(p.error().message().find(std::to_string(n)) != std::string::npos);
    CHECK_FALSE(tessera::cat_map_jump_matrix(n, 3).ok());
  }
}
