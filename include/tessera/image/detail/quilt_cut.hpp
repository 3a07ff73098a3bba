// tessera/image/detail/quilt_cut.hpp: minimum-error boundary cuts of image quilting (Efros & Freeman
// 2001 §2.1: dynamic programming on the overlap error surface), used by detail/quilt_kernel.hpp.
// Internal.
//
// A patch window of p × p pixels may overlap known pixels on each of its four sides. For every side
// whose band holds known pixels one path is found: for each line b ∈ [0, p) along the side, the
// depth pos[b] of the first new pixel, consecutive depths differing by at most one. Where the west
// and north bands are both active the two paths form Efros & Freeman's L-shaped cut: they meet at
// the point of the corner square that minimizes their summed cost, and the corner region before the
// meeting point stays old. plan_cuts() computes the paths (tested against brute-force enumeration),
// cut_labels() turns them into new / old labels.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tile_coloring.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

enum class pixel_state : std::uint8_t { empty = 0, filled = 1, fixed = 2 };

/// A p × p window of the site: error surface and states (empty for pixels outside the canvas,
/// marked `outside`).
struct site_window {
  index_t p = 0;
  std::vector<double> error;  // (old − new)² summed over channels; 0 where not known
  std::vector<pixel_state> state;
  std::vector<std::uint8_t> outside;  // 1 where the window leaves a non-wrapping canvas
  [[nodiscard]] std::size_t idx(index_t i, index_t j) const noexcept { return to_size(j * p + i); }
};

inline constexpr double fixed_pixel_penalty = 1e9;

/// Window coordinates of depth a into the patch from `side` at position b along it.
struct window_xy {
  index_t i, j;
};
inline window_xy side_pixel(int side, index_t p, index_t a, index_t b) noexcept {
  switch (side) {
    case side_west: return {a, b};
    case side_north: return {b, a};
    case side_east: return {p - 1 - a, b};
    default: return {b, p - 1 - a};
  }
}

/// Cost of making pixel `x` (depth) the first new pixel of line b of `side`'s band of `width`: the
/// error there, plus fixed_pixel_penalty per fixed pixel at depth >= x (they would be new), or
/// infinity when an empty pixel lies before x (empty pixels must be new).
inline double cut_pixel_cost(const site_window& win, int side, index_t width, index_t x, index_t b) noexcept {
  const index_t p = win.p;
  double fixed_after = 0;
  for (index_t a = 0; a < width; ++a) {
    const window_xy q = side_pixel(side, p, a, b);
    const std::size_t k = win.idx(q.i, q.j);
    if (win.outside[k]) continue;
    if (a < x && win.state[k] == pixel_state::empty) return std::numeric_limits<double>::infinity();
    if (a >= x && win.state[k] == pixel_state::fixed) fixed_after += fixed_pixel_penalty;
  }
  const window_xy q = side_pixel(side, p, x, b);
  return win.error[win.idx(q.i, q.j)] + fixed_after;
}

/// DP of one side's cut over depths [0, width): cum[b · width + x] = cheapest cost of a path from
/// (b, x) to the far end b = p − 1 with |pos[b + 1] − pos[b]| <= 1 (Efros & Freeman's E_ij =
/// e_ij + min(E_{i−1, j−1}, E_{i−1, j}, E_{i−1, j+1}), run from the far end).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
void side_cut(const site_window& win, int side, index_t width, std::vector<double>& cum) {
  const index_t p = win.p, S = width;
  TESSERA_ASSERT(width >= 1 && width < p);
  cum.assign(to_size(p * S), std::numeric_limits<double>::infinity());
  for (index_t b = p - 1; b >= 0; --b)
    for (index_t x = 0; x < S; ++x) {
      double next = 0;
      if (b + 1 < p) {
        next = std::numeric_limits<double>::infinity();
        for (index_t d = -1; d <= 1; ++d)
          if (x + d >= 0 && x + d < S) next = std::min(next, cum[to_size((b + 1) * S + x + d)]);
      }
      cum[to_size(b * S + x)] = cut_pixel_cost(win, side, width, x, b) + next;
    }
}

/// Traces the cheapest path through `cum` starting at (b0, x0), towards b = p − 1; positions before
/// b0 are set to 0. Ties go to the smallest depth.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
void trace_cut(const std::vector<double>& cum, index_t p, index_t width, index_t b0, index_t x0,
               std::vector<index_t>& pos) {
  const index_t S = width;
  pos.assign(to_size(p), 0);
  index_t x = x0;
  pos[to_size(b0)] = x;
  for (index_t b = b0 + 1; b < p; ++b) {
    index_t best = x;
    double best_cost = std::numeric_limits<double>::infinity();
    for (index_t d = -1; d <= 1; ++d)
      if (x + d >= 0 && x + d < S && cum[to_size(b * S + x + d)] < best_cost) {
        best_cost = cum[to_size(b * S + x + d)];
        best = x + d;
      }
    x = best;
    pos[to_size(b)] = x;
  }
}

