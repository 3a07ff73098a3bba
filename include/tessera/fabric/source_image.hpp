// tessera/fabric/source_image.hpp: the "source image" of paper 001 §1.3, built from main tones.
//
// The paper designs a source image whose main tones S1..Sk and their proportions match the fabric to
// generate (figure 3: about 75 % black and 25 % white for flannel and twill); the cat map then only
// rearranges pixels, so the proportions carry over and mixed tones appear as grey to the eye. This
// header builds such images from a palette (colours with proportions) and a layout:
//
//   stripes  bands of feature_size pixels, each band split among the tones in palette order
//   blocks   a grid of feature_size squares, tones shuffled over the blocks with exact counts
//   cells    jittered Voronoi cells about feature_size apart, tones given out by area deficit
//
// Proportions are relative weights: they are normalized to sum to 1 (negative, non-finite or
// all-zero weights are rejected). The other way to get a source (a photo, §1.3) is simply to pass
// any image to cat_map / make_fabric; tone_proportions.hpp measures the tones of any image.
//
//   auto pal = tessera::parse_palette("#000000:0.75,#ffffff:0.25");
//   tessera::image_buffer<std::uint8_t, 3> src(400, 400);
//   auto s = tessera::make_source_image(src, *pal, {.layout = tessera::source_layout::blocks});
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"

TESSERA_NAMESPACE_BEGIN

/// One main tone: an RGB colour in [0, 1] and its share of the image (a relative weight).
struct tone {
  /// Unit RGB colour.
  pixel<float, 3> color{};
  /// Relative share of the image.
  double proportion = 0;
};

/// The main tones of a fabric (S1..Sk of paper 001 §1.3).
using palette = std::vector<tone>;

/// Layouts of a generated source image.
enum class source_layout { stripes, blocks, cells };

/// Options of a generated source image (the palette form of make_fabric).
struct source_image_options {
  /// stripes, blocks or cells.
  source_layout layout = source_layout::stripes;
  index_t feature_size = 0;  ///< stripe period, block side or cell spacing in pixels; 0 = min(W, H) / 8
  bool vertical = false;     ///< stripes: vertical bands instead of horizontal ones
  std::uint64_t seed = 1;    ///< blocks and cells: which arrangement (stripes do not use it)
};

/// Checks a palette and returns its proportions normalized to sum to 1. Errors (invalid_argument,
/// naming the entry): an empty palette, a colour channel outside [0, 1] or NaN, a negative or
/// non-finite proportion, or proportions summing to 0 or overflowing to infinity. Thread-safe.
inline result<std::vector<double>> normalized_proportions(const palette& tones) {
  if (tones.empty()) return status::invalid_argument("palette: it is empty; give at least one tone");
  double sum = 0;
  for (std::size_t i = 0; i < tones.size(); ++i) {
    for (float c : tones[i].color)
      if (!(c >= 0.0f && c <= 1.0f))
        return status::invalid_argument(
            detail::cat("palette: tone ", i, " has a colour channel ", c, " outside [0, 1]"));
    const double p = tones[i].proportion;
    if (!(p >= 0.0) || !std::isfinite(p))
      return status::invalid_argument(
          detail::cat("palette: tone ", i, " has proportion ", p, "; it must be >= 0 and finite"));
    sum += p;
  }
  if (!(sum > 0.0)) return status::invalid_argument("palette: the proportions sum to 0");
  if (!std::isfinite(sum))
    return status::invalid_argument(
        detail::cat("palette: the proportions sum to ", sum, " (overflow); give relative weights of a sane size"));
  std::vector<double> out;
  for (const tone& t : tones) out.push_back(t.proportion / sum);
  return out;
}

