// tessera/geometry/detail/tile_frames.hpp: the frames of planar geometric Wang tiles, paper 000
// §3.1-3.2: choosing one edge strip per colour so that crossing elements keep clear of the tile
// corners and the border elements of horizontal and vertical strips never collide at a corner, and
// building a tile's frame from the halves of its four strips, merging free elements that collide where
// strips overlap (tile border held fixed).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/random.hpp"
#include "../../core/status.hpp"
#include "../../tiling/complete_tile_set.hpp"
#include "../constrained_mesh_quilt.hpp"
#include "../quilt_exemplar.hpp"
#include "edge_strips.hpp"
#include "element_merge.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// What building one tile's frame did: the frame, and the corner merges of §3.2 (free strip elements
/// that collide with elements of another strip where strips overlap: merged, with the tile border
/// held fixed, or dropped).
struct tile_frame_result {
  quilt_frame frame;
  index_t merges_attempted = 0;  ///< merge_pair calls
  index_t merged = 0;            ///< free elements merged into the frame element(s) they hit
  index_t dropped = 0;           ///< free elements left out (a failed merge, or not inside the tile)
};

// Frame of one tile (§3.2): border elements of the four strip halves, then free elements; a free
// element colliding with frame elements where strips overlap is deformed and merged with each of
// them in turn (free or border: the border ones keep their border triangles and fixed vertices, the
// tile border is never moved), or dropped when a merge fails or the result hits another element.
// Border elements of two strips never collide: choose_strips picks vertical strips that fit every
// horizontal one at all four corners.
template <class Deferred = void>  // compiled only where tiles are built (see merge_pair)
tile_frame_result build_frame(const std::vector<edge_strip>& hs, const std::vector<edge_strip>& vs, const wang_edges& e,
                              double w, double hh, double cell, bool merge_free = true) {
  tile_frame_result r;
  struct part {
    std::vector<texture_element> elems;
    xy_rect window;
  };
  const part parts[4] = {{place_half(hs[to_size(e.south)], true, side_south, 0), {0, 0, w, hh}},
                         {place_half(vs[to_size(e.east)], false, side_east, w), {w - hh, 0, w, w}},
                         {place_half(hs[to_size(e.north)], false, side_north, w), {0, w - hh, w, w}},
                         {place_half(vs[to_size(e.west)], true, side_west, 0), {0, 0, hh, w}}};
  std::vector<texture_element>& out = r.frame.elements;
  std::vector<int> owner;  // which part each frame element came from
  for (int i = 0; i < 4; ++i)
    for (const auto& el : parts[i].elems)
      if (el.border) {
        out.push_back(el);
        owner.push_back(i);
      }
  const xy_rect tile{0, 0, w, w};
  auto collides = [&](const texture_element& x, const texture_element& y) {
    if (!boxes_overlap(x.box, y.box)) return false;
    const triangle_bvh bx(x.mesh), by(y.mesh);
    bool hit = false;
    for_each_intersecting_pair(bx, by, [&](index_t, index_t) { hit = true; });
    return hit;
  };
  for (int i = 0; i < 4; ++i)
    for (const auto& el : parts[i].elems) {
      if (el.border) continue;
      bool inside = true;
      for (const vec3& p : el.mesh.positions) inside = inside && strictly_inside(tile, p, inside_margin_fraction * w);
      if (!inside) {
        ++r.dropped;
        continue;
      }
      std::vector<std::size_t> hits;
      for (std::size_t k = 0; k < out.size(); ++k)
        if (collides(out[k], el)) hits.push_back(k);
      if (hits.empty()) {
        out.push_back(el);
        owner.push_back(i);
        continue;
      }
      if (!merge_free) {  // a whole element already stands there (see mesh_quilt_options::merge_whole)
        ++r.dropped;
        continue;
      }
      // merge with every element it hits, the frame element as C_T (its window is the old region)
      std::optional<texture_element> cur = el;
      for (std::size_t k : hits) {
        merge_params mp;
        mp.domain = tile;
        mp.constrained = true;
        mp.corr_dist = 0.5 * cell;
        mp.margin = inside_margin_fraction * w;
        const xy_rect old_w = parts[owner[k]].window, new_w = parts[i].window;
        mp.is_old = [old_w](vec3 p) { return old_w.contains(p); };
        mp.in_patch = [new_w](vec3 p) { return new_w.contains(p); };
        merge_counters mc;
        cur = merge_pair(out[k], *cur, mp, mc);
        r.merges_attempted += mc.attempted;
        if (!cur) break;
      }
      bool clear = cur.has_value();
      for (std::size_t k = 0; k < out.size() && clear; ++k)
        if (std::find(hits.begin(), hits.end(), k) == hits.end()) clear = !collides(out[k], *cur);
      if (!clear) {
        ++r.dropped;
        continue;
      }
      // the merged element replaces the first element it hit; the others it absorbed go
      out[hits[0]] = std::move(*cur);
      for (std::size_t j = hits.size(); j-- > 1;) {
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(hits[j]));
        owner.erase(owner.begin() + static_cast<std::ptrdiff_t>(hits[j]));
      }
      ++r.merged;
    }
  // the cells the frame's elements cover start occupied (§3.3.1); the rest of the strips is filled
  // by the interior synthesis like any other unoccupied cell
  for (const auto& el : out) r.frame.occupied.push_back({el.box.min.x, el.box.min.y, el.box.max.x, el.box.max.y});
  return r;
}

