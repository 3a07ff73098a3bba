// tessera/image/detail/wang_edge_samples.hpp: the corner sample, the edge samples and the frame of the
// tiles of an image Wang tile set (image/wang_tiles.hpp). Internal.
//
// Cohen et al. take one exemplar strip per edge colour; where two strips meet at a tile corner the
// tiles then disagree (the "corner problem"), so no atlas can be sampled exactly across corners.
// Here every tile corner of the tiled plane shows the same corner sample K: a calm 2·D × 2·D
// exemplar window centred on the corner point (chosen where the texture is calm across the edge
// lines through it), D being the fixed border. A horizontal colour's strip
// is ts × 2·ov pixels centred on the edge line (rows [0, ov) end the tile above, rows [ov, 2·ov)
// start the tile below; vertical strips are the transpose); within D of the edge line its two ends
// are K's halves (fixed), and the rest is synthesized by constrained quilting continuing them. So
// within D of a tile's side its pixels depend only on that side's colour, and within D of a corner
// they are the same in every tile: exactly what bilinear filtering and D-texel-deep mip levels of an
// atlas need (image/wang_atlas.hpp). The price: K repeats at every tile corner of the plane.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/executor.hpp"
#include "../../core/image_buffer.hpp"
#include "../../core/random.hpp"
#include "../../core/status.hpp"
#include "../../tiling/complete_tile_set.hpp"
#include "quilt_kernel.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Absolute slack on the accepted-cost limit best * (1 + tolerance): candidates within it of the best
/// count as ties even when best is 0 or rounding separates equal costs.
inline constexpr double edge_cost_tie_slack = 1e-12;

struct strip_origin {
  index_t x = 0, y = 0;
};

/// The corner sample and one strip per edge colour.
template <Channel T, int C>
struct wang_frame_samples {
  index_t ts = 0, ov = 0, border = 0;
  image_buffer<T, C> corner;                   ///< K: 2·border × 2·border, centred on a tile corner point
  std::vector<image_buffer<T, C>> horizontal;  ///< ts × 2·ov, centred on a horizontal edge
  std::vector<image_buffer<T, C>> vertical;    ///< 2·ov × ts, centred on a vertical edge
};

/// Origin of the corner sample: the 2d × 2d exemplar window whose centre lines (the tile edges
/// through the corner point) cross the calmest texture, i.e. the smallest summed squared
/// differences between rows d − 1 and d and between columns d − 1 and d, drawn among those within
/// (1 + tolerance) of the best. Every strip continues the corner sample, so the edges of the whole
/// set follow its phase: placed where a structured texture (a weave, bricks) is calm, the edge
/// rows stay as smooth as the exemplar.
template <Channel T, int C>
void choose_corner(const quilt_source<T, C>& src, index_t d, double tolerance, const counter_rng& rng, index_t& ox,
                   index_t& oy) {
  const index_t w = src.width(), h = src.height(), k = 2 * d, U = w - k + 1, V = h - k + 1;
  auto at = [&](int c, index_t x, index_t y) { return static_cast<double>(src.planes[to_size((c * h + y) * w + x)]); };
  std::vector<double> cost(to_size(U * V), 0.0);
  for (index_t y = 0; y < V; ++y)
    for (index_t x = 0; x < U; ++x) {
      double e = 0;
      for (index_t t = 0; t < k; ++t)
        for (int c = 0; c < C; ++c) {
          const double across_h = at(c, x + t, y + d) - at(c, x + t, y + d - 1);  // horizontal edge line
          const double across_v = at(c, x + d, y + t) - at(c, x + d - 1, y + t);  // vertical edge line
          e += across_h * across_h + across_v * across_v;
        }
      cost[to_size(y * U + x)] = e;
    }
  const double best = *std::min_element(cost.begin(), cost.end());
  const double limit = best * (1 + tolerance) + edge_cost_tie_slack;
  std::uint64_t count = 0;
  for (double e : cost) count += e <= limit;
  std::uint64_t pick = rng.below(count, 0);
  ox = oy = 0;
  for (std::size_t i = 0; i < cost.size(); ++i)
    if (cost[i] <= limit && pick-- == 0) {
      ox = static_cast<index_t>(i) % U;
      oy = static_cast<index_t>(i) / U;
      return;
    }
}

