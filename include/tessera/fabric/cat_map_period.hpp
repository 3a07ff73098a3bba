// tessera/fabric/cat_map_period.hpp: the period of the cat map on an N x N image, from number theory.
//
// One step of Arnold's cat map (eq. 2 of paper 001) moves pixel (x, y) to A (x, y) mod N with
// A = [1 1; 1 2]; tessera also offers the family A = [1 a; b ab+1] (determinant 1, so still a
// permutation; a = b = 1 is the paper's map). The paper observes (§1.1, §2) that iterating returns to
// the original image and that the period depends on N. That period is the order of A in SL2(Z/N):
//
//   * factor N = p1^k1 ... pr^kr (trial division, then Miller-Rabin + Pollard's rho);
//   * mod an odd prime p, the characteristic polynomial x^2 - t x + 1 (t = ab + 2) has discriminant
//     D = t^2 - 4 (D = 5 for the paper's map). If D is a non-zero square mod p the eigenvalues lie in
//     F_p and the order divides p - 1; if D is a non-square they lie in F_{p^2} with norm 1 and the
//     order divides p + 1; if p | D (p = 5 for the paper's map) the eigenvalue is +-1, A = +-(I + nilpotent)
//     and the order divides 2p. The exact order is that bound with prime factors removed while
//     A^(bound / q) is still the identity. p = 2 is done by direct iteration (SL2(F_2) has order 6);
//   * lifting to p^k: the kernel of SL2(Z/p^k) -> SL2(Z/p) is a p-group, so the order mod p^k is
//     d p^j with j <= k - 1, found by raising A^d to the p-th power until it is the identity;
//   * the period is the lcm of the prime-power orders.
//
// For the paper's map this is half the Pisano period for N > 2 (N = 400 gives 300). Cost: microseconds
// for any N up to 10^12 and far beyond (N < 2^62 is accepted).
#pragma once

#include <array>
#include <cstdint>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "detail/number_theory.hpp"

TESSERA_NAMESPACE_BEGIN

/// The generalized cat map [1 a; b ab+1] (determinant 1). a = b = 1 is Arnold's map of paper 001.
/// Different (a, b) give different fabrics from one source image.
struct cat_map_family {
  /// Upper-right entry a.
  std::int64_t a = 1;
  /// Lower-left entry b.
  std::int64_t b = 1;
};

/// Largest N accepted by cat_map_period and cat_map_jump_matrix (2^62): keeps 2p and lcms in 64 bits.
inline constexpr std::int64_t max_cat_map_modulus = std::int64_t{1} << 62;

/// A 2x2 matrix mod N, row-major: (x, y) -> (m[0] x + m[1] y, m[2] x + m[3] y) mod N.
using cat_map_matrix = std::array<std::uint64_t, 4>;

namespace detail {
inline status check_cat_modulus(std::int64_t n, const char* what) {
  if (n <= 0 || n > max_cat_map_modulus)
    return status::invalid_argument(cat(what, ": the image side N must be in [1, 2^62], got ", n));
  return {};
}
inline mat2 family_matrix(const cat_map_family& f, u64 m) {
  const u64 a = reduce_signed(f.a, m), b = reduce_signed(f.b, m);
  return {1 % m, a, b, addmod(mulmod(a, b, m), 1 % m, m)};
}
/// Order of A in SL2(Z/p) for a prime p.
inline u64 order_mod_prime(const mat2& a_full, u64 p) {
  const mat2 a{a_full.a % p, a_full.b % p, a_full.c % p, a_full.d % p};
  const mat2 id = mat_identity(p);
  if (p == 2) {  // SL2(F_2) has 6 elements: iterate
    mat2 x = a;
    u64 k = 1;
    while (!(x == id)) {
      x = mat_mul(x, a, p);
      ++k;
    }
    return k;
  }
  const u64 t = addmod(a.a, a.d, p);
  const u64 disc = (mulmod(t, t, p) + p - (4 % p)) % p;
  const int chi = legendre(disc, p);
  u64 order = chi > 0 ? p - 1 : chi < 0 ? p + 1 : 2 * p;
  for (const prime_power& q : factorize(order)) {
    for (int i = 0; i < q.k && order % q.p == 0; ++i) {
      if (!(mat_pow(a, order / q.p, p) == id)) break;
      order /= q.p;
    }
  }
  return order;
}
}  // namespace detail

/// The matrix of n steps of the cat map family mod N: A^n for n >= 0 and (A^-1)^|n| for n < 0, by
/// binary exponentiation with 64-bit-safe modular products (eq. 3 of paper 001 applied n times).
/// Errors: invalid_argument when N is not in [1, 2^62]. Complexity O(log |n|). Thread-safe.
inline result<cat_map_matrix> cat_map_jump_matrix(std::int64_t n_side, std::int64_t steps,
                                                  const cat_map_family& family = {}) {
  if (auto s = detail::check_cat_modulus(n_side, "cat_map_jump_matrix"); !s) return s;
  const auto m = static_cast<detail::u64>(n_side);
  detail::mat2 a = detail::family_matrix(family, m);
  detail::u64 e = static_cast<detail::u64>(steps);
  if (steps < 0) {
    // inverse of [p q; r s] with determinant 1 is [s -q; -r p]
    a = {a.d, (m - a.b) % m, (m - a.c) % m, a.a};
    e = detail::u64{0} - static_cast<detail::u64>(steps);
  }
  const detail::mat2 r = detail::mat_pow(a, e, m);
  return cat_map_matrix{r.a, r.b, r.c, r.d};
}

/// The period of the cat map family on an N x N image: the smallest n > 0 such that n steps return
/// every image to itself (the order of [1 a; b ab+1] mod N), computed from the factorization of N as
/// described at the top of this header; N = 1 gives 1. Paper 001 §1.1 and §2 (periodicity).
/// Errors: invalid_argument when N is not in [1, 2^62]; size_overflow if the period does not fit in
/// 64 bits (not reachable for N <= 10^15). Complexity: dominated by factoring N and p +- 1 for each
/// prime p | N, microseconds for N <= 10^12. Thread-safe.
inline result<std::uint64_t> cat_map_period(std::int64_t n_side, const cat_map_family& family = {}) {
  if (auto s = detail::check_cat_modulus(n_side, "cat_map_period"); !s) return s;
  using detail::u64;
  const auto n = static_cast<u64>(n_side);
  u64 period = 1;
  for (const detail::prime_power& f : detail::factorize(n)) {
    u64 pk = 1;
    for (int i = 0; i < f.k; ++i) pk *= f.p;
    const detail::mat2 a = detail::family_matrix(family, pk);
    u64 order = detail::order_mod_prime(a, f.p);
    // lift: A^order is I mod p; raise to p until it is I mod p^k (at most k - 1 times)
    detail::mat2 x = detail::mat_pow(a, order, pk);
    const detail::mat2 id = detail::mat_identity(pk);
    while (!(x == id)) {
      x = detail::mat_pow(x, f.p, pk);
      order *= f.p;
    }
    period = detail::lcm_checked(period, order);
    if (period == 0)
      return status::size_overflow(detail::cat("cat_map_period: the period for N = ", n_side, " exceeds 2^64"));
  }
  return period;
}

TESSERA_NAMESPACE_END
