// tessera/fabric/make_fabric.hpp: the fabric pipeline of paper 001 and its presets.
//
//   source image (§1.3: generated from main tones, or a photo)
//     -> n steps of the cat map (§1.1, eq. 3)              regular weaves: flannel, twill, linen
//     -> optional game-of-life lightness perturbation      irregular cloth: tweeds, coatings
//     -> any output size: the N x N result is periodic (a torus), so it tiles seamlessly
//
// Presets reproduce the paper's figures in spirit: flannel (figure 4: 60 steps of a 75 % black,
// 25 % white source), twill khaki (figure 5: 31 steps of the same source), linen-like cloth from a
// photo-like image (figures 6-7: 80 steps; tessera's procedural "cells" exemplar, beige pebbles,
// stands in for the scanned photo), and tweed (figures 8-9: a wool palette, cat map, then perturbation).
//
//   tessera::image_buffer<std::uint8_t, 3> cloth(1024, 1024);
//   auto s = tessera::make_fabric(tessera::fabric_preset::twill, cloth, {.tile_size = 400});  // tiled
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/image_rows.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "../image/exemplars.hpp"
#include "cat_map.hpp"
#include "life_perturbation.hpp"
#include "source_image.hpp"

TESSERA_NAMESPACE_BEGIN

/// How make_fabric(source, out) reads a source image that is not already the N x N square it maps
/// (the counterpart of cat_map_options::non_square).
enum class source_fit {
  reject,           ///< invalid_argument unless the source is N x N (default: nothing is cut or repeated silently)
  centered_square,  ///< map the source's largest centred square at its own side S = min(width, height)
                    ///< (tile_size must be 0 or S); the periodic result tiles the output without seams
  crop_or_repeat    ///< an N x N window: centred where the source is larger, the source repeated from its
                    ///< top-left corner where it is smaller (seams where the source does not tile)
};

/// Options of make_fabric: the cat map, the tile and the perturbation.
struct fabric_options {
  std::int64_t iterations = 60;                                 ///< cat-map steps n (negative: inverse map)
  cat_map_family family = {};                                   ///< [1 a; b ab+1]; a = b = 1 is the paper's map
  life_perturbation_options perturbation = {.generations = 0};  ///< generations > 0 perturbs (tweed)
  index_t tile_size = 0;                ///< side N of the periodic square; 0 = max(width, height) of the output
  source_fit fit = source_fit::reject;  ///< a source image that is not N x N (make_fabric(source, ...) only)
  tessera::progress progress = {};      ///< stages "source", "cat_map", "perturbation"; may cancel
};

namespace detail {
inline status check_fabric_size(index_t w, index_t h, int channels, const fabric_options& o, index_t& n) {
  if (o.tile_size < 0)
    return status::invalid_argument(
        cat("make_fabric: options.tile_size must be >= 0 (0 = output size), got ", o.tile_size));
  n = o.tile_size > 0 ? o.tile_size : std::max(w, h);
  return validate_image_extent(n, n, std::max(channels, 3), "make_fabric: tile");
}

/// Cat map, perturbation and tiling of an N x N square in the output's format.
template <class T, int C, WritableImage O, class E>
status finish_fabric(image_buffer<T, C>& square, O& out, const fabric_options& o, E& exec) {
  if (!o.progress.report(0.1, "cat_map")) return status::cancelled();
  auto made = image_buffer<T, C>::create(square.width(), square.height());
  if (!made) return made.error();
  image_buffer<T, C>& mapped = *made;
  if (auto s = cat_map(square, mapped, o.iterations, {.family = o.family}, exec); !s) return s;
  if (o.perturbation.generations > 0) {
    life_perturbation_options p = o.perturbation;
    const tessera::progress& outer = o.progress;
    p.progress.token = outer.token;
    p.progress.callback = [&outer, inner = o.perturbation.progress](double f, std::string_view stage) {
      if (inner.callback && !inner.callback(f, stage)) return false;
      return !outer.callback || outer.callback(0.2 + 0.8 * f, "perturbation");
    };
    if (auto s = life_perturbation(mapped, mapped, p, exec); !s) return s;
  }
  const index_t n = mapped.width(), w = width_of(out), h = height_of(out);
  const auto tile = [&](auto& dst) {
    using D = std::remove_cvref_t<decltype(dst)>;
    for (index_t y = 0; y < h; ++y)
      for (index_t x = 0; x < w; ++x)
        image_traits<D>::write(dst, x, y, convert_pixel<pixel_t<D>>(mapped.read(x % n, y % n)));
  };
  if constexpr (ContiguousImage<O>) {  // adapted output over rows of memory (core/image_rows.hpp)
    auto view = checked_contiguous_view(out, "make_fabric: output");
    if (!view) return view.error();
    tile(*view);
  } else {
    tile(out);
  }
  o.progress.report(1.0, "done");
  return {};
}
}  // namespace detail

