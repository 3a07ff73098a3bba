// tessera/geometry/detail/quilt_engine.hpp: the patch loop of (constrained) mesh quilting, paper 000
// §3.3.1-3.3.6: XY grid with occupancy; seed = the unoccupied cell with most occupied neighbours;
// translation of the exemplar on grid multiples minimising eq. 1-4 over the M_T vertices of the
// patch P_T, refined by translation ICP (eq. 5); element correspondence in the overlap; deformation
// and merging of corresponding pairs (element_merge.hpp); elements entirely inside the new region
// added whole. Every stored element is checked, so the output never holds intersecting, open or
// non-manifold elements, and fixed vertices are never touched.
#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/progress.hpp"
#include "../../core/random.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../bvh.hpp"
#include "../icp.hpp"
#include "../mesh_quilt_types.hpp"
#include "../mesh_elements.hpp"
#include "../quilt_exemplar.hpp"
#include "../texture_quality.hpp"
#include "element_merge.hpp"
#include "hole_fill.hpp"
#include "hole_relax.hpp"
#include "hole_replace.hpp"
#include "mesh_clip.hpp"
#include "triangle_geometry.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

struct mesh_quilt_params {
  int patch_cells = 0;
  double lambda = 1.0;
  int max_samples = 160;
  double tolerance = 0.05;
  bool icp = true;
  int icp_iterations = 30;
  double correspondence_distance = 0;
  double deform_weight = 1.0;
  bool merge = true;
  int smooth_rings = 2;
  std::uint64_t seed = 0;
  std::uint64_t stream = 0;  // distinguishes tiles of one set
  bool constrained = false;
  merge_rules rules = merge_rules::tessera;
  bool merge_whole = false;
  bool thread_joins = true;
  int cell_retries = 1;
  bool nudge_inside = true;
  bool occupancy_aware = false;
  bool fill_holes = true;
  bool fill_relax = true;
  bool fill_replace = true;
  double fill_border_margin = 0;
};

// A class template (`Deferred` is always void) only so that its merge step, and the Eigen sparse
// solves behind it, are compiled by the translation units that quilt (see merge_pair).
template <class Deferred = void>
class basic_quilt_engine {
 public:
  /// Runs fn(i) for i in [0, n), possibly in parallel (an Executor's parallel_for).
  using parallel_for_fn = std::function<void(index_t, const std::function<void(index_t)>&)>;

  basic_quilt_engine(const quilt_exemplar& ex, xy_rect domain, const mesh_quilt_params& p, parallel_for_fn pfor = {})
      : ex_(ex), domain_(domain), p_(p), pfor_(std::move(pfor)) {
    if (!pfor_)
      pfor_ = [](index_t n, const std::function<void(index_t)>& fn) {
        for (index_t i = 0; i < n; ++i) fn(i);
      };
    cell_ = ex.cell_size();
    cols_ = std::max<index_t>(1, static_cast<index_t>(std::ceil(domain.width() / cell_ - cell_rounding)));
    rows_ = std::max<index_t>(1, static_cast<index_t>(std::ceil(domain.height() / cell_ - cell_rounding)));
    occ_.assign(to_size(cols_ * rows_), 0);
    retries_.assign(occ_.size(), 0);
    const vec3 ext = ex.bounds().extent();
    margin_ = 0.25 * ex.element_diameter();
    const double room = std::min(ext.x, ext.y) - 2 * margin_;
    k_ = p.patch_cells > 0 ? p.patch_cells : std::max(2, static_cast<int>(std::floor(0.5 * room / cell_)));
    corr_ = p.correspondence_distance > 0 ? p.correspondence_distance : 0.5 * cell_;
  }

  /// Adds frame elements (kept as given) and marks the cells whose centre lies in `occupied`.
  void add_frame(std::vector<texture_element> frame, const std::vector<xy_rect>& occupied) {
    for (auto& e : frame) {
      e.update_box();
      if (e.fixed.size() != e.mesh.positions.size()) e.fixed.resize(e.mesh.positions.size(), 0);
      push(std::move(e));
    }
    for (index_t j = 0; j < rows_; ++j)
      for (index_t i = 0; i < cols_; ++i) {
        const vec3 c{domain_.x0 + (i + 0.5) * cell_, domain_.y0 + (j + 0.5) * cell_, 0};
        for (const xy_rect& r : occupied)
          if (r.contains(c)) occ_[to_size(j * cols_ + i)] = 1;
      }
  }

  status run(const progress& prog) {
    const auto total = static_cast<double>(occ_.size());
    for (;;) {
      const index_t seed = pick_seed();
      if (seed < 0) break;
      if (!prog.report(static_cast<double>(std::count(occ_.begin(), occ_.end(), 1)) / total, "mesh quilting"))
        return status::cancelled();
      const index_t si = seed % cols_, sj = seed / cols_;
      const index_t k = std::min<index_t>(k_, std::max(cols_, rows_));
      const index_t i0 = std::clamp<index_t>(si - k / 2, 0, std::max<index_t>(0, cols_ - k));
      const index_t j0 = std::clamp<index_t>(sj - k / 2, 0, std::max<index_t>(0, rows_ - k));
      const index_t i1 = std::min(cols_, i0 + k), j1 = std::min(rows_, j0 + k);
      const xy_rect window{domain_.x0 + i0 * cell_, domain_.y0 + j0 * cell_,
                           std::min(domain_.x1, domain_.x0 + i1 * cell_),
                           std::min(domain_.y1, domain_.y0 + j1 * cell_)};
      const vec3 t = find_translation(window, stats_.patches);
      place_patch(t, window);
      for (index_t j = j0; j < j1; ++j)
        for (index_t i = i0; i < i1; ++i) occ_[to_size(j * cols_ + i)] = 1;
      occ_[to_size(seed)] = 1;
      // a cell whose element was dropped goes back to the seed search (at most cell_retries times):
      // the next patch there draws another translation instead of leaving a hole
      for (index_t c : dropped_cells_)
        if (c >= 0 && occ_[to_size(c)] && retries_[to_size(c)] < p_.cell_retries && !covered(c)) {
          occ_[to_size(c)] = 0;
          ++retries_[to_size(c)];
          ++stats_.cells_retried;
        }
      dropped_cells_.clear();
      ++stats_.patches;
    }
    prog.report(1.0, "mesh quilting");
    return {};
  }

