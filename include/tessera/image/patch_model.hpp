// tessera/image/patch_model.hpp: the reusable preprocessing of patch synthesis (paper 002 §2): the
// exemplar's patches at every phase, grouped by phase, and for each patch and side its compatible
// set, the k patches whose overlap strip matches best. Build it once per exemplar, keep it, and
// synthesize any number of outputs or windows from it (image/patch_synthesis.hpp).
//
//   auto model = tessera::build_patch_model(exemplar).value();          // ~0.1-0.5 s for 128 x 128
//   tessera::synthesize(model, output, {.seed = 7});                     // milliseconds
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_checks.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "detail/patch_model_sets.hpp"
#include "patch_size.hpp"

TESSERA_NAMESPACE_BEGIN

/// Deprecated spelling of the patch sides: tessera has one side vocabulary, the `int` sides of
/// core/tile_coloring.hpp (side_north 0, side_east 1, side_south 2, side_west 3), which every
/// patch_model query takes. `patch_side::east` still reads as `side_east`.
struct [[deprecated("use tessera::side_north, side_east, side_south, side_west (core/tile_coloring.hpp)")]] patch_side {
  /// Same as side_north.
  static constexpr int north = side_north;
  /// Same as side_east.
  static constexpr int east = side_east;
  /// Same as side_south.
  static constexpr int south = side_south;
  /// Same as side_west.
  static constexpr int west = side_west;
};

/// Options of build_patch_model (docs/patch_synthesis.md has the table of fields and defaults).
struct patch_model_options {
  index_t patch_width = 0;    ///< cell pitch in x; 0: chosen by analyze_patch_size (paper §2.1)
  index_t patch_height = 0;   ///< cell pitch in y; 0: chosen by analyze_patch_size
  index_t overlap = 0;        ///< overlap width between neighbouring patches; 0: chosen by the analysis
  int candidates = 8;         ///< k, the size of each compatible set (paper: 8), 1 to 64; at most the number of patches
  bool exact_sets = false;    ///< exact top-k sets (branch and bound); slower on stochastic exemplars
  int pca_dims = 8;           ///< PCA dimensions of the strip descriptors
  index_t pca_samples = 384;  ///< strips sampled to estimate the PCA basis
  int search_pool = 16;       ///< approximate sets: kd-tree candidates re-ranked by exact L2 per patch and side
  int refine_iterations = 4;  ///< approximate sets: coherence propagation rounds after the kd-tree search
  bool seams = false;         ///< also precompute a minimum-error seam for every compatible pair
  patch_size_options analysis = {};  ///< options of the size analysis when a size or the overlap is 0
  /// Smallest patch side the size analysis tries, as a fraction of the exemplar's smaller side, when
  /// `analysis.min_size` is 0: 0.375 (ours; on photographs the paper's 1/4 breaks the structure at the
  /// scale of the patches, docs/patch_synthesis.md "Patch size"); 0.25 is paper 002 §2.1's range. In (0, 0.5].
  double min_patch_fraction = 0.375;
  tessera::progress progress = {};  ///< fraction done; return false (or raise the token) to cancel
};

namespace detail {
struct patch_model_builder;
}  // namespace detail

/// Exemplar coordinates of a patch's top-left pixel.
struct patch_origin {
  /// Column.
  index_t x = 0;
  /// Row.
  index_t y = 0;
  friend bool operator==(const patch_origin&, const patch_origin&) = default;
};

/// A member of a compatible set and its overlap error.
struct indexed_candidate {
  /// The patch index.
  std::uint32_t patch = 0;
  /// Its overlap error with the set's owner.
  float error = 0;
};

/// A shift between two phases and how alike patches of the two phases look (autocorrelation).
struct phase_offset {
  /// Shift in x.
  index_t dx = 0;
  /// Shift in y.
  index_t dy = 0;
  /// Autocorrelation at the shift.
  double similarity = 0;
};

