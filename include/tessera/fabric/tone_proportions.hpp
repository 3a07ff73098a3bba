// tessera/fabric/tone_proportions.hpp: the main tones of any image and their proportions.
//
// Paper 001 §1.3 asks that the source image have the same main tones S1..Sk, in about the same
// proportions, as the fabric to generate (e.g. P(black) + P(grey) ~ 70 %, P(white) < 30 % for
// figures 4 and 5). Two measurements help a user match a target fabric:
//
//   tone_proportions(img, palette)  share of pixels whose nearest palette colour (Euclidean RGB
//                                   distance, ties to the first tone) is each tone;
//   dominant_tones(img, k)          k-means in RGB: the k dominant colours and their shares, found
//                                   without a palette (for example from a scanned fabric).
//
// Since the cat map only permutes pixels, both are invariant under it. Float images may hold HDR
// values: tone_proportions measures distances to them as they are, dominant_tones bins them clamped
// to [0, 1]. A pixel with a NaN or infinite channel is rejected (invalid_argument naming it), never
// counted as some tone.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "../core/config.hpp"
#include "../core/image.hpp"
#include "../core/image_checks.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "source_image.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// Pixel (x, y) as RGB in [0, 1] (HDR float values kept), or a status naming it when a channel the
/// tone measurements read is NaN or infinite.
template <Image I>
result<unit_rgba> tone_pixel(const I& img, index_t x, index_t y, const char* what) {
  const unit_rgba q = to_unit_rgba(image_traits<I>::read(img, x, y));
  if constexpr (std::is_floating_point_v<channel_t<I>>) {
    for (const float v : {q.r, q.g, q.b})
      if (!std::isfinite(v))
        return status::invalid_argument(cat(what, ": image pixel (", x, ", ", y, ") has a non-finite channel ", v,
                                            "; tones are measured on finite colours only"));
  }
  return q;
}
}  // namespace detail

/// For each palette tone, the fraction of the image's pixels nearest to it (Euclidean distance in
/// RGB [0, 1]; grey images are compared as grey RGB; alpha is ignored; ties go to the smaller index).
/// The fractions sum to 1. The palette's own proportions are not used, only validated.
/// Errors: invalid_argument for an empty image, an invalid palette, or a pixel with a NaN or
/// infinite channel (named with its coordinates). Complexity O(W H k). Thread-safe.
template <Image I>
[[nodiscard]] result<std::vector<double>> tone_proportions(const I& img, const palette& tones) {
  if (auto s = validate_image(img, "tone_proportions: image"); !s) return s;
  if (auto p = normalized_proportions(tones); !p) return p.error();
  std::vector<double> count(tones.size(), 0.0);
  const index_t w = width_of(img), h = height_of(img);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      const auto px = detail::tone_pixel(img, x, y, "tone_proportions");
      if (!px) return px.error();
      const detail::unit_rgba q = *px;
      std::size_t best = 0;
      float best_d = std::numeric_limits<float>::max();
      for (std::size_t t = 0; t < tones.size(); ++t) {
        const float dr = q.r - tones[t].color[0], dg = q.g - tones[t].color[1], db = q.b - tones[t].color[2];
        const float d = dr * dr + dg * dg + db * db;
        if (d < best_d) {
          best_d = d;
          best = t;
        }
      }
      count[best] += 1.0;
    }
  for (double& c : count) c /= static_cast<double>(w * h);
  return count;
}

/// Options of dominant_tones.
struct dominant_tones_options {
  int max_iterations = 50;  ///< Lloyd iterations (stops earlier when the assignment is stable)
  std::uint64_t seed = 1;   ///< k-means++ initialization
};

