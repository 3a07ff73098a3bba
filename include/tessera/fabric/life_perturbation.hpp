// tessera/fabric/life_perturbation.hpp: the game-of-life lightness perturbation of paper 001 §1.3.
//
// Cat-map fabrics are very regular; coats and tweeds are not. The paper perturbs them in HLS space,
// changing only lightness so the pattern and its colours survive (§1.3, end). Every pixel is a cell;
// from its 8 neighbours (toroidal wrap, which matches the periodic cat-map image) it takes
//
//   L_bright = mean lightness of the neighbours brighter than the pixel,
//   L_dim    = mean lightness of the neighbours dimmer than the pixel,
//
// counts its live and dead neighbours, and then
//
//   lives (brightens):  L' = L + (L_bright - L) r          (the two equations of §1.3)
//   dies  (darkens):    L' = L_dim + (L - L_dim) r
//
// with r uniform in [0, 1) (the paper: "a random number in [0, 1]"; 24-bit steps, 1 excluded),
// counter-based and keyed by (seed, generation, pixel): a SplitMix64 key per row of a generation,
// then a 32-bit hash of the column (detail/life_kernels.hpp, life_random), so it never depends on
// evaluation order or thread count. Generations are synchronous.
//
// Reading of the thresholds. §1.2 states the general rules with three numbers: a cell lives when
// exactly M neighbours are alive (M = 3), dies when K neighbours are dead (K = 6), and dies of
// crowding when N neighbours are alive (N = 7). §1.3 then names only two, "K = 3, N = 6": the live
// threshold 3 and the death threshold 6, i.e. §1.2's M and K under new letters. So here
//
//   live_count  = §1.3's K = §1.2's M: brighten when exactly (or, optionally, at least) K are live;
//   dead_count  = §1.3's N = §1.2's K: darken when at least N are dead;
//   crowding_count = §1.2's N: darken when at least this many are live (0, the default, = off,
//                    since §1.3 does not use it). Darkening wins when both rules fire.
//
// A neighbour is "live" when it is brighter than the pixel (default) or, optionally, when its
// lightness is above a fixed threshold; "dead" is dimmer than the pixel, respectively not live.
// A rule that fires with no brighter (dimmer) neighbour leaves L unchanged.
//
// Hue and saturation are kept exactly: lightness evolves in float, and each output pixel is the
// input pixel relit from its own L to the final L' (hls.hpp, `relight`), so rounding never
// accumulates over generations. Alpha is untouched; grey images perturb their single value.
//
// 8- and 16-bit images run their first generation in integers (detail/life_int_kernels.hpp): the
// lightness of a pixel is (max + min) / 2M exactly, neighbour sums and counts are exact integers
// (SIMD: SSE2, and AVX2 when the machine has it; the output is the same on every machine), and
// only the pixels whose rule fires draw r and are relit. Later generations and float images use
// the float kernel (detail/life_kernels.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "detail/life_int_kernels.hpp"
#include "detail/life_kernels.hpp"
#include "detail/square_regions.hpp"
#include "hls.hpp"

TESSERA_NAMESPACE_BEGIN

/// Which neighbours count as "live".
enum class life_test {
  brighter_than_pixel,  ///< live: lighter than the pixel; dead: darker (equal ones are neither)
  above_threshold       ///< live: lightness > threshold; dead: the others
};

/// Options of the game-of-life perturbation (paper 001 §1.2-1.3).
struct life_perturbation_options {
  int generations = 1;     ///< synchronous generations (0 copies the input)
  int live_count = 3;      ///< K of §1.3 (§1.2's M), in [0, 8]
  bool live_exact = true;  ///< brighten when exactly K are live (§1.2); false: at least K
  int dead_count = 6;      ///< N of §1.3 (§1.2's K), in [1, 8]: darken when at least N are dead
  int crowding_count = 0;  ///< §1.2's N, in [1, 8]: darken when at least this many are live; 0 = off
  /// How a neighbour counts as live.
  life_test live_test = life_test::brighter_than_pixel;
  float threshold = 0.5f;           ///< above_threshold: the lightness in [0, 1] a live neighbour exceeds
  std::uint64_t seed = 1;           ///< the random factors r
  tessera::progress progress = {};  ///< reported once per generation; may cancel
};