/// The preprocessed exemplar. A patch is a (patch_width + overlap) x (patch_height + overlap) block of
/// the exemplar; synthesis places patches on a grid of pitch patch_width x patch_height, so neighbours
/// overlap by `overlap` pixels. Patches start at every exemplar position ("every phase"): patch p has
/// origin (p % patches_x, p / patches_x), and its phase is (x mod patch_width, y mod patch_height).
/// Immutable after building; safe to share between threads.
template <Channel T, int C>
class patch_model {
 public:
  /// The exemplar's channel type T.
  using channel_type = T;
  /// The exemplar's channel count C.
  static constexpr int channels = C;

  patch_model() = default;

  /// Cell pitch in x.
  [[nodiscard]] index_t patch_width() const noexcept { return pw_; }
  /// Cell pitch in y.
  [[nodiscard]] index_t patch_height() const noexcept { return ph_; }
  /// Overlap width between neighbouring patches.
  [[nodiscard]] index_t overlap() const noexcept { return v_; }
  /// Size of every compatible set.
  [[nodiscard]] index_t candidates() const noexcept { return k_; }
  /// The exemplar, converted to the model's pixel type.
  [[nodiscard]] const image_buffer<T, C>& exemplar() const noexcept { return exemplar_; }
  /// Number of patches (patches_x * patches_y).
  [[nodiscard]] index_t num_patches() const noexcept { return nx_ * ny_; }
  /// Patch positions per exemplar row.
  [[nodiscard]] index_t patches_x() const noexcept { return nx_; }
  /// Patch positions per exemplar column.
  [[nodiscard]] index_t patches_y() const noexcept { return ny_; }
  /// Exemplar position of a patch's top-left pixel.
  [[nodiscard]] patch_origin origin(index_t patch) const noexcept { return {patch % nx_, patch / nx_}; }

  /// The k patches that fit best on `side` of `patch` (b on the east side of a: a's last `overlap`
  /// columns against b's first ones, over the full patch height), ascending by overlap_error, ties by
  /// index.
  [[nodiscard]] std::span<const std::uint32_t> compatible(index_t patch, int side) const noexcept {
    const auto s = detail::to_size(side);
    return {compat_[s].data() + patch * k_, detail::to_size(k_)};
  }
  /// The compatible set with its errors ordered by patch index (for set intersections).
  [[nodiscard]] std::span<const indexed_candidate> compatible_by_index(index_t patch, int side) const noexcept {
    const auto s = detail::to_size(side);
    return {by_index_[s].data() + patch * k_, detail::to_size(k_)};
  }
  /// overlap_error(patch, compatible(patch, side)[r], side) for every r (ascending), as floats.
  [[nodiscard]] std::vector<float> compatible_errors(index_t patch, int side) const {
    std::vector<float> out;
    const auto by_id = compatible_by_index(patch, side);
    for (std::uint32_t q : compatible(patch, side))
      for (const indexed_candidate& c : by_id)
        if (c.patch == q) out.push_back(c.error);
    return out;
  }
  /// The largest error in the set (its k-th), a lower bound of the error of any patch outside it.
  [[nodiscard]] float kth_error(index_t patch, int side) const noexcept {
    return worst_[detail::to_size(patch * 4 + side)];
  }
  /// The exemplar's normalized autocorrelation at a shift of one patch pitch (mean of the shifts
  /// (patch_width, 0) and (0, patch_height)): near 1 when the texture repeats with the patch grid.
  [[nodiscard]] double pitch_alignment() const noexcept { return alignment_; }
  /// Every phase offset (dx in [0, patch_width), dy in [0, patch_height)) with the exemplar's
  /// autocorrelation at that shift (its smallest representative modulo the pitch), most similar first
  /// (stable: ties keep row-major order). Phases this similar look alike: synthesis draws its
  /// distributed patches from the phases most similar to one phase.
  [[nodiscard]] std::span<const phase_offset> phase_similarity() const noexcept { return phase_order_; }

  /// Exact sum of squared channel differences (in channel units) over the overlap strip when patch b
  /// sits on `side` of patch a. Integer-exact for uint8 and uint16 channels.
  [[nodiscard]] double overlap_error(index_t a, index_t b, int side) const {
    return bounded_error(a, b, side, std::numeric_limits<double>::infinity());
  }