/// Origin of the exemplar sample of strip `colour` of one direction (horizontal: ts × 2·ov), drawn
/// among those within (1 + tolerance) of the best cost, away from the samples already chosen for
/// the same direction (unless the exemplar is too small for distinct ones). The cost is the mean
/// squared difference across the strip's centre line (the tile edge: edges placed where the
/// exemplar is calm stay inconspicuous) plus a quarter of the mean squared difference between the
/// sample's ends and the corner sample they will be joined to (a lighter weight keeps the edges
/// calm; over seven textures and three seeds it gives the lowest seam ratios).
template <Channel T, int C>
strip_origin choose_strip(const quilt_source<T, C>& src, const image_buffer<T, C>& corner, index_t ts, index_t ov,
                          index_t d, const std::vector<strip_origin>& same, int colour, bool horizontal,
                          double tolerance, const counter_rng& rng) {
  const index_t w = horizontal ? ts : 2 * ov, h = horizontal ? 2 * ov : ts;
  const index_t U = src.width() - w + 1, V = src.height() - h + 1;
  auto at = [&](int c, index_t x, index_t y) {
    return static_cast<double>(src.planes[to_size((c * src.height() + y) * src.width() + x)]);
  };
  // (along, across) strip coordinates -> exemplar offsets from the origin
  auto ex = [&](index_t along, index_t across, index_t& x, index_t& y) {
    x = horizontal ? along : across;
    y = horizontal ? across : along;
  };
  std::vector<double> cost(to_size(U * V));
  std::vector<std::uint8_t> distinct(cost.size(), 1);
  bool any_distinct = false;
  for (index_t oy = 0; oy < V; ++oy)
    for (index_t ox = 0; ox < U; ++ox) {
      const std::size_t i = to_size(oy * U + ox);
      for (int k = 0; k < colour; ++k) {
        const strip_origin o = same[to_size(k)];
        if (std::abs(o.x - ox) * 2 < w && std::abs(o.y - oy) * 2 < h) distinct[i] = 0;
      }
      any_distinct = any_distinct || distinct[i];
      double centre = 0, ends = 0;
      for (index_t a = 0; a < ts; ++a)
        for (int c = 0; c < C; ++c) {
          index_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
          ex(a, ov - 1, x0, y0);
          ex(a, ov, x1, y1);
          const double diff = at(c, ox + x1, oy + y1) - at(c, ox + x0, oy + y0);
          centre += diff * diff;
        }
      for (index_t a = 0; a < d; ++a)
        for (index_t b = 0; b < 2 * d; ++b) {
          const T* k0 = horizontal ? corner.pixel_ptr(d + a, b) : corner.pixel_ptr(b, d + a);
          const T* k1 = horizontal ? corner.pixel_ptr(a, b) : corner.pixel_ptr(b, a);
          index_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
          ex(a, ov - d + b, x0, y0);
          ex(ts - d + a, ov - d + b, x1, y1);
          for (int c = 0; c < C; ++c) {
            const double e0 = at(c, ox + x0, oy + y0) - static_cast<double>(channel_to_unit(k0[c]));
            const double e1 = at(c, ox + x1, oy + y1) - static_cast<double>(channel_to_unit(k1[c]));
            ends += e0 * e0 + e1 * e1;
          }
        }
      cost[i] = centre / static_cast<double>(ts) + 0.25 * ends / static_cast<double>(4 * d * d);
    }
  auto allowed = [&](std::size_t i) { return !any_distinct || distinct[i]; };
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < cost.size(); ++i)
    if (allowed(i)) best = std::min(best, cost[i]);
  const double limit = best * (1 + tolerance) + edge_cost_tie_slack;
  std::uint64_t count = 0;
  for (std::size_t i = 0; i < cost.size(); ++i) count += allowed(i) && cost[i] <= limit;
  std::uint64_t k = rng.below(count, horizontal ? 0 : 1, colour);
  for (std::size_t i = 0; i < cost.size(); ++i)
    if (allowed(i) && cost[i] <= limit && k-- == 0) return {static_cast<index_t>(i) % U, static_cast<index_t>(i) / U};
  return {};
}

