// tessera/image/exemplars.hpp: procedural exemplar images for tests, examples, benchmarks and docs,
// so that everything tessera shows can be reproduced without shipping photographs. Each kind is a
// pure function of (kind, size, seed):
//   grass   stochastic: thin vertical blades over a dark green ground
//   sand    stochastic, fine grain with soft ripples
//   rock    stochastic, multi-octave grey with dark cracks
//   bricks  structured: running-bond bricks with mortar (the case feathering handles badly)
//   cells   semi-structured: Voronoi pebbles with dark outlines
//   weave   regular: over-under threads
//   dots    regular: a jittered lattice of round dots
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "../core/config.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"

TESSERA_NAMESPACE_BEGIN

/// The procedural exemplars make_exemplar draws.
enum class exemplar_kind { grass, sand, rock, bricks, cells, weave, dots };

/// Every exemplar_kind, in declaration order.
inline constexpr std::array<exemplar_kind, 7> all_exemplar_kinds = {
    exemplar_kind::grass, exemplar_kind::sand,  exemplar_kind::rock, exemplar_kind::bricks,
    exemplar_kind::cells, exemplar_kind::weave, exemplar_kind::dots};

/// The kind's name ("grass", "bricks", ...), as parse_exemplar_kind reads it.
constexpr std::string_view to_string(exemplar_kind k) noexcept {
  constexpr std::array<std::string_view, 7> names = {"grass", "sand", "rock", "bricks", "cells", "weave", "dots"};
  return names[detail::to_size(k)];
}

/// Parses a kind name ("bricks"); an invalid_argument status lists the valid names.
inline result<exemplar_kind> parse_exemplar_kind(std::string_view name) {
  for (exemplar_kind k : all_exemplar_kinds)
    if (to_string(k) == name) return k;
  return status::invalid_argument(
      detail::cat("unknown exemplar kind '", name, "' (expected grass, sand, rock, bricks, cells, weave or dots)"));
}

/// Options of make_exemplar.
struct exemplar_options {
  /// Width in pixels.
  index_t width = 128;
  /// Height in pixels.
  index_t height = 128;
  /// Seed of the procedural pattern.
  std::uint64_t seed = 1;
};

