// tessera/detail/wang_edge_samples.hpp: choosing the exemplar strip each Wang edge colour stands
// for (image/wang_tiles.hpp). Internal.
//
// Cohen et al. pick the samples at random. Structured textures (bricks, weaves) then get tiles whose
// west strip is out of phase with their north strip. Here the horizontal strips are drawn at random
// and then every vertical strip is chosen, among all exemplar positions, to agree with the
// horizontal strips where they would overlap at tile corners: for a vertical candidate the cost is
// the mean squared difference between its corner squares and those of every horizontal strip, over
// the four corner configurations (north-west, north-east, south-west, south-east), plus the mean
// squared difference across the strip's centre line (the tile edge): edges placed where the
// exemplar is calm keep the few pixels that differ across an edge (at tile corners) inconspicuous.
// The horizontal strips are then re-chosen the same way against the vertical ones. A candidate is
// drawn among those within (1 + tolerance) of the best, away from the strips already chosen for the
// same direction.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "quilt_kernel.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

struct strip_origin {
  index_t x = 0, y = 0;
};

struct edge_samples {
  std::vector<strip_origin> horizontal;  // ts × 2·ov strips
  std::vector<strip_origin> vertical;    // 2·ov × ts strips
};

template <Channel T, int C>
class edge_sample_chooser {
 public:
  edge_sample_chooser(const quilt_source<T, C>& src, index_t ts, index_t ov) : src_(src), ts_(ts), ov_(ov) {}

  edge_samples choose(int nh, int nv, double tolerance, const counter_rng& rng) const {
    edge_samples s;
    const index_t ew = src_.width(), eh = src_.height();
    for (int c = 0; c < nh; ++c)
      s.horizontal.push_back({static_cast<index_t>(rng.below(static_cast<std::uint64_t>(ew - ts_ + 1), 0, c, 0)),
                              static_cast<index_t>(rng.below(static_cast<std::uint64_t>(eh - 2 * ov_ + 1), 0, c, 1))});
    s.vertical.resize(static_cast<std::size_t>(nv));
    for (int c = 0; c < nv; ++c) s.vertical[static_cast<std::size_t>(c)] = pick(s.horizontal, s.vertical, c, false, tolerance, rng);
    for (int c = 0; c < nh; ++c) s.horizontal[static_cast<std::size_t>(c)] = pick(s.vertical, s.horizontal, c, true, tolerance, rng);
    return s;
  }

 private:
  [[nodiscard]] float at(int c, index_t x, index_t y) const noexcept {
    return src_.planes[static_cast<std::size_t>((c * src_.height() + y) * src_.width() + x)];
  }
  // mean squared difference across the centre line of a strip (the tile edge it stands for)
  [[nodiscard]] double centre_cost(strip_origin o, bool horizontal) const noexcept {
    double sum = 0;
    for (index_t k = 0; k < ts_; ++k)
      for (int c = 0; c < C; ++c) {
        const double d = horizontal ? static_cast<double>(at(c, o.x + k, o.y + ov_ - 1)) - at(c, o.x + k, o.y + ov_)
                                    : static_cast<double>(at(c, o.x + ov_ - 1, o.y + k)) - at(c, o.x + ov_, o.y + k);
        sum += d * d;
      }
    return sum / static_cast<double>(ts_);
  }
  // SSD over the four corner squares between horizontal strip h and vertical strip v
  [[nodiscard]] double corner_cost(strip_origin h, strip_origin v) const noexcept {
    const index_t ts = ts_, ov = ov_;
    double sum = 0;
    for (int corner = 0; corner < 4; ++corner) {
      const bool south = corner >= 2, east = corner & 1;
      for (index_t j = 0; j < ov; ++j)
        for (index_t i = 0; i < ov; ++i) {
          const index_t ti = east ? ts - ov + i : i, tj = south ? ts - ov + j : j;  // tile coordinates
          const index_t hxp = h.x + ti, hyp = south ? h.y + tj - (ts - ov) : h.y + ov + tj;
          const index_t vxp = east ? v.x + ti - (ts - ov) : v.x + ov + ti, vyp = v.y + tj;
          for (int c = 0; c < C; ++c) {
            const double d = static_cast<double>(at(c, hxp, hyp)) - static_cast<double>(at(c, vxp, vyp));
            sum += d * d;
          }
        }
    }
    return sum;
  }
  // chooses strip `colour` of one direction (horizontal when `horizontal`) against the other's strips
  strip_origin pick(const std::vector<strip_origin>& others, const std::vector<strip_origin>& same, int colour, bool horizontal,
                    double tolerance, const counter_rng& rng) const {
    const index_t w = horizontal ? ts_ : 2 * ov_, h = horizontal ? 2 * ov_ : ts_;
    const index_t U = src_.width() - w + 1, V = src_.height() - h + 1;
    std::vector<double> cost(static_cast<std::size_t>(U * V));
    std::vector<std::uint8_t> distinct(cost.size(), 1);  // away from the strips of other colours of this direction
    bool any_distinct = false;
    for (index_t y = 0; y < V; ++y)
      for (index_t x = 0; x < U; ++x) {
        const std::size_t i = static_cast<std::size_t>(y * U + x);
        for (int k = 0; k < colour; ++k) {
          const strip_origin o = same[static_cast<std::size_t>(k)];
          if (std::abs(o.x - x) * 2 < w && std::abs(o.y - y) * 2 < h) distinct[i] = 0;
        }
        any_distinct = any_distinct || distinct[i];
        double c = 0;
        for (const strip_origin& o : others) c += horizontal ? corner_cost({x, y}, o) : corner_cost(o, {x, y});
        cost[i] = c / static_cast<double>(4 * ov_ * ov_ * static_cast<index_t>(others.size())) + centre_cost({x, y}, horizontal);
      }
    // an exemplar too small for distinct strips allows repeats
    auto allowed = [&](std::size_t i) { return !any_distinct || distinct[i]; };
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < cost.size(); ++i)
      if (allowed(i)) best = std::min(best, cost[i]);
    const double limit = best * (1 + tolerance);
    std::uint64_t count = 0;
    for (std::size_t i = 0; i < cost.size(); ++i) count += allowed(i) && cost[i] <= limit;
    std::uint64_t k = rng.below(count, 2, horizontal ? 0 : 1, colour);
    for (std::size_t i = 0; i < cost.size(); ++i)
      if (allowed(i) && cost[i] <= limit && k-- == 0) return {static_cast<index_t>(i) % U, static_cast<index_t>(i) / U};
    return {};
  }

  const quilt_source<T, C>& src_;
  index_t ts_, ov_;
};

}  // namespace detail
TESSERA_NAMESPACE_END
