// tessera/image/detail/patch_plan.hpp: the per-cell decisions of patch synthesis (paper 002 §2):
// which patch every cell of a window holds (checkerboard distribution, then filling by compatible-set
// intersection) and, for seam cuts, which seam joins every pair of neighbours. Internal.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/random.hpp"
#include "../patch_model.hpp"
#include "patch_model_kernels.hpp"
#include "patch_model_sets.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// floor(a / b) for b > 0.
constexpr index_t floor_div(index_t a, index_t b) noexcept {
  const index_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

/// Counts a synthesis call reports.
struct plan_counts {
  index_t cells = 0, placed = 0, filled = 0, empty_intersections = 0, computed_seams = 0, phase_group = 0;
  index_t evaluated = 0;         ///< overlap errors computed by exact fallbacks (sides outside the sets)
  double fill_error = 0;         ///< summed overlap error (SSD, channel units) of the filled cells, all four sides
  index_t fill_error_known = 0;  ///< filled cells whose four side errors are all known (so in fill_error)
};

/// How fill_cell picks a patch when the four compatible sets have no common member.
struct fill_policy {
  bool exact = false;      ///< true: smallest true overlap error against all four neighbours
  bool estimated = false;  ///< (when not exact) smallest overlap error, the errors the sets miss estimated from
                           ///< the strips' PCA descriptors; both false: the paper's "present in the most sets"
  int budget = 8;          ///< exact: at most this many candidates get their missing errors computed
};

/// The decisions for a window [ox, ox + w) x [oy, oy + h) of the infinite texture. Cell (i, j) holds a
/// patch whose top-left pixel lands on (i pw, j ph); cells [ci0, ci0 + ncx) x [cj0, cj0 + ncy) touch
/// the window (including the left and top neighbours that overlap it).
struct patch_plan {
  index_t pw = 0, ph = 0, v = 0;
  index_t ox = 0, oy = 0, w = 0, h = 0;
  index_t ci0 = 0, cj0 = 0, ncx = 0, ncy = 0;
  std::vector<index_t> sx, sy;  ///< per cell (row-major): exemplar origin of its patch
  index_t band = 0;             ///< feathering: width of the blend band centred in each overlap (1 to v)
  bool cut = false;
  std::vector<const std::uint8_t*> vseam;  ///< per cell: cut against the west neighbour (ph + v entries) or null
  std::vector<const std::uint8_t*> hseam;  ///< per cell: cut against the north neighbour (pw + v entries) or null
  std::vector<std::uint8_t> own_seams;     ///< seams computed for this plan (pairs outside the compatible sets)
  plan_counts counts;
  [[nodiscard]] index_t cell(index_t ci, index_t cj) const noexcept { return cj * ncx + ci; }
};

/// The patches placed on the checkerboard, the phase group (paper §2 and Fig. 2: "only patches of near
/// phases"): around a phase drawn from the seed (among the phases holding patches), either the phases
/// within Chebyshev distance `radius` (modulo the pitch; a radius of max(pw, ph) or more takes every
/// phase, so larger radii are clamped to it), or (radius < 0) the phases in order of appearance
/// similarity to it (the model's phase_similarity(): for a texture that repeats, phases a period apart
/// look alike) - all phases at least `equivalent` similar, then more until the group holds `min_size`
/// patches. Never empty: the centre phase holds a patch.
template <Channel T, int C>
std::vector<std::uint32_t> phase_group(const patch_model<T, C>& m, std::uint64_t seed, index_t radius, index_t min_size,
                                       double equivalent = 0.9) {
  const index_t pw = m.patch_width(), ph = m.patch_height();
  std::vector<index_t> nonempty;
  for (index_t p = 0; p < m.num_phases(); ++p)
    if (!m.phase_patches(p).empty()) nonempty.push_back(p);
  const counter_rng rng(seed, stream_id("patch.phase"));
  const index_t center = nonempty[to_size(rng.below(nonempty.size()))];
  const index_t cx = center % pw, cy = center / pw;
  std::vector<std::uint32_t> group;
  auto add = [&](index_t dx, index_t dy) {
    const index_t px = ((cx + dx) % pw + pw) % pw, py = ((cy + dy) % ph + ph) % ph;
    for (std::uint32_t p : m.phase_patches(py * pw + px)) group.push_back(p);
  };
  if (radius >= 0) {
    radius = std::min(radius, std::max(pw, ph));  // no overflow in 2 radius + 1 below
    const index_t nxp = std::min(2 * radius + 1, pw), nyp = std::min(2 * radius + 1, ph);
    for (index_t dy = 0; dy < nyp; ++dy)
      for (index_t dx = 0; dx < nxp; ++dx) add(dx - radius, dy - radius);
    return group;
  }
  for (const phase_offset& o : m.phase_similarity()) {
    if (o.similarity < equivalent && static_cast<index_t>(group.size()) >= min_size) break;
    add(o.dx, o.dy);
  }
  return group;
}

/// What fill_cell decided.
struct fill_result {
  std::uint32_t patch = 0;
  bool empty = false;     ///< the four sets had no common member (a fallback chose)
  bool known = false;     ///< `error` is the exact total overlap error against the four neighbours
  index_t evaluated = 0;  ///< strip errors computed
  double error = 0;       ///< total overlap error (exact when `known`, else the estimate)
};

/// Fills a vacant cell from its four placed neighbours (paper 002 §2): a random member of the
/// intersection of their compatible sets facing the cell (sorted small vectors), keyed by (seed, i, j).
/// When the intersection is empty:
///  - policy.exact (fill_fallback::overlap_error): among the union of the four sets, the patch with the smallest
///    **true** overlap error summed over its four neighbours. Errors the sets hold are exact; the others
///    are computed from the exemplar (strip_error), candidates taken in order of their lower bound (the
///    known errors plus each missing set's k-th error, a lower bound when the sets are the exact top k;
///    ties by index), stopping when the next lower bound exceeds the best total or after
///    `policy.budget` candidates; equal totals go to the smaller index. With exact sets and a budget of
///    at least the union's size this is the exact minimum over the union (tests check it by brute force);
///  - policy.estimated (fill_fallback::estimated_error): the same minimum over the union, every error the
///    sets miss estimated from the two strips' descriptors (patch_model::estimated_error) instead of
///    computed; equal totals go to the smaller index;
///  - otherwise the paper's rule: the patch appearing in the most sets; ties go to the smallest
///    lower bound above, then the smallest index.
template <Channel T, int C>
fill_result fill_cell(const patch_model<T, C>& m, std::uint32_t west, std::uint32_t east, std::uint32_t north,
                      std::uint32_t south, const counter_rng& rng, index_t i, index_t j,
                      const fill_policy& policy = {}) {
  // a 4-way merge of the sets ordered by patch index, branch-free: copies end with a sentinel
  const std::uint32_t owners[4] = {west, east, north, south};
  constexpr int facing[4] = {side_east, side_west, side_south, side_north};
  const index_t k = m.candidates();
  constexpr std::uint32_t none = ~std::uint32_t{0};
  std::uint32_t ids[4][65];
  float errs[4][65];
  float worst[4];
  for (int s = 0; s < 4; ++s) {
    const auto set = m.compatible_by_index(owners[s], facing[s]);
    for (index_t r = 0; r < k; ++r) {
      ids[s][r] = set[to_size(r)].patch;
      errs[s][r] = set[to_size(r)].error;
    }
    ids[s][k] = none;
    errs[s][k] = 0;
    worst[s] = m.kth_error(owners[s], facing[s]);
  }
  struct member {
    double bound;  // known errors + k-th error of each set not holding it
    double known;  // the known errors alone
    std::uint32_t patch;
    unsigned mask;  // bit s: set s holds it
  };
  member uni[4 * 64];
  std::uint32_t inter[64];
  double inter_error[64];
  index_t ni = 0, nu = 0, head[4] = {0, 0, 0, 0};
  std::uint32_t best = ids[0][0];
  int best_count = 0;
  double best_error = 0;
  for (;;) {
    const std::uint32_t p =
        std::min(std::min(ids[0][head[0]], ids[1][head[1]]), std::min(ids[2][head[2]], ids[3][head[3]]));
    if (p == none) break;
    int count = 0;
    unsigned mask = 0;
    double error = 0, known = 0;  // summed over the sets in order west, east, north, south
    for (int s = 0; s < 4; ++s) {
      const bool hit = ids[s][head[s]] == p;
      const double e = static_cast<double>(hit ? errs[s][head[s]] : worst[s]);
      error += e;
      known += hit ? e : 0.0;
      count += hit;
      mask |= hit ? 1u << s : 0u;
      head[s] += hit;
    }
    uni[nu++] = {error, known, p, mask};
    inter[ni] = p;
    inter_error[ni] = error;
    ni += count == 4;
    const bool better = count > best_count || (count == best_count && error < best_error);
    best = better ? p : best;
    best_count = better ? count : best_count;
    best_error = better ? error : best_error;
  }
  if (ni > 0) {
    const auto r = to_size(rng.below(static_cast<std::uint64_t>(ni), i, j));
    return {inter[r], false, true, 0, inter_error[r]};
  }
  if (policy.estimated && !policy.exact) {
    // known errors plus, for each set missing the candidate, the descriptor estimate of its error
    const float* own[4];
    for (int s = 0; s < 4; ++s) own[s] = m.strip_descriptor(owners[s], facing[s]);
    fill_result out{uni[0].patch, true, false, 0, std::numeric_limits<double>::infinity()};
    for (index_t c = 0; c < nu; ++c) {
      const member& u = uni[c];
      double total = u.known;
      for (int s = 0; s < 4; ++s)
        if ((u.mask & (1u << s)) == 0)
          total += m.descriptor_distance(own[s], m.strip_descriptor(u.patch, (facing[s] + 2) % 4), facing[s]);
      if (total < out.error) {  // union in index order: equal totals keep the smaller index
        out.error = total;
        out.patch = u.patch;
      }
    }
    return out;
  }
  if (!policy.exact) return {best, true, false, 0, best_error};

  // exact fallback: branch and bound over the union, by lower bound
  std::sort(uni, uni + nu, [](const member& a, const member& b) {
    return a.bound < b.bound || (a.bound == b.bound && a.patch < b.patch);
  });
  const patch_geometry g{m.patch_width(), m.patch_height(), m.overlap(), m.patches_x(), m.patches_y()};
  fill_result out{uni[0].patch, true, false, 0, uni[0].bound};
  double best_total = std::numeric_limits<double>::infinity();
  for (index_t c = 0; c < nu && c < policy.budget; ++c) {
    const member& u = uni[c];
    if (u.bound > best_total) break;  // no later candidate can do better (bounds ascend)
    double total = u.known;
    for (int s = 0; s < 4 && total <= best_total; ++s) {
      if (u.mask & (1u << s)) continue;
      // the candidate sits on side facing[s]'s opposite of owner s: east of the west owner, etc.
      total += strip_error(m.exemplar(), g, owners[s], u.patch, facing[s], best_total - total);
      ++out.evaluated;
    }
    if (total < best_total || (total == best_total && u.patch < out.patch)) {
      best_total = total;
      out.patch = u.patch;
      out.known = true;
      out.error = total;
    }
  }
  return out;
}

/// Decides every cell of the window: placed cells ((i + j) even) from the phase group, vacant cells
/// by fill_cell, then (cut mode) the seam of every neighbouring pair inside the plan: the model's
/// precomputed seam when the pair is in a compatible set, else one computed here.
template <Channel T, int C, class Ex>
patch_plan make_plan(const patch_model<T, C>& m, index_t ox, index_t oy, index_t w, index_t h, std::uint64_t seed,
                     bool cut, index_t radius, index_t min_group, Ex&& exec, const fill_policy& policy = {}) {
  patch_plan p;
  p.pw = m.patch_width();
  p.ph = m.patch_height();
  p.v = m.overlap();
  p.ox = ox;
  p.oy = oy;
  p.w = w;
  p.h = h;
  p.ci0 = floor_div(ox, p.pw) - 1;
  p.cj0 = floor_div(oy, p.ph) - 1;
  p.ncx = floor_div(ox + w - 1, p.pw) - p.ci0 + 1;
  p.ncy = floor_div(oy + h - 1, p.ph) - p.cj0 + 1;
  p.cut = cut;
  p.band = p.v;
  const index_t ncells = p.ncx * p.ncy;
  const std::vector<std::uint32_t> group = phase_group(m, seed, radius, min_group);
  TESSERA_ASSERT(!group.empty());
  const counter_rng place_rng(seed, stream_id("patch.place")), fill_rng(seed, stream_id("patch.fill"));
  // distributed cells first, on a grid one cell wider on every side (the vacant cells' neighbours)
  const index_t gx = p.ncx + 2, gy = p.ncy + 2;
  std::vector<std::uint32_t> grid(to_size(gx * gy));
  exec.parallel_for(0, gy, [&](index_t row) {
    const index_t j = p.cj0 - 1 + row;
    for (index_t col = (p.ci0 - 1 + j) & 1; col < gx; col += 2)  // (i + j) even
      grid[to_size(row * gx + col)] = group[to_size(place_rng.below(group.size(), p.ci0 - 1 + col, j))];
  });
  std::vector<std::uint32_t> patch(to_size(ncells));
  std::vector<index_t> empty_count(to_size(p.ncy), 0), evaluated(to_size(p.ncy), 0), known(to_size(p.ncy), 0);
  std::vector<double> fill_error(to_size(p.ncy), 0.0);
  exec.parallel_for(0, p.ncy, [&](index_t cj) {
    const index_t j = p.cj0 + cj;
    const std::uint32_t* up = grid.data() + cj * gx + 1;  // row cj - 1 of the plan, column 0 at index 0
    const std::uint32_t* mid = up + gx;
    const std::uint32_t* down = mid + gx;
    for (index_t ci = 0; ci < p.ncx; ++ci) {
      const index_t i = p.ci0 + ci;
      std::uint32_t chosen;
      if (((i + j) & 1) == 0) {  // distributed cell
        chosen = mid[ci];
      } else {
        const fill_result f = fill_cell(m, mid[ci - 1], mid[ci + 1], up[ci], down[ci], fill_rng, i, j, policy);
        chosen = f.patch;
        empty_count[to_size(cj)] += f.empty ? 1 : 0;
        evaluated[to_size(cj)] += f.evaluated;
        known[to_size(cj)] += f.known ? 1 : 0;
        fill_error[to_size(cj)] += f.known ? f.error : 0.0;
      }
      patch[to_size(p.cell(ci, cj))] = chosen;
    }
  });
  p.sx.resize(to_size(ncells));
  p.sy.resize(to_size(ncells));
  for (index_t c = 0; c < ncells; ++c) {
    const patch_origin o = m.origin(patch[to_size(c)]);
    p.sx[to_size(c)] = o.x;
    p.sy[to_size(c)] = o.y;
  }
  p.counts.cells = ncells;
  p.counts.phase_group = static_cast<index_t>(group.size());
  for (index_t cj = 0; cj < p.ncy; ++cj)
    for (index_t ci = 0; ci < p.ncx; ++ci)
      (((p.ci0 + ci + p.cj0 + cj) & 1) == 0 ? p.counts.placed : p.counts.filled) += 1;
  for (index_t r = 0; r < p.ncy; ++r) {
    p.counts.empty_intersections += empty_count[to_size(r)];
    p.counts.evaluated += evaluated[to_size(r)];
    p.counts.fill_error_known += known[to_size(r)];
    p.counts.fill_error += fill_error[to_size(r)];
  }
  if (!cut) return p;

  // seams: look up the pair in the compatible sets (either direction), else compute it
  p.vseam.assign(to_size(ncells), nullptr);
  p.hseam.assign(to_size(ncells), nullptr);
  auto lookup = [&](std::uint32_t first, std::uint32_t second, bool vertical) -> const std::uint8_t* {
    if (!m.has_seams()) return nullptr;
    const int fwd = vertical ? side_east : side_south;
    const int back = vertical ? side_west : side_north;
    const auto a = m.compatible(first, fwd);
    for (std::size_t r = 0; r < a.size(); ++r)
      if (a[r] == second) return m.seam(first, fwd, static_cast<index_t>(r)).data();
    const auto b = m.compatible(second, back);
    for (std::size_t r = 0; r < b.size(); ++r)
      if (b[r] == first) return m.seam(second, back, static_cast<index_t>(r)).data();
    return nullptr;
  };
  const index_t vlen = p.ph + p.v, hlen = p.pw + p.v;
  std::vector<index_t> voff(to_size(ncells), -1), hoff(to_size(ncells), -1);
  index_t storage = 0;
  for (index_t cj = 0; cj < p.ncy; ++cj)
    for (index_t ci = 0; ci < p.ncx; ++ci) {
      const auto c = to_size(p.cell(ci, cj));
      if (ci > 0) {
        p.vseam[c] = lookup(patch[to_size(p.cell(ci - 1, cj))], patch[c], true);
        if (p.vseam[c] == nullptr) voff[c] = std::exchange(storage, storage + vlen);
      }
      if (cj > 0) {
        p.hseam[c] = lookup(patch[to_size(p.cell(ci, cj - 1))], patch[c], false);
        if (p.hseam[c] == nullptr) hoff[c] = std::exchange(storage, storage + hlen);
      }
    }
  p.own_seams.assign(to_size(storage), 0);
  exec.parallel_for(0, p.ncy, [&](index_t cj) {
    seam_scratch scratch;
    for (index_t ci = 0; ci < p.ncx; ++ci) {
      const auto c = to_size(p.cell(ci, cj));
      if (voff[c] >= 0) {
        const auto l = to_size(p.cell(ci - 1, cj));
        min_error_seam(m.exemplar(), p.sx[l], p.sy[l], p.sx[c], p.sy[c], p.pw, p.v, vlen, false,
                       p.own_seams.data() + voff[c], scratch);
      }
      if (hoff[c] >= 0) {
        const auto u = to_size(p.cell(ci, cj - 1));
        min_error_seam(m.exemplar(), p.sx[u], p.sy[u], p.sx[c], p.sy[c], p.ph, p.v, hlen, true,
                       p.own_seams.data() + hoff[c], scratch);
      }
    }
  });
  for (std::size_t c = 0; c < to_size(ncells); ++c) {
    if (voff[c] >= 0) {
      p.vseam[c] = p.own_seams.data() + voff[c];
      ++p.counts.computed_seams;
    }
    if (hoff[c] >= 0) {
      p.hseam[c] = p.own_seams.data() + hoff[c];
      ++p.counts.computed_seams;
    }
  }
  return p;
}

}  // namespace detail
TESSERA_NAMESPACE_END
