// tessera/fabric/detail/cat_map_kernels.hpp: the passes that apply a linear permutation
// p -> M p (mod N) to an N x N square of pixels. Internal: no stability promise.
//
// Every kernel is a gather, out(p') = in(G p') with G = M^-1, whose inner loop is incremental: along
// an output row the source coordinates advance by constants mod N (an add and a conditional
// subtract, no multiplication or division). Two strategies:
//
//   direct     one pass, out(x', y') = in(G (x', y')). Sources jump across the whole square, so it
//              is used when the square fits in cache (or when asked for).
//   separable  G factored into 2 (rarely 3) passes that each permute pixels inside one row or inside
//              one column:  row pass     out(x', y) = in(u x' + v y, y)
//                           column pass  out(x, y') = in(x, u y' + v x)     (u a unit mod N)
//              A row pass reads one row (L1-resident); a column pass works on strips of columns
//              four cache lines wide, staged into contiguous scratch that stays in L2. So a jump
//              costs about two streaming passes over memory whatever the matrix, instead of one
//              cache miss (and often a TLB miss) per pixel.
//
// Factorizations (det G = 1): with g11 a unit,  G = [1/g11 g01/g11; 0 1] [1 0; g10 g11]  (row
// pass, then column pass; preferred, measured 10-20 % faster at 4096^2); with g00 a unit,
// G = [1 0; g10/g00 1/g00] [g00 g01; 0 1]  (column, then row); otherwise G = [1 s; 0 1] G' with s
// chosen so that g'00 = g00 - s g10 is a unit (it exists because gcd(g00, g10, N) = 1) and G'
// factored as in the second case.
//
// All writes of one pass go to distinct pixels (a permutation), so rows or strips run in parallel
// and the output does not depend on the executor.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/image_view.hpp"
#include "number_theory.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// One row or column pass: kind, unit multiplier u and offset coefficient v (both in [0, N)).
struct cat_pass {
  bool rows = true;
  index_t u = 1;
  index_t v = 0;
};

/// The passes of the separable strategy for the gather matrix g (entries in [0, n)).
inline std::vector<cat_pass> plan_separable(const mat2& g, u64 n) {
  auto idx = [](u64 v) { return static_cast<index_t>(v); };
  std::vector<cat_pass> passes;
  mat2 h = g;
  if (std::gcd(g.d, n) == 1) {  // preferred: the row pass streams from the input, the column pass works in place
    const u64 inv = invmod(g.d, n);
    passes.push_back({true, idx(inv), idx(mulmod(g.b, inv, n))});
    passes.push_back({false, idx(g.d), idx(g.c)});
    return passes;
  }
  if (std::gcd(g.a, n) != 1) {
    u64 s = 1;
    while (std::gcd((g.a + n - mulmod(s, g.c, n)) % n, n) != 1) ++s;  // terminates: see header
    passes.push_back({true, 1, idx(s)});
    h = {(g.a + n - mulmod(s, g.c, n)) % n, (g.b + n - mulmod(s, g.d, n)) % n, g.c, g.d};
  }
  const u64 inv = invmod(h.a, n);
  passes.push_back({false, idx(inv), idx(mulmod(h.c, inv, n))});
  passes.push_back({true, idx(h.a), idx(h.b)});
  return passes;
}

template <class T, int C>
inline void copy_px(T* dst, const T* src) noexcept {
  std::memcpy(dst, src, sizeof(T) * C);
}

/// out(x', y') = in(G (x', y')): one pass, parallel over output rows.
template <class T, int C, class E>
void gather_direct(image_view<const T, C> src, image_view<T, C> dst, const mat2& g, E& exec) {
  const index_t n = src.width();
  const index_t ss = src.stride();
  const index_t step_x = static_cast<index_t>(g.a) * C, wrap_x = n * C;
  const index_t step_y = static_cast<index_t>(g.c) * ss, wrap_y = n * ss;
  const u64 un = static_cast<u64>(n);
  exec.parallel_for(0, n, [&](index_t y) {
    index_t ox = static_cast<index_t>(mulmod(g.b, static_cast<u64>(y), un)) * C;
    index_t oy = static_cast<index_t>(mulmod(g.d, static_cast<u64>(y), un)) * ss;
    const T* base = src.data();
    T* out = dst.row(y);
    for (index_t x = 0; x < n; ++x, out += C) {
      copy_px<T, C>(out, base + oy + ox);
      ox += step_x;
      ox -= ox >= wrap_x ? wrap_x : 0;
      oy += step_y;
      oy -= oy >= wrap_y ? wrap_y : 0;
    }
  });
}

/// Gathers one row: out[x'] = in[(u x' + v y) mod n], for x' in [0, n).
template <class T, int C>
inline void gather_row(const T* in, T* out, index_t n, index_t u, index_t start) noexcept {
  const index_t step = u * C, wrap = n * C;
  index_t o = start * C;
  for (index_t x = 0; x < n; ++x, out += C) {
    copy_px<T, C>(out, in + o);
    o += step;
    o -= o >= wrap ? wrap : 0;
  }
}