/// Makes K invariant under quarter turns (x, y) -> (2d - 1 - y, x) about its centre, each orbit of four
/// pixels taking their mean: three-axis sets (image/axis_wang_tiles.hpp) use one strip both along and
/// across a tile, and polycube corners join three or five tile corners, which only a corner sample
/// that looks the same from every side can serve.
template <Channel T, int C>
void make_corner_rotation_symmetric(image_buffer<T, C>& k) {
  const index_t n = k.width();
  for (index_t y = 0; y < n / 2; ++y)
    for (index_t x = 0; x < n / 2; ++x) {
      const index_t xs[4] = {x, n - 1 - y, n - 1 - x, y}, ys[4] = {y, x, n - 1 - y, n - 1 - x};
      for (int c = 0; c < C; ++c) {
        float sum = 0;
        for (int r = 0; r < 4; ++r) sum += channel_to_unit(k.pixel_ptr(xs[r], ys[r])[c]);
        const T mean = unit_to_channel<T>(sum / 4);
        for (int r = 0; r < 4; ++r) k.pixel_ptr(xs[r], ys[r])[c] = mean;
      }
    }
}

/// Builds K and every strip (see the header comment; with `rotation_symmetric_corner`, K is made
/// invariant under quarter turns first): a strip holds its exemplar sample in its
/// middle (along [ov, ts − ov), cuttable), K's halves at its ends (fixed), and the rest is quilted
/// with the tiles' patch size and overlap, joining the ends to the sample by minimum-error cuts. Strips are quilted in
/// parallel through `exec`, each keyed by its colour, so the result does not depend on the executor.
template <Channel T, int C, class X>
status build_frame_samples(const quilt_source<T, C>& src, index_t ts, index_t ov, index_t border, int nh, int nv,
                           const quilt_params& prm, double tolerance, X& exec, wang_frame_samples<T, C>& out,
                           bool rotation_symmetric_corner = false) {
  out.ts = ts;
  out.ov = ov;
  out.border = border;
  const index_t d = border;
  index_t kx = 0, ky = 0;
  choose_corner(src, d, tolerance, prm.rng.substream(7), kx, ky);
  out.corner = image_buffer<T, C>(2 * d, 2 * d);
  for (index_t y = 0; y < 2 * d; ++y)
    std::memcpy(out.corner.pixel_ptr(0, y), src.pixels.pixel_ptr(kx, ky + y), to_size(2 * d * C) * sizeof(T));
  if (rotation_symmetric_corner) make_corner_rotation_symmetric(out.corner);
  // exemplar samples, chosen in order (distinct per direction)
  std::vector<strip_origin> h_origin, v_origin;
  for (int c = 0; c < nh; ++c)
    h_origin.push_back(choose_strip(src, out.corner, ts, ov, d, h_origin, c, true, tolerance, prm.rng.substream(9)));
  for (int c = 0; c < nv; ++c)
    v_origin.push_back(choose_strip(src, out.corner, ts, ov, d, v_origin, c, false, tolerance, prm.rng.substream(9)));
  out.horizontal.assign(to_size(nh), {});
  out.vertical.assign(to_size(nv), {});
  std::vector<status> failures(to_size(nh + nv));
  exec.parallel_for(0, static_cast<index_t>(nh + nv), [&](index_t k) {
    const bool horizontal = k < nh;
    const strip_origin o = horizontal ? h_origin[to_size(k)] : v_origin[to_size(k - nh)];
    quilt_canvas<T, C> canvas(horizontal ? ts : 2 * ov, horizontal ? 2 * ov : ts);
    auto xy = [&](index_t along, index_t across, index_t& x, index_t& y) {
      x = horizontal ? along : across;
      y = horizontal ? across : along;
    };
    for (index_t along = ov; along < ts - ov; ++along)  // the sample, cuttable
      for (index_t across = 0; across < 2 * ov; ++across) {
        index_t x = 0, y = 0;
        xy(along, across, x, y);
        std::memcpy(canvas.pixels.pixel_ptr(x, y), src.pixels.pixel_ptr(o.x + x, o.y + y), sizeof(T) * C);
        canvas.at(x, y) = pixel_state::filled;
      }
    for (index_t a = 0; a < d; ++a)  // K's halves at both ends, fixed
      for (index_t b = 0; b < 2 * d; ++b) {
        index_t sx = 0, sy = 0, ex = 0, ey = 0;
        xy(a, ov - d + b, sx, sy);
        xy(ts - d + a, ov - d + b, ex, ey);
        std::memcpy(canvas.pixels.pixel_ptr(sx, sy),
                    horizontal ? out.corner.pixel_ptr(d + a, b) : out.corner.pixel_ptr(b, d + a), sizeof(T) * C);
        std::memcpy(canvas.pixels.pixel_ptr(ex, ey),
                    horizontal ? out.corner.pixel_ptr(a, b) : out.corner.pixel_ptr(b, a), sizeof(T) * C);
        canvas.at(sx, sy) = canvas.at(ex, ey) = pixel_state::fixed;
      }
    quilt_params local = prm;
    local.patch = std::min(prm.patch, ts);
    local.rng = prm.rng.substream(8);
    local.key = static_cast<std::uint64_t>(k);
    serial_executor serial;
    failures[to_size(k)] = fill_canvas(src, canvas, local, ov, serial);
    (horizontal ? out.horizontal[to_size(k)] : out.vertical[to_size(k - nh)]) = std::move(canvas.pixels);
  });
  for (const status& s : failures)
    if (!s) return s;
  return {};
}