namespace detail {
inline status check_life_options(const life_perturbation_options& o) {
  auto bad = [](const char* name, auto value, const char* range) {
    return status::invalid_argument(cat("life_perturbation: options.", name, " must be ", range, ", got ", value));
  };
  if (o.generations < 0) return bad("generations", o.generations, ">= 0");
  if (o.live_count < 0 || o.live_count > 8) return bad("live_count (K)", o.live_count, "in [0, 8]");
  if (o.dead_count < 1 || o.dead_count > 8) return bad("dead_count (N)", o.dead_count, "in [1, 8]");
  if (o.crowding_count < 0 || o.crowding_count > 8)
    return bad("crowding_count", o.crowding_count, "0 (off) or in [1, 8]");
  if (!(o.threshold >= 0.0f && o.threshold <= 1.0f)) return bad("threshold", o.threshold, "in [0, 1]");
  if (o.live_test != life_test::brighter_than_pixel && o.live_test != life_test::above_threshold)
    return bad("live_test", static_cast<int>(o.live_test), "brighter_than_pixel or above_threshold");
  return {};
}

template <class T, int C>
inline float pixel_lightness(const T* p) noexcept {
  if constexpr (C <= 2) {
    return channel_to_unit(p[0]);
  } else if constexpr (std::is_integral_v<T>) {  // exact: (max + min) / (2 max_value), no per-channel division
    const unsigned mx = std::max(p[0], std::max(p[1], p[2])), mn = std::min(p[0], std::min(p[1], p[2]));
    return static_cast<float>(mx + mn) * (0.5f / static_cast<float>(std::numeric_limits<T>::max()));
  } else {
    return hls_lightness(p[0], p[1], p[2]);
  }
}

/// Writes the input pixel, whose lightness is l_old, relit to lightness l_new (hue, saturation and
/// alpha kept, see `relight`); a pixel whose lightness did not change is copied bit for bit. Integer
/// channels are relit in channel units and rounded to nearest.
template <class T, int C>
inline void relight_pixel(const T* in, T* out, float l_old, float l_new) noexcept {
  if (l_new == l_old) {
    if (in != out) std::memcpy(out, in, sizeof(T) * C);
    return;
  }
  if constexpr (C <= 2) {
    out[0] = unit_to_channel<T>(l_new);
  } else if constexpr (std::is_integral_v<T>) {
    constexpr float top = static_cast<float>(std::numeric_limits<T>::max());
    const float span_old = 1.0f - std::abs(2.0f * l_old - 1.0f), span_new = 1.0f - std::abs(2.0f * l_new - 1.0f);
    const float k = span_old > 0.0f ? span_new / span_old : 0.0f;
    const float base = (l_new - l_old * k) * top + 0.5f;  // c' = L' + (c - L) k, in channel units, + rounding
    for (int c = 0; c < 3; ++c) {
      float v = base + static_cast<float>(in[c]) * k;
      v = v > 0.0f ? v : 0.0f;
      v = v < top ? v : top;
      out[c] = static_cast<T>(v);
    }
  } else {
    const auto c = relight(in[0], in[1], in[2], l_old, l_new);
    for (int k = 0; k < 3; ++k) out[k] = c[to_size(k)];
  }
  if constexpr (C == 2 || C == 4) out[C - 1] = in[C - 1];
}

/// Runs the first generation of an 8- or 16-bit image in integers (detail/life_int_kernels.hpp).
/// With one generation it writes `dst`; with more it writes the lightness after it to `field`.
template <class T, int C, class E>
void life_first_generation(image_view<const T, C> src, image_view<T, C> dst, std::vector<float>& field,
                           const life_perturbation_options& o, const counter_rng& rng, E& exec) {
  using V = typename life_lane<T>::value;
  constexpr V low = (V{1} << life_lane<T>::shift) - 1;
  constexpr float to_unit = 0.5f / static_cast<float>(std::numeric_limits<T>::max());
  const index_t w = src.width(), h = src.height();
  const life_int_rule<V> rule{static_cast<V>(o.live_count),
                              static_cast<V>(o.dead_count),
                              static_cast<V>(o.crowding_count > 0 ? o.crowding_count : 9),
                              static_cast<V>(std::floor(static_cast<double>(o.threshold) * 2.0 *
                                                        static_cast<double>(std::numeric_limits<T>::max()))),
                              o.live_exact,
                              o.live_test == life_test::above_threshold};
  const life_random random(rng, 0);
  const bool last = o.generations == 1;
  // neighbours' rows are read from the image unless one generation is written over it: then from a
  // plane of q taken first
  std::vector<V> plane;
  if (last && views_overlap(src, dst)) {
    plane.resize(to_size((w + 2) * h));
    exec.parallel_for(0, h, [&](index_t y) { life_q_row<T, C>(src.row(y), w, plane.data() + y * (w + 2)); });
  }
  auto emit = [&](index_t y, const V* q, const life_int_scratch<T>& s, std::size_t n) {
    if (!last) {  // the field after the generation: unchanged pixels keep pixel_lightness exactly
      float* l = field.data() + y * w;
      for (index_t x = 0; x < w; ++x) l[x] = static_cast<float>(q[x + 1] & low) * to_unit;
      for (std::size_t i = 0; i < n; ++i) l[s.fired[i]] = s.lq[i] * to_unit;
      return;
    }
    const T* in = src.row(y);
    T* out = dst.row(y);
    if (in != out) std::memcpy(out, in, sizeof(T) * to_size(w * C));
    life_int_relight_row<T, C>(in, out, s, n);
  };
  constexpr index_t band = 32;
  exec.parallel_for(0, (h + band - 1) / band, [&](index_t b) {
    life_int_scratch<T> scratch(w);
    const index_t y0 = b * band, y1 = std::min(h, (b + 1) * band);
    if (plane.empty()) {
      life_int_band<T>(
          w, h, y0, y1, rule, random, scratch, [&](index_t y, V* row) { life_q_row<T, C>(src.row(y), w, row); }, emit);
    } else {
      life_int_band<T>(
          w, h, y0, y1, rule, random, scratch,
          [&](index_t y, V* row) { std::memcpy(row, plane.data() + y * (w + 2), sizeof(V) * to_size(w + 2)); }, emit);
    }
  });
}

/// The perturbation on packed views of one format. `src` and `dst` may be the same memory.
template <class T, int C, class E>
status life_views(image_view<const T, C> src, image_view<T, C> dst, const life_perturbation_options& o, E& exec) {
  const index_t w = src.width(), h = src.height();
  if (o.generations == 0) {
    if (src.data() != dst.data()) copy_view<T, C>(src, dst);
    return {};
  }
  // in place (the same rows) is handled below; views that overlap otherwise read from a copy
  if (views_overlap(src, dst) && (src.data() != dst.data() || src.stride() != dst.stride())) {
    auto copy = image_buffer<T, C>::create(w, h);
    if (!copy) return copy.error();
    copy_view<T, C>(src, copy->view());
    return life_views<T, C>(copy->cview(), dst, o, exec);
  }
  const life_rule rule{
      o.live_count, o.live_exact, o.dead_count, o.crowding_count, o.live_test == life_test::above_threshold,
      o.threshold};
  const counter_rng rng(o.seed, stream_id("fabric.life"));
  std::vector<float> cur, next;
  int first = 0;  // the first generation done in float
  if constexpr (std::is_integral_v<T>) {
    if (w < (index_t{1} << 31)) {  // (column indices are 32-bit there; wider rows take the float path)
      if (!o.progress.report(0.0, "life_perturbation")) return status::cancelled();
      if (o.generations > 1) cur.resize(to_size(w * h));
      life_first_generation<T, C>(src, dst, cur, o, rng, exec);
      if (o.generations == 1) {
        o.progress.report(1.0, "life_perturbation");
        return {};
      }
      first = 1;
      next.resize(cur.size());
    }
  }
  // float images: lightness computed on the fly for one generation into a separate output (bands
  // read their neighbours' rows), else kept in a float field
  auto fill_from_image = [&](index_t y, float* padded) {
    const T* p = src.row(y);
    for (index_t x = 0; x < w; ++x, p += C) padded[x + 1] = pixel_lightness<T, C>(p);
    padded[0] = padded[w];
    padded[w + 1] = padded[1];
  };
  const bool on_the_fly = o.generations == 1 && !views_overlap(src, dst);
  if (!on_the_fly && cur.empty()) {
    cur.resize(to_size(w * h));
    if (o.generations > 1) next.resize(cur.size());
    exec.parallel_for(0, h, [&](index_t y) {
      const T* p = src.row(y);
      float* l = cur.data() + y * w;
      for (index_t x = 0; x < w; ++x, p += C) l[x] = pixel_lightness<T, C>(p);
    });
  }
  auto fill_from_field = [&](index_t y, float* padded) { pad_row(cur.data() + y * w, w, padded); };
  constexpr index_t band = 16;
  const index_t bands = (h + band - 1) / band;
  for (int g = first; g < o.generations; ++g) {
    if (!o.progress.report(static_cast<double>(g) / o.generations, "life_perturbation")) return status::cancelled();
    const life_random random(rng, static_cast<std::uint64_t>(g));
    const bool last = g + 1 == o.generations;
    auto emit = [&](index_t y, const float* l_old, const float* l_new, const index_t* fired, index_t n_fired) {
      if (!last) {
        std::memcpy(next.data() + y * w, l_new, sizeof(float) * to_size(w));
        return;
      }
      // the last generation relights the output straight from the input pixels
      const T* in = src.row(y);
      T* out = dst.row(y);
      if (o.generations > 1) {  // earlier generations may have changed any pixel
        for (index_t x = 0; x < w; ++x)
          relight_pixel<T, C>(in + x * C, out + x * C, pixel_lightness<T, C>(in + x * C), l_new[x]);
        return;
      }
      if (in != out) std::memcpy(out, in, sizeof(T) * to_size(w * C));
      for (index_t k = 0; k < n_fired; ++k) {
        const index_t x = fired[k];
        relight_pixel<T, C>(in + x * C, out + x * C, l_old[x], l_new[x]);
      }
    };
    exec.parallel_for(0, bands, [&](index_t b) {
      life_scratch scratch(w);
      const index_t y0 = b * band, y1 = std::min(h, (b + 1) * band);
      if (on_the_fly)
        life_band(w, h, y0, y1, rule, random, scratch, fill_from_image, emit);
      else
        life_band(w, h, y0, y1, rule, random, scratch, fill_from_field, emit);
    });
    if (!last) cur.swap(next);
  }
  o.progress.report(1.0, "life_perturbation");
  return {};
}
}  // namespace detail

