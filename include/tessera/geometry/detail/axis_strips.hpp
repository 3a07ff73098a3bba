// tessera/geometry/detail/axis_strips.hpp: the edge strips of three-axis geometric Wang tiles, paper
// 000 §3.1 (Fig. 2-3): one strip per colour of each axis, nX + nY + nZ in all. A strip is stored in its
// canonical form, a horizontal strip (along = +x, left = +y, height +z). The same strip borders tiles
// of four face directions: as their horizontal edge (north / south) on faces whose first in-plane axis
// is the strip's axis, as their vertical edge (east / west), turned a quarter, on the others. Every
// tile receives the left half of the strips on its sides 0 and 1 of a quad (south, east: the sides a
// quad traverses along +axis) and the right half on the other two, so the two quads of any polycube
// grid edge, coplanar or meeting at a convex or concave polycube edge, hold the two halves of the same
// strip, cut on the same line (docs/geometry.md, "Three-axis sets").
#pragma once

#include <array>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/random.hpp"
#include "../../core/status.hpp"
#include "../../tiling/axis_tile_set.hpp"
#include "../quilt_exemplar.hpp"
#include "edge_strips.hpp"
#include "tile_frames.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// The vertical form of a canonical (horizontal) strip: every point turned a quarter counter-clockwise,
/// (x, y) -> (-y, x), so the strip runs along +y. Its left half (y >= 0) lands on x <= 0, the half a
/// tile's east side takes, and its right half on x >= 0, the west side's (a vertical strip's `negative`
/// and `positive`, as edge_strip names them). Exact: cut vertices on y = 0 land on x = +0.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
edge_strip quarter_turn(const edge_strip& h) {
  edge_strip v;
  v.horizontal = false;
  v.origin = h.origin;
  v.crossing = h.crossing;
  auto turn = [](std::vector<texture_element> els) {
    for (auto& e : els) {
      for (vec3& p : e.mesh.positions) p = {0.0 - p.y, p.x, p.z};
      e.update_box();
    }
    return els;
  };
  v.negative = turn(h.positive);
  v.positive = turn(h.negative);
  return v;
}

/// The strips of a three-axis set: per axis, its colours' strips in canonical (horizontal) form and
/// turned a quarter (vertical form).
struct axis_strip_set {
  std::array<std::vector<edge_strip>, 3> horizontal, vertical;
};

/// Chooses the nX + nY + nZ strips (§3.1) from horizontal windows of `src`: X strips first, then Y
/// strips that fit every X strip, then Z strips that fit every X and Y strip. Two axes a, b share the
/// faces ±c, where a is the horizontal axis of one and b of the other, so a new strip must fit each
/// earlier strip of another axis at the four tile corners in both roles (strips_fit(new, earlier
/// turned) and strips_fit(earlier, new turned)). Windows already used by any axis are avoided while
/// half the windows remain. A strip is taken only when every later axis keeps some window
/// (strip_lookahead) that fits it and the strips taken before. Errors: invalid_argument naming the
/// axis when no window fits.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
status choose_axis_strips(const quilt_exemplar& src, const axis_color_counts& n, const strip_params& sp,
                          std::uint64_t seed, axis_strip_set& out) {
  const counter_rng rng(seed, stream_id("geometry.wang.axis_strips"));
  const auto cands = strip_candidates(src, true, sp, 0.5 * src.cell_size());
  out = {};
  std::vector<const edge_strip*> mine;
  for (int a = 0; a < 3; ++a) {
    auto& hs = out.horizontal[to_size(a)];
    auto& vs = out.vertical[to_size(a)];
    hs.reserve(to_size(n[to_size(a)]));
    vs.reserve(to_size(n[to_size(a)]));
  }
  // s (of axis a) and t (of another axis) fit at the corners of the faces they share, in both roles
  const auto pair_fits = [&](const edge_strip& s, const edge_strip& s_turned, const edge_strip& t,
                             const edge_strip& t_turned) {
    return strips_fit(s, t_turned, sp) && strips_fit(t, s_turned, sp);
  };
  strip_lookahead ahead(src, true, sp, cands);
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < n[to_size(a)]; ++c) {
      const auto fits = [&](const edge_strip& s) {
        const edge_strip turned = quarter_turn(s);
        for (int b = 0; b < a; ++b)
          for (std::size_t k = 0; k < out.horizontal[to_size(b)].size(); ++k)
            if (!pair_fits(s, turned, out.horizontal[to_size(b)][k], out.vertical[to_size(b)][k])) return false;
        // lookahead: every later axis with colours keeps some window that fits all strips so far and s
        // (in a lattice of crossing threads, strips of different phases leave none)
        for (int b = a + 1; b < 3; ++b) {
          if (n[to_size(b)] == 0) continue;
          const bool some = ahead.any([&](const edge_strip& t) {
            const edge_strip t_turned = quarter_turn(t);
            if (!pair_fits(s, turned, t, t_turned)) return false;
            for (int x = 0; x <= a; ++x)
              for (std::size_t k = 0; k < out.horizontal[to_size(x)].size(); ++k)
                if (x != b && !pair_fits(out.horizontal[to_size(x)][k], out.vertical[to_size(x)][k], t, t_turned))
                  return false;
            return true;
          });
          if (!some) return false;
        }
        return true;
      };
      edge_strip s;
      if (!pick_strip(src, true, static_cast<std::uint64_t>(a), c, cands, mine, sp, rng, fits, s))
        return status::invalid_argument(
            detail::cat("geometric wang tiles: no edge strip of width ", sp.tile_size, " and height ",
                        2 * sp.half_height, " for colour ", c, " of the edges parallel to ", "XYZ"[a],
                        " avoids the tile corners and fits the strips of the other axes there (", cands.size(),
                        " candidate windows); try another tile_size, edge_height or corner_margin, or fewer colours"));
      out.vertical[to_size(a)].push_back(quarter_turn(s));
      out.horizontal[to_size(a)].push_back(std::move(s));
      mine.push_back(&out.horizontal[to_size(a)].back());
    }
  return {};
}

}  // namespace detail
TESSERA_NAMESPACE_END