  /// Estimated overlap_error(a, b, side), from the strips' PCA descriptors kept by the model: the
  /// squared distance of the two overlap strips' projections on the model's PCA basis (pca_dims) plus
  /// both strips' residuals (their squared distances to that subspace, taken as uncorrelated). Cheap (d +
  /// 1 values per strip); used by the estimated fallback of synthesis (fill_fallback::estimated_error).
  [[nodiscard]] double estimated_error(index_t a, index_t b, int side) const noexcept {
    const float* sa = strip_descriptor(a, side);
    const float* sb = strip_descriptor(b, (side + 2) % 4);
    return strips_[side == side_east || side == side_west ? 0 : 1].estimate(sa, sb);
  }
  /// The descriptor of one side's overlap strip of a patch (d projections and the residual); internal
  /// layout, for estimated_error and synthesis.
  [[nodiscard]] const float* strip_descriptor(index_t patch, int side) const noexcept {
    const patch_origin o = origin(patch);
    switch (side) {
      case side_east: return strips_[0].at(o.x + pw_, o.y);
      case side_west: return strips_[0].at(o.x, o.y);
      case side_south: return strips_[1].at(o.x, o.y + ph_);
      default: return strips_[1].at(o.x, o.y);
    }
  }
  /// The distance estimate between two strip descriptors of a side's family (see estimated_error).
  [[nodiscard]] double descriptor_distance(const float* a, const float* b, int side) const noexcept {
    return strips_[side == side_east || side == side_west ? 0 : 1].estimate(a, b);
  }

  /// Phases are numbered py * patch_width + px.
  [[nodiscard]] index_t num_phases() const noexcept { return pw_ * ph_; }
  /// The phase of a patch: its origin modulo the patch size.
  [[nodiscard]] index_t phase_of(index_t patch) const noexcept {
    const patch_origin o = origin(patch);
    return (o.y % ph_) * pw_ + o.x % pw_;
  }
  /// The patches of one phase, ascending.
  [[nodiscard]] std::span<const std::uint32_t> phase_patches(index_t phase) const noexcept {
    const auto b = phase_start_[detail::to_size(phase)], e = phase_start_[detail::to_size(phase + 1)];
    return {phase_members_.data() + b, detail::to_size(e - b)};
  }

  /// True when minimum-error seams were precomputed (patch_model_options::seams).
  [[nodiscard]] bool has_seams() const noexcept { return !seams_[0].empty(); }
  /// The precomputed minimum-error seam between `patch` and compatible(patch, side)[rank], oriented
  /// from the left (or top) patch to the right (or bottom) one: entry t is the cut c in [0, overlap)
  /// along the overlap (row t of a vertical overlap, column t of a horizontal one); pixels before the
  /// cut come from the left/top patch. Empty when the model was built without seams.
  [[nodiscard]] std::span<const std::uint8_t> seam(index_t patch, int side, index_t rank) const noexcept {
    const auto s = detail::to_size(side);
    if (seams_[s].empty()) return {};
    const index_t len = seam_length(side);
    return {seams_[s].data() + (patch * k_ + rank) * len, detail::to_size(len)};
  }
  /// Length of a seam along an overlap on `side` (patch height + overlap for east/west).
  [[nodiscard]] index_t seam_length(int side) const noexcept {
    return side == side_east || side == side_west ? ph_ + v_ : pw_ + v_;
  }

  /// The size analysis, when the model ran it (a size or the overlap was left at 0).
  [[nodiscard]] const std::optional<patch_size_analysis>& analysis() const noexcept { return analysis_; }

