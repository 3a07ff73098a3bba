// tessera/image/metrics.hpp: quality measures for synthesized textures, used by tests as invariants,
// by the `tessera` command's --stats and by benchmarks:
//
//   neighborhood_energy   how far output neighbourhoods are from the exemplar's (0: all occur in it)
//   multiscale_energy     the same at 1x, 1/2x, 1/4x...: breaks in structure larger than a window
//   seam_gradient_ratio   how visible given seams are, relative to the exemplar's own gradients
//   histogram_distance    how different two images' per-channel value histograms are
//   repetition_score      how strongly an image repeats itself (largest autocorrelation at a distance)
//
// All channel values are taken in the unit range (uint8 0..255 and uint16 0..65535 map to 0..1, float
// as is), so figures are comparable across pixel types. When two images have different channel
// counts, the second is converted to the first's with convert_pixel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/status.hpp"
#include "detail/fft.hpp"
#include "detail/nearest.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of neighborhood_energy.
struct neighborhood_energy_options {
  index_t window = 5;        ///< neighbourhood side in pixels (>= 1, at most the smaller image side)
  index_t sample_step = 2;   ///< output windows are taken every sample_step pixels in x and y (>= 1)
  bool brute_force = false;  ///< compare with every exemplar window instead of the kd-tree (same result)
};

namespace detail {
/// Copies the w x w window at (x, y) of a float buffer into `out` (row by row).
template <int C>
void gather_window(const image_buffer<float, C>& img, index_t x, index_t y, index_t w, float* out) {
  for (index_t r = 0; r < w; ++r) out = std::copy_n(img.pixel_ptr(x, y + r), w * C, out);
}
/// Squared distance of two windows of `rows` rows of `row` floats; stops once above `bound`.
inline double squared_distance(const float* a, const float* b, index_t rows, index_t row,
                               double bound = std::numeric_limits<double>::infinity()) {
  double s = 0;
  for (index_t r = 0; r < rows && s <= bound; ++r)
    for (index_t i = r * row; i < (r + 1) * row; ++i) {
      const double d = static_cast<double>(a[i]) - static_cast<double>(b[i]);
      s += d * d;
    }
  return s;
}
}  // namespace detail