/// Parses "#000000:0.75,#ffffff:0.25" (comma-separated `#rrggbb:weight`, the '#' optional) into a
/// palette; weights are relative (see normalized_proportions). Errors: parse_error naming the entry.
inline result<palette> parse_palette(std::string_view text) {
  palette out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    std::string_view item = text.substr(start, end - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    const std::size_t colon = item.find(':');
    std::string_view hex = item.substr(0, colon);
    if (!hex.empty() && hex.front() == '#') hex.remove_prefix(1);
    auto bad = [&](const char* why) {
      return status::parse_error(detail::cat("palette entry '", item, "': ", why, " (expected #rrggbb:weight)"));
    };
    if (colon == std::string_view::npos) return bad("missing ':weight'");
    if (hex.size() != 6) return bad("the colour needs 6 hex digits");
    tone t;
    for (int c = 0; c < 3; ++c) {
      int v = 0;
      for (int k = 0; k < 2; ++k) {
        const char ch = hex[detail::to_size(2 * c + k)];
        const int d = ch >= '0' && ch <= '9'   ? ch - '0'
                      : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10
                      : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10
                                               : -1;
        if (d < 0) return bad("not a hex digit in the colour");
        v = v * 16 + d;
      }
      t.color[detail::to_size(c)] = static_cast<float>(v) / 255.0f;
    }
    const std::string weight(item.substr(colon + 1));
    char* stop = nullptr;
    t.proportion = std::strtod(weight.c_str(), &stop);
    if (weight.empty() || *stop != '\0') return bad("the weight is not a number");
    out.push_back(t);
    start = end + 1;
  }
  if (auto p = normalized_proportions(out); !p) return status::parse_error(p.error().message());
  return out;
}

namespace detail {
/// Splits `total` items among weights with exact integer counts (largest remainder, ties to the
/// smallest index).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<index_t> apportion(const std::vector<double>& w, index_t total) {
  std::vector<index_t> count(w.size());
  std::vector<std::pair<double, std::size_t>> rest;  // (-remainder, index): ascending = largest first, ties by index
  index_t given = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double exact = w[i] * static_cast<double>(total);
    count[i] = static_cast<index_t>(std::floor(exact));
    given += count[i];
    rest.push_back({static_cast<double>(count[i]) - exact, i});
  }
  std::sort(rest.begin(), rest.end());
  for (std::size_t k = 0; given < total && k < rest.size(); ++k, ++given) ++count[rest[k].second];
  for (std::size_t k = 0; given < total; k = (k + 1) % w.size(), ++given) ++count[k];  // rounding slack
  return count;
}
/// A seeded permutation of the tone labels with exact counts (Fisher-Yates, keyed by position).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<int> shuffled_labels(const std::vector<index_t>& count, const counter_rng& rng) {
  std::vector<int> labels;
  for (std::size_t i = 0; i < count.size(); ++i) labels.insert(labels.end(), to_size(count[i]), static_cast<int>(i));
  for (std::size_t i = labels.size(); i > 1; --i) std::swap(labels[i - 1], labels[to_size(rng.below(i, i))]);
  return labels;
}
/// Index of the tone at fraction f in [0, 1) of the cumulative proportions.
inline int tone_at(const std::vector<double>& p, double f) {
  double acc = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    acc += p[i];
    if (f < acc) return static_cast<int>(i);
  }
  return static_cast<int>(p.size() - 1);
}
/// Tone label of every pixel for the given layout.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<int> source_labels(index_t w, index_t h, const std::vector<double>& p, const source_image_options& o) {
  const index_t s = o.feature_size > 0 ? o.feature_size : std::max<index_t>(1, std::min(w, h) / 8);
  std::vector<int> label(to_size(w * h));
  const counter_rng rng(o.seed, stream_id("fabric.source"));
  switch (o.layout) {
    case source_layout::stripes: {
      // each band of s pixels is split among the tones in palette order
      for (index_t y = 0; y < h; ++y)
        for (index_t x = 0; x < w; ++x) {
          const index_t t = o.vertical ? x : y;
          label[to_size(y * w + x)] = tone_at(p, (static_cast<double>(t % s) + 0.5) / static_cast<double>(s));
        }
      break;
    }
    case source_layout::blocks: {
      const index_t bw = (w + s - 1) / s, bh = (h + s - 1) / s;
      const auto labels = shuffled_labels(apportion(p, bw * bh), rng);
      for (index_t y = 0; y < h; ++y)
        for (index_t x = 0; x < w; ++x) label[to_size(y * w + x)] = labels[to_size((y / s) * bw + x / s)];
      break;
    }
    case source_layout::cells: {
      // one jittered site per s x s grid cell; pixels take the nearest site (ties: smallest index)
      const index_t gw = (w + s - 1) / s, gh = (h + s - 1) / s;
      std::vector<std::array<double, 2>> site(to_size(gw * gh));
      for (index_t j = 0; j < gh; ++j)
        for (index_t i = 0; i < gw; ++i)
          site[to_size(j * gw + i)] = {
              (static_cast<double>(i) + 0.1 + 0.8 * rng.uniform(i, j, 0)) * static_cast<double>(s),
              (static_cast<double>(j) + 0.1 + 0.8 * rng.uniform(i, j, 1)) * static_cast<double>(s)};
      std::vector<index_t> owner(label.size()), area(site.size(), 0);
      for (index_t y = 0; y < h; ++y)
        for (index_t x = 0; x < w; ++x) {
          double best = std::numeric_limits<double>::max();
          index_t arg = 0;
          for (index_t j = std::max<index_t>(0, y / s - 2); j <= std::min(gh - 1, y / s + 2); ++j)
            for (index_t i = std::max<index_t>(0, x / s - 2); i <= std::min(gw - 1, x / s + 2); ++i) {
              const auto& c = site[to_size(j * gw + i)];
              const double dx = static_cast<double>(x) + 0.5 - c[0], dy = static_cast<double>(y) + 0.5 - c[1];
              const double d = dx * dx + dy * dy;
              const index_t k = j * gw + i;
              if (d < best || (d == best && k < arg)) {
                best = d;
                arg = k;
              }
            }
          owner[to_size(y * w + x)] = arg;
          ++area[to_size(arg)];
        }
      // cells in seeded order; each goes to the tone furthest below its target area
      std::vector<index_t> order(site.size());
      std::iota(order.begin(), order.end(), 0);
      for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[to_size(rng.below(i, i, 7))]);
      std::vector<double> deficit(p.size());
      for (std::size_t t = 0; t < p.size(); ++t) deficit[t] = p[t] * static_cast<double>(w * h);
      std::vector<int> cell_tone(site.size(), 0);
      for (index_t c : order) {
        const auto t = to_size(std::max_element(deficit.begin(), deficit.end()) - deficit.begin());
        cell_tone[to_size(c)] = static_cast<int>(t);
        deficit[t] -= static_cast<double>(area[to_size(c)]);
      }
      for (std::size_t k = 0; k < label.size(); ++k) label[k] = cell_tone[to_size(owner[k])];
      break;
    }
  }
  return label;
}
}  // namespace detail

