// tessera/surface/polycube_distortion.hpp: distortion of a polycube map per face and summarized (issue
// 14): area distortion max(r, 1/r) of the normalized area ratio r = (A_polycube / total polycube area) /
// (A_base / total base area), and angle distortion σ₁/σ₂, the ratio of the singular values of each
// face's affine map from the base triangle to its polycube triangle; both averaged with base-area weights
// (1 is no distortion).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "../core/config.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN

/// Per-face and summary distortion figures of a polycube map.
struct polycube_distortion_report {
  std::vector<double> area;     ///< max(r, 1/r) per face
  std::vector<double> angle;    ///< σ₁/σ₂ per face
  double area_distortion = 1;   ///< base-area-weighted mean of `area`
  double angle_distortion = 1;  ///< base-area-weighted mean of `angle`
};

/// Distortion of `map` (a map from build_polycube_map: every face non-degenerate on both sides).
/// O(F); allocates the per-face vectors.
inline polycube_distortion_report polycube_distortion(const polycube_map& map) {
  polycube_distortion_report r;
  const auto nf = map.base.faces.size();
  r.area.assign(nf, 1.0);
  r.angle.assign(nf, 1.0);
  std::vector<double> ab(nf), ap(nf);
  double tb = 0, tp = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& fv = map.base.faces[f];
    const vec3 b0 = map.base.position(fv[0]), b1 = map.base.position(fv[1]), b2 = map.base.position(fv[2]);
    const vec3 p0 = map.polycube[detail::to_size(fv[0])], p1 = map.polycube[detail::to_size(fv[1])],
               p2 = map.polycube[detail::to_size(fv[2])];
    ab[f] = 0.5 * norm(cross(b1 - b0, b2 - b0));
    ap[f] = 0.5 * norm(cross(p1 - p0, p2 - p0));
    tb += ab[f];
    tp += ap[f];
    // 2D frames of both triangles
    auto frame = [](vec3 a, vec3 b, vec3 c, double& x1, double& x2, double& y2) {
      const vec3 e1 = normalized(b - a), n = normalized(cross(b - a, c - a)), e2 = cross(n, e1);
      x1 = norm(b - a);
      x2 = dot(c - a, e1);
      y2 = dot(c - a, e2);
    };
    double bx1, bx2, by2, px1, px2, py2;
    frame(b0, b1, b2, bx1, bx2, by2);
    frame(p0, p1, p2, px1, px2, py2);
    if (!(bx1 > 0 && by2 > 0 && px1 > 0 && py2 > 0)) continue;
    // J maps (bx1, 0) -> (px1, 0) and (bx2, by2) -> (px2, py2)
    const double a = px1 / bx1, c = 0, b = (px2 - a * bx2) / by2, d = py2 / by2;
    const double e = a * a + b * b + c * c + d * d, det = std::abs(a * d - b * c);
    const double disc = std::sqrt(std::max(0.0, e * e - 4 * det * det));
    const double s1 = std::sqrt((e + disc) / 2), s2 = std::sqrt(std::max(0.0, (e - disc) / 2));
    r.angle[f] = s2 > 0 ? s1 / s2 : 1e300;
  }
  double wa = 0, wg = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const double ratio = (ap[f] / tp) / (ab[f] / tb);
    r.area[f] = ratio > 0 ? std::max(ratio, 1 / ratio) : 1e300;
    wa += ab[f] * r.area[f];
    wg += ab[f] * r.angle[f];
  }
  if (tb > 0) {
    r.area_distortion = wa / tb;
    r.angle_distortion = wg / tb;
  }
  return r;
}

TESSERA_NAMESPACE_END