namespace detail {
/// neighborhood_energy of a float output against the windows of several float exemplars (each window
/// lies inside one of them); the window fits every image (checked by the callers).
template <int C, class X>
result<double> energy_against(const image_buffer<float, C>& out, std::span<const image_buffer<float, C>> exemplars,
                              const neighborhood_energy_options& opts, X&& exec) {
  const index_t w = opts.window, D = w * w * C;
  index_t ne = 0;
  for (const auto& ex : exemplars) ne += (ex.width() - w + 1) * (ex.height() - w + 1);
  std::vector<float> windows(to_size(ne * D));
  float* dst = windows.data();
  for (const auto& ex : exemplars)
    for (index_t y = 0; y + w <= ex.height(); ++y)
      for (index_t x = 0; x + w <= ex.width(); ++x, dst += D) gather_window(ex, x, y, w, dst);
  const index_t qnx = (out.width() - w) / opts.sample_step + 1, qny = (out.height() - w) / opts.sample_step + 1;

  // kd-tree over PCA projections of the exemplar windows (unless brute force is cheaper or asked for)
  const bool brute =
      opts.brute_force || static_cast<double>(ne) * static_cast<double>(qnx * qny) * static_cast<double>(D) < 4e6;
  // Eigen and the kd-tree through dependent_t: compiled only where neighborhood_energy is used
  using real = dependent_t<double, std::remove_cvref_t<X>>;
  using matrix = Eigen::Matrix<real, Eigen::Dynamic, Eigen::Dynamic>;
  using column = Eigen::Matrix<real, Eigen::Dynamic, 1>;
  using row = Eigen::Matrix<real, 1, Eigen::Dynamic>;
  using knn = dependent_knn<-1, std::remove_cvref_t<X>>;
  matrix basis;
  knn index;
  if (!brute) {
    const index_t m = std::min<index_t>(ne, 512);
    matrix samples(m, D);
    for (index_t s = 0; s < m; ++s) {
      const float* v = windows.data() + (s * ne / m) * D;
      for (index_t j = 0; j < D; ++j) samples(s, j) = v[j];
    }
    basis = pca_basis(std::move(samples), 12);
    const int d = static_cast<int>(basis.cols());
    std::vector<double> proj(to_size(ne * d));
    column v(D);
    double scale = 0;
    for (index_t i = 0; i < ne; ++i) {
      for (index_t j = 0; j < D; ++j) v(j) = windows[to_size(i * D + j)];
      Eigen::Map<row>(proj.data() + i * d, d) = v.transpose() * basis;
      scale = std::max(scale, v.squaredNorm());
    }
    index = knn(std::move(proj), ne, d, scale);
  }

  std::vector<double> row_sums(to_size(qny), 0.0);
  exec.parallel_for(0, qny, [&](index_t qy) {
    std::vector<float> q(to_size(D));
    std::vector<neighbor> best;
    column qv(D);
    double sum = 0;
    for (index_t qx = 0; qx < qnx; ++qx) {
      gather_window(out, qx * opts.sample_step, qy * opts.sample_step, w, q.data());
      double nearest = 0;
      if (brute) {
        nearest = std::numeric_limits<double>::infinity();
        for (index_t i = 0; i < ne; ++i)
          nearest = std::min(nearest, squared_distance(q.data(), windows.data() + i * D, w, w * C, nearest));
      } else {
        for (index_t j = 0; j < D; ++j) qv(j) = q[to_size(j)];
        const row qp = qv.transpose() * basis;
        index.search(
            qp.data(), 1,
            [&](std::uint32_t i, double bound) {
              return squared_distance(q.data(), windows.data() + i * D, w, w * C, bound);
            },
            best);
        nearest = best.front().dist;
      }
      sum += std::sqrt(nearest / static_cast<double>(D));
    }
    row_sums[to_size(qy)] = sum;
  });
  double total = 0;
  for (double s : row_sums) total += s;
  return total / static_cast<double>(qnx * qny);
}
}  // namespace detail

/// Neighbourhood energy of `output` against `exemplar`: the mean, over output windows of
/// `window` x `window` pixels taken every `sample_step` pixels, of the smallest RMS distance (channel
/// values in unit range) to any exemplar window. 0 means every output neighbourhood occurs verbatim
/// in the exemplar; white noise against a smooth exemplar scores around 0.3 and more. This is the
/// texture energy that patch-based synthesis implicitly minimizes (paper 002 §1, the MRF model of its
/// ref. [1]); tests use it as "far closer to the exemplar than noise".
///
/// The nearest exemplar window is exact: a nanoflann kd-tree over PCA projections prunes with exact
/// distances (see image/detail/nearest.hpp), or brute force when `brute_force` is set or the inputs
/// are tiny. Errors: invalid_argument for an empty image, window < 1 or larger than either image,
/// sample_step < 1. Complexity: about O(Nq log Ne * window^2) for Nq output windows and Ne exemplar
/// windows on textured inputs, O(Nq Ne window^2) worst case. Runs on `exec`; the result does not
/// depend on it. Thread safety: pure function of its inputs.
template <Image O, Image E, Executor X = serial_executor>
result<double> neighborhood_energy(const O& output, const E& exemplar, const neighborhood_energy_options& opts = {},
                                   X&& exec = {}) {
  constexpr int C = channels_v<O>;
  if (auto s = validate_image(output, "output"); !s) return s;
  if (auto s = validate_finite_pixels(output, "output"); !s) return s;
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  const index_t w = opts.window;
  if (w < 1) return status::invalid_argument(detail::cat("neighborhood_energy: window must be >= 1, got ", w));
  if (opts.sample_step < 1)
    return status::invalid_argument(
        detail::cat("neighborhood_energy: sample_step must be >= 1, got ", opts.sample_step));
  if (w > width_of(exemplar) || w > height_of(exemplar) || w > width_of(output) || w > height_of(output))
    return status::invalid_argument(detail::cat("neighborhood_energy: window ", w, " does not fit the output (",
                                                width_of(output), " x ", height_of(output), ") and the exemplar (",
                                                width_of(exemplar), " x ", height_of(exemplar), ")"));
  auto out = to_buffer<float, C>(output, "output");
  auto ex = to_buffer<float, C>(exemplar, "exemplar");
  if (!out) return out.error();
  if (!ex) return ex.error();
  return detail::energy_against(*out, std::span<const image_buffer<float, C>>(&*ex, 1), opts, exec);
}