/// Makes a fabric from any source image (paper 001 §1.3, "existing image material"): the N x N
/// square it maps is read from the source as options.fit says (by default the source must be
/// N x N already), mapped by options.iterations cat-map steps, optionally perturbed, and tiled over
/// `out`. N is options.tile_size, else the larger side of `out`; with fit = centered_square it is
/// the smaller side of the source.
/// Parameters: source (any Image), out (any WritableImage, any size), options, exec (parallel rows).
/// Errors: invalid_argument for empty images, a source that does not fit (naming both sizes and
/// the options that would accept it), or options out of range (see cat_map and life_perturbation);
/// size_overflow when the square cannot be allocated; cancelled when options.progress asks.
/// Complexity O(N^2 (1 + generations) + W H). Output is a pure function of (source, options),
/// identical for every executor.
template <Image S, WritableImage O, Executor E = serial_executor>
[[nodiscard]] status make_fabric(const S& source, O& out, const fabric_options& options = {}, E&& exec = {}) {
  if (auto s = validate_image(source, "make_fabric: source"); !s) return s;
  if (auto s = validate_finite_pixels(source, "make_fabric: source"); !s) return s;
  if (auto s = validate_image(out, "make_fabric: output"); !s) return s;
  if (auto s = detail::check_life_options(options.perturbation); !s) return s;
  const index_t sw = width_of(source), sh = height_of(source);
  index_t n = 0;
  switch (options.fit) {
    case source_fit::reject:
    case source_fit::crop_or_repeat:
      if (auto s = detail::check_fabric_size(width_of(out), height_of(out), channels_v<O>, options, n); !s) return s;
      if (options.fit == source_fit::reject && (sw != n || sh != n))
        return status::invalid_argument(detail::cat(
            "make_fabric: the source is ", sw, " x ", sh, " but the fabric square is ", n, " x ", n,
            " (options.tile_size, or the larger side of the output); give a square source of that size, or set "
            "options.fit to centered_square (map the source's largest centred square and tile it) or crop_or_repeat"));
      break;
    case source_fit::centered_square: {
      n = std::min(sw, sh);
      if (options.tile_size != 0 && options.tile_size != n)
        return status::invalid_argument(
            detail::cat("make_fabric: options.fit = centered_square maps the source's largest "
                        "centred square at its own side ",
                        n, "; options.tile_size must be 0 or ", n, ", got ", options.tile_size));
      break;
    }
    default:
      return status::invalid_argument(
          detail::cat("make_fabric: options.fit has an unknown value ", static_cast<int>(options.fit)));
  }
  if (!options.progress.report(0.0, "source")) return status::cancelled();
  using T = channel_t<O>;
  constexpr int C = channels_v<O>;
  const index_t ox = std::max<index_t>(0, (sw - n) / 2), oy = std::max<index_t>(0, (sh - n) / 2);
  auto made = image_buffer<T, C>::create(n, n);
  if (!made) return made.error();
  image_buffer<T, C>& square = *made;
  for (index_t y = 0; y < n; ++y)
    for (index_t x = 0; x < n; ++x)
      square.write(x, y, convert_pixel<pixel<T, C>>(image_traits<S>::read(source, (x + ox) % sw, (y + oy) % sh)));
  return detail::finish_fabric(square, out, options, exec);
}

/// Makes a fabric from main tones (paper 001 §1.3, "generated on the computer"): an N x N source in
/// the palette and layout of `source` (make_source_image), then as the form above.
/// Errors: those of make_source_image and of the form above.
template <WritableImage O, Executor E = serial_executor>
[[nodiscard]] status make_fabric(const palette& tones, const source_image_options& source, O& out,
                                 const fabric_options& options = {}, E&& exec = {}) {
  if (auto s = validate_image(out, "make_fabric: output"); !s) return s;
  if (auto s = detail::check_life_options(options.perturbation); !s) return s;
  index_t n = 0;
  if (auto s = detail::check_fabric_size(width_of(out), height_of(out), channels_v<O>, options, n); !s) return s;
  if (!options.progress.report(0.0, "source")) return status::cancelled();
  auto made = image_buffer<channel_t<O>, channels_v<O>>::create(n, n);
  if (!made) return made.error();
  if (auto s = make_source_image(*made, tones, source); !s) return s;
  auto& square = *made;
  return detail::finish_fabric(square, out, options, exec);
}

/// The paper's fabrics.
enum class fabric_preset { flannel, twill, linen, tweed };

