// tessera/geometry/geometric_wang_tiles.hpp: planar geometric-texture Wang tiles, paper 000 §3.1-3.2:
// one edge strip per colour is cut out of the exemplar (§3.1; from a larger quilted texture when the
// exemplar is too small); each tile's frame is built from the halves of its four edge strips that lie
// inside it, free elements that collide where strips overlap at the corners are deformed and merged
// (or dropped) with the tile border held fixed (§3.2); the interior is filled by constrained mesh
// quilting (§3.3). The complete set has nh^2 * nv^2 tiles; every tile carrying a colour on a side has
// bit-identical border geometry there, so any valid tiling is continuous.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/tri_mesh.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "constrained_mesh_quilt.hpp"
#include "detail/edge_strips.hpp"
#include "mesh_quilt.hpp"
#include "quilt_exemplar.hpp"

TESSERA_NAMESPACE_BEGIN

struct geometric_wang_options {
  int horizontal_colors = 2;     ///< nh: colours of north/south edges
  int vertical_colors = 2;       ///< nv: colours of east/west edges
  double tile_size = 0;          ///< w_T (required)
  double edge_height = 0;        ///< h_E, strip height across an edge; 0 = 1.5 x the exemplar's element size
  double corner_margin = -1;     ///< crossing elements keep this far from the tile corners; < 0 = 0.15 x element size
  /// When the exemplar cannot hold a strip (smaller than w_T + ...), quilt a larger texture first and
  /// cut the strips from it (§3.1). When false, such exemplars are rejected.
  bool quilt_larger_source = true;
  mesh_quilt_options quilt = {};  ///< interior synthesis (and the larger source); its seed seeds everything
  tessera::progress progress = {};
};

/// A complete planar tile set. Tile i has edges complete_tile_edges(i, nh, nv) and covers
/// [0, tile_size]^2 in XY (north = +Y, east = +X); its border vertices lie exactly on x = 0,
/// x = tile_size, y = 0, y = tile_size.
struct geometric_tile_set {
  double tile_size = 0;
  double edge_height = 0;
  int horizontal_colors = 0, vertical_colors = 0;
  std::vector<wang_edges> edges;
  std::vector<tri_mesh> tiles;
  mesh_quilt_stats stats;           ///< summed over the tiles' interior synthesis
  bool quilted_source = false;      ///< the strips came from a larger quilted texture
  index_t crossing_elements = 0;    ///< elements split on an edge line, over all strips
};