/// Writes the frame of the tile with edges `e` into `canvas` (ts × ts): every pixel within ov of
/// the border takes the nearest edge's strip (at corners both strips hold K where either is within
/// `border`); pixels within `border` of the border are fixed, the rest of the frame is filled
/// (cuttable), except in the corner squares where both distances are at least `border`: those are
/// left empty for the interior quilting, since two strips would meet there along a diagonal.
template <Channel T, int C>
void write_tile_frame(const wang_frame_samples<T, C>& f, const wang_edges& e, quilt_canvas<T, C>& canvas) {
  const index_t ts = f.ts, ov = f.ov, border = f.border;
  auto strip = [](const std::vector<image_buffer<T, C>>& v, int colour) -> const image_buffer<T, C>& {
    return v[to_size(colour)];
  };
  for (index_t j = 0; j < ts; ++j)
    for (index_t i = 0; i < ts; ++i) {
      const index_t dn = j, ds = ts - 1 - j, dw = i, de = ts - 1 - i;
      const index_t d = std::min({dn, ds, dw, de});
      if (d >= ov) continue;
      const bool corner = std::min(dn, ds) < ov && std::min(dw, de) < ov;
      if (corner && d >= border) continue;
      const T* px = nullptr;
      if (dn == d)
        px = strip(f.horizontal, e.north).pixel_ptr(i, ov + j);
      else if (ds == d)
        px = strip(f.horizontal, e.south).pixel_ptr(i, j - (ts - ov));
      else if (dw == d)
        px = strip(f.vertical, e.west).pixel_ptr(ov + i, j);
      else
        px = strip(f.vertical, e.east).pixel_ptr(i - (ts - ov), j);
      std::memcpy(canvas.pixels.pixel_ptr(i, j), px, sizeof(T) * C);
      canvas.at(i, j) = d < border ? pixel_state::fixed : pixel_state::filled;
    }
}

}  // namespace detail
TESSERA_NAMESPACE_END
