// tessera/fabric/hls.hpp: the HLS colour space (hue, lightness, saturation) used by the
// game-of-life perturbation of paper 001 §1.3, which changes only lightness.
//
//   L = (max + min) / 2,   S = (max - min) / (1 - |2L - 1|),   H = the usual hexagonal hue in [0, 360).
//
// `relight` moves a colour to a new lightness L' keeping H and S exactly: the chroma offsets of the
// channels from L scale by (1 - |2L' - 1|) / (1 - |2L - 1|), so ratios between channels (the hue) and
// chroma / (1 - |2L - 1|) (the saturation) are unchanged, and no hue is ever computed. Black and white
// (S undefined) relight to grey.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "../core/config.hpp"

TESSERA_NAMESPACE_BEGIN

/// Hue in degrees [0, 360), lightness and saturation in [0, 1].
struct hls_color {
  /// Hue, lightness, saturation.
  float h = 0, l = 0, s = 0;
};

/// HLS lightness (max + min) / 2 of an RGB colour in [0, 1].
constexpr float hls_lightness(float r, float g, float b) noexcept {
  const float mx = std::max(r, std::max(g, b)), mn = std::min(r, std::min(g, b));
  return 0.5f * (mx + mn);
}

/// RGB in [0, 1] to HLS (hue 0 and saturation 0 for greys). Computed in double for test oracles.
inline hls_color rgb_to_hls(float r, float g, float b) noexcept {
  const double R = r, G = g, B = b;
  const double mx = std::max({R, G, B}), mn = std::min({R, G, B});
  const double l = 0.5 * (mx + mn), c = mx - mn;
  hls_color out{0.0f, static_cast<float>(l), 0.0f};
  if (c <= 0) return out;
  out.s = static_cast<float>(c / (1.0 - std::abs(2.0 * l - 1.0)));
  double h = mx == R ? (G - B) / c : mx == G ? 2.0 + (B - R) / c : 4.0 + (R - G) / c;
  h *= 60.0;
  if (h < 0) h += 360.0;
  out.h = static_cast<float>(h >= 360.0 ? h - 360.0 : h);
  return out;
}

/// HLS to RGB in [0, 1].
inline std::array<float, 3> hls_to_rgb(const hls_color& c) noexcept {
  const double l = c.l, s = c.s;
  const double chroma = (1.0 - std::abs(2.0 * l - 1.0)) * s;
  const double hp = std::fmod(static_cast<double>(c.h), 360.0) / 60.0;
  const double x = chroma * (1.0 - std::abs(std::fmod(hp, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hp)) {
    case 0:
      r = chroma;
      g = x;
      break;
    case 1:
      r = x;
      g = chroma;
      break;
    case 2:
      g = chroma;
      b = x;
      break;
    case 3:
      g = x;
      b = chroma;
      break;
    case 4:
      r = x;
      b = chroma;
      break;
    default:
      r = chroma;
      b = x;
      break;
  }
  const double m = l - chroma / 2;
  auto clamp01 = [](double v) { return static_cast<float>(std::clamp(v, 0.0, 1.0)); };
  return {clamp01(r + m), clamp01(g + m), clamp01(b + m)};
}

/// The colour with HLS lightness `l_new` and the hue and saturation of (r, g, b), whose lightness is
/// `l_old` (= hls_lightness(r, g, b)). Results are clamped to [0, 1] against rounding.
constexpr std::array<float, 3> relight(float r, float g, float b, float l_old, float l_new) noexcept {
  const float span_old = 1.0f - (l_old > 0.5f ? 2.0f * l_old - 1.0f : 1.0f - 2.0f * l_old);
  const float span_new = 1.0f - (l_new > 0.5f ? 2.0f * l_new - 1.0f : 1.0f - 2.0f * l_new);
  const float k = span_old > 0.0f ? span_new / span_old : 0.0f;
  auto f = [&](float v) { return std::clamp(l_new + (v - l_old) * k, 0.0f, 1.0f); };
  return {f(r), f(g), f(b)};
}

TESSERA_NAMESPACE_END
