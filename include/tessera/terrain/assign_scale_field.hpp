// tessera/terrain/assign_scale_field.hpp: the per-triangle scale factor field of paper 003, §2.2.
//
//   step 1  D_i: distance from the eye to the centroid of visible triangle i (its "view distance")
//   step 2  maxδ = max |D_i - D_j| over pairs of ADJACENT VISIBLE triangles
//   step 3  min_scale: how far the exemplar shrinks (0.5: scales run from 1 down to 0.5)
//   step 5  levels: the range [D_min, D_max] is cut into slices maxδ wide, so D values in one slice
//           share a level and adjacent triangles (|D_i - D_j| <= maxδ) are never more than one
//           level apart; at most `max_levels` slices (wider slices keep the rule)
//   step 6  scale of level l: 1 - (1 - min_scale) l / (L - 1), in [min_scale, 1]; near is 1
//
// The continuous variant keeps the same levels but sets each triangle's scale from its own
// distance, 1 - (1 - min_scale) (D_i - D_min) / (D_max - D_min): the staircase of step 6 smoothed
// into a ramp (adjacent scales then differ by at most (1 - min_scale) maxδ / (D_max - D_min)), with
// level = the nearest level, which still keeps adjacent levels at most one apart.
//
// Edge cases (documented behaviour, tested): maxδ = 0 (no two adjacent visible triangles, or all
// at one distance) leaves the paper's division undefined; with nothing to keep continuous the field
// uses the finest allowed division (`max_levels` levels, or one level when every distance is equal).
// maxδ >= D_max - D_min (a mesh far coarser than its view) gives a single level: every stepped
// scale is 1, because no cut of the range keeps adjacent triangles within one level otherwise; the
// continuous variant still ramps the scale.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "prepare_terrain_mesh.hpp"
#include "project_mesh.hpp"

TESSERA_NAMESPACE_BEGIN

/// How a face's scale follows from its distance.
enum class scale_mode {
  stepped,     ///< the paper: scale is its level's scale
  continuous,  ///< scale from the triangle's own distance; level = nearest level
};

/// Options of assign_scale_field (§2.2).
struct scale_field_options {
  double min_scale = 0.5;   ///< smallest scale (step 3), in (0, 1]
  index_t max_levels = 64;  ///< at most this many levels (1 to 65536); match the exemplar pyramid's
  /// stepped (the paper) or continuous.
  scale_mode mode = scale_mode::stepped;
};

/// Per-face results (indexed like the mesh; culled faces hold distance NaN, level -1, scale 0) and
/// the figures of §2.2.
struct scale_field {
  std::vector<double> distance;     ///< D_i (step 1)
  std::vector<std::int32_t> level;  ///< 0 (nearest) to levels - 1
  std::vector<float> scale;         ///< in [min_scale, 1]
  index_t levels = 0;               ///< L; 0 when nothing is visible
  /// Smallest and largest D_i over the visible faces.
  double min_distance = 0, max_distance = 0;
  double max_delta = 0;    ///< maxδ (step 2)
  double level_width = 0;  ///< distance slice per level (>= maxδ), 0 for one level
  /// The min_scale used.
  double min_scale = 1;
  index_t adjacent_pairs = 0;  ///< adjacent visible pairs examined
  int max_level_jump = 0;      ///< largest |level_i - level_j| over adjacent visible pairs (<= 1)
  /// The scale of level l.
  [[nodiscard]] double level_scale(index_t l) const noexcept {
    return levels <= 1 ? 1.0 : 1.0 - (1.0 - min_scale) * static_cast<double>(l) / static_cast<double>(levels - 1);
  }
};