namespace detail {

struct tile_frame_result {
  quilt_frame frame;
  index_t dropped = 0, merged = 0;
};

// Frame of one tile (§3.2): border elements of the four strip halves, then free elements, merged with
// the free elements they collide with where strips overlap (tile border fixed) or dropped.
inline tile_frame_result build_frame(const std::vector<edge_strip>& hs, const std::vector<edge_strip>& vs, const wang_edges& e, double w,
                                     double hh, double cell) {
  tile_frame_result r;
  struct part {
    std::vector<texture_element> elems;
    xy_rect window;
  };
  const part parts[4] = {
      {place_half(hs[static_cast<std::size_t>(e.south)], true, side_south, 0), {0, 0, w, hh}},
      {place_half(vs[static_cast<std::size_t>(e.east)], false, side_east, w), {w - hh, 0, w, w}},
      {place_half(hs[static_cast<std::size_t>(e.north)], false, side_north, w), {0, w - hh, w, w}},
      {place_half(vs[static_cast<std::size_t>(e.west)], true, side_west, 0), {0, 0, hh, w}}};
  std::vector<texture_element>& out = r.frame.elements;
  std::vector<int> owner;  // which part each frame element came from
  for (int i = 0; i < 4; ++i) {
    for (const auto& el : parts[i].elems)
      if (el.border) out.push_back(el), owner.push_back(i);
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
      for (const vec3& p : el.mesh.positions) inside = inside && strictly_inside(tile, p, 1e-7 * w);
      if (!inside) {
        ++r.dropped;
        continue;
      }
      std::vector<std::size_t> hits;
      for (std::size_t k = 0; k < out.size(); ++k)
        if (collides(out[k], el)) hits.push_back(k);
      if (hits.empty()) {
        out.push_back(el), owner.push_back(i);
        continue;
      }
      if (hits.size() == 1 && !out[hits[0]].border) {
        merge_params mp;
        mp.domain = tile;
        mp.constrained = true;
        mp.corr_dist = 0.5 * cell;
        mp.margin = 1e-7 * w;
        const xy_rect old_w = parts[owner[hits[0]]].window, new_w = parts[i].window;
        mp.is_old = [old_w](vec3 p) { return old_w.contains(p); };
        mp.in_patch = [new_w](vec3 p) { return new_w.contains(p); };
        merge_counters mc;
        auto merged = merge_pair(out[hits[0]], el, mp, mc);
        if (merged) {
          bool clear = true;
          for (std::size_t k = 0; k < out.size() && clear; ++k)
            if (k != hits[0]) clear = !collides(out[k], *merged);
          if (clear) {
            out[hits[0]] = std::move(*merged);
            ++r.merged;
            continue;
          }
        }
      }
      ++r.dropped;
    }
  // the cells the frame's elements cover start occupied (§3.3.1); the rest of the strips is filled
  // by the interior synthesis like any other unoccupied cell
  for (const auto& el : out) r.frame.occupied.push_back({el.box.min.x, el.box.min.y, el.box.max.x, el.box.max.y});
  return r;
}

inline status choose_strips(const quilt_exemplar& src, const geometric_wang_options& o, const strip_params& sp, std::uint64_t seed,
                            std::vector<edge_strip>& hs, std::vector<edge_strip>& vs) {
  const double step = 0.5 * src.cell_size();
  const counter_rng rng(seed, stream_id("geometry.wang.strips"));
  auto pick = [&](bool horizontal, int color, std::vector<strip_candidate>& cands, const std::vector<edge_strip>& against,
                  edge_strip& out) -> bool {
    // prefer windows with many crossing elements (continuity across the edge), random among those,
    // away from windows used by other colours
    std::vector<std::size_t> order(cands.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::vector<double> key(cands.size());
    for (std::size_t i = 0; i < cands.size(); ++i) key[i] = -double(cands[i].crossing) - rng.uniform(horizontal ? 1 : 2, color, i);
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return key[x] < key[y] || (key[x] == key[y] && x < y); });
    const std::vector<edge_strip>& mine = horizontal ? hs : vs;
    int tries = 0;
    for (std::size_t i : order) {
      const strip_candidate& c = cands[i];
      bool far = true;
      for (const edge_strip& s : mine) {
        const int a = horizontal ? 0 : 1, b = horizontal ? 1 : 0;
        far = far && (std::abs(s.origin[a] - c.along0) > 0.5 * sp.tile_size || std::abs(s.origin[b] - c.across0) > sp.half_height);
      }
      if (!far && tries < static_cast<int>(order.size()) / 2) continue;
      if (++tries > 400) break;
      edge_strip s;
      if (!extract_strip(src, horizontal, sp, c, s)) continue;
      // vertical strips must not collide with any horizontal strip at any of the four corners
      bool ok = true;
      for (const edge_strip& h : against) {
        for (int corner = 0; corner < 4 && ok; ++corner) {
          const bool north = corner >= 2, east = corner % 2 == 1;
          ok = !border_elements_collide(place_half(h, !north, north ? side_north : side_south, north ? sp.tile_size : 0.0),
                                        place_half(s, !east, east ? side_east : side_west, east ? sp.tile_size : 0.0));
        }
        if (!ok) break;
      }
      if (!ok) continue;
      out = std::move(s);
      return true;
    }
    return false;
  };
  auto hc = strip_candidates(src, true, sp, step), vc = strip_candidates(src, false, sp, step);
  for (int c = 0; c < o.horizontal_colors; ++c) {
    edge_strip s;
    if (!pick(true, c, hc, {}, s))
      return status::invalid_argument(detail::cat("geometric wang tiles: no horizontal edge strip of width ", sp.tile_size, " and height ",
                                                  2 * sp.half_height, " avoids elements crossing the tile corners (", hc.size(),
                                                  " candidate windows); try another tile_size, edge_height or corner_margin"));
    hs.push_back(std::move(s));
  }
  for (int c = 0; c < o.vertical_colors; ++c) {
    edge_strip s;
    if (!pick(false, c, vc, hs, s))
      return status::invalid_argument(detail::cat("geometric wang tiles: no vertical edge strip of width ", sp.tile_size, " and height ",
                                                  2 * sp.half_height, " fits every horizontal strip at the tile corners (", vc.size(),
                                                  " candidate windows); try another tile_size, edge_height or corner_margin"));
    vs.push_back(std::move(s));
  }
  return {};
}

}  // namespace detail