/// True when the border elements of horizontal strip `h` and vertical strip `v` collide at none of a
/// tile's four corners (each strip's halves placed on both of its sides).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool strips_fit(const edge_strip& h, const edge_strip& v, const strip_params& sp) {
  for (int corner = 0; corner < 4; ++corner) {
    const bool north = corner >= 2, east = corner % 2 == 1;
    if (border_elements_collide(place_half(h, !north, north ? side_north : side_south, north ? sp.tile_size : 0.0),
                                place_half(v, !east, east ? side_east : side_west, east ? sp.tile_size : 0.0)))
      return false;
  }
  return true;
}

/// Picks the strip of colour `color` among `cands` (windows of orientation `horizontal`): windows with
/// many crossing elements first (continuity across the edge), random among those (draw keyed by
/// (`key`, color, window)), away from the windows of the strips in `mine` while half the windows
/// remain, and accepted by `fits` (the corner test against strips already chosen). At most 400
/// windows are cut. False when none fits.
template <class Fits>
bool pick_strip(const quilt_exemplar& src, bool horizontal, std::uint64_t key, int color,
                const std::vector<strip_candidate>& cands, const std::vector<const edge_strip*>& mine,
                const strip_params& sp, const counter_rng& rng, Fits&& fits, edge_strip& out) {
  std::vector<std::size_t> order(cands.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::vector<double> rank(cands.size());
  for (std::size_t i = 0; i < cands.size(); ++i) rank[i] = -double(cands[i].crossing) - rng.uniform(key, color, i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return rank[x] < rank[y] || (rank[x] == rank[y] && x < y); });
  const int a = horizontal ? 0 : 1, b = horizontal ? 1 : 0;
  int tries = 0;
  for (std::size_t i : order) {
    const strip_candidate& c = cands[i];
    bool far = true;
    for (const edge_strip* s : mine)
      far = far && (std::abs(s->origin[a] - c.along0) > 0.5 * sp.tile_size ||
                    std::abs(s->origin[b] - c.across0) > sp.half_height);
    if (!far && tries < static_cast<int>(order.size()) / 2) continue;
    if (++tries > 400) break;
    edge_strip s;
    if (!extract_strip(src, horizontal, sp, c, s)) continue;
    if (!fits(s)) continue;
    out = std::move(s);
    return true;
  }
  return false;
}

/// The lookahead of the strip choice looks at most this many windows of the other orientation (as
/// many as pick_strip cuts).
inline constexpr std::size_t strip_lookahead_windows = 400;

