// tessera/geometry/icp.hpp: translation-only iterative closest points (Besl & McKay 1992, restricted to
// a translation as in eq. 5 of paper 000, §3.3.3). Mesh quilting uses it to refine the grid-restricted
// best translation of the exemplar so that it matches the already synthesized geometry.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "bvh.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of the translation-only ICP.
struct icp_translation_options {
  /// At most this many updates.
  int max_iterations = 50;
  /// Stop when the update moves the translation by less than this (absolute length).
  double tolerance = 1e-6;
  /// Pairs whose closest-point distance exceeds this are ignored (outlier rejection). Infinity keeps all.
  double max_distance = std::numeric_limits<double>::infinity();
  /// Which axes the translation may move along; {true, true, false} keeps a planar texture on its base plane.
  std::array<bool, 3> free_axes{true, true, true};
};

/// What the translation-only ICP found.
struct icp_translation_result {
  vec3 translation;          ///< t such that (target + t) matches the points
  int iterations = 0;        ///< updates applied
  bool converged = false;    ///< the last update was below tolerance
  double mean_distance = 0;  ///< mean closest-point distance of the used pairs at the final t
  index_t pairs = 0;         ///< pairs used at the final t
};

/// Finds the translation t for which the target surface moved by t best fits `points` (M_T vertices
/// in the patch P_T). Each iteration pairs every point v with its closest point h on target + t and
/// moves t by the mean of (v - h): the update of eq. 5 of paper 000 written so that it reduces the
/// distance (the paper's h and v are relative to the moved exemplar). Starts from `initial`.
/// Errors: empty target, non-finite points or initial translation, max_iterations < 1, tolerance
/// or max_distance not positive. O(iterations * |points| * log F). Thread safe (reads only).
inline result<icp_translation_result> icp_translation(std::span<const vec3> points, const triangle_bvh& target,
                                                      vec3 initial, const icp_translation_options& options = {}) {
  if (target.empty()) return status::invalid_argument("icp_translation: the target has no triangles");
  if (options.max_iterations < 1)
    return status::invalid_argument(
        detail::cat("icp_translation: max_iterations must be >= 1, got ", options.max_iterations));
  if (!(options.tolerance > 0))
    return status::invalid_argument(detail::cat("icp_translation: tolerance must be > 0, got ", options.tolerance));
  if (!(options.max_distance > 0))
    return status::invalid_argument(
        detail::cat("icp_translation: max_distance must be > 0, got ", options.max_distance));
  if (!is_finite(initial)) return status::invalid_argument("icp_translation: the initial translation is not finite");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite(points[i]))
      return status::invalid_argument(detail::cat("icp_translation: point ", i, " is not finite"));

  const double max_d2 = options.max_distance * options.max_distance;
  icp_translation_result r;
  r.translation = initial;
  auto pair_up = [&](vec3 t, vec3& mean_offset, double& mean_dist) {
    vec3 sum;
    double dist = 0;
    index_t n = 0;
    for (const vec3& v : points) {
      const auto hit = target.closest_point(v - t, max_d2);
      if (hit.face < 0) continue;
      sum += v - (hit.point + t);
      dist += std::sqrt(hit.squared_distance);
      ++n;
    }
    mean_offset = n > 0 ? sum / double(n) : vec3{};
    mean_dist = n > 0 ? dist / double(n) : 0.0;
    return n;
  };
  for (int it = 0; it < options.max_iterations; ++it) {
    vec3 step;
    double mean_dist = 0;
    r.pairs = pair_up(r.translation, step, mean_dist);
    r.mean_distance = mean_dist;
    if (r.pairs == 0) return r;
    for (int a = 0; a < 3; ++a)
      if (!options.free_axes[detail::to_size(a)]) step[a] = 0;
    r.translation += step;
    r.iterations = it + 1;
    if (norm(step) < options.tolerance) {
      r.converged = true;
      break;
    }
  }
  vec3 unused;
  r.pairs = pair_up(r.translation, unused, r.mean_distance);
  return r;
}

TESSERA_NAMESPACE_END