  /// After run() (an extension of §3.3): places single exemplar elements (not long ones) into the
  /// holes the patches left where their elements were dropped. The holes are the local maxima of the
  /// distance to the elements' XY projections (hole_fill.hpp), largest first; each gets an exemplar
  /// element centred there with its exemplar orientation and height; one that would intersect an
  /// element, or leave a constrained domain, is not placed. Up to hole_passes passes (the distances
  /// are recomputed after each), fewer when a pass places nothing; filling stops when the exemplar's
  /// covered share is reached. Random draws are keyed by (seed, stream, pass, hole), so the result
  /// is deterministic.
  ///
  /// With fill_relax (the default), the exemplar's elements are split into hole_size_classes classes
  /// of footprint radius, and a hole gets an element of the largest class the output holds fewer of
  /// than the exemplar's density asks for (or whose elements bring at least the covered area each
  /// element still to come should bring), its movable neighbours (added whole or filled: not frame
  /// elements, not elements merged across a patch seam) pushed apart by up to hole_push_diameters
  /// element diameters when it does not fit as it stands (hole_relax.hpp). Once the output's
  /// element count reaches the exemplar's density, only holes that hold an empty square of
  /// hole_empty_diameters are filled. Without, each hole gets an element drawn from the larger half
  /// of those whose footprint, plus the exemplar's clearance between elements, fits as it stands.
  status fill_holes(const progress& prog) {
    if (!p_.fill_holes) return {};
    std::vector<std::pair<double, index_t>> fits;  // (footprint radius, exemplar element), smallest first
    for (index_t e = 0; e < ex_.num_elements(); ++e)
      if (!ex_.is_long(e)) fits.push_back({footprint_radius(ex_.elements()[to_size(e)]), e});
    if (fits.empty()) return {};
    std::sort(fits.begin(), fits.end());
    const double d = ex_.element_diameter();
    // unconstrained: elements may stand across the domain's sides (their centres inside), so the
    // raster reaches a diameter beyond them; constrained: the domain itself
    const double pad = p_.constrained ? 0.0 : d;
    const xy_rect area{domain_.x0 - pad, domain_.y0 - pad, domain_.x1 + pad, domain_.y1 + pad};
    const xy_raster grid = make_xy_raster(area, d / hole_raster_per_diameter, hole_raster_max_pixels);
    const double h = grid.px;
    const auto w = static_cast<index_t>(grid.nx), rows = static_cast<index_t>(grid.ny);
    // the exemplar's own spacing (+ a pixel: the raster is sampled)
    std::vector<unsigned char> is_long(to_size(ex_.num_elements()));
    for (index_t e = 0; e < ex_.num_elements(); ++e) is_long[to_size(e)] = ex_.is_long(e) ? 1 : 0;
    const double clearance = std::max(hole_min_clearance_diameters * d,
                                      exemplar_clearance(ex_.elements(), is_long, h, d, hole_clearance_quantile)) +
                             h;
    const bool relax = p_.fill_relax;
    // neighbours are pushed only when the exemplar's element sizes vary: a lattice of equal elements
    // keeps its spacing (pushed, the beads quilt had 14 % of its spacings outside the exemplar's
    // spread, from 0 %)
    const double max_push =
        relax && fits.back().first >= hole_relax_size_spread * fits.front().first ? hole_push_diameters * d : 0.0;
    // relaxation: size classes (upper footprint radius of each; the exemplar's share of its elements
    // and their mean projected area in each)
    const std::vector<double> bounds = relax ? size_class_bounds(fits) : std::vector<double>{};
    std::vector<double> class_share(bounds.size(), 0), class_area(bounds.size(), 0);
    if (relax) {
      std::vector<double> n(bounds.size(), 0);
      for (const auto& f : fits) {
        const std::size_t k = class_of(bounds, f.first);
        class_share[k] += 1.0 / static_cast<double>(fits.size());
        class_area[k] += projected_area(ex_.elements()[to_size(f.second)].mesh);
        n[k] += 1;
      }
      for (std::size_t k = 0; k < n.size(); ++k) class_area[k] = n[k] > 0 ? class_area[k] / n[k] : 0.0;
    }
    // filling stops where the exemplar's covered share is reached (on this raster, as the output's
    // is counted): the holes left are the smallest
    const double target = exemplar_coverage(ex_.elements(), h, d);
    // with relaxation, the element count stops it too, at the exemplar's density as its likeness
    // figure reads it (texture_quality.hpp, the figure the output is measured by; no count limit when
    // that cannot be measured). The output is counted where that figure reads a texture:
    // unconstrained, inside the domain inset as far as the figure insets it (a quilt's outer edges are
    // open); constrained, in the whole tile, an element with fixed vertices (a frame element cut at a
    // tile side, whose other part is the neighbouring tile's) counting as half.
    double target_density = std::numeric_limits<double>::infinity();
    double ex_empty = 0;  // the exemplar's empty-cell rate, as texture_quality reads it
    xy_rect count_win = domain_;
    if (relax) {
      const auto ref = quality_reference(ex_.mesh());
      const auto q = ref ? measure_texture_quality(ex_.mesh(), *ref) : result<texture_quality>(ref.error());
      if (q && q->density > 0) {
        target_density = q->density;
        ex_empty = q->empty_cell_rate;
        const texture_quality_options qo;
        double in = std::max(qo.margin_diameters * ref->diameter, 1.25 * ref->nn_median);
        // constrained: the part of the tile filling may reach (off the border band)
        if (p_.constrained) in = p_.fill_border_margin;
        if (2 * in < std::min(domain_.width(), domain_.height()))
          count_win = {domain_.x0 + in, domain_.y0 + in, domain_.x1 - in, domain_.y1 - in};
      }
    }
    const double target_count = target_density * count_win.width() * count_win.height();
    const counter_rng rng(p_.seed, p_.stream);
    bool reached = false;
    for (int pass = 0; pass < hole_passes && !reached; ++pass) {
      if (prog.cancelled()) return status::cancelled();
      coverage_raster r(grid);
      r.count_in(domain_);
      for (std::size_t i = 0; i < elems_.size(); ++i)
        if (alive_[i]) r.add_mesh(elems_[i].mesh, static_cast<index_t>(i));
      if (r.counted_share() >= target) break;
      // the output's (not long) elements by size class, and how many each class lacks
      std::vector<double> lack(bounds.size(), 0);
      double count = 0;
      if (relax) {
        for (std::size_t k = 0; k < bounds.size(); ++k) lack[k] = class_share[k] * target_count;
        count = tally(count_win, bounds, hole_long_footprint_factor * fits.back().first, lack);
      }
      const double min_site = std::max(h, fits.front().first + clearance - max_push);
      const auto sites = hole_sites(distance_to_covered(r), w, rows, static_cast<float>(min_site / h));
      index_t placed = 0;
      for (const hole_site& s : sites) {
        // past the exemplar's density, only holes that hold an empty square as wide as
        // texture_quality's empty cells are filled
        const bool capped = relax && count >= target_count;
        if (capped && static_cast<double>(s.radius) * h < 0.5 * hole_empty_diameters * d) break;
        const vec3 c = r.centre(s.i, s.j);
        if (capped && !r.square_free(c, 0.5 * hole_empty_diameters * d)) continue;
        if (!domain_.contains(c)) continue;
        if (!r.disc_free(c, min_site - h)) continue;  // an element placed since stands there
        const auto room = static_cast<double>(s.radius) * h - clearance + max_push;
        const auto n_fit = static_cast<std::size_t>(
            std::upper_bound(fits.begin(), fits.end(), std::pair{room, std::numeric_limits<index_t>::max()}) -
            fits.begin());
        if (n_fit == 0) continue;
        const auto site = static_cast<std::uint64_t>(s.j * w + s.i);
        // the draws: without relaxation, from the larger half of the elements that fit (small ones
        // fit nearly everywhere, and filling with them would add more elements than the covered area
        // calls for); with, from the largest class that lacks elements, then the next
        std::vector<std::pair<std::size_t, std::size_t>> ranges;  // [first, last) of fits to draw from
        if (!relax) {
          for (int t = 0; t < hole_tries; ++t) ranges.push_back({n_fit / 2, n_fit});
        } else {
          // the covered area each element still to come should bring, on average: a class whose
          // elements bring that much is drawn from even when the output holds enough of them (the
          // patches drop large elements more often than small ones, so the covered area lags)
          const double to_come = std::max(1.0, (target_count - count) * domain_.width() * domain_.height() /
                                                   (count_win.width() * count_win.height()));
          const double wanted = (target - r.counted_share()) * domain_.width() * domain_.height() / to_come;
          for (std::size_t k = bounds.size(); k-- > 0;) {
            if (!capped && lack[k] <= 0 && class_area[k] < wanted) continue;
            const std::size_t lo = class_begin(fits, bounds, k), hi = std::min(n_fit, class_begin(fits, bounds, k + 1));
            for (int t = 0; t < hole_tries_per_class && lo < hi; ++t) ranges.push_back({lo, hi});
          }
        }
        for (std::size_t t = 0; t < ranges.size(); ++t) {
          const auto [lo, hi] = ranges[t];
          const auto& [re, e] = fits[lo + to_size(rng.below(hi - lo, 3, static_cast<std::uint64_t>(pass), site,
                                                            static_cast<std::uint64_t>(t)))];
          if (!relax && !r.disc_free(c, re + clearance)) continue;  // an element placed since covers part of it
          auto candidate = fill_candidate(e, re, c);
          if (!candidate) continue;
          texture_element& el = *candidate;
          if (relax ? !place_relaxed(el, c, r, h, clearance, max_push) : intersects_alive(el, {})) continue;
          r.add_mesh(el.mesh, static_cast<index_t>(elems_.size()));
          if (relax && count_win.contains(c)) {
            lack[class_of(bounds, re)] -= 1;
            count += 1;
          }
          push(std::move(el), true);
          ++stats_.elements_filled;
          ++placed;
          reached = r.counted_share() >= target;
          break;
        }
        if (reached) break;
      }
      if (placed == 0) break;
    }
    if (relax && p_.fill_replace && max_push > 0)
      return replace_small(fits, bounds, grid, clearance, count_win, target_count, target, ex_empty, prog);
    return {};
  }