/// The windows of `cands` that the strip choice looks ahead to, extracted on demand: the first
/// strip_lookahead_windows by crossing elements (most first, then window order).
class strip_lookahead {
 public:
  strip_lookahead(const quilt_exemplar& src, bool horizontal, const strip_params& sp,
                  const std::vector<strip_candidate>& cands)
      : src_(src), horizontal_(horizontal), sp_(sp), cands_(cands) {
    for (std::size_t i = 0; i < cands.size(); ++i) order_.push_back(i);
    std::stable_sort(order_.begin(), order_.end(),
                     [&](std::size_t x, std::size_t y) { return cands[x].crossing > cands[y].crossing; });
    order_.resize(std::min(order_.size(), strip_lookahead_windows));
    strips_.resize(order_.size());
    state_.assign(order_.size(), 0);
  }
  /// True when some window's strip passes `fits`.
  template <class Fits>
  bool any(Fits&& fits) {
    for (std::size_t k = 0; k < order_.size(); ++k) {
      if (state_[k] == 0) state_[k] = extract_strip(src_, horizontal_, sp_, cands_[order_[k]], strips_[k]) ? 1 : 2;
      if (state_[k] == 1 && fits(strips_[k])) return true;
    }
    return false;
  }

 private:
  const quilt_exemplar& src_;
  bool horizontal_;
  strip_params sp_;
  const std::vector<strip_candidate>& cands_;
  std::vector<std::size_t> order_;
  std::vector<edge_strip> strips_;
  std::vector<unsigned char> state_;  // 0 not extracted, 1 extracted, 2 cannot be cut
};

/// The strips of a planar set (§3.1): nh horizontal strips, then nv vertical strips that fit every
/// horizontal one at all four tile corners (strips_fit). A horizontal strip is taken only when some
/// vertical window (strip_lookahead) fits it and the horizontal strips taken before: in a lattice of
/// crossing threads (weave) two horizontal strips cut at different phases leave no vertical strip
/// that fits both, and the choice used to fail there.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
status choose_strips(const quilt_exemplar& src, int horizontal_colors, int vertical_colors, const strip_params& sp,
                     std::uint64_t seed, std::vector<edge_strip>& hs, std::vector<edge_strip>& vs) {
  const double step = 0.5 * src.cell_size();
  const counter_rng rng(seed, stream_id("geometry.wang.strips"));
  const auto hc = strip_candidates(src, true, sp, step), vc = strip_candidates(src, false, sp, step);
  std::vector<const edge_strip*> mine;
  hs.reserve(static_cast<std::size_t>(horizontal_colors));
  vs.reserve(static_cast<std::size_t>(vertical_colors));
  strip_lookahead ahead(src, false, sp, vc);
  for (int c = 0; c < horizontal_colors; ++c) {
    edge_strip s;
    const auto leaves_a_vertical = [&](const edge_strip& h) {
      return ahead.any([&](const edge_strip& v) {
        if (!strips_fit(h, v, sp)) return false;
        for (const edge_strip& earlier : hs)
          if (!strips_fit(earlier, v, sp)) return false;
        return true;
      });
    };
    if (!pick_strip(src, true, 1, c, hc, mine, sp, rng, leaves_a_vertical, s))
      return status::invalid_argument(detail::cat(
          "geometric wang tiles: no horizontal edge strip of width ", sp.tile_size, " and height ", 2 * sp.half_height,
          " avoids elements crossing the tile corners and leaves a vertical strip that fits it there (", hc.size(),
          " candidate windows); try another tile_size, edge_height or corner_margin"));
    hs.push_back(std::move(s));
    mine.push_back(&hs.back());
  }
  mine.clear();
  for (int c = 0; c < vertical_colors; ++c) {
    edge_strip s;
    const auto fits = [&](const edge_strip& v) {
      for (const edge_strip& h : hs)
        if (!strips_fit(h, v, sp)) return false;
      return true;
    };
    if (!pick_strip(src, false, 2, c, vc, mine, sp, rng, fits, s))
      return status::invalid_argument(
          detail::cat("geometric wang tiles: no vertical edge strip of width ", sp.tile_size, " and height ",
                      2 * sp.half_height, " fits every horizontal strip at the tile corners (", vc.size(),
                      " candidate windows); try another tile_size, edge_height or corner_margin"));
    vs.push_back(std::move(s));
    mine.push_back(&vs.back());
  }
  return {};
}

}  // namespace detail
TESSERA_NAMESPACE_END