/// Fills `out` with a source image of the palette's tones in the chosen layout (paper 001 §1.3,
/// "generated on the computer"). Stripes and blocks reproduce the normalized proportions up to the
/// rounding of one band or block; cells up to the area of one cell. Colours are written through
/// convert_pixel (grey outputs get Rec. 601 luma, alpha is opaque).
/// Errors: invalid_argument for an empty or invalid palette (see normalized_proportions), an empty
/// output, a negative feature_size or an unknown layout. Complexity O(W H) (cells: O(W H) with a
/// 5 x 5 site search). Thread-safe; output is a pure function of (size, palette, options).
template <WritableImage O>
[[nodiscard]] status make_source_image(O& out, const palette& tones, const source_image_options& options = {}) {
  auto p = normalized_proportions(tones);
  if (!p) return p.error();
  if (auto s = validate_image(out, "make_source_image: output"); !s) return s;
  if (options.feature_size < 0)
    return status::invalid_argument(
        detail::cat("make_source_image: options.feature_size must be >= 0, got ", options.feature_size));
  if (options.layout != source_layout::stripes && options.layout != source_layout::blocks &&
      options.layout != source_layout::cells)
    return status::invalid_argument(
        detail::cat("make_source_image: unknown options.layout ", static_cast<int>(options.layout)));
  const index_t w = width_of(out), h = height_of(out);
  const std::vector<int> label = detail::source_labels(w, h, *p, options);
  std::vector<pixel_t<O>> colors;
  for (const tone& t : tones) colors.push_back(convert_pixel<pixel_t<O>>(t.color));
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x)
      image_traits<O>::write(out, x, y, colors[detail::to_size(label[detail::to_size(y * w + x)])]);
  return {};
}

TESSERA_NAMESPACE_END