/// Options of multiscale_energy.
struct multiscale_energy_options {
  index_t window = 7;        ///< neighbourhood side at every level (>= 1, fits both images at the coarsest level)
  index_t sample_step = 2;   ///< output windows every sample_step pixels of each level (>= 1)
  int levels = 2;            ///< 1: full resolution only; 2: also half resolution; ... (1 to 6)
  bool brute_force = false;  ///< compare with every exemplar window instead of the kd-tree (same result)
};

namespace detail {
/// The f x f block means of `img` starting at (dx, dy): (width - dx) / f x (height - dy) / f pixels
/// (partial blocks at the right and bottom are dropped).
template <int C>
image_buffer<float, C> box_shrink(const image_buffer<float, C>& img, index_t f, index_t dx, index_t dy) {
  const index_t w = (img.width() - dx) / f, h = (img.height() - dy) / f;
  image_buffer<float, C> out(w, h);
  const double scale = 1.0 / static_cast<double>(f * f);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      double sum[C] = {};
      for (index_t r = 0; r < f; ++r) {
        const float* p = img.pixel_ptr(dx + x * f, dy + y * f + r);
        for (index_t i = 0; i < f; ++i)
          for (int c = 0; c < C; ++c) sum[c] += static_cast<double>(p[i * C + c]);
      }
      float* o = out.pixel_ptr(x, y);
      for (int c = 0; c < C; ++c) o[c] = static_cast<float>(sum[c] * scale);
    }
  return out;
}
}  // namespace detail

/// Multi-scale neighbourhood energy: neighborhood_energy of `output` against `exemplar` at full
/// resolution, then at 1/2, 1/4, ... (`levels` values; element l is the energy at 1 / 2^l). At level l
/// the output is shrunk by 2^l (means of 2^l x 2^l blocks) and compared with the windows of the
/// exemplar shrunk the same way **at every one of the 4^l block phases**, so that a verbatim copy of the
/// exemplar at any offset scores 0 at every level (shrinking both images on one block grid would
/// penalize copies at odd offsets, which patch synthesis makes everywhere). Same window and sample step
/// at every level. Synthesis that keeps every small neighbourhood plausible but breaks the structure at
/// the scale of its patches scores well at 1x and worse at 1/2x; scripts/quality-patch.sh reports both.
///
/// Errors: those of neighborhood_energy (the window must fit both images shrunk by 2^(levels - 1))
/// and invalid_argument for levels outside [1, 6]. Complexity: level l compares output windows with
/// 4^l shrunk exemplars of 1/4^l the pixels, so every level costs about as much as the first.
/// Runs on `exec`; the result does not depend on it. Thread safety: pure function of its inputs.
template <Image O, Image E, Executor X = serial_executor>
result<std::vector<double>> multiscale_energy(const O& output, const E& exemplar,
                                              const multiscale_energy_options& opts = {}, X&& exec = {}) {
  constexpr int C = channels_v<O>;
  if (opts.levels < 1 || opts.levels > 6)
    return status::invalid_argument(detail::cat("multiscale_energy: levels must be in [1, 6], got ", opts.levels));
  const neighborhood_energy_options eo{
      .window = opts.window, .sample_step = opts.sample_step, .brute_force = opts.brute_force};
  auto first = neighborhood_energy(output, exemplar, eo, exec);  // validates the images and options
  if (!first) return first.error();
  std::vector<double> energies{*first};
  const index_t w = opts.window, shrink = index_t{1} << (opts.levels - 1);
  if (w * shrink > width_of(output) || w * shrink > height_of(output) || w * shrink + shrink > width_of(exemplar) ||
      w * shrink + shrink > height_of(exemplar))
    return status::invalid_argument(detail::cat("multiscale_energy: window ", w, " does not fit the output (",
                                                width_of(output), " x ", height_of(output), ") and the exemplar (",
                                                width_of(exemplar), " x ", height_of(exemplar), ") at 1/", shrink));
  auto out = to_buffer<float, C>(output, "output");
  auto ex = to_buffer<float, C>(exemplar, "exemplar");
  if (!out) return out.error();
  if (!ex) return ex.error();
  for (int level = 1; level < opts.levels; ++level) {
    const index_t f = index_t{1} << level;
    std::vector<image_buffer<float, C>> phases;
    for (index_t dy = 0; dy < f; ++dy)
      for (index_t dx = 0; dx < f; ++dx) phases.push_back(detail::box_shrink(*ex, f, dx, dy));
    auto energy = detail::energy_against(detail::box_shrink(*out, f, 0, 0),
                                         std::span<const image_buffer<float, C>>(phases), eo, exec);
    if (!energy) return energy.error();
    energies.push_back(*energy);
  }
  return energies;
}