/// The k dominant colours of an image by k-means in RGB [0, 1], with the share of pixels of each,
/// sorted by decreasing share. Pixels are first binned on a 32^3 colour grid (keeping each bin's
/// exact mean colour), so the cost does not grow with the image beyond one pass; centres start by
/// seeded k-means++ and follow Lloyd's iterations. Fewer than k tones are returned when the image
/// has fewer distinct colour bins. Deterministic for a given seed. HDR float values are binned
/// clamped to [0, 1] (the reported colours are means of the clamped values).
/// Errors: invalid_argument for an empty image, k < 1, max_iterations < 0, or a pixel with a NaN or
/// infinite channel (named with its coordinates).
/// Complexity O(W H + B k iterations), B <= 32768 bins. Thread-safe.
template <Image I>
[[nodiscard]] result<palette> dominant_tones(const I& img, int k, const dominant_tones_options& options = {}) {
  if (auto s = validate_image(img, "dominant_tones: image"); !s) return s;
  if (k < 1) return status::invalid_argument(detail::cat("dominant_tones: k must be >= 1, got ", k));
  if (options.max_iterations < 0)
    return status::invalid_argument(
        detail::cat("dominant_tones: options.max_iterations must be >= 0, got ", options.max_iterations));
  using vec = std::array<double, 3>;
  // bin the pixels: weight and colour sum per occupied bin
  std::vector<double> bin_w(32768, 0.0);
  std::vector<vec> bin_sum(32768, vec{0, 0, 0});
  const index_t w = width_of(img), h = height_of(img);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      const auto px = detail::tone_pixel(img, x, y, "dominant_tones");
      if (!px) return px.error();
      const float r = std::clamp(px->r, 0.0f, 1.0f), g = std::clamp(px->g, 0.0f, 1.0f),
                  b = std::clamp(px->b, 0.0f, 1.0f);
      auto b5 = [](float v) { return std::min(31, static_cast<int>(v * 32.0f)); };
      const auto bin = detail::to_size((b5(r) << 10) | (b5(g) << 5) | b5(b));
      bin_w[bin] += 1;
      bin_sum[bin][0] += r;
      bin_sum[bin][1] += g;
      bin_sum[bin][2] += b;
    }
  std::vector<vec> pts;
  std::vector<double> wt;
  for (std::size_t b = 0; b < bin_w.size(); ++b)
    if (bin_w[b] > 0) {
      pts.push_back({bin_sum[b][0] / bin_w[b], bin_sum[b][1] / bin_w[b], bin_sum[b][2] / bin_w[b]});
      wt.push_back(bin_w[b]);
    }
  const std::size_t kk = std::min(detail::to_size(k), pts.size());
  auto dist2 = [](const vec& a, const vec& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
  };
  // k-means++: the heaviest bin first, then bins drawn with probability ~ weight x squared distance
  const counter_rng rng(options.seed, stream_id("fabric.dominant_tones"));
  std::vector<vec> centre{pts[detail::to_size(std::max_element(wt.begin(), wt.end()) - wt.begin())]};
  std::vector<double> d2(pts.size());
  while (centre.size() < kk) {
    double total = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double best = std::numeric_limits<double>::max();
      for (const vec& c : centre) best = std::min(best, dist2(pts[i], c));
      d2[i] = best * wt[i];
      total += d2[i];
    }
    double r = rng.uniform(centre.size()) * total;
    std::size_t pick = 0;
    while (pick + 1 < pts.size() && (r >= d2[pick] || d2[pick] == 0)) r -= d2[pick++];
    centre.push_back(pts[pick]);
  }
  std::vector<std::size_t> assign(pts.size(), kk);
  for (int it = 0; it <= options.max_iterations; ++it) {
    bool changed = false;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      std::size_t best = 0;
      double best_d = std::numeric_limits<double>::max();
      for (std::size_t c = 0; c < kk; ++c)
        if (const double d = dist2(pts[i], centre[c]); d < best_d) {
          best_d = d;
          best = c;
        }
      changed |= assign[i] != best;
      assign[i] = best;
    }
    if (!changed || it == options.max_iterations) break;
    std::vector<vec> sum(kk, vec{0, 0, 0});
    std::vector<double> cw(kk, 0.0);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      for (int c = 0; c < 3; ++c) sum[assign[i]][detail::to_size(c)] += wt[i] * pts[i][detail::to_size(c)];
      cw[assign[i]] += wt[i];
    }
    for (std::size_t c = 0; c < kk; ++c)
      if (cw[c] > 0) centre[c] = {sum[c][0] / cw[c], sum[c][1] / cw[c], sum[c][2] / cw[c]};
  }
  // report each cluster's exact weighted mean colour and its share of the pixels
  palette out(kk);
  std::vector<vec> sum(kk, vec{0, 0, 0});
  for (std::size_t i = 0; i < pts.size(); ++i) {
    out[assign[i]].proportion += wt[i];
    for (std::size_t c = 0; c < 3; ++c) sum[assign[i]][c] += wt[i] * pts[i][c];
  }
  for (std::size_t c = 0; c < kk; ++c) {
    if (out[c].proportion > 0)
      for (std::size_t ch = 0; ch < 3; ++ch) out[c].color[ch] = static_cast<float>(sum[c][ch] / out[c].proportion);
    out[c].proportion /= static_cast<double>(w * h);
  }
  out.erase(std::remove_if(out.begin(), out.end(), [](const tone& t) { return t.proportion <= 0; }), out.end());
  std::stable_sort(out.begin(), out.end(), [](const tone& a, const tone& b) { return a.proportion > b.proportion; });
  return out;
}

TESSERA_NAMESPACE_END