namespace detail {
/// Smooth value noise on a lattice of spacing `cell` pixels (hash-keyed, so seeded and unbounded).
inline double value_noise(const counter_rng& rng, double x, double y, double cell, std::uint64_t octave) {
  const double fx = x / cell, fy = y / cell;
  const auto ix = static_cast<std::int64_t>(std::floor(fx)), iy = static_cast<std::int64_t>(std::floor(fy));
  const double tx = fx - static_cast<double>(ix), ty = fy - static_cast<double>(iy);
  auto smooth = [](double t) { return t * t * (3 - 2 * t); };
  auto at = [&](std::int64_t a, std::int64_t b) { return rng.uniform(octave, a, b); };
  const double sx = smooth(tx), sy = smooth(ty);
  const double top = at(ix, iy) + (at(ix + 1, iy) - at(ix, iy)) * sx;
  const double bottom = at(ix, iy + 1) + (at(ix + 1, iy + 1) - at(ix, iy + 1)) * sx;
  return top + (bottom - top) * sy;
}
/// Fractal sum of value noise, in [0, 1].
inline double fbm(const counter_rng& rng, double x, double y, double cell, int octaves) {
  double sum = 0, amp = 1, norm = 0;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * value_noise(rng, x, y, cell, static_cast<std::uint64_t>(o));
    norm += amp;
    amp *= 0.5;
    cell *= 0.5;
  }
  return sum / norm;
}
using rgb = std::array<double, 3>;
inline rgb mix(const rgb& a, const rgb& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}
inline rgb scale(const rgb& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

inline rgb exemplar_pixel(exemplar_kind kind, const counter_rng& rng, double x, double y, double size) {
  switch (kind) {
    case exemplar_kind::grass: {
      // blades: noise stretched vertically, so streaks run along y
      const double blades = fbm(rng, x * 4.0, y * 0.35, size / 6, 3);
      const double ground = fbm(rng.substream(1), x, y, size / 4, 4);
      const double t = std::clamp((blades - 0.35) * 2.2, 0.0, 1.0);
      return mix(scale({0.10, 0.22, 0.05}, 0.6 + 0.6 * ground), {0.35, 0.62, 0.18}, t);
    }
    case exemplar_kind::sand: {
      const double grain = rng.uniform(std::int64_t(x), std::int64_t(y));
      const double ripple = 0.5 + 0.5 * std::sin((y + 6 * fbm(rng, x, y, size / 3, 3) * size / 8) * 0.45);
      const double t = 0.55 * ripple + 0.3 * grain + 0.15 * fbm(rng.substream(2), x, y, size / 5, 3);
      return mix({0.62, 0.50, 0.32}, {0.90, 0.80, 0.60}, t);
    }
    case exemplar_kind::rock: {
      const double base = fbm(rng, x, y, size / 3, 6);
      const double crack = std::abs(fbm(rng.substream(3), x, y, size / 4, 4) - 0.5);
      const double dark = crack < 0.025 ? 0.35 : 1.0;
      return scale(mix({0.30, 0.29, 0.28}, {0.72, 0.70, 0.66}, base), dark);
    }
    case exemplar_kind::bricks: {
      const double bw = size / 4, bh = size / 8, mortar = std::max(1.0, size / 64);
      const auto row = static_cast<std::int64_t>(std::floor(y / bh));
      const double xs = x + (row % 2 != 0 ? bw / 2 : 0);
      const auto col = static_cast<std::int64_t>(std::floor(xs / bw));
      const double lx = xs - static_cast<double>(col) * bw, ly = y - static_cast<double>(row) * bh;
      const double grain = fbm(rng.substream(4), x, y, size / 16, 3);
      if (lx < mortar || ly < mortar) return scale({0.75, 0.73, 0.68}, 0.8 + 0.3 * grain);
      const double tone = rng.uniform(row, col);
      return scale(mix({0.55, 0.20, 0.14}, {0.72, 0.36, 0.22}, tone), 0.75 + 0.4 * grain);
    }
    case exemplar_kind::cells: {
      const double cell = size / 6;
      const auto cx = static_cast<std::int64_t>(std::floor(x / cell)),
                 cy = static_cast<std::int64_t>(std::floor(y / cell));
      double d1 = 1e30, d2 = 1e30;
      std::int64_t best_x = 0, best_y = 0;
      for (std::int64_t j = cy - 1; j <= cy + 1; ++j)
        for (std::int64_t i = cx - 1; i <= cx + 1; ++i) {
          const double px = (static_cast<double>(i) + 0.15 + 0.7 * rng.uniform(i, j, 0)) * cell;
          const double py = (static_cast<double>(j) + 0.15 + 0.7 * rng.uniform(i, j, 1)) * cell;
          const double d = std::hypot(x - px, y - py);
          if (d < d1) {
            d2 = d1;
            d1 = d;
            best_x = i;
            best_y = j;
          } else if (d < d2)
            d2 = d;
        }
      const double edge = std::clamp((d2 - d1) / (cell * 0.08), 0.0, 1.0);
      const rgb stone = mix({0.45, 0.40, 0.35}, {0.80, 0.74, 0.64}, rng.uniform(best_x, best_y, 2));
      return mix({0.15, 0.13, 0.12}, scale(stone, 0.85 + 0.3 * fbm(rng, x, y, cell / 2, 2)), edge);
    }
    case exemplar_kind::weave: {
      const double period = size / 8, half = period / 2;
      const auto tx = static_cast<std::int64_t>(std::floor(x / half)),
                 ty = static_cast<std::int64_t>(std::floor(y / half));
      const double lx = x - static_cast<double>(tx) * half, ly = y - static_cast<double>(ty) * half;
      const bool warp_on_top = ((tx + ty) & 1) == 0;
      const double across = warp_on_top ? lx / half : ly / half;  // position across the visible thread
      const double along = warp_on_top ? ly / half : lx / half;
      const double shade = std::sin(3.14159265358979 * across) * (0.75 + 0.25 * std::sin(3.14159265358979 * along));
      const rgb thread = warp_on_top ? rgb{0.20, 0.32, 0.55} : rgb{0.80, 0.72, 0.50};
      return scale(thread, 0.35 + 0.65 * shade + 0.1 * (rng.uniform(std::int64_t(x), std::int64_t(y)) - 0.5));
    }
    case exemplar_kind::dots: {
      const double cell = size / 8;
      const auto cx = static_cast<std::int64_t>(std::floor(x / cell)),
                 cy = static_cast<std::int64_t>(std::floor(y / cell));
      const double jx = (rng.uniform(cx, cy, 0) - 0.5) * cell * 0.2, jy = (rng.uniform(cx, cy, 1) - 0.5) * cell * 0.2;
      const double d =
          std::hypot(x - (static_cast<double>(cx) + 0.5) * cell - jx, y - (static_cast<double>(cy) + 0.5) * cell - jy);
      const double t = std::clamp((cell * 0.3 - d) / 1.5, 0.0, 1.0);
      return mix({0.93, 0.90, 0.82}, {0.75, 0.15, 0.12}, t);
    }
  }
  return {0, 0, 0};
}
}  // namespace detail

/// Largest exemplar make_exemplar renders, in pixels (2^26: 8192 x 8192); exemplars are small.
inline constexpr index_t max_exemplar_pixels = index_t{1} << 26;

/// Renders a procedural exemplar of the given kind into C channels of T (grey for C = 1 or 2, opaque
/// alpha for C = 2 or 4). Errors: invalid_argument for an unknown kind or a non-positive size;
/// size_overflow for more than max_exemplar_pixels pixels (checked before allocating) or when the
/// system cannot allocate the image.
template <Channel T = std::uint8_t, int C = 3>
result<image_buffer<T, C>> make_exemplar(exemplar_kind kind, const exemplar_options& opts = {}) {
  if (auto s =
          validate_enum(kind, {"grass", "sand", "rock", "bricks", "cells", "weave", "dots"}, "make_exemplar: kind");
      !s)
    return s;
  if (auto s = validate_image_extent(opts.width, opts.height, C, "exemplar"); !s) return s;
  if (opts.width > max_exemplar_pixels / opts.height)
    return status::size_overflow(detail::cat("make_exemplar: ", opts.width, " x ", opts.height,
                                             " pixels exceed max_exemplar_pixels = ", max_exemplar_pixels));
  const counter_rng rng(opts.seed, stream_id("exemplar") + static_cast<std::uint64_t>(kind));
  const double size = static_cast<double>(std::min(opts.width, opts.height));
  auto created = image_buffer<T, C>::create(opts.width, opts.height);
  if (!created) return created.error();
  image_buffer<T, C>& out = *created;
  for (index_t y = 0; y < opts.height; ++y)
    for (index_t x = 0; x < opts.width; ++x) {
      const auto c = detail::exemplar_pixel(kind, rng, static_cast<double>(x), static_cast<double>(y), size);
      const pixel<float, 3> rgb{static_cast<float>(std::clamp(c[0], 0.0, 1.0)),
                                static_cast<float>(std::clamp(c[1], 0.0, 1.0)),
                                static_cast<float>(std::clamp(c[2], 0.0, 1.0))};
      out.write(x, y, convert_pixel<pixel<T, C>>(rgb));
    }
  return created;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_exemplars.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