  [[nodiscard]] std::vector<texture_element> take_elements() {
    std::vector<texture_element> out;
    for (std::size_t i = 0; i < elems_.size(); ++i)
      if (alive_[i]) out.push_back(std::move(elems_[i]));
    return out;
  }
  [[nodiscard]] const mesh_quilt_stats& stats() const noexcept { return stats_; }

  /// §3.3.3: the translation of the exemplar for the patch window `w` (the `patch`-th patch: seeds
  /// the random pick). Candidates are the grid multiples that cover `w` with a margin; each is
  /// scored by eq. 4, the sum over M_T's vertices in `w` of eq. 2, the minimum over exemplar faces
  /// of eq. 1. Simplifications (docs/geometry.md): eq. 2 looks at faces within one grid cell (farther
  /// surface costs as if a cell away with an orthogonal normal); eq. 4 runs on at most max_samples
  /// evenly thinned vertices; with more than 8 candidates, every 4th sample ranks them all and only
  /// the best 8 get the full eq. 4; one is drawn among those within (1 + tolerance) of the best.
  /// ICP (eq. 5) then refines it in XY for at most icp_iterations steps; its result is discarded
  /// when it pairs nothing or moves a cell or more. Public for tests; run() calls it per patch.
  vec3 find_translation(const xy_rect& w, index_t patch) {
    const aabb& eb = ex_.bounds();
    const vec3 ext = eb.extent();
    auto range = [&](double lo_edge, double hi_edge, double origin, double ex_size) {
      const double lo = std::ceil((hi_edge - origin - ex_size + margin_) / cell_ - cell_rounding);
      const double hi = std::floor((lo_edge - origin - margin_) / cell_ + cell_rounding);
      if (lo <= hi) return std::pair{static_cast<index_t>(lo), static_cast<index_t>(hi)};
      const auto mid = static_cast<index_t>(std::llround(0.5 * (lo + hi)));
      return std::pair{mid, mid};
    };
    const auto [ix0, ix1] = range(w.x0, w.x1, domain_.x0, ext.x);
    const auto [iy0, iy1] = range(w.y0, w.y1, domain_.y0, ext.y);
    std::vector<vec3> cands;
    for (index_t j = iy0; j <= iy1; ++j)
      for (index_t i = ix0; i <= ix1; ++i)
        cands.push_back({domain_.x0 + i * cell_ - eb.min.x, domain_.y0 + j * cell_ - eb.min.y, 0});
    const counter_rng rng(p_.seed, p_.stream);
    const std::vector<sample> s = samples_in(w);
    if (s.empty()) return cands[to_size(rng.below(cands.size(), 1, patch))];
    const auto& normals = ex_.face_normals();
    const double saturated = (1 + cell_) * (1 + p_.lambda);
    auto cost = [&](vec3 t, double limit, std::size_t stride) {
      double sum = 0;
      for (std::size_t qi = 0; qi < s.size(); qi += stride) {
        const sample& q = s[qi];
        const vec3 x = q.p - t;
        // eq. 2 searches the faces within one grid cell; when there is none the point costs as if the
        // surface were a cell away with an orthogonal normal
        const auto [f, c] = ex_.bvh().min_cost_face(
            [&](index_t face, const std::array<vec3, 3>& tri) {
              const double d = norm(closest_point_on_triangle(x, tri[0], tri[1], tri[2]).point - x);
              return (1 + d) * (1 + p_.lambda * (1 - dot(q.n, normals[to_size(face)])));  // eq. 1
            },
            [&](const aabb& b) {
              const double d2 = squared_distance_to_box(x, b);
              return d2 > cell_ * cell_ ? std::numeric_limits<double>::infinity() : 1 + std::sqrt(d2);
            },
            saturated);
        sum += f >= 0 ? c : saturated;  // eq. 2 and 4
        if (sum > limit) return sum;
      }
      return sum;
    };
    // Two stages: every fourth sample ranks all candidates, then the best few are scored with all
    // samples (eq. 4). Candidates run in parallel; the shared running minimum only cuts off sums
    // that are already above the final threshold, so the result does not depend on the schedule.
    // with the occupancy term, candidates within (1 + occupancy_tolerance_factor x tolerance) of the
    // best are scored exactly, so that the choice among them does not depend on the schedule
    const double tol = p_.tolerance * (p_.occupancy_aware ? occupancy_tolerance_factor : 1.0);
    auto search = [&](const std::vector<std::size_t>& which, std::size_t stride, std::vector<double>& costs) {
      std::atomic<double> best{std::numeric_limits<double>::infinity()};
      pfor_(static_cast<index_t>(which.size()), [&](index_t i) {
        const std::size_t c = which[to_size(i)];
        const double v = cost(cands[c], best.load(std::memory_order_relaxed) * (1 + tol), stride);
        costs[c] = v;
        double cur = best.load(std::memory_order_relaxed);
        while (v < cur && !best.compare_exchange_weak(cur, v, std::memory_order_relaxed)) {}
      });
      return best.load();
    };
    std::vector<std::size_t> all(cands.size());
    for (std::size_t c = 0; c < cands.size(); ++c) all[c] = c;
    std::vector<double> costs(cands.size(), std::numeric_limits<double>::infinity());
    constexpr std::size_t coarse_stride = 4, finalists = 8;
    if (s.size() >= 4 * coarse_stride && cands.size() > finalists) {
      // rank by the coarse cost without cut-offs (exact partial sums)
      pfor_(static_cast<index_t>(cands.size()), [&](index_t c) {
        costs[to_size(c)] = cost(cands[to_size(c)], std::numeric_limits<double>::infinity(), coarse_stride);
      });
      std::stable_sort(all.begin(), all.end(), [&](std::size_t a, std::size_t b) { return costs[a] < costs[b]; });
      all.resize(finalists);
      std::sort(all.begin(), all.end());
      std::fill(costs.begin(), costs.end(), std::numeric_limits<double>::infinity());
    }
    const double best = search(all, 1, costs);
    std::vector<std::size_t> good;
    for (std::size_t c : all)
      if (costs[c] <= best * (1 + p_.tolerance)) good.push_back(c);
    if (p_.occupancy_aware) {
      // occupancy term: among the translations within (1 + tol) of the best, those that would drop
      // the fewest exemplar elements (colliding with what stands, or across a tile side)
      std::vector<std::size_t> wide;
      std::vector<index_t> drops;
      for (std::size_t c : all)
        if (costs[c] <= best * (1 + tol)) {
          wide.push_back(c);
          drops.push_back(count_drops(cands[c], w));
        }
      const index_t fewest = *std::min_element(drops.begin(), drops.end());
      good.clear();
      for (std::size_t i = 0; i < wide.size(); ++i)
        if (drops[i] == fewest) good.push_back(wide[i]);
    }
    vec3 t = cands[good[to_size(rng.below(good.size(), 2, patch))]];
    if (p_.icp) {
      std::vector<vec3> pts;
      for (const sample& q : s) pts.push_back(q.p);
      const auto r = icp_translation(pts, ex_.bvh(), t,
                                     {.max_iterations = p_.icp_iterations,
                                      .tolerance = icp_tolerance_cells * cell_,
                                      .max_distance = 2 * corr_,
                                      .free_axes = {true, true, false}});
      if (r && r->pairs > 0 && norm(r->translation - t) < cell_) {
        t = r->translation;
        stats_.icp_iterations += r->iterations;
      } else {
        ++stats_.icp_discarded;
      }
    }
    return t;
  }