/// Row pass: dst(x', y) = src(u x' + v y, y). src may equal dst (then each row is staged in scratch).
template <class T, int C, class E>
void row_pass(const T* src, index_t src_stride, image_view<T, C> dst, const cat_pass& p, E& exec) {
  const index_t n = dst.width();
  const bool in_place = src == dst.data();
  constexpr index_t rows_per_task = 8;
  const index_t tasks = (n + rows_per_task - 1) / rows_per_task;
  exec.parallel_for(0, tasks, [&](index_t t) {
    std::vector<T> scratch(in_place ? to_size(n * C) : 0);
    const index_t y1 = std::min(n, (t + 1) * rows_per_task);
    for (index_t y = t * rows_per_task; y < y1; ++y) {
      const T* in = src + y * src_stride;
      if (in_place) {
        std::memcpy(scratch.data(), in, sizeof(T) * to_size(n * C));
        in = scratch.data();
      }
      const auto start = static_cast<index_t>(mulmod(static_cast<u64>(p.v), static_cast<u64>(y), static_cast<u64>(n)));
      gather_row<T, C>(in, dst.row(y), n, p.u, start);
    }
  });
}

/// Width of a column strip in bytes (four cache lines: measured best at 4096^2 on a 1 MiB L2).
inline constexpr index_t cat_strip_bytes = 256;

/// Column pass: dst(x, y') = src(x, u y' + v x), by strips of columns cat_strip_bytes wide.
/// Each strip is first staged into contiguous scratch (its N rows then share few pages, so the
/// random row accesses hit L2 instead of missing the TLB); src may therefore equal dst.
template <class T, int C, class E>
void column_pass(const T* src, index_t src_stride, image_view<T, C> dst, const cat_pass& p, E& exec) {
  const index_t n = dst.width();
  constexpr index_t strip = std::max<index_t>(1, cat_strip_bytes / static_cast<index_t>(sizeof(T) * C));
  const index_t strips = (n + strip - 1) / strip;
  const u64 un = static_cast<u64>(n);
  exec.parallel_for(0, strips, [&](index_t s) {
    const index_t x0 = s * strip, w = std::min(strip, n - x0);
    std::vector<T> scratch(to_size(n * w * C));
    const index_t row_bytes = static_cast<index_t>(sizeof(T)) * w * C;
    for (index_t y = 0; y < n; ++y)
      std::memcpy(scratch.data() + y * w * C, src + y * src_stride + x0 * C, to_size(row_bytes));
    const T* in = scratch.data();
    const index_t in_stride = w * C;
    index_t off[strip];  // offset of the source row of each column
    for (index_t j = 0; j < w; ++j)
      off[j] = static_cast<index_t>(mulmod(static_cast<u64>(p.v), static_cast<u64>(x0 + j), un)) * in_stride;
    const index_t step = p.u * in_stride, wrap = n * in_stride;
    for (index_t y = 0; y < n; ++y) {
      T* out = dst.row(y) + x0 * C;
      for (index_t j = 0; j < w; ++j) {
        copy_px<T, C>(out + j * C, in + off[j] + j * C);
        off[j] += step;
        off[j] -= off[j] >= wrap ? wrap : 0;
      }
    }
  });
}

/// Applies the gather matrix g to the square src -> dst (distinct memory), choosing the strategy.
/// `direct_bytes`: squares of at most this many bytes use the direct pass (0 forces separable,
/// a negative value forces direct).
template <class T, int C, class E>
void apply_gather(image_view<const T, C> src, image_view<T, C> dst, const mat2& g, index_t direct_bytes, E& exec) {
  const index_t n = src.width();
  const u64 un = static_cast<u64>(n);
  const index_t bytes = n * n * C * static_cast<index_t>(sizeof(T));
  if (n <= 2 || direct_bytes < 0 || bytes <= direct_bytes) {
    gather_direct<T, C>(src, dst, g, exec);
    return;
  }
  const std::vector<cat_pass> passes = plan_separable(g, un);
  const T* from = src.data();
  index_t from_stride = src.stride();
  for (const cat_pass& p : passes) {
    if (p.rows)
      row_pass<T, C>(from, from_stride, dst, p, exec);
    else
      column_pass<T, C>(from, from_stride, dst, p, exec);
    from = dst.data();
    from_stride = dst.stride();
  }
}

/// One forward step of the family [1 a; b ab+1] as the paper iterates it (eq. 3 of paper 001):
/// every source pixel (x, y) is moved to (x + a y, b x + (ab+1) y) mod N. Parallel over source rows;
/// along a row the target advances by (1, b) mod N.
template <class T, int C, class E>
void scatter_step(image_view<const T, C> src, image_view<T, C> dst, u64 a, u64 b, E& exec) {
  const index_t n = src.width();
  const u64 un = static_cast<u64>(n);
  const u64 d = addmod(mulmod(a, b, un), 1 % un, un);
  exec.parallel_for(0, n, [&](index_t y) {
    index_t tx = static_cast<index_t>(mulmod(a, static_cast<u64>(y), un));
    index_t ty = static_cast<index_t>(mulmod(d, static_cast<u64>(y), un));
    const index_t db = static_cast<index_t>(b);
    const T* in = src.row(y);
    for (index_t x = 0; x < n; ++x, in += C) {
      copy_px<T, C>(dst.pixel_ptr(tx, ty), in);
      tx = tx + 1 == n ? 0 : tx + 1;
      ty += db;
      ty -= ty >= n ? n : 0;
    }
  });
}

}  // namespace detail
TESSERA_NAMESPACE_END