/// Assigns distance, level and scale to every visible face of `projection` (paper 003, §2.2 steps
/// 1-3, 5, 6; see the file comment for the edge cases) into `out`, reusing its storage. Errors:
/// min_scale outside (0, 1], max_levels outside 1..65536, a projection that does not belong to
/// `mesh` (sizes differ, a visible entry naming a culled or missing face), a mesh whose arrays do
/// not agree (see validate_terrain_mesh), a non-finite view distance. Nothing visible is not an error: levels = 0. O(F), parallel through `exec`;
/// deterministic (maxima are order-independent).
template <Executor E = serial_executor>
status assign_scale_field(const terrain_mesh& mesh, const screen_projection& projection,
                          const scale_field_options& opts, scale_field& out, E&& exec = {}) {
  if (auto s = validate_enum(opts.mode, {"stepped", "continuous"}, "options.mode"); !s) return s;
  if (!(opts.min_scale > 0 && opts.min_scale <= 1))
    return status::invalid_argument(detail::cat("min_scale must be in (0, 1], got ", opts.min_scale));
  if (opts.max_levels < 1 || opts.max_levels > 65536)
    return status::invalid_argument(detail::cat("max_levels must be 1 to 65536, got ", opts.max_levels));
  if (auto s = detail::check_projection(mesh, projection, "assign_scale_field"); !s) return s;
  const index_t nf = mesh.num_faces();
  constexpr index_t block = 16384;
  // culled faces: distance NaN, level -1, scale 0 (filled in parallel; a 10^6-face mesh has 16 MB of them)
  out.distance.resize(detail::to_size(nf));
  out.level.resize(detail::to_size(nf));
  out.scale.resize(detail::to_size(nf));
  exec.parallel_for(0, (nf + block - 1) / block, [&](index_t c) {
    const auto a = detail::to_size(c * block), b = detail::to_size(std::min(nf, (c + 1) * block));
    std::fill(out.distance.begin() + static_cast<std::ptrdiff_t>(a),
              out.distance.begin() + static_cast<std::ptrdiff_t>(b), std::numeric_limits<double>::quiet_NaN());
    std::fill(out.level.begin() + static_cast<std::ptrdiff_t>(a), out.level.begin() + static_cast<std::ptrdiff_t>(b),
              -1);
    std::fill(out.scale.begin() + static_cast<std::ptrdiff_t>(a), out.scale.begin() + static_cast<std::ptrdiff_t>(b),
              0.0f);
  });
  out.min_scale = opts.min_scale;
  out.levels = 0;
  out.min_distance = out.max_distance = out.max_delta = out.level_width = 0;
  out.adjacent_pairs = 0;
  out.max_level_jump = 0;
  const index_t nvis = projection.num_visible();
  if (nvis == 0) return {};
  const std::int32_t* vis = projection.visible.data();
  const index_t chunks = (nvis + block - 1) / block;
  struct partial {
    double dmin = std::numeric_limits<double>::infinity(), dmax = -std::numeric_limits<double>::infinity(), delta = 0;
    index_t pairs = 0;
    int jump = 0;
    index_t bad = -1;  ///< first visible entry naming no visible face, or with a non-finite distance
  };
  std::vector<partial> part(detail::to_size(chunks));
  auto for_chunks = [&](auto&& body) {
    exec.parallel_for(0, chunks, [&](index_t c) {
      for (index_t i = c * block; i < std::min(nvis, (c + 1) * block); ++i) body(part[detail::to_size(c)], vis[i]);
    });
  };
  // step 1: view distances (and the check that every visible entry is a visible face)
  exec.parallel_for(0, chunks, [&](index_t c) {
    partial& p = part[detail::to_size(c)];
    for (index_t i = c * block; i < std::min(nvis, (c + 1) * block); ++i) {
      const std::int32_t f = vis[i];
      const double d = detail::is_visible_face(projection, f)
                           ? norm(mesh.centroids[detail::to_size(f)] - projection.eye)
                           : std::numeric_limits<double>::quiet_NaN();
      if (!std::isfinite(d)) {
        if (p.bad < 0) p.bad = i;
        continue;
      }
      out.distance[detail::to_size(f)] = d;
      p.dmin = std::min(p.dmin, d);
      p.dmax = std::max(p.dmax, d);
    }
  });
  for (const partial& p : part)
    if (p.bad >= 0) {
      const std::int32_t f = vis[p.bad];
      if (!detail::is_visible_face(projection, f)) return detail::bad_visible_entry("assign_scale_field", p.bad, f);
      return status::invalid_argument(detail::cat("assign_scale_field: face ", f, " has a non-finite view distance"));
    }
  // step 2: maxδ over adjacent visible pairs (each pair once: from its smaller face)
  for_chunks([&](partial& p, std::int32_t f) {
    for (std::int32_t n : mesh.neighbors[detail::to_size(f)])
      if (n > f && n < nf && !std::isnan(out.distance[detail::to_size(n)])) {  // visible: has a distance
        p.delta = std::max(p.delta, std::abs(out.distance[detail::to_size(f)] - out.distance[detail::to_size(n)]));
        ++p.pairs;
      }
  });
  double dmin = std::numeric_limits<double>::infinity(), dmax = -dmin, delta = 0;
  for (const partial& p : part) {
    dmin = std::min(dmin, p.dmin);
    dmax = std::max(dmax, p.dmax);
    delta = std::max(delta, p.delta);
  }
  for (const partial& p : part) out.adjacent_pairs += p.pairs;
  const double range = dmax - dmin;
  // step 5: slice width h >= maxδ (with a relative margin of 1e-9 that absorbs rounding, so floors
  // of adjacent distances provably differ by at most one), and wide enough for max_levels slices.
  double h = 0;
  index_t levels = 1;
  if (range > 0) {
    // the relative margin on maxδ, and the slack that keeps range / finest just below max_levels
    constexpr double delta_margin = 1e-9, level_slack = 1e-6;
    const double finest = range / (static_cast<double>(opts.max_levels) - level_slack);
    h = std::max(delta * (1 + delta_margin), finest);
    levels = std::min<index_t>(opts.max_levels, static_cast<index_t>(std::floor(range / h)) + 1);
    if (levels <= 1) {
      levels = 1;
      h = 0;
    }
  }
  out.min_distance = dmin;
  out.max_distance = dmax;
  out.max_delta = delta;
  out.level_width = h;
  out.levels = levels;
  // step 6: levels and scales
  const double span = 1 - opts.min_scale;
  // a level is a pure function of the distance, so the jump check of each adjacent pair can
  // recompute its neighbour's level instead of waiting for another pass over the faces
  auto level_of = [&](double d) -> index_t {
    if (opts.mode == scale_mode::continuous) {
      const double t = range > 0 ? (d - dmin) / range : 0.0;
      return std::min<index_t>(levels - 1, static_cast<index_t>(std::floor(t * static_cast<double>(levels - 1) + 0.5)));
    }
    return h > 0 ? std::min<index_t>(levels - 1, static_cast<index_t>(std::floor((d - dmin) / h))) : 0;
  };
  for_chunks([&](partial& p, std::int32_t f) {
    const double d = out.distance[detail::to_size(f)];
    const index_t l = level_of(d);
    const double s =
        opts.mode == scale_mode::continuous ? 1 - span * (range > 0 ? (d - dmin) / range : 0.0) : out.level_scale(l);
    out.level[detail::to_size(f)] = static_cast<std::int32_t>(l);
    out.scale[detail::to_size(f)] = static_cast<float>(std::clamp(s, opts.min_scale, 1.0));
    for (std::int32_t n : mesh.neighbors[detail::to_size(f)])
      if (n > f && n < nf) {
        const double dn = out.distance[detail::to_size(n)];
        if (!std::isnan(dn))
          p.jump = std::max(p.jump, static_cast<int>(std::abs(l - level_of(dn))));  // visible: has a distance
      }
  });
  for (const partial& p : part) out.max_level_jump = std::max(out.max_level_jump, p.jump);
  TESSERA_ASSERT(out.max_level_jump <= 1);
  return {};
}

/// As above, returning a new scale_field.
template <Executor E = serial_executor>
result<scale_field> assign_scale_field(const terrain_mesh& mesh, const screen_projection& projection,
                                       const scale_field_options& opts = {}, E&& exec = {}) {
  scale_field out;
  if (auto s = assign_scale_field(mesh, projection, opts, out, exec); !s) return s;
  return out;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_assign_scale_field.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
