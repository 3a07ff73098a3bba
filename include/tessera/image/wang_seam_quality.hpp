// tessera/image/wang_seam_quality.hpp: how well the tiles of a Wang tile set continue each other.
// For every ordered pair of tiles that can touch — A west of B when A's east colour is B's west
// colour, A north of B when A's south colour is B's north colour — the seam gradient ratio
// (image/metrics.hpp) across their shared edge against the exemplar's own gradients: about 1 means
// the edge is as smooth as the exemplar itself, 2 and more a visible seam.
#pragma once

#include <algorithm>
#include <cstring>
#include <span>
#include <vector>

#include "../core/config.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"
#include "../tiling/tile_lookup.hpp"
#include "metrics.hpp"
#include "wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN

/// The ratio of one touching pair.
struct wang_pair_seam {
  index_t first = 0;     ///< west (or north) tile
  index_t second = 0;    ///< east (or south) tile
  bool vertical = true;  ///< true: first | second side by side; false: first above second
  /// The pair's seam gradient ratio (metrics.hpp seam_gradient_ratio; 1: no more visible than the exemplar's own gradients).
  double ratio = 0;
};

/// Seam figures of a whole set.
struct wang_seam_report {
  std::vector<wang_pair_seam> pairs;  ///< every pair that can touch, horizontal pairs first
  /// Mean ratio over the pairs.
  double mean_ratio = 0;
  /// Largest ratio.
  double max_ratio = 0;
  wang_pair_seam worst;  ///< the pair with the largest ratio
};

/// Largest number of touching pairs wang_seam_quality() measures (2^20; a complete set of 7 x 7
/// colours has 1.6 million). Larger sets return size_overflow.
inline constexpr index_t max_wang_seam_pairs = index_t{1} << 20;

/// Measures every pair of tiles of `set` that can touch (see the header comment) with
/// seam_gradient_ratio against `exemplar`.
/// Errors: empty set or exemplar; more than max_wang_seam_pairs pairs (size_overflow); a NaN or
/// infinite value in a float exemplar (names the pixel); an exemplar without gradients (flat).
/// Complexity O(pairs · (tile pixels + exemplar pixels)); pairs ≤ 2 n² for n tiles. Thread safety: pure.
template <Channel T, int C, Image E>
[[nodiscard]] result<wang_seam_report> wang_seam_quality(const wang_tile_set<T, C>& set, const E& exemplar) {
  if (set.size() == 0) return status::invalid_argument("wang_seam_quality: the tile set is empty");
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  {
    index_t pairs = 0;
    for (index_t a = 0; a < set.size(); ++a)
      pairs += static_cast<index_t>(set.edges().with_west(set.edges()[a].east).size() +
                                    set.edges().with_north(set.edges()[a].south).size());
    if (pairs > max_wang_seam_pairs)
      return status::size_overflow(
          detail::cat("wang_seam_quality: the set's ", set.size(), " tiles form ", pairs,
                      " touching pairs, more than max_wang_seam_pairs = ", max_wang_seam_pairs));
  }
  auto reference = to_buffer<float, C>(exemplar, "exemplar");
  if (!reference) return reference.error();
  const index_t ts = set.tile_size();
  const tile_set_edges& edges = set.edges();
  wang_seam_report report;
  image_buffer<T, C> side_by_side(2 * ts, ts), stacked(ts, 2 * ts);
  for (int vertical = 1; vertical >= 0; --vertical)
    for (index_t a = 0; a < set.size(); ++a) {
      const auto partners = vertical ? edges.with_west(edges[a].east) : edges.with_north(edges[a].south);
      for (index_t b : partners) {
        image_buffer<T, C>& img = vertical ? side_by_side : stacked;
        for (index_t y = 0; y < ts; ++y) {
          const std::size_t row = detail::to_size(ts * C) * sizeof(T);
          if (vertical) {
            std::memcpy(img.pixel_ptr(0, y), set.tile_row(a, y), row);
            std::memcpy(img.pixel_ptr(ts, y), set.tile_row(b, y), row);
          } else {
            std::memcpy(img.pixel_ptr(0, y), set.tile_row(a, y), row);
            std::memcpy(img.pixel_ptr(0, ts + y), set.tile_row(b, y), row);
          }
        }
        const seam_segment seam{vertical != 0, ts, 0, ts};
        auto r = seam_gradient_ratio(img, std::span<const seam_segment>(&seam, 1), *reference);
        if (!r) return r.error();
        report.pairs.push_back({a, b, vertical != 0, *r});
      }
    }
  double sum = 0;
  for (std::size_t i = 0; i < report.pairs.size(); ++i) {
    const wang_pair_seam& p = report.pairs[i];
    sum += p.ratio;
    if (i == 0 || p.ratio > report.max_ratio) {
      report.max_ratio = p.ratio;
      report.worst = p;
    }
  }
  report.mean_ratio = report.pairs.empty() ? 0 : sum / static_cast<double>(report.pairs.size());
  return report;
}

/// The tile borders inside a width × height image showing the plane window whose top-left pixel is
/// plane pixel (x, y), as seam_segments (for seam_gradient_ratio of a composed image).
inline std::vector<seam_segment> tile_border_seams(index_t width, index_t height, index_t tile_size, index_t x = 0,
                                                   index_t y = 0) {
  std::vector<seam_segment> seams;
  if (tile_size <= 0 || width <= 0 || height <= 0) return seams;
  for (index_t px = 1; px < width; ++px)
    if ((x + px) % tile_size == 0) seams.push_back({true, px, 0, height});
  for (index_t py = 1; py < height; ++py)
    if ((y + py) % tile_size == 0) seams.push_back({false, py, 0, width});
  return seams;
}

TESSERA_NAMESPACE_END