  /// Bytes held by the model (exemplar, phase lists, compatible sets, seams).
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    std::size_t b = exemplar_.size_bytes() + phase_start_.size() * sizeof(index_t) +
                    phase_members_.size() * sizeof(std::uint32_t) + phase_order_.size() * sizeof(phase_offset);
    for (int s = 0; s < 4; ++s)
      b += compat_[s].size() * sizeof(std::uint32_t) + worst_.size() * sizeof(float) / 4 +
           by_index_[s].size() * sizeof(indexed_candidate) + seams_[s].size();
    return b + strips_[0].bytes() + strips_[1].bytes() + sizeof(*this);
  }

 private:
  friend struct detail::patch_model_builder;

  /// overlap_error, or a partial sum above `bound` once it exceeds `bound`.
  [[nodiscard]] double bounded_error(index_t a, index_t b, int side, double bound) const {
    return detail::strip_error(exemplar_, {pw_, ph_, v_, nx_, ny_}, a, b, side, bound);
  }

  image_buffer<T, C> exemplar_;
  index_t pw_ = 0, ph_ = 0, v_ = 0, k_ = 0, nx_ = 0, ny_ = 0;
  std::vector<index_t> phase_start_;
  std::vector<std::uint32_t> phase_members_;
  std::vector<std::uint32_t> compat_[4];
  std::vector<float> worst_;  ///< per patch and side: the k-th error
  std::vector<indexed_candidate> by_index_[4];
  double alignment_ = 0;
  std::vector<phase_offset> phase_order_;
  std::vector<std::uint8_t> seams_[4];
  detail::strip_descriptors strips_[2];  ///< vertical and horizontal overlap strips, every exemplar position
  std::optional<patch_size_analysis> analysis_;
};

