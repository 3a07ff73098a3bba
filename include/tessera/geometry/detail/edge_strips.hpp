// tessera/geometry/detail/edge_strips.hpp: edge extraction for geometric Wang tiles, paper 000 §3.1:
// for each edge colour a strip of width w_T (along the edge) and height h_E (across it) is cut out of
// the exemplar, centred on a line that no element crosses near the strip's ends (elements must not
// cross tile corners). Elements crossing the line are split on it, with cut vertices exactly on the
// line and shared by both halves, so the two tiles meeting at that edge get bit-identical borders.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/random.hpp"
#include "../../core/tri_mesh.hpp"
#include "../bvh.hpp"
#include "../mesh_elements.hpp"
#include "../quilt_exemplar.hpp"
#include "mesh_clip.hpp"
#include "triangle_geometry.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// One edge strip in strip-local coordinates: along the edge in [0, w_T], across it in
/// [-h_E / 2, h_E / 2], the edge line at across = 0. Horizontal strips (north/south edges) have x
/// along and y across; vertical strips (east/west edges) have y along and x across.
struct edge_strip {
  bool horizontal = true;
  vec3 origin;  ///< where strip-local (0, 0) lies in the source texture
  /// Halves on the positive (across >= 0) and negative side; border elements (split on the line)
  /// have border = 1 and their border vertices fixed; free elements have border = 0.
  std::vector<texture_element> positive, negative;
  index_t crossing = 0;  ///< elements split on the line
};

/// Strip windows reach the exemplar's far side up to this absolute slack (a window that ends exactly
/// there, up to rounding, is a candidate).
inline constexpr double strip_window_slack = 1e-12;
/// An element counts as inside a strip (or on one side of its centre line) only when it clears the
/// strip's ends and centre line by this fraction of the tile side: rounding cannot put it across.
inline constexpr double strip_clearance_fraction = 1e-7;

struct strip_params {
  double tile_size = 0;            ///< w_T
  double half_height = 0;          ///< h_E / 2
  double corner_margin = 0;        ///< crossing elements stay this far from the strip's ends
  double snap = 0;                 ///< vertices this close to the line are moved onto it
  bool deep_free_elements = true;  ///< free elements may reach past the strip into the tile
};

struct strip_candidate {
  double along0 = 0, across0 = 0;
  index_t crossing = 0;
};

/// Windows of the source where a strip may be cut: crossing elements clear of the ends by the corner
/// margin and (unless long) inside the strip. Positions on a lattice of step `step`.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<strip_candidate> strip_candidates(const quilt_exemplar& src, bool horizontal, const strip_params& sp,
                                              double step) {
  const int a = horizontal ? 0 : 1, b = horizontal ? 1 : 0;
  const aabb& bb = src.bounds();
  std::vector<strip_candidate> out;
  for (double b0 = bb.min[b] + sp.half_height; b0 <= bb.max[b] - sp.half_height + strip_window_slack; b0 += step)
    for (double a0 = bb.min[a]; a0 + sp.tile_size <= bb.max[a] + strip_window_slack; a0 += step) {
      bool ok = true;
      index_t crossing = 0;
      for (index_t e = 0; e < src.num_elements() && ok; ++e) {
        const aabb& x = src.elements()[to_size(e)].box;
        if (x.max[a] < a0 || x.min[a] > a0 + sp.tile_size) continue;
        if (!(x.min[b] < b0 && x.max[b] > b0)) continue;
        ++crossing;
        if (x.min[a] < a0 + sp.corner_margin || x.max[a] > a0 + sp.tile_size - sp.corner_margin) ok = false;
        if (!src.is_long(e) && (x.min[b] < b0 - sp.half_height || x.max[b] > b0 + sp.half_height)) ok = false;
      }
      if (ok) out.push_back({a0, b0, crossing});
    }
  return out;
}

template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<texture_element> split_components(const tri_mesh& m) {
  auto parts = extract_elements(m, {.require_closed = false, .require_manifold = true});
  if (!parts) return {};
  return std::move(*parts);
}