/// Every fabric_preset, in declaration order.
inline constexpr std::array<fabric_preset, 4> all_fabric_presets = {fabric_preset::flannel, fabric_preset::twill,
                                                                    fabric_preset::linen, fabric_preset::tweed};

/// The preset's name ("flannel", "twill", "linen", "tweed"); "unknown" for a value outside the enum.
constexpr std::string_view to_string(fabric_preset p) noexcept {
  constexpr std::array<std::string_view, 4> names = {"flannel", "twill", "linen", "tweed"};
  const auto i = detail::to_size(p);  // a negative value wraps to a huge index
  return i < names.size() ? names[i] : std::string_view("unknown");
}

/// Parses a preset name; invalid_argument lists the valid ones.
inline result<fabric_preset> parse_fabric_preset(std::string_view name) {
  for (fabric_preset p : all_fabric_presets)
    if (to_string(p) == name) return p;
  return status::invalid_argument(
      detail::cat("unknown fabric preset '", name, "' (expected flannel, twill, linen or tweed)"));
}

/// Everything a preset does: a palette source (tones + layout) or a procedural "photo", and the
/// pipeline options. Edit a recipe to vary a preset.
struct fabric_recipe {
  palette tones;                       ///< empty when `photo` is the source
  source_image_options source;         ///< layout of the palette source
  std::optional<exemplar_kind> photo;  ///< a procedural exemplar standing in for a scanned photo
  /// The pipeline options.
  fabric_options options;
};

/// The recipe of a preset; `seed` seeds the source layout, the photo and the perturbation.
inline fabric_recipe fabric_preset_recipe(fabric_preset preset, std::uint64_t seed = 1) {
  const palette black_white = {{{0.0f, 0.0f, 0.0f}, 0.75}, {{1.0f, 1.0f, 1.0f}, 0.25}};
  fabric_recipe r;
  r.source.seed = seed;
  r.options.perturbation.seed = seed;
  switch (preset) {
    case fabric_preset::flannel:  // figure 4: 60 steps of the figure-3 source
      r.tones = black_white;
      r.source.layout = source_layout::blocks;
      r.options.iterations = 60;
      break;
    case fabric_preset::twill:  // figure 5: 31 steps of the same source
      r.tones = black_white;
      r.source.layout = source_layout::blocks;
      r.options.iterations = 31;
      break;
    case fabric_preset::linen:  // figures 6-7: a photo-like source, 80 steps
      r.photo = exemplar_kind::cells;
      r.options.iterations = 80;
      break;
    case fabric_preset::tweed:  // figures 8-9: wool tones, cat map, game-of-life perturbation
      r.tones = {{{0.30f, 0.22f, 0.16f}, 0.40},
                 {{0.55f, 0.45f, 0.33f}, 0.30},
                 {{0.78f, 0.72f, 0.60f}, 0.20},
                 {{0.60f, 0.25f, 0.15f}, 0.10}};
      r.source.layout = source_layout::blocks;
      r.options.iterations = 45;
      r.options.perturbation.generations = 3;
      break;
  }
  return r;
}

/// Options of make_fabric with a preset.
struct fabric_preset_options {
  index_t tile_size = 0;            ///< side N of the periodic square; 0 = max(width, height) of the output
  std::uint64_t seed = 1;           ///< source layout, photo and perturbation
  tessera::progress progress = {};  ///< as fabric_options::progress
};

/// Makes a preset fabric (the recipe of fabric_preset_recipe) into `out`, of any size.
/// Errors and complexity as make_fabric; output is a pure function of (preset, size, options).
template <WritableImage O, Executor E = serial_executor>
[[nodiscard]] status make_fabric(fabric_preset preset, O& out, const fabric_preset_options& options = {},
                                 E&& exec = {}) {
  if (auto s = validate_image(out, "make_fabric: output"); !s) return s;
  if (to_string(preset) == "unknown")
    return status::invalid_argument(detail::cat("make_fabric: unknown preset value ", static_cast<int>(preset)));
  fabric_recipe r = fabric_preset_recipe(preset, options.seed);
  r.options.tile_size = options.tile_size;
  r.options.progress = options.progress;
  if (r.photo) {
    index_t n = 0;
    if (auto s = detail::check_fabric_size(width_of(out), height_of(out), channels_v<O>, r.options, n); !s) return s;
    auto photo = make_exemplar<float, 3>(*r.photo, {.width = n, .height = n, .seed = options.seed});
    if (!photo) return photo.error();
    return make_fabric(*photo, out, r.options, exec);
  }
  return make_fabric(r.tones, r.source, out, r.options, exec);
}

TESSERA_NAMESPACE_END