/// A straight seam in an image: `vertical` is the boundary between columns position-1 and position
/// over rows [begin, end); horizontal is the boundary between rows position-1 and position over
/// columns [begin, end).
struct seam_segment {
  /// True: between columns; false: between rows.
  bool vertical = true;
  /// The column (or row) right of (below) the seam.
  index_t position = 0;
  /// First row (or column) of the seam.
  index_t begin = 0;
  /// One past its last row (or column).
  index_t end = 0;
};

namespace detail {
/// The checks seam_gradient_ratio and seam_step_ratio share: images valid and finite, seams inside.
template <Image I, Image R>
status validate_seam_inputs(const I& image, std::span<const seam_segment> seams, const R& reference,
                            std::string_view fn) {
  if (auto s = validate_image(image, "image"); !s) return s;
  if (auto s = validate_finite_pixels(image, "image"); !s) return s;
  if (auto s = validate_image(reference, "reference"); !s) return s;
  if (auto s = validate_finite_pixels(reference, "reference"); !s) return s;
  if (seams.empty()) return status::invalid_argument(cat(fn, ": seams is empty"));
  const index_t w = width_of(image), h = height_of(image);
  for (std::size_t i = 0; i < seams.size(); ++i) {
    const seam_segment& s = seams[i];
    const index_t across = s.vertical ? w : h, along = s.vertical ? h : w;
    if (s.position < 1 || s.position > across - 1 || s.begin < 0 || s.begin >= s.end || s.end > along)
      return status::out_of_range(cat(fn, ": seams[", i, "] (", s.vertical ? "vertical" : "horizontal", ", position ",
                                      s.position, ", rows/columns [", s.begin, ", ", s.end, ")) lies outside the ", w,
                                      " x ", h, " image"));
  }
  return {};
}

/// Per-channel integral image (sums over [0, x) x [0, y)) for box means in O(1).
template <int C>
class box_sums {
 public:
  explicit box_sums(const image_buffer<float, C>& img)
      : w_(img.width() + 1), sums_(to_size(w_ * (img.height() + 1) * C)) {
    for (index_t y = 0; y < img.height(); ++y)
      for (index_t x = 0; x < img.width(); ++x)
        for (int c = 0; c < C; ++c)
          at(x + 1, y + 1, c) =
              static_cast<double>(img.pixel_ptr(x, y)[c]) + at(x, y + 1, c) + at(x + 1, y, c) - at(x, y, c);
  }
  /// Mean of channel c over [x, x + bw) x [y, y + bh).
  [[nodiscard]] double mean(index_t x, index_t y, index_t bw, index_t bh, int c) const {
    return (at(x + bw, y + bh, c) - at(x, y + bh, c) - at(x + bw, y, c) + at(x, y, c)) / static_cast<double>(bw * bh);
  }

 private:
  [[nodiscard]] double at(index_t x, index_t y, int c) const { return sums_[to_size((y * w_ + x) * C + c)]; }
  double& at(index_t x, index_t y, int c) { return sums_[to_size((y * w_ + x) * C + c)]; }
  index_t w_;
  std::vector<double> sums_;
};
}  // namespace detail