 private:
  // `movable`: hole filling may move the element a little (hole_relax.hpp): added whole or filled,
  // not a frame element nor one merged across a patch seam
  void push(texture_element e, bool movable = false) {
    elems_.push_back(std::move(e));
    alive_.push_back(1);
    movable_.push_back(movable && !elems_.back().has_fixed() ? 1 : 0);
    bvh_.emplace_back();
    normals_.emplace_back();
  }
  const triangle_bvh& bvh_of(std::size_t i) {
    if (!bvh_[i]) bvh_[i].emplace(elems_[i].mesh);
    return *bvh_[i];
  }

  /// The live elements whose boxes come within `reach` of `box` in x and y, in index order.
  [[nodiscard]] std::vector<std::size_t> alive_near(const aabb& box, double reach) const {
    std::vector<std::size_t> near;
    for (std::size_t i = 0; i < elems_.size(); ++i) {
      const aabb& b = elems_[i].box;
      if (alive_[i] && b.min.x <= box.max.x + reach && b.max.x >= box.min.x - reach && b.min.y <= box.max.y + reach &&
          b.max.y >= box.min.y - reach)
        near.push_back(i);
    }
    return near;
  }
  /// In a tile, how far a filled, moved or removed element keeps from the tile's sides: the band where
  /// a tile's elements must agree with its neighbour's strip, plus the inside margin.
  [[nodiscard]] double fill_band() const { return p_.fill_border_margin + 2 * inside_margin_fraction * cell_; }
  /// Exemplar element e (bounding radius re) centred at c for hole filling, or nothing where it may
  /// not go: in a tile, within its radius plus the margin of the band where a tile's elements must
  /// agree with its neighbour's strip, or not strictly inside the tile.
  [[nodiscard]] std::optional<texture_element> fill_candidate(index_t e, double re, vec3 c) const {
    if (p_.constrained &&
        std::min({c.x - domain_.x0, domain_.x1 - c.x, c.y - domain_.y0, domain_.y1 - c.y}) < re + p_.fill_border_margin)
      return std::nullopt;
    const texture_element& src = ex_.elements()[to_size(e)];
    const vec3 shift{c.x - src.box.center().x, c.y - src.box.center().y, 0};
    texture_element el;
    el.mesh = src.mesh;
    for (vec3& q : el.mesh.positions) q += shift;
    el.fixed.assign(el.mesh.positions.size(), 0);
    el.update_box();
    if (p_.constrained && !all_strictly_inside(el.mesh, 2 * inside_margin_fraction * cell_)) return std::nullopt;
    return el;
  }
  [[nodiscard]] bool all_strictly_inside(const tri_mesh& m, double margin) const {
    return std::all_of(m.positions.begin(), m.positions.end(),
                       [&](const vec3& q) { return strictly_inside(domain_, q, margin); });
  }

  // Hole filling with relaxation: the upper footprint radius of each of hole_size_classes classes
  // (quantiles of the exemplar's, smallest first; the last class is open above).
  [[nodiscard]] static std::vector<double> size_class_bounds(const std::vector<std::pair<double, index_t>>& fits) {
    std::vector<double> b;
    for (int k = 1; k < hole_size_classes; ++k)
      b.push_back(fits[to_size(k) * fits.size() / to_size(hole_size_classes)].first);
    b.push_back(std::numeric_limits<double>::infinity());
    return b;
  }
  // the class of footprint radius `fr`: the first whose bound lies above it
  [[nodiscard]] static std::size_t class_of(const std::vector<double>& bounds, double fr) {
    return std::min<std::size_t>(
        bounds.size() - 1,
        static_cast<std::size_t>(std::upper_bound(bounds.begin(), bounds.end(), fr) - bounds.begin()));
  }
  // the index in `fits` (sorted) of class k's first element (fits.size() past the last class)
  [[nodiscard]] static std::size_t class_begin(const std::vector<std::pair<double, index_t>>& fits,
                                               const std::vector<double>& bounds, std::size_t k) {
    if (k == 0) return 0;
    if (k >= bounds.size()) return fits.size();
    return static_cast<std::size_t>(
        std::upper_bound(fits.begin(), fits.end(), std::pair{bounds[k - 1], std::numeric_limits<index_t>::max()}) -
        fits.begin());
  }

  // Hole filling with relaxation: the output's (not long) elements whose centre lies in `win`,
  // counted (constrained, an element with fixed vertices as half: its other part is the neighbouring
  // tile's) and taken off `lack` by size class; a footprint above `long_fr` is a thread piece or the
  // like and does not count.
  [[nodiscard]] double tally(const xy_rect& win, const std::vector<double>& bounds, double long_fr,
                             std::vector<double>& lack) const {
    double count = 0;
    for (std::size_t i = 0; i < elems_.size(); ++i) {
      const vec3 c = elems_[i].box.center();
      if (!alive_[i] || !win.contains({c.x, c.y, 0})) continue;
      const double fr = footprint_radius(elems_[i]);
      if (fr > long_fr) continue;
      const double n = p_.constrained && elems_[i].has_fixed() ? 0.5 : 1.0;
      lack[class_of(bounds, fr)] -= n;
      count += n;
    }
    return count;
  }