/// Cuts the strip at `c` out of the source. Returns false when an element cannot be cut cleanly
/// (a cap that cannot be triangulated).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool extract_strip(const quilt_exemplar& src, bool horizontal, const strip_params& sp, const strip_candidate& c,
                   edge_strip& out) {
  const int a = horizontal ? 0 : 1, b = horizontal ? 1 : 0;
  out = {};
  out.horizontal = horizontal;
  out.origin[a] = c.along0;
  out.origin[b] = c.across0;
  const double hh = sp.half_height, w = sp.tile_size;
  const double eps = strip_clearance_fraction * w;
  for (index_t e = 0; e < src.num_elements(); ++e) {
    const texture_element& el = src.elements()[to_size(e)];
    const aabb& x = el.box;
    if (x.max[a] < c.along0 || x.min[a] > c.along0 + w || x.max[b] < c.across0 - hh || x.min[b] > c.across0 + hh)
      continue;
    tri_mesh m = el.mesh;
    for (vec3& p : m.positions) {
      p[a] -= c.along0;
      p[b] -= c.across0;
    }
    const bool crossing = x.min[b] < c.across0 && x.max[b] > c.across0;
    if (!crossing) {
      // a free element: kept when it lies on one side of the line, clear of the tile's sides, and
      // starts inside the strip (it may reach past the strip's inner edge into the tile: the frame
      // then keeps the exemplar's own arrangement along the border, which the interior synthesis,
      // unable to place anything across a tile side, could not rebuild there)
      const double lo = x.min[b] - c.across0, hi = x.max[b] - c.across0;
      const bool inside_a = x.min[a] - c.along0 > eps && x.max[a] - c.along0 < w - eps;
      if (!inside_a) continue;
      texture_element f;
      f.mesh = std::move(m);
      f.fixed.assign(f.mesh.positions.size(), 0);
      f.update_box();
      const bool deep = sp.deep_free_elements;
      if (lo > eps && (deep ? lo < hh : hi <= hh))
        out.positive.push_back(std::move(f));
      else if (hi < -eps && (deep ? hi > -hh : lo >= -hh))
        out.negative.push_back(std::move(f));
      continue;
    }
    ++out.crossing;
    // long elements leaving the strip are clipped at its outer edges and capped there
    for (const double lim : {hh, -hh}) {
      const aabb mb = bounding_box(m);
      if (lim > 0 ? mb.max[b] <= lim : mb.min[b] >= lim) continue;
      auto sp2 = split_mesh_by_plane(m, b, lim, sp.snap);
      m = lim > 0 ? std::move(sp2.below) : std::move(sp2.above);
      compact_vertices(m);
      if (!cap_plane_loops(m, b, lim)) return false;
    }
    auto halves = split_mesh_by_plane(m, b, 0.0, sp.snap);
    for (int side = 0; side < 2; ++side) {
      tri_mesh& h = side == 0 ? halves.above : halves.below;
      compact_vertices(h);
      if (h.faces.empty()) continue;
      for (auto& part : split_components(h)) {
        bool touches = false;
        for (const vec3& p : part.mesh.positions) touches = touches || p[b] == 0.0;
        part.fixed.assign(part.mesh.positions.size(), 0);
        if (touches) {
          part.border = 1;
          for (const auto& f : part.mesh.faces) {
            bool on = false;
            for (index_t v : f) on = on || part.mesh.positions[to_size(v)][b] == 0.0;
            if (on)
              for (index_t v : f) part.fixed[to_size(v)] = 1;
          }
        } else if (count_edge_defects(part.mesh).open_edges > 0) {
          continue;  // a sliver cut off without touching the line: cannot be closed, drop it
        }
        part.update_box();
        (side == 0 ? out.positive : out.negative).push_back(std::move(part));
      }
    }
  }
  return true;
}

/// Places a strip half into tile coordinates: `shift` along the across axis (w_T for the north and
/// east sides, which take the negative half), border bit for `side`.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<texture_element> place_half(const edge_strip& s, bool positive, int side, double shift) {
  std::vector<texture_element> out = positive ? s.positive : s.negative;
  const int b = s.horizontal ? 1 : 0;
  for (auto& e : out) {
    if (shift != 0)
      for (vec3& p : e.mesh.positions) p[b] += shift;
    e.border = e.border ? border_bit(side) : 0u;
    e.update_box();
  }
  return out;
}

/// True when some border element of `a` intersects some border element of `b` (tile coordinates).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool border_elements_collide(const std::vector<texture_element>& a, const std::vector<texture_element>& b) {
  for (const auto& x : a) {
    if (!x.border) continue;
    for (const auto& y : b) {
      if (!y.border || !boxes_overlap(x.box, y.box)) continue;
      const triangle_bvh bx(x.mesh), by(y.mesh);
      bool hit = false;
      for_each_intersecting_pair(bx, by, [&](index_t, index_t) { hit = true; });
      if (hit) return true;
    }
  }
  return false;
}

}  // namespace detail
TESSERA_NAMESPACE_END