/// Seam gradient ratio: the mean absolute difference across the given seams (over the pixel pairs
/// the seams separate and all channels, unit range) divided by the mean absolute difference between
/// neighbouring pixels of `reference` (the exemplar) in the same directions, weighted by how many seam
/// pixels run in each direction. About 1 means the seams are as smooth as the exemplar's own texture;
/// hard, mismatched seams give 2 and more. Measures the visibility of the block boundaries that paper
/// 002 blends by feathering (§2) and that a minimum-error cut hides.
///
/// Errors: invalid_argument for an empty image or reference, no seams, a seam outside the image
/// (position must be in [1, width-1] for a vertical seam, [1, height-1] for a horizontal one; 0 <=
/// begin < end <= height or width), or a reference without gradients in the needed direction.
/// Complexity O(seam pixels + reference pixels). Thread safety: pure function of its inputs.
template <Image I, Image R>
result<double> seam_gradient_ratio(const I& image, std::span<const seam_segment> seams, const R& reference) {
  constexpr int C = channels_v<I>;
  if (auto s = detail::validate_seam_inputs(image, seams, reference, "seam_gradient_ratio"); !s) return s;
  auto img = to_buffer<float, C>(image, "image");
  auto ref = to_buffer<float, C>(reference, "reference");
  if (!img) return img.error();
  if (!ref) return ref.error();
  auto absdiff = [](const float* a, const float* b) {
    double s = 0;
    for (int c = 0; c < C; ++c) s += std::abs(static_cast<double>(a[c]) - static_cast<double>(b[c]));
    return s / C;
  };
  double seam_sum = 0;
  index_t n_vertical = 0, n_horizontal = 0;
  for (const seam_segment& s : seams)
    for (index_t t = s.begin; t < s.end; ++t) {
      if (s.vertical) {
        seam_sum += absdiff(img->pixel_ptr(s.position - 1, t), img->pixel_ptr(s.position, t));
        ++n_vertical;
      } else {
        seam_sum += absdiff(img->pixel_ptr(t, s.position - 1), img->pixel_ptr(t, s.position));
        ++n_horizontal;
      }
    }
  // reference gradients: across vertical boundaries (x neighbours) and horizontal ones (y neighbours)
  double ref_x = 0, ref_y = 0;
  const index_t rw = ref->width(), rh = ref->height();
  for (index_t y = 0; y < rh; ++y)
    for (index_t x = 0; x < rw; ++x) {
      if (x > 0) ref_x += absdiff(ref->pixel_ptr(x - 1, y), ref->pixel_ptr(x, y));
      if (y > 0) ref_y += absdiff(ref->pixel_ptr(x, y - 1), ref->pixel_ptr(x, y));
    }
  if ((n_vertical > 0 && rw < 2) || (n_horizontal > 0 && rh < 2))
    return status::invalid_argument(detail::cat("seam_gradient_ratio: reference ", rw, " x ", rh,
                                                " is too small to measure gradients across the seams"));
  const double mean_x = rw > 1 ? ref_x / static_cast<double>((rw - 1) * rh) : 0;
  const double mean_y = rh > 1 ? ref_y / static_cast<double>(rw * (rh - 1)) : 0;
  const double expected = (static_cast<double>(n_vertical) * mean_x + static_cast<double>(n_horizontal) * mean_y) /
                          static_cast<double>(n_vertical + n_horizontal);
  if (!(expected > 0))
    return status::invalid_argument(
        "seam_gradient_ratio: reference has no gradients in the seams' directions (flat image)");
  return seam_sum / static_cast<double>(n_vertical + n_horizontal) / expected;
}