  // After hole filling with relaxation (hole_replace.hpp): while the output holds more elements than
  // the exemplar's density in `count_win` (`target_count`), an element of the exemplar's largest size
  // class takes the place of small free ones; below the exemplar's covered share (`target`, the
  // output's counted in `count_win`) only where they cover less than it, above only where they cover
  // more (up to hole_replace_loss times). Removable: movable elements (added whole or filled), below the
  // largest size class, centred in `count_win` and, in a tile, off its border band. Their places
  // are the local maxima of the distance to every other element (hole_fill.hpp), those in the largest
  // holes of the output as it stands first; an element drawn from the largest class whose footprint
  // fits there with `clearance` displaces the removable ones nearer than `clearance`, when there are
  // two or more, their area is within those bounds, it intersects nothing else, and it opens no empty
  // square of texture_quality's empty-cell size where a displaced one stood beyond what the
  // exemplar's empty-cell rate (`ex_empty`) allows. Up to hole_passes passes.
  status replace_small(const std::vector<std::pair<double, index_t>>& fits, const std::vector<double>& bounds,
                       const xy_raster& grid, double clearance, const xy_rect& count_win, double target_count,
                       double target, double ex_empty, const progress& prog) {
    const double h = grid.px;
    const auto w = static_cast<index_t>(grid.nx), rows = static_cast<index_t>(grid.ny);
    const double long_fr = hole_long_footprint_factor * fits.back().first;
    const double small_fr = bounds[bounds.size() - 2];  // below the largest class
    const std::size_t lo = class_begin(fits, bounds, bounds.size() - 1);
    if (lo >= fits.size()) return {};
    const double band = fill_band();
    const counter_rng rng(p_.seed, p_.stream);
    for (int pass = 0; pass < hole_passes; ++pass) {
      if (prog.cancelled()) return status::cancelled();
      std::vector<double> lack(bounds.size(), 0);
      double count = tally(count_win, bounds, long_fr, lack);
      coverage_raster all(grid), stay(grid);
      all.count_in(count_win);  // the covered share where the elements are counted
      std::vector<unsigned char> removable(elems_.size(), 0);
      for (std::size_t i = 0; i < elems_.size(); ++i) {
        if (!alive_[i]) continue;
        all.add_mesh(elems_[i].mesh, static_cast<index_t>(i));
        const vec3 c = elems_[i].box.center();
        removable[i] = movable_[i] && count_win.contains({c.x, c.y, 0}) && footprint_radius(elems_[i]) <= small_fr &&
                       (!p_.constrained || all_strictly_inside(elems_[i].mesh, band));
        if (!removable[i]) stay.add_mesh(elems_[i].mesh);
      }
      auto pays = [&] { return count > target_count; };
      if (!pays()) break;
      // places: where the elements that stay leave room for the smallest of the largest class;
      // those in the largest holes of the output as it stands first
      const double min_site = fits[lo].first + clearance;
      auto sites = hole_sites(distance_to_covered(stay), w, rows, static_cast<float>(min_site / h));
      const std::vector<float> gap = distance_to_covered(all);
      std::stable_sort(sites.begin(), sites.end(), [&](const hole_site& a, const hole_site& b) {
        return gap[to_size(a.j * w + a.i)] > gap[to_size(b.j * w + b.i)];
      });
      index_t replaced = 0;
      // the empty squares an exchange may open: as many as the exemplar's empty-cell rate leaves to
      // the output (its empty cells counted on a grid of hole_empty_diameters from the domain's corner)
      const double cell = hole_empty_diameters * ex_.element_diameter();
      double may_open = 0;
      if (ex_empty > 0) {
        const auto nx = static_cast<index_t>(domain_.width() / cell),
                   ny = static_cast<index_t>(domain_.height() / cell);
        index_t empty = 0;
        for (index_t j = 0; j < ny; ++j)
          for (index_t i = 0; i < nx; ++i)
            empty += all.square_free({domain_.x0 + (double(i) + 0.5) * cell, domain_.y0 + (double(j) + 0.5) * cell, 0},
                                     0.5 * cell)
                         ? 1
                         : 0;
        may_open = ex_empty * static_cast<double>(nx * ny) - static_cast<double>(empty);
      }
      for (const hole_site& s : sites) {
        if (!pays()) break;
        const vec3 c = all.centre(s.i, s.j);
        if (!domain_.contains(c) || !stay.disc_free(c, min_site - h)) continue;  // a large one placed since
        const double room = static_cast<double>(s.radius) * h - clearance;
        const auto hi = static_cast<std::size_t>(
            std::upper_bound(fits.begin(), fits.end(), std::pair{room, std::numeric_limits<index_t>::max()}) -
            fits.begin());
        if (hi <= lo) continue;
        const auto site = static_cast<std::uint64_t>(s.j * w + s.i);
        for (int t = 0; t < hole_replace_tries; ++t) {
          const auto& [re, e] = fits[lo + to_size(rng.below(hi - lo, 5, static_cast<std::uint64_t>(pass), site,
                                                            static_cast<std::uint64_t>(t)))];
          auto candidate = fill_candidate(e, re, c);
          if (!candidate) continue;
          texture_element& el = *candidate;
          const std::vector<std::size_t> near = alive_near(el.box, clearance + h);
          std::vector<replace_neighbour> nb;
          for (std::size_t i : near) nb.push_back({&elems_[i].mesh, projected_area(elems_[i].mesh), removable[i] != 0});
          // below the exemplar's covered share the covered area may only grow; above, only shrink
          // (by at most a factor hole_replace_loss of the element's own area)
          const double a = projected_area(el.mesh);
          const bool under = all.counted_share() < target;
          const auto out =
              displaced_neighbours(el.mesh, nb, h, clearance, under ? 0.0 : a, under ? a : hole_replace_loss * a);
          if (out.empty()) continue;
          std::vector<std::size_t> gone;
          for (std::size_t k : out) gone.push_back(near[k]);
          if (intersects_alive(el, gone)) continue;
          // tentatively: no empty square as wide as texture_quality's empty cells may open where a
          // displaced one stood (squares about its centre, shifted by up to half their side)
          const auto idx = static_cast<index_t>(elems_.size());
          for (std::size_t i : gone) all.remove_owner(static_cast<index_t>(i), elems_[i].box);
          all.add_mesh(el.mesh, idx);
          bool opens = false;
          const double half = 0.5 * cell;
          for (std::size_t i = 0; i < gone.size() && !opens; ++i) {
            const vec3 g = elems_[gone[i]].box.center();
            for (int dy = -2; dy <= 2 && !opens; ++dy)
              for (int dx = -2; dx <= 2 && !opens; ++dx)
                opens = all.square_free(g + vec3{0.5 * half * dx, 0.5 * half * dy, 0}, half);
          }
          if (opens && may_open >= 1) {
            may_open -= 1;
            opens = false;
          }
          if (opens) {  // undone
            all.remove_owner(idx, el.box);
            for (std::size_t i : gone) all.add_mesh(elems_[i].mesh, static_cast<index_t>(i));
            continue;
          }
          for (std::size_t i : gone) alive_[i] = 0;
          count -= static_cast<double>(gone.size()) - 1;  // removable ones are counted whole
          stay.add_mesh(el.mesh);
          stats_.elements_replaced += static_cast<index_t>(gone.size());
          ++stats_.elements_filled;
          push(std::move(el), true);
          removable.push_back(0);  // the large one stays
          ++replaced;
          break;
        }
      }
      if (replaced == 0) break;
    }
    return {};
  }