/// Builds the complete planar geometric Wang tile set (nh^2 * nv^2 tiles) from a prepared exemplar,
/// as paper 000 §3.1-3.3 describe. Tiles are synthesized in parallel through `exec`; the result is
/// the same for every executor.
/// Errors: colour counts outside [1, 4096] ("zero colours"), tile_size not positive, edge_height
/// larger than the exemplar or than half the tile, an exemplar smaller than a tile when
/// quilt_larger_source is false, no strip window avoiding the tile corners, bad quilt options;
/// cancelled through options.progress. Time: dominated by nh^2 nv^2 constrained quilts of one tile.
template <Executor E = serial_executor>
result<geometric_tile_set> build_geometric_wang_tiles(const quilt_exemplar& exemplar, const geometric_wang_options& o, E&& exec = {}) {
  if (auto s = validate_color_counts(o.horizontal_colors, o.vertical_colors); !s)
    return status::invalid_argument(detail::cat("geometric wang tiles: ", s.message()));
  if (!(o.tile_size > 0) || !std::isfinite(o.tile_size))
    return status::invalid_argument(detail::cat("geometric wang tiles: tile_size must be > 0, got ", o.tile_size));
  if (exemplar.num_elements() == 0) return status::invalid_argument("geometric wang tiles: the exemplar is empty (not prepared)");
  if (auto s = detail::check_quilt_options(o.quilt); !s) return s;
  const double he = o.edge_height > 0 ? o.edge_height : 1.5 * exemplar.element_diameter();
  if (!(o.edge_height >= 0) || !std::isfinite(o.edge_height))
    return status::invalid_argument(detail::cat("geometric wang tiles: edge_height must be >= 0, got ", o.edge_height));
  const vec3 ext = exemplar.bounds().extent();
  if (he > std::min(ext.x, ext.y))
    return status::invalid_argument(detail::cat("geometric wang tiles: edge_height ", he, " is larger than the exemplar (", ext.x, " x ",
                                                ext.y, ")"));
  if (he > 0.5 * o.tile_size)
    return status::invalid_argument(detail::cat("geometric wang tiles: edge_height ", he, " leaves no interior in a tile of size ",
                                                o.tile_size, "; it must be at most half the tile"));
  const double margin = o.corner_margin >= 0 ? o.corner_margin : 0.15 * exemplar.element_diameter();
  if (!std::isfinite(margin) || margin * 2 >= o.tile_size)
    return status::invalid_argument(detail::cat("geometric wang tiles: corner_margin ", margin, " does not fit a tile of size ", o.tile_size));
  const detail::strip_params sp{o.tile_size, 0.5 * he, margin, 1e-9 * o.tile_size};

  geometric_tile_set set;
  set.tile_size = o.tile_size;
  set.edge_height = he;
  set.horizontal_colors = o.horizontal_colors;
  set.vertical_colors = o.vertical_colors;
  // §3.1: strips from the exemplar, or from a larger quilted texture when it is too small
  const quilt_exemplar* src = &exemplar;
  quilt_exemplar bigger;
  const double need = o.tile_size + 2 * exemplar.cell_size();
  std::vector<detail::edge_strip> hs, vs;
  status picked = status::invalid_argument("geometric wang tiles: exemplar smaller than a tile");
  if (ext.x >= need && ext.y >= need) picked = detail::choose_strips(exemplar, o, sp, o.quilt.seed, hs, vs);
  if (!picked) {
    if (!o.quilt_larger_source)
      return status::invalid_argument(detail::cat("geometric wang tiles: the exemplar (", ext.x, " x ", ext.y, ") cannot hold the edge strips of a ",
                                                  o.tile_size, " tile (", picked.message(), ") and quilt_larger_source is off"));
    const double size = 2 * o.tile_size + 2 * he;
    mesh_quilt_options qo = o.quilt;
    qo.progress = {};
    auto big = mesh_quilt(exemplar, size, size, qo, exec);
    if (!big) return big.error();
    auto prepared = prepare_quilt_exemplar(big->mesh, {.cell_size = exemplar.cell_size()});
    if (!prepared) return prepared.error();
    bigger = std::move(*prepared);
    src = &bigger;
    set.quilted_source = true;
    hs.clear(), vs.clear();
    if (auto s = detail::choose_strips(*src, o, sp, o.quilt.seed, hs, vs); !s) return s;
  }
  for (const auto& s : hs) set.crossing_elements += s.crossing;
  for (const auto& s : vs) set.crossing_elements += s.crossing;

  // §3.2-3.3: frame and interior of every tile, in parallel
  const index_t n = complete_tile_count(o.horizontal_colors, o.vertical_colors);
  set.edges.resize(static_cast<std::size_t>(n));
  set.tiles.resize(static_cast<std::size_t>(n));
  std::vector<mesh_quilt_stats> stats(static_cast<std::size_t>(n));
  std::vector<status> errors(static_cast<std::size_t>(n));
  const index_t batch = 4;
  for (index_t first = 0; first < n; first += batch) {
    if (!o.progress.report(double(first) / double(n), "geometric wang tiles")) return status::cancelled();
    const index_t last = std::min(n, first + batch);
    exec.parallel_for(first, last, [&](index_t t) {
      const wang_edges e = complete_tile_edges(t, o.horizontal_colors, o.vertical_colors);
      set.edges[static_cast<std::size_t>(t)] = e;
      auto fr = detail::build_frame(hs, vs, e, o.tile_size, sp.half_height, exemplar.cell_size());
      mesh_quilt_options qo = o.quilt;
      qo.progress = {};
      if (o.progress.token) qo.progress.token = o.progress.token;
      auto q = constrained_mesh_quilt(exemplar, {0, 0, o.tile_size, o.tile_size}, std::move(fr.frame), qo,
                                      static_cast<std::uint64_t>(t) + 1);
      if (!q) {
        errors[static_cast<std::size_t>(t)] = q.error();
        return;
      }
      stats[static_cast<std::size_t>(t)] = q->stats;
      set.tiles[static_cast<std::size_t>(t)] = std::move(q->mesh);
    });
    for (index_t t = first; t < last; ++t)
      if (!errors[static_cast<std::size_t>(t)]) return errors[static_cast<std::size_t>(t)];
  }
  for (const auto& s : stats) set.stats += s;
  o.progress.report(1.0, "geometric wang tiles");
  return set;
}

/// build_geometric_wang_tiles for any Mesh exemplar (prepared with default options); rejects open or
/// non-manifold exemplars and NaN vertices (see prepare_quilt_exemplar).
template <Mesh M, Executor E = serial_executor>
result<geometric_tile_set> build_geometric_wang_tiles(const M& exemplar, const geometric_wang_options& o, E&& exec = {}) {
  auto ex = prepare_quilt_exemplar(exemplar);
  if (!ex) return ex.error();
  return build_geometric_wang_tiles(*ex, o, exec);
}

TESSERA_NAMESPACE_END
