// tessera/fabric/detail/number_theory.hpp: 64-bit modular arithmetic, 2x2 matrices mod N,
// deterministic Miller-Rabin and Pollard-rho factorization. Used by the cat map (matrix powers
// mod N) and by cat_map_period (orders of matrices mod prime powers). Internal: no stability promise.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

using u64 = std::uint64_t;

#if defined(__SIZEOF_INT128__)
__extension__ typedef unsigned __int128 fabric_u128;
/// (a * b) mod m without overflow, for any m > 0 (a, b < m).
inline u64 mulmod(u64 a, u64 b, u64 m) noexcept { return static_cast<u64>(static_cast<fabric_u128>(a) * b % m); }
#else
/// (a * b) mod m without overflow, for any m > 0 (a, b < m): double-and-add fallback.
inline u64 mulmod(u64 a, u64 b, u64 m) noexcept {
  if (m <= (u64{1} << 32)) return a * b % m;
  u64 r = 0;
  a %= m;
  while (b != 0) {
    if (b & 1) r = (r >= m - a) ? r - (m - a) : r + a;
    b >>= 1;
    a = (a >= m - a) ? a - (m - a) : a + a;
  }
  return r;
}
#endif

inline u64 addmod(u64 a, u64 b, u64 m) noexcept { return a >= m - b ? a - (m - b) : a + b; }

inline u64 powmod(u64 base, u64 e, u64 m) noexcept {
  u64 r = 1 % m;
  base %= m;
  while (e != 0) {
    if (e & 1) r = mulmod(r, base, m);
    base = mulmod(base, base, m);
    e >>= 1;
  }
  return r;
}

/// A 2x2 matrix with entries in [0, m): [[a, b], [c, d]].
struct mat2 {
  u64 a = 1, b = 0, c = 0, d = 1;
  friend bool operator==(const mat2&, const mat2&) = default;
};

inline mat2 mat_mul(const mat2& x, const mat2& y, u64 m) noexcept {
  return {addmod(mulmod(x.a, y.a, m), mulmod(x.b, y.c, m), m), addmod(mulmod(x.a, y.b, m), mulmod(x.b, y.d, m), m),
          addmod(mulmod(x.c, y.a, m), mulmod(x.d, y.c, m), m), addmod(mulmod(x.c, y.b, m), mulmod(x.d, y.d, m), m)};
}

inline mat2 mat_identity(u64 m) noexcept { return {1 % m, 0, 0, 1 % m}; }

/// x^e mod m by binary exponentiation: O(log e) matrix products.
inline mat2 mat_pow(mat2 x, u64 e, u64 m) noexcept {
  mat2 r = mat_identity(m);
  while (e != 0) {
    if (e & 1) r = mat_mul(r, x, m);
    x = mat_mul(x, x, m);
    e >>= 1;
  }
  return r;
}

/// Reduces a signed integer into [0, m).
inline u64 reduce_signed(std::int64_t v, u64 m) noexcept {
  if (v >= 0) return static_cast<u64>(v) % m;
  const u64 r = (u64{0} - static_cast<u64>(v)) % m;  // |v| mod m, safe for INT64_MIN
  return r == 0 ? 0 : m - r;
}

/// Deterministic Miller-Rabin for all 64-bit n (the first 12 primes are a proven witness set).
inline bool is_prime_u64(u64 n) noexcept {
  if (n < 2) return false;
  static constexpr std::array<u64, 12> small = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
  for (u64 p : small) {
    if (n % p == 0) return n == p;
  }
  u64 d = n - 1;
  int s = 0;
  while ((d & 1) == 0) {
    d >>= 1;
    ++s;
  }
  for (u64 a : small) {
    u64 x = powmod(a, d, n);
    if (x == 1 || x == n - 1) continue;
    bool composite = true;
    for (int r = 1; r < s; ++r) {
      x = mulmod(x, x, n);
      if (x == n - 1) {
        composite = false;
        break;
      }
    }
    if (composite) return false;
  }
  return true;
}

/// A non-trivial factor of the odd composite n (Brent's variant of Pollard's rho with batched gcds;
/// deterministic: the polynomial constants are tried in order 1, 2, 3, ...).
inline u64 pollard_rho(u64 n) noexcept {
  for (u64 c = 1;; ++c) {
    auto f = [&](u64 x) { return addmod(mulmod(x, x, n), c, n); };
    u64 y = 2, x = 2, g = 1, q = 1, ys = 2;
    const u64 batch = 128;
    for (u64 r = 1; g == 1; r <<= 1) {
      x = y;
      for (u64 i = 0; i < r; ++i) y = f(y);
      for (u64 k = 0; k < r && g == 1; k += batch) {
        ys = y;
        for (u64 i = 0; i < std::min(batch, r - k); ++i) {
          y = f(y);
          q = mulmod(q, x > y ? x - y : y - x, n);
        }
        g = std::gcd(q, n);
      }
    }
    if (g == n) {  // the batch overshot: step one at a time from its start
      do {
        ys = f(ys);
        g = std::gcd(x > ys ? x - ys : ys - x, n);
      } while (g == 1);
    }
    if (g != n) return g;
  }
}

/// A prime and its exponent.
struct prime_power {
  u64 p = 0;
  int k = 0;
};

inline void factor_into(u64 n, std::vector<u64>& primes) {
  if (n == 1) return;
  if (is_prime_u64(n)) {
    primes.push_back(n);
    return;
  }
  const u64 f = pollard_rho(n);
  factor_into(f, primes);
  factor_into(n / f, primes);
}

/// Prime factorization of n >= 1, primes ascending: trial division by primes below 1000, then
/// Miller-Rabin and Pollard's rho. Microseconds for any 64-bit n of practical size.
inline std::vector<prime_power> factorize(u64 n) {
  std::vector<u64> primes;
  for (u64 p = 2; p < 1000 && p * p <= n; p += (p == 2 ? 1 : 2)) {
    while (n % p == 0) {
      primes.push_back(p);
      n /= p;
    }
  }
  factor_into(n, primes);
  std::sort(primes.begin(), primes.end());
  std::vector<prime_power> out;
  for (u64 p : primes) {
    if (!out.empty() && out.back().p == p)
      ++out.back().k;
    else
      out.push_back({p, 1});
  }
  return out;
}

/// The inverse of a modulo m when gcd(a, m) = 1 (extended Euclid); 0 otherwise.
inline u64 invmod(u64 a, u64 m) noexcept {
  if (m == 1) return 0;
  std::int64_t t0 = 0, t1 = 1;
  u64 r0 = m, r1 = a % m;
  while (r1 != 0) {
    const u64 q = r0 / r1;
    const std::int64_t t2 = t0 - static_cast<std::int64_t>(q) * t1;
    t0 = t1;
    t1 = t2;
    const u64 r2 = r0 - q * r1;
    r0 = r1;
    r1 = r2;
  }
  if (r0 != 1) return 0;
  return reduce_signed(t0, m);
}

/// Legendre symbol (a / p) for an odd prime p: 1, -1, or 0 when p divides a.
inline int legendre(u64 a, u64 p) noexcept {
  a %= p;
  if (a == 0) return 0;
  return powmod(a, (p - 1) / 2, p) == 1 ? 1 : -1;
}

/// lcm(a, b), or 0 when it does not fit in 64 bits.
inline u64 lcm_checked(u64 a, u64 b) noexcept {
  const u64 g = std::gcd(a, b);
  const u64 q = a / g;
  if (q != 0 && b > ~u64{0} / q) return 0;
  return q * b;
}

}  // namespace detail
TESSERA_NAMESPACE_END