  // Places `el` (centred at `c`) when its movable neighbours can make room (relax_pushes: each keeps
  // `clearance` from it, moving at most `max_push`); a moved element must keep a pixel of room from
  // every other element in `r`, stay off a tile's border band, and intersect nothing. Commits the
  // moves (in `r` too); the caller adds `el`.
  bool place_relaxed(const texture_element& el, vec3 c, coverage_raster& r, double h, double clearance,
                     double max_push) {
    const std::vector<std::size_t> near = alive_near(el.box, clearance + h);
    std::vector<relax_neighbour> nb;
    for (std::size_t i : near) nb.push_back({&elems_[i].mesh, elems_[i].box.center(), movable_[i] != 0});
    const auto shifts = relax_pushes(el.mesh, c, nb, h, clearance, max_push);
    if (!shifts) return false;
    std::vector<std::size_t> moved;
    std::vector<texture_element> moved_el;
    const double band = fill_band();
    const double gap = std::max(h, hole_min_clearance_diameters * ex_.element_diameter());
    for (std::size_t k = 0; k < near.size(); ++k) {
      const vec3 sh = (*shifts)[k];
      if (sh.x == 0 && sh.y == 0) continue;
      const std::size_t i = near[k];
      if (p_.constrained && !all_strictly_inside(elems_[i].mesh, band)) return false;  // in the band: stays
      texture_element m;
      m.mesh = elems_[i].mesh;
      for (vec3& q : m.mesh.positions) q += sh;
      m.fixed = elems_[i].fixed;
      m.border = elems_[i].border;
      m.update_box();
      if (p_.constrained && !all_strictly_inside(m.mesh, band)) return false;
      moved.push_back(i);
      moved_el.push_back(std::move(m));
    }
    if (moved.empty()) return !intersects_alive(el, {});
    auto is_moved = [&](index_t o) {
      return std::find(moved.begin(), moved.end(), static_cast<std::size_t>(o)) != moved.end();
    };
    for (std::size_t k = 0; k < moved.size(); ++k)
      for (const vec3& q : moved_el[k].mesh.positions)
        if (r.owned_near(q, gap, is_moved)) return false;  // pushed against an element that stays
    // nothing intersects: the new element and the moved ones against what stays and each other
    if (intersects_alive(el, moved)) return false;
    std::vector<triangle_bvh> mb;
    for (const auto& m : moved_el) mb.emplace_back(m.mesh);
    const triangle_bvh eb(el.mesh);
    for (std::size_t k = 0; k < moved.size(); ++k) {
      if (intersects_alive(moved_el[k], moved)) return false;
      bool hit = false;
      auto any = [&](index_t, index_t) { hit = true; };
      if (boxes_overlap(moved_el[k].box, el.box)) for_each_intersecting_pair(mb[k], eb, any);
      for (std::size_t l = k + 1; l < moved.size() && !hit; ++l)
        if (boxes_overlap(moved_el[k].box, moved_el[l].box)) for_each_intersecting_pair(mb[k], mb[l], any);
      if (hit) return false;
    }
    for (std::size_t k = 0; k < moved.size(); ++k) {
      const std::size_t i = moved[k];
      r.remove_owner(static_cast<index_t>(i), elems_[i].box);
      elems_[i] = std::move(moved_el[k]);
      bvh_[i].emplace(std::move(mb[k]));
      normals_[i].clear();
      r.add_mesh(elems_[i].mesh, static_cast<index_t>(i));
      ++stats_.elements_relaxed;
    }
    return true;
  }

  [[nodiscard]] index_t cell_of(vec3 p) const {
    const auto i = static_cast<index_t>(std::floor((p.x - domain_.x0) / cell_));
    const auto j = static_cast<index_t>(std::floor((p.y - domain_.y0) / cell_));
    if (i < 0 || j < 0 || i >= cols_ || j >= rows_) return -1;
    return j * cols_ + i;
  }
  // The occupancy term of the translation search: how many exemplar elements (not long) whose
  // centre the translation `t` puts in the new region of window `w` would be dropped, judged on
  // XY boxes: one whose box overlaps a standing element's box (shrunk by a tenth of an element
  // diameter) without being its duplicate (centres within a quarter diameter: skipped, not dropped),
  // or, constrained, one reaching across a tile side by more than the nudge.
  [[nodiscard]] index_t count_drops(vec3 t, const xy_rect& w) const {
    const double d = ex_.element_diameter(), shrink = 0.1 * d, dup = 0.25 * d;
    index_t n = 0;
    for (index_t e = 0; e < ex_.num_elements(); ++e) {
      if (ex_.is_long(e)) continue;
      aabb b = ex_.elements()[to_size(e)].box;
      b.min += t;
      b.max += t;
      const vec3 c = b.center();
      if (!w.contains({c.x, c.y, 0}) || occupied({c.x, c.y, 0})) continue;
      if (p_.constrained) {
        const double over =
            std::max({domain_.x0 - b.min.x, domain_.y0 - b.min.y, b.max.x - domain_.x1, b.max.y - domain_.y1});
        if (over > (p_.nudge_inside ? nudge_diameters * d : 0.0)) {
          ++n;
          continue;
        }
      }
      for (std::size_t i = 0; i < elems_.size(); ++i) {
        if (!alive_[i]) continue;
        const aabb& x = elems_[i].box;
        const vec3 xc = x.center();
        if (std::hypot(xc.x - c.x, xc.y - c.y) < dup) break;  // a duplicate: skipped
        if (x.min.x + shrink < b.max.x - shrink && x.max.x - shrink > b.min.x + shrink &&
            x.min.y + shrink < b.max.y - shrink && x.max.y - shrink > b.min.y + shrink) {
          ++n;
          break;
        }
      }
    }
    return n;
  }

  // True when one partner of thread piece `cin` spans it along the thread (up to thread_cover_cells)
  // and lies on the same line: the piece would add nothing (it reaches the new region only by
  // rounding at the window's side), and merging it can only fail.
  [[nodiscard]] bool thread_covered(const texture_element& cin,
                                    const std::vector<std::pair<index_t, std::size_t>>& mine) const {
    const vec3 x = cin.box.extent();
    const int along = x.x >= x.y ? 0 : 1, side = 1 - along;
    const double tol = thread_cover_cells * cell_;
    for (const auto& pr : mine) {
      const aabb& b = elems_[pr.second].box;
      if (b.min[along] <= cin.box.min[along] + tol && b.max[along] >= cin.box.max[along] - tol &&
          std::abs(b.center()[side] - cin.box.center()[side]) <= corr_)
        return true;
    }
    return false;
  }

  // True when some alive element's XY box holds the cell's centre (something stands there).
  [[nodiscard]] bool covered(index_t c) const {
    const vec3 p{domain_.x0 + (double(c % cols_) + 0.5) * cell_, domain_.y0 + (double(c / cols_) + 0.5) * cell_, 0};
    for (std::size_t i = 0; i < elems_.size(); ++i)
      if (alive_[i] && elems_[i].box.min.x <= p.x && elems_[i].box.max.x >= p.x && elems_[i].box.min.y <= p.y &&
          elems_[i].box.max.y >= p.y)
        return true;
    return false;
  }
  [[nodiscard]] bool occupied(vec3 p) const {
    const index_t c = cell_of(p);
    return c >= 0 && occ_[to_size(c)];
  }