/// Seam step ratio: how much the mean colour steps across the given seams, against the exemplar's own
/// steps at the same scale. At every `box` pixels along a seam, the box x box squares on either side
/// of it (touching it) are averaged; the step is the mean absolute difference of the two means over
/// the channels (unit range). The result is the mean step over the seams divided by the mean step
/// between side-by-side squares of `reference` at every position in the same directions (weighted
/// like seam_gradient_ratio). About 1: the patches meet like any two neighbouring regions of the
/// exemplar; well above 1: a visible grid of brighter and darker patches, which a narrow blend band
/// spreads over a few pixels, so that seam_gradient_ratio (one pixel across) and the neighbourhood
/// energies miss it (docs/patch_synthesis.md, "The current figures"). Positions whose squares do not
/// fit the image are skipped.
///
/// Errors: those of seam_gradient_ratio's inputs; invalid_argument for box < 1, no seam position
/// whose squares fit the image, a reference smaller than 2 box x box in a needed direction or with no
/// steps (flat). Complexity O(image pixels + reference pixels). Thread safety: pure function.
template <Image I, Image R>
result<double> seam_step_ratio(const I& image, std::span<const seam_segment> seams, const R& reference,
                               index_t box = 8) {
  constexpr int C = channels_v<I>;
  if (auto s = detail::validate_seam_inputs(image, seams, reference, "seam_step_ratio"); !s) return s;
  if (box < 1) return status::invalid_argument(detail::cat("seam_step_ratio: box must be >= 1, got ", box));
  auto img = to_buffer<float, C>(image, "image");
  auto ref = to_buffer<float, C>(reference, "reference");
  if (!img) return img.error();
  if (!ref) return ref.error();
  const detail::box_sums<C> is(*img), rs(*ref);
  // the step between the squares left of / above (x, y) and right of / below it
  auto step = [&](const detail::box_sums<C>& b, bool vertical, index_t x, index_t y) {
    double d = 0;
    for (int c = 0; c < C; ++c)
      d += vertical ? std::abs(b.mean(x - box, y, box, box, c) - b.mean(x, y, box, box, c))
                    : std::abs(b.mean(x, y - box, box, box, c) - b.mean(x, y, box, box, c));
    return d / C;
  };
  const index_t w = img->width(), h = img->height();
  double seam_sum = 0;
  index_t n_vertical = 0, n_horizontal = 0;
  for (const seam_segment& s : seams) {
    const index_t across = s.vertical ? w : h;  // validated: s.end is inside the image
    if (s.position < box || s.position + box > across) continue;
    for (index_t t = s.begin; t + box <= s.end; t += box) {
      seam_sum += s.vertical ? step(is, true, s.position, t) : step(is, false, t, s.position);
      ++(s.vertical ? n_vertical : n_horizontal);
    }
  }
  if (n_vertical + n_horizontal == 0)
    return status::invalid_argument(detail::cat("seam_step_ratio: no seam position has ", box, " x ", box,
                                                " squares on both sides inside the ", w, " x ", h, " image"));
  const index_t rw = ref->width(), rh = ref->height();
  if ((n_vertical > 0 && rw < 2 * box) || (n_horizontal > 0 && rh < 2 * box) || rw < box || rh < box)
    return status::invalid_argument(detail::cat("seam_step_ratio: reference ", rw, " x ", rh, " is too small for ", box,
                                                " x ", box, " squares on both sides of a step"));
  double ref_x = 0, ref_y = 0;
  index_t nx = 0, ny = 0;
  for (index_t y = 0; y + box <= rh; ++y)
    for (index_t x = box; x + box <= rw; ++x, ++nx) ref_x += step(rs, true, x, y);
  for (index_t y = box; y + box <= rh; ++y)
    for (index_t x = 0; x + box <= rw; ++x, ++ny) ref_y += step(rs, false, x, y);
  const double mean_x = nx > 0 ? ref_x / static_cast<double>(nx) : 0;
  const double mean_y = ny > 0 ? ref_y / static_cast<double>(ny) : 0;
  const double expected = (static_cast<double>(n_vertical) * mean_x + static_cast<double>(n_horizontal) * mean_y) /
                          static_cast<double>(n_vertical + n_horizontal);
  if (!(expected > 0))
    return status::invalid_argument("seam_step_ratio: reference has no steps in the seams' directions (flat image)");
  return seam_sum / static_cast<double>(n_vertical + n_horizontal) / expected;
}