/// The cuts of one patch window.
struct cut_plan {
  index_t band[4] = {0, 0, 0, 0};                 ///< band width per side, clamped to [0, p − 1]
  bool active[4] = {false, false, false, false};  ///< the band holds a known pixel
  bool meet = false;                              ///< west and north both active: L-shaped cut
  index_t mx = 0, my = 0;                         ///< L-cut meeting point (window coordinates)
  std::vector<index_t> path[4];                   ///< per active side, the first new depth of each line
};

/// Finds the cut of every active side (see the header comment). `band_in` as in quilt_site.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
void plan_cuts(const site_window& win, const index_t band_in[4], cut_plan& plan) {
  const index_t p = win.p;
  for (int s = 0; s < 4; ++s) {
    plan.band[s] = std::clamp<index_t>(band_in[s], 0, p - 1);
    plan.active[s] = false;
    plan.path[s].clear();
    for (index_t a = 0; a < plan.band[s] && !plan.active[s]; ++a)
      for (index_t b = 0; b < p && !plan.active[s]; ++b) {
        const window_xy q = side_pixel(s, p, a, b);
        plan.active[s] = !win.outside[win.idx(q.i, q.j)] && win.state[win.idx(q.i, q.j)] != pixel_state::empty;
      }
  }
  std::vector<double> cum;
  auto cheapest_start = [&](index_t width) {
    index_t best = 0;
    for (index_t x = 1; x < width; ++x)
      if (cum[to_size(x)] < cum[to_size(best)]) best = x;
    return best;
  };
  plan.mx = plan.my = 0;
  plan.meet = plan.active[side_west] && plan.active[side_north];
  if (plan.meet) {
    // L-shaped overlap: the west path runs from the bottom and the north path from the right; they
    // meet at the point (mx, my) of the corner square minimizing their summed cost (the meeting
    // pixel counted once).
    std::vector<double> cum_w, cum_n;
    side_cut(win, side_west, plan.band[side_west], cum_w);
    side_cut(win, side_north, plan.band[side_north], cum_n);
    const index_t Sw = plan.band[side_west], Sn = plan.band[side_north];
    double best = std::numeric_limits<double>::infinity();
    for (index_t y = 0; y < Sn; ++y)
      for (index_t x = 0; x < Sw; ++x) {
        const double c = cum_w[to_size(y * Sw + x)] + cum_n[to_size(x * Sn + y)] - win.error[win.idx(x, y)];
        if (c < best) {
          best = c;
          plan.mx = x;
          plan.my = y;
        }
      }
    trace_cut(cum_w, p, Sw, plan.my, plan.mx, plan.path[side_west]);
    trace_cut(cum_n, p, Sn, plan.mx, plan.my, plan.path[side_north]);
  }
  for (int s = 0; s < 4; ++s) {
    if (!plan.active[s] || (plan.meet && (s == side_west || s == side_north))) continue;
    side_cut(win, s, plan.band[s], cum);
    trace_cut(cum, p, plan.band[s], 0, cheapest_start(plan.band[s]), plan.path[s]);
  }
}

/// Labels window pixels new (1) or old (0) from a plan: a pixel is new when it lies on the new side
/// of every active cut (for the L-cut: outside the corner region before the meeting point and past
/// both paths where they apply). Empty pixels are always new: they have nothing old to keep.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
void labels_from_plan(const site_window& win, const cut_plan& plan, std::vector<std::uint8_t>& is_new) {
  const index_t p = win.p;
  is_new.assign(to_size(p * p), 1);
  auto at = [](const std::vector<index_t>& v, index_t k) { return v[to_size(k)]; };
  for (index_t j = 0; j < p; ++j)
    for (index_t i = 0; i < p; ++i) {
      bool ok = true;
      if (plan.meet) {
        if (j < plan.my && i < plan.mx) ok = false;
        if (j >= plan.my) ok = ok && i >= at(plan.path[side_west], j);
        if (i >= plan.mx) ok = ok && j >= at(plan.path[side_north], i);
      } else {
        if (plan.active[side_west]) ok = ok && i >= at(plan.path[side_west], j);
        if (plan.active[side_north]) ok = ok && j >= at(plan.path[side_north], i);
      }
      if (plan.active[side_east]) ok = ok && p - 1 - i >= at(plan.path[side_east], j);
      if (plan.active[side_south]) ok = ok && p - 1 - j >= at(plan.path[side_south], i);
      const std::size_t k = win.idx(i, j);
      is_new[k] = ok || (!win.outside[k] && win.state[k] == pixel_state::empty);
    }
}

/// plan_cuts followed by labels_from_plan.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
void cut_labels(const site_window& win, const index_t band_in[4], std::vector<std::uint8_t>& is_new) {
  cut_plan plan;
  plan_cuts(win, band_in, plan);
  labels_from_plan(win, plan, is_new);
}

}  // namespace detail
TESSERA_NAMESPACE_END