  // §3.3.2: the unoccupied cell with the most occupied neighbours (ties: smallest index)
  [[nodiscard]] index_t pick_seed() const {
    index_t best = -1;
    int best_n = -1;
    for (index_t j = 0; j < rows_; ++j)
      for (index_t i = 0; i < cols_; ++i) {
        if (occ_[to_size(j * cols_ + i)]) continue;
        int n = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const index_t a = i + di, b = j + dj;
            if ((di || dj) && a >= 0 && b >= 0 && a < cols_ && b < rows_ && occ_[to_size(b * cols_ + a)]) ++n;
          }
        if (n > best_n) {
          best_n = n;
          best = j * cols_ + i;
        }
      }
    return best;
  }

  struct sample {
    vec3 p, n;
  };
  std::vector<sample> samples_in(const xy_rect& w) {
    std::vector<sample> s;
    for (std::size_t i = 0; i < elems_.size(); ++i) {
      if (!alive_[i] || !w.overlaps(elems_[i].box)) continue;
      if (normals_[i].empty()) normals_[i] = vertex_normals(elems_[i].mesh);
      const auto& m = elems_[i].mesh;
      for (std::size_t v = 0; v < m.positions.size(); ++v)
        if (w.contains(m.positions[v])) s.push_back({m.positions[v], normals_[i][v]});
    }
    if (static_cast<int>(s.size()) > p_.max_samples) {
      std::vector<sample> sub;
      const double step = double(s.size()) / p_.max_samples;
      for (int i = 0; i < p_.max_samples; ++i) sub.push_back(s[to_size(i * step)]);
      s = std::move(sub);
    }
    return s;
  }

  // The part of an exemplar element inside `clip` (capped where cut); one element per component.
  std::vector<texture_element> clipped(const tri_mesh& m, const xy_rect& clip) {
    tri_mesh cur = m;
    const double snap = clip_snap_fraction * cell_;
    const struct {
      int axis;
      double value;
      bool keep_above;
    } planes[4] = {{0, clip.x0, true}, {0, clip.x1, false}, {1, clip.y0, true}, {1, clip.y1, false}};
    for (const auto& pl : planes) {
      const aabb b = bounding_box(cur);
      if (pl.keep_above ? b.min[pl.axis] >= pl.value : b.max[pl.axis] <= pl.value) continue;
      auto sp = split_mesh_by_plane(cur, pl.axis, pl.value, snap);
      cur = pl.keep_above ? std::move(sp.above) : std::move(sp.below);
      compact_vertices(cur);
      if (cur.faces.empty()) return {};
      if (!cap_plane_loops(cur, pl.axis, pl.value)) return {};
    }
    auto parts = extract_elements(cur, {.require_closed = true, .require_manifold = true});
    if (!parts) return {};
    return std::move(*parts);
  }

  bool intersects_alive(const texture_element& e, const std::vector<std::size_t>& skip) {
    const triangle_bvh b(e.mesh);
    for (std::size_t i = 0; i < elems_.size(); ++i) {
      if (!alive_[i] || std::find(skip.begin(), skip.end(), i) != skip.end()) continue;
      if (!boxes_overlap(elems_[i].box, e.box)) continue;
      bool hit = false;
      for_each_intersecting_pair(b, bvh_of(i), [&](index_t, index_t) { hit = true; });
      if (hit) return true;
    }
    return false;
  }

  void place_patch(vec3 t, const xy_rect& w) {
    auto in_new = [&](vec3 p) { return w.contains(p) && !occupied(p); };
    merge_params mp;
    mp.domain = domain_;
    mp.constrained = p_.constrained;
    mp.corr_dist = corr_;
    mp.mu = p_.deform_weight;
    mp.smooth_rings = p_.smooth_rings;
    mp.rules = p_.rules;
    mp.margin = inside_margin_fraction * cell_;
    mp.is_old = [&](vec3 p) { return occupied(p); };
    mp.in_patch = [&](vec3 p) { return w.contains(p); };
    // §3.3.4: correspondences output element -> exemplar element (votes of its vertices in P_T)
    std::map<index_t, std::vector<std::pair<index_t, std::size_t>>>
        partners;  // exemplar element -> (-votes, output element)
    for (std::size_t i = 0; i < elems_.size() && p_.merge; ++i) {
      if (!alive_[i] || !w.overlaps(elems_[i].box)) continue;
      std::map<index_t, index_t> votes;
      index_t n = 0;
      for (const vec3& v : elems_[i].mesh.positions) {
        if (!w.contains(v)) continue;
        ++n;
        const auto h = ex_.bvh().closest_point(v - t, corr_ * corr_);
        if (h.face >= 0) ++votes[ex_.element_of_face(h.face)];
      }
      index_t best_e = -1, best_v = 0;
      for (const auto& [e, c] : votes)
        if (c > best_v) {
          best_v = c;
          best_e = e;
        }
      if (best_e >= 0 && best_v >= std::max<index_t>(min_partner_votes, n / partner_vote_share))
        partners[best_e].push_back({-best_v, i});
    }
    const double in = long_clip_inset_cells * cell_;
    const xy_rect inset{domain_.x0 + in, domain_.y0 + in, domain_.x1 - in, domain_.y1 - in};
    for (index_t e = 0; e < ex_.num_elements(); ++e) {
      aabb box = ex_.elements()[to_size(e)].box;
      box.min += t;
      box.max += t;
      if (!w.overlaps(box)) continue;
      tri_mesh moved = ex_.elements()[to_size(e)].mesh;
      for (vec3& q : moved.positions) q += t;
      std::vector<texture_element> pieces;
      if (ex_.is_long(e)) {
        xy_rect clip{std::max(w.x0, inset.x0), std::max(w.y0, inset.y0), std::min(w.x1, inset.x1),
                     std::min(w.y1, inset.y1)};
        if (p_.thread_joins) {
          // a thread is cut only across its length: the window's sides along it would slice it
          // lengthwise into a ribbon; it belongs to the window that holds its middle line
          const vec3 x = box.extent(), c = box.center();
          const int along = x.x >= x.y ? 0 : 1;
          if (x[1 - along] < long_lateral_share * x[along]) {
            const double lo = along == 0 ? w.y0 : w.x0, hi = along == 0 ? w.y1 : w.x1;
            if (c[1 - along] < lo || c[1 - along] >= hi) continue;
            if (along == 0) {
              clip.y0 = inset.y0;
              clip.y1 = inset.y1;
            } else {
              clip.x0 = inset.x0;
              clip.x1 = inset.x1;
            }
          }
        }
        pieces = clipped(moved, clip);
      } else {
        texture_element el;
        el.mesh = std::move(moved);
        el.fixed.assign(el.mesh.positions.size(), 0);
        el.update_box();
        pieces.push_back(std::move(el));
      }
      auto it = partners.find(e);
      mp.thread_pieces = p_.thread_joins && ex_.is_long(e);
      for (auto& cin : pieces) {
        std::vector<std::pair<index_t, std::size_t>> mine;
        if (it != partners.end())
          for (const auto& pr : it->second)
            if (alive_[pr.second] && boxes_overlap(elems_[pr.second].box, cin.box)) mine.push_back(pr);
        std::sort(mine.begin(), mine.end());
        bool reaches_new = false;
        for (const vec3& q : cin.mesh.positions) reaches_new = reaches_new || in_new(q);
        if (!mine.empty()) {
          if (!reaches_new) continue;
          if (!p_.merge_whole && !ex_.is_long(e)) {  // a whole element stands there already
            ++stats_.elements_skipped;
            continue;
          }
          if (mp.thread_pieces && thread_covered(cin, mine)) {  // the thread stands there already
            ++stats_.elements_skipped;
            continue;
          }
          texture_element cur = std::move(cin);
          std::vector<std::size_t> consumed;
          for (const auto& pr : mine) {
            merge_counters mc;
            auto merged = merge_pair(elems_[pr.second], cur, mp, mc);
            stats_.merges_attempted += mc.attempted;
            stats_.merges_succeeded += mc.merged;
            stats_.merge_fail_correspondence += mc.fail_correspondence;
            stats_.merge_fail_deform += mc.fail_deform;
            stats_.merge_fail_cut += mc.fail_cut;
            stats_.merge_fail_loops += mc.fail_loops;
            stats_.merge_fail_check += mc.fail_check;
            stats_.merges_plane_cut += mc.plane_cut;
            if (!merged) break;
            cur = std::move(*merged);
            consumed.push_back(pr.second);
          }
          if (consumed.empty() || intersects_alive(cur, consumed)) {
            ++stats_.elements_dropped;
            continue;
          }
          for (std::size_t c : consumed) alive_[c] = 0;
          push(std::move(cur));
          ++stats_.elements_merged;
          continue;
        }
        // no correspondence: added whole when it belongs to the new region (§3.3.6)
        const vec3 c = cin.box.center();
        if (!in_new({c.x, c.y, 0})) continue;
        bool ok = true;
        if (p_.constrained) {
          // an element reaching a little across a tile side is moved back inside by as much (at most
          // nudge_diameters element diameters) rather than dropped: the bands along tile borders
          // would otherwise stay emptier than the inside, since nothing may cross a tile side there
          const double m = 2 * inside_margin_fraction * cell_;
          const double dx =
              std::max(0.0, domain_.x0 + m - cin.box.min.x) - std::max(0.0, cin.box.max.x - domain_.x1 + m);
          const double dy =
              std::max(0.0, domain_.y0 + m - cin.box.min.y) - std::max(0.0, cin.box.max.y - domain_.y1 + m);
          if (p_.nudge_inside && (dx != 0 || dy != 0) &&
              std::max(std::abs(dx), std::abs(dy)) <= nudge_diameters * ex_.element_diameter()) {
            for (vec3& q : cin.mesh.positions) q += vec3{dx, dy, 0};
            cin.update_box();
            ++stats_.elements_nudged;
          }
          for (const vec3& q : cin.mesh.positions)
            ok = ok && strictly_inside(domain_, q, inside_margin_fraction * cell_);
        }
        if (!ok || intersects_alive(cin, {})) {
          ++stats_.elements_dropped;
          if (!ex_.is_long(e)) dropped_cells_.push_back(cell_of({c.x, c.y, 0}));
          continue;
        }
        push(std::move(cin), true);
        ++stats_.elements_added;
      }
    }
  }

  /// Grid counts and translation ranges in cells are rounded with this slack, so that a length a
  /// whole number of cells long (up to floating-point rounding) gets no extra cell.
  static constexpr double cell_rounding = 1e-9;
  /// ICP (eq. 5) stops when its translation step is below this fraction of a cell.
  static constexpr double icp_tolerance_cells = 1e-3;
  /// An output element in the patch pairs with the exemplar element most of its vertices
  /// correspond to, when those votes are at least min_partner_votes and 1 / partner_vote_share of
  /// its vertices in the patch (fewer: the two only touch, and merging them would fail).
  static constexpr index_t min_partner_votes = 3, partner_vote_share = 5;
  /// Long elements (threads) are clipped this fraction of a cell inside the domain, so that their
  /// caps lie strictly inside it.
  static constexpr double long_clip_inset_cells = 1e-6;
  /// A long element narrower across than this share of its length is a thread: windows cut it only
  /// across its length.
  static constexpr double long_lateral_share = 0.5;
  /// A thread piece spanned by a partner to within this fraction of a cell at both ends is skipped.
  static constexpr double thread_cover_cells = 0.01;
  /// Constrained quilting moves an element that reaches at most this many element diameters across a
  /// tile side back inside (then checks it like any other).
  static constexpr double nudge_diameters = 0.35;
  /// The occupancy term chooses among translations within (1 + this x tolerance) of the best eq. 4.
  static constexpr double occupancy_tolerance_factor = 3.0;
  /// Hole filling: raster pixels per exemplar element diameter (at most hole_raster_max_pixels in
  /// all); the empty margin kept around a placed element: the exemplar's (exemplar_clearance at this
  /// quantile), at least this many element diameters; draws per hole, and passes.
  static constexpr double hole_raster_per_diameter = 12;
  static constexpr index_t hole_raster_max_pixels = index_t{1} << 24;
  static constexpr double hole_min_clearance_diameters = 0.04, hole_clearance_quantile = 0.25;
  static constexpr int hole_tries = 4, hole_passes = 3;
  /// Hole filling with relaxation: size classes (quantiles of the exemplar's footprint radii), draws
  /// per class and hole (hole_tries in all), the farthest a neighbour moves (element diameters), and
  /// output elements with a footprint above this factor times the exemplar's largest are not counted
  /// (pieces of long elements).
  static constexpr int hole_size_classes = 4, hole_tries_per_class = 2;
  static constexpr double hole_push_diameters = 0.25, hole_long_footprint_factor = 1.5;
  /// Neighbours are pushed only when the exemplar's largest footprint radius is at least this many
  /// times its smallest (elements of one size: a lattice, whose spacing moving would break).
  static constexpr double hole_relax_size_spread = 1.25;
  /// Past the exemplar's density, holes are still filled where an empty square this many element
  /// diameters wide is centred (texture_quality's empty cells are 1.5 diameters wide).
  static constexpr double hole_empty_diameters = 1.5;
  /// Replacement (replace_small): draws of a large element per place; past the exemplar's covered
  /// share, the small elements it displaces may cover up to this many times its own area.
  static constexpr int hole_replace_tries = 4;
  static constexpr double hole_replace_loss = 1.5;

  const quilt_exemplar& ex_;
  xy_rect domain_;
  mesh_quilt_params p_;
  parallel_for_fn pfor_;
  double cell_ = 1, margin_ = 0, corr_ = 0;
  index_t cols_ = 1, rows_ = 1;
  int k_ = 2;
  std::vector<unsigned char> occ_;
  std::vector<unsigned char> retries_;  // times each cell went back to the seed search
  std::vector<index_t> dropped_cells_;  // cells of the elements the current patch dropped
  std::vector<texture_element> elems_;
  std::vector<unsigned char> alive_;
  std::vector<unsigned char> movable_;  // see push()
  std::vector<std::optional<triangle_bvh>> bvh_;
  std::vector<std::vector<vec3>> normals_;
  mesh_quilt_stats stats_;
};
using quilt_engine = basic_quilt_engine<>;

}  // namespace detail
TESSERA_NAMESPACE_END