/// Perturbs the lightness of `in` by the game-of-life rule of paper 001 §1.3 (see the top of this
/// header for the rule, the K/N reading and the live test), writing `out`; hue, saturation and
/// alpha are unchanged. `in` and `out` may be the same image.
/// Parameters: in, out (same size; out's pixel format is used, converting with convert_pixel);
/// options (generations, thresholds, live test, seed, progress); exec (parallel over rows).
/// Errors: invalid_argument for an empty input, mismatched sizes, or an option out of range (the
/// message names it and its value); cancelled when options.progress asks to stop (out is then
/// unspecified). Complexity O(W H generations) time; extra memory O(W) for one generation into a
/// separate output (lightness is read straight from the image), else one or two float fields of W H.
/// Output is a pure function of (in, options): bit-identical for every executor and thread count.
template <Image I, WritableImage O, Executor E = serial_executor>
[[nodiscard]] status life_perturbation(const I& in, O& out, const life_perturbation_options& options = {},
                                       E&& exec = {}) {
  if (auto s = validate_image(in, "life_perturbation: input"); !s) return s;
  if (auto s = validate_image(out, "life_perturbation: output"); !s) return s;
  if (auto s = validate_finite_pixels(in, "life_perturbation: input"); !s) return s;
  if (auto s = validate_same_size(in, "life_perturbation: input", out, "life_perturbation: output"); !s) return s;
  if (auto s = detail::check_life_options(options); !s) return s;
  using T = channel_t<O>;
  constexpr int C = channels_v<O>;
  if constexpr (detail::raw_image_v<I> && detail::raw_image_v<O> && std::is_same_v<channel_t<I>, T> &&
                channels_v<I> == C) {
    return detail::life_views<T, C>(detail::const_view_of(in), detail::mutable_view_of(out), options, exec);
  } else {
    auto src = to_buffer<T, C>(in, "life_perturbation: input");
    if (!src) return src.error();
    if (auto s = detail::life_views<T, C>(src->cview(), src->view(), options, exec); !s) return s;
    return copy_image(*src, out);
  }
}

TESSERA_NAMESPACE_END