namespace detail {
/// Builds patch models per (channel type, count); friend of patch_model. The heavy steps live in
/// detail/patch_model_sets.hpp.
struct patch_model_builder {
  template <Channel T, int C, Executor E>
  static result<patch_model<T, C>> build(image_buffer<T, C> ex, const patch_model_options& opts, E&& exec) {
    patch_model<T, C> m;
    m.exemplar_ = std::move(ex);
    const index_t W = m.exemplar_.width(), H = m.exemplar_.height();
    m.pw_ = opts.patch_width;
    m.ph_ = opts.patch_height;
    m.v_ = opts.overlap;
    if (m.pw_ == 0 || m.ph_ == 0 || m.v_ == 0) {  // step 1: the size analysis (§2.1)
      patch_size_options a = opts.analysis;
      if (!a.progress.callback && a.progress.token == nullptr) a.progress.token = opts.progress.token;
      if (a.min_size == 0) {  // at least 2, at most the largest side the analysis tries
        const index_t largest = a.max_size > 0 ? a.max_size : std::max<index_t>(2, std::min(W, H) / 2);
        a.min_size =
            std::clamp<index_t>(static_cast<index_t>(opts.min_patch_fraction * static_cast<double>(std::min(W, H))), 2,
                                std::max<index_t>(2, largest));
      }
      auto analysis = (m.pw_ == 0 || m.ph_ == 0) ? analyze_patch_size(m.exemplar_, a, exec)
                                                 : analyze_overlap(m.exemplar_, m.pw_, m.ph_, a);
      if (!analysis) return analysis.error();
      if (m.pw_ == 0) m.pw_ = analysis->patch_width;
      if (m.ph_ == 0) m.ph_ = analysis->patch_height;
      if (m.v_ == 0)
        m.v_ = m.pw_ == analysis->patch_width && m.ph_ == analysis->patch_height
                   ? analysis->overlap
                   : std::max<index_t>(1, std::min({analysis->overlap, m.pw_, m.ph_}));
      m.analysis_ = std::move(*analysis);
    }
    const index_t pw = m.pw_, ph = m.ph_, v = m.v_;
    if (pw < 2 || ph < 2 || v < 1 || v > pw || v > ph)
      return status::invalid_argument(cat("build_patch_model: patch ", pw, " x ", ph, " with overlap ", v,
                                          " is invalid (patch sides >= 2, 1 <= overlap <= patch side)"));
    if (pw + v > W || ph + v > H)
      return status::invalid_argument(cat("build_patch_model: patches of ", pw + v, " x ", ph + v, " (patch ", pw,
                                          " x ", ph, " + overlap ", v, ") do not fit the ", W, " x ", H, " exemplar"));
    m.nx_ = W - pw - v + 1;
    m.ny_ = H - ph - v + 1;
    const index_t n = m.nx_ * m.ny_;
    if (n < 2)
      return status::invalid_argument(cat("build_patch_model: the ", W, " x ", H,
                                          " exemplar holds fewer than two patches of ", pw + v, " x ", ph + v));
    if (n > index_t{1} << 31)
      return status::size_overflow(cat("build_patch_model: ", n, " patches exceed the supported 2^31"));
    if (opts.seams && v > 255)
      return status::invalid_argument(cat("build_patch_model: seams need overlap <= 255, got ", v));
    m.k_ = std::min<index_t>(opts.candidates, n);
    const index_t k = m.k_;

    {  // the exemplar's autocorrelation at the patch pitch and at every phase offset
      const pitch_correlation at(m.exemplar_, pw, ph);
      m.alignment_ = 0.5 * (at(at.mx, 0) + at(0, at.my));
      for (index_t dy = 0; dy < ph; ++dy)
        for (index_t dx = 0; dx < pw; ++dx) {
          // the shift between the phases, taken as its smallest representative modulo the pitch
          const index_t sx = 2 * dx <= pw ? dx : dx - pw, sy = 2 * dy <= ph ? dy : dy - ph;
          m.phase_order_.push_back({dx, dy, dx == 0 && dy == 0 ? 1.0 : at(sx, sy)});
        }
      std::stable_sort(m.phase_order_.begin(), m.phase_order_.end(),
                       [](const phase_offset& a, const phase_offset& b) { return a.similarity > b.similarity; });
    }
    if (!opts.progress.report(0.05, "patch model: phases")) return status::cancelled();

    // step 2: patches grouped by phase (counting sort, so each phase lists its patches ascending)
    m.phase_start_.assign(to_size(pw * ph + 1), 0);
    for (index_t p = 0; p < n; ++p) ++m.phase_start_[to_size(m.phase_of(p) + 1)];
    for (std::size_t i = 1; i < m.phase_start_.size(); ++i) m.phase_start_[i] += m.phase_start_[i - 1];
    m.phase_members_.resize(to_size(n));
    std::vector<index_t> fill(m.phase_start_.begin(), m.phase_start_.end() - 1);
    for (index_t p = 0; p < n; ++p)
      m.phase_members_[to_size(fill[to_size(m.phase_of(p))]++)] = static_cast<std::uint32_t>(p);

    // step 3: compatible sets, stored by error and by patch index (for the intersections)
    const patch_geometry g{pw, ph, v, m.nx_, m.ny_};
    const compatible_set_options so{
        k, opts.exact_sets, opts.pca_dims, opts.pca_samples, opts.search_pool, opts.refine_iterations};
    auto sets = compatible_sets(
        m.exemplar_, g, so, exec,
        [&](double f) { return opts.progress.report(0.05 + 0.8 * f, "patch model: compatible sets"); }, m.strips_);
    if (sets.empty()) return status::cancelled();
    m.worst_.resize(to_size(n * 4));
    for (int si = 0; si < 4; ++si) {
      const auto& set = sets[to_size(si)];
      m.compat_[si] = set.ids;
      auto& by_id = m.by_index_[si];
      by_id.resize(to_size(n * k));
      for (index_t a = 0; a < n; ++a) {
        m.worst_[to_size(a * 4 + si)] = static_cast<float>(set.dist[to_size(a * k + k - 1)]);
        auto* e = by_id.data() + a * k;
        for (index_t r = 0; r < k; ++r)
          e[r] = {set.ids[to_size(a * k + r)], static_cast<float>(set.dist[to_size(a * k + r)])};
        std::sort(e, e + k, [](const indexed_candidate& x, const indexed_candidate& y) { return x.patch < y.patch; });
      }
    }

    // step 4 (optional): a minimum-error seam per compatible pair; east and south first, so that west
    // and north copy the seams of mirrored pairs
    constexpr int seam_order[4] = {1, 2, 3, 0};
    for (int i = 0; i < 4 && opts.seams; ++i) {
      const int si = seam_order[i], mirror = i < 2 ? -1 : seam_order[i - 2];
      m.seams_[si] =
          mirror < 0 ? seam_table(m.exemplar_, g, k, si, m.compat_[si], exec)
                     : seam_table(m.exemplar_, g, k, si, m.compat_[si], exec, &m.compat_[mirror], &m.seams_[mirror]);
      if (!opts.progress.report(0.85 + 0.15 * (i + 1) / 4.0, "patch model: seams")) return status::cancelled();
    }
    if (!opts.progress.report(1.0, "patch model")) return status::cancelled();
    return m;
  }
};
}  // namespace detail