/// Histogram distance: per channel, the L1 distance between the normalized histograms of `a` and
/// `b` (`bins` equal bins over the unit range; values outside it are clamped, NaN counts as 0),
/// averaged over channels. In [0, 2]: 0 for identical value distributions, 2 for disjoint ones.
/// The images may differ in size. Paper 002 §2.1.1 compares grey histograms the same way (with an
/// L2 distance) to measure how much of the exemplar a patch contains.
/// Errors: invalid_argument for an empty image or bins outside [1, 65536]. Complexity O(pixels + bins).
template <Image A, Image B>
result<double> histogram_distance(const A& a, const B& b, int bins = 32) {
  constexpr int C = channels_v<A>;
  if (auto s = validate_image(a, "a"); !s) return s;
  if (auto s = validate_image(b, "b"); !s) return s;  // non-finite values are binned (documented above)
  if (bins < 1 || bins > 65536)
    return status::invalid_argument(detail::cat("histogram_distance: bins must be in [1, 65536], got ", bins));
  auto fa = to_buffer<float, C>(a, "a");
  auto fb = to_buffer<float, C>(b, "b");
  if (!fa) return fa.error();
  if (!fb) return fb.error();
  auto histogram = [&](const image_buffer<float, C>& img, int c) {
    std::vector<double> hist(detail::to_size(bins), 0.0);
    const index_t n = img.width() * img.height();
    for (index_t i = 0; i < n; ++i) {
      const float v = img.data()[i * C + c];
      const double u = v > 0 ? std::min(static_cast<double>(v), 1.0) : 0.0;  // NaN -> 0
      hist[detail::to_size(std::min<index_t>(bins - 1, static_cast<index_t>(u * bins)))] +=
          1.0 / static_cast<double>(n);
    }
    return hist;
  };
  double total = 0;
  for (int c = 0; c < C; ++c) {
    const auto ha = histogram(*fa, c), hb = histogram(*fb, c);
    for (int i = 0; i < bins; ++i) total += std::abs(ha[detail::to_size(i)] - hb[detail::to_size(i)]);
  }
  return total / C;
}

/// Repetition score: the largest normalized autocorrelation of `image` (the Pearson correlation
/// between the image and itself shifted by (dx, dy), over the overlapping pixels, all channels
/// pooled with per-channel means) over the offsets with max(|dx|, |dy|) >= min_offset, |dx| <= width/2
/// and |dy| <= height/2 (so at least a quarter of the image overlaps). Near 1 means visible
/// repetition (a tiled or copied-through exemplar); synthesized stochastic textures stay well below.
/// Offsets where either side is flat are skipped; 0 when all are.
///
/// Errors: invalid_argument for an empty image or min_offset outside [1, max(width, height) / 2].
/// Complexity O(C N log N) for N pixels (FFT correlation sums plus integral images).
/// Thread safety: pure function of its inputs.
template <Image I>
result<double> repetition_score(const I& image, index_t min_offset) {
  constexpr int C = channels_v<I>;
  if (auto s = validate_image(image, "image"); !s) return s;
  if (auto s = validate_finite_pixels(image, "image"); !s) return s;
  const index_t w = width_of(image), h = height_of(image), mx = w / 2, my = h / 2;
  if (min_offset < 1 || min_offset > std::max(mx, my))
    return status::invalid_argument(detail::cat("repetition_score: min_offset must be in [1, ",
                                                std::max<index_t>(1, std::max(mx, my)), "] for a ", w, " x ", h,
                                                " image, got ", min_offset));
  auto img = to_buffer<float, C>(image, "image");
  if (!img) return img.error();
  const std::vector<double> values(img->data(), img->data() + w * h * C);
  const std::vector<double> corr = detail::correlation_field(values.data(), w, h, C, mx, my);
  double best = 0;
  for (index_t dy = 0; dy <= my; ++dy)
    for (index_t dx = -mx; dx <= mx; ++dx) {
      const double r = corr[detail::to_size(dy * (2 * mx + 1) + dx + mx)];
      if (std::max(std::abs(dx), dy) >= min_offset && r > best) best = r;
    }
  return best;
}

TESSERA_NAMESPACE_END