/// Builds the patch model of an exemplar (paper 002 §2, preprocessing):
///  1. patch size and overlap width from analyze_patch_size (§2.1) unless given;
///  2. patches at every phase (every exemplar position), grouped by phase (§2, Fig. 2);
///  3. for every patch and each of its four sides, the compatible set: the `candidates` (k = 8) patches
///     whose overlap strip has the smallest L2 error. The paper takes an approximate nearest-neighbour
///     search (ANN); here strips are projected on a PCA basis (Eigen) and searched in a nanoflann
///     kd-tree over the projections. By default (approximate sets) the `search_pool` nearest
///     projections are re-ranked by exact L2 and improved by `refine_iterations` rounds of coherence
///     propagation (the neighbours' candidates, shifted); with `exact_sets` the search prunes with exact
///     L2 (projections never overestimate distances), so the sets are the exact top k. Either way each
///     set is ordered by exact error, ties broken by the smaller patch index;
///  4. optionally (`seams`), a minimum-error seam for every compatible pair: the improvement the paper
///     names for strongly structured textures but did not build (§2).
/// The exemplar is converted to the model's pixel type (its own channel type and count).
///
/// Errors: invalid_argument for an empty exemplar, an exemplar holding fewer than two patches, patch or
/// overlap sizes that do not fit (patch side < 2, overlap < 1 or > patch side, patch + overlap larger
/// than the exemplar), candidates outside [1, 64], pca_dims outside [1, 64], pca_samples < 2, seams with an
/// overlap > 255; errors of analyze_patch_size; cancelled when `progress` says so.
/// Complexity: about O(4 n k D) for n patches and strips of D channel values when the PCA captures the
/// strips well, O(n^2 D) worst case; memory O(n k) (+ O(n k (patch + overlap)) bytes with seams).
/// Runs on `exec`; the model does not depend on it. Thread safety: pure function of its inputs.
template <Image I, Executor E = serial_executor>
auto build_patch_model(const I& exemplar, const patch_model_options& opts = {}, E&& exec = {})
    -> result<patch_model<channel_t<I>, channels_v<I>>> {
  if (auto s = validate_image(exemplar, "exemplar"); !s) return s;
  if (auto s = validate_finite_pixels(exemplar, "exemplar"); !s) return s;
  if (opts.patch_width < 0 || opts.patch_height < 0 || opts.overlap < 0)
    return status::invalid_argument(
        detail::cat("build_patch_model: patch_width, patch_height and overlap must be >= 0 (0: automatic), got ",
                    opts.patch_width, ", ", opts.patch_height, ", ", opts.overlap));
  if (opts.candidates < 1 || opts.candidates > 64)
    return status::invalid_argument(
        detail::cat("build_patch_model: candidates must be in [1, 64], got ", opts.candidates));
  if (opts.pca_dims < 1 || opts.pca_dims > 64)
    return status::invalid_argument(detail::cat("build_patch_model: pca_dims must be in [1, 64], got ", opts.pca_dims));
  if (opts.pca_samples < 2)
    return status::invalid_argument(detail::cat("build_patch_model: pca_samples must be >= 2, got ", opts.pca_samples));
  if (!(opts.min_patch_fraction > 0 && opts.min_patch_fraction <= 0.5))
    return status::invalid_argument(
        detail::cat("build_patch_model: min_patch_fraction must be in (0, 0.5], got ", opts.min_patch_fraction));
  if (opts.search_pool < 1 || opts.refine_iterations < 0 || opts.refine_iterations > 64)
    return status::invalid_argument(
        detail::cat("build_patch_model: search_pool must be >= 1 and refine_iterations in [0, 64], got ",
                    opts.search_pool, " and ", opts.refine_iterations));

  auto ex = to_buffer<channel_t<I>, channels_v<I>>(exemplar, "exemplar");
  if (!ex) return ex.error();
  return detail::patch_model_builder::build(std::move(*ex), opts, exec);
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_patch_model.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
