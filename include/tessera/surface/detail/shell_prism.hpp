// tessera/surface/detail/shell_prism.hpp: the prism of a shell over one base face and its split into three
// tetrahedra (Porumbescu et al. 2005, "Shell maps"; paper 000 §4 ref. [7]). The corners are taken in
// ascending global vertex index i0 < i1 < i2, and every side quad of the prism is cut by the diagonal
// from the lower-index base vertex to the higher-index top vertex: a rule that depends on the side's two
// vertices only, so the two prisms sharing a side cut it the same way (the "sorted" rule of Jiang et al.
// 2020, "Bijective projection in a shell"). With b_k the base and t_k the top corners (sorted order):
//   T1 = (b0, b1, b2, t2),  T2 = (b0, b1, t2, t1),  T3 = (b0, t0, t1, t2),
// each positively oriented when the sorted order is an even permutation of the face's corners.
#pragma once

#include <array>
#include <utility>

#include "../../core/config.hpp"
#include "../../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// The corners of a face in ascending vertex index, and whether that order is an even permutation of
/// the face's own (counter-clockwise) order.
struct prism_order {
  std::array<int, 3> corner{};  ///< corner slots (0..2 of the face) in ascending vertex index
  bool even = true;             ///< the sorted order has the face's orientation
};

inline prism_order sorted_prism_order(const std::array<index_t, 3>& f) noexcept {
  prism_order o{{0, 1, 2}, true};
  auto& c = o.corner;
  auto swap_if = [&](int a, int b) {
    if (f[to_size(c[to_size(a)])] > f[to_size(c[to_size(b)])]) {
      std::swap(c[to_size(a)], c[to_size(b)]);
      o.even = !o.even;
    }
  };
  swap_if(0, 1);
  swap_if(1, 2);
  swap_if(0, 1);
  return o;
}

/// The three tetrahedra of a prism as corner codes: 0..2 base corners, 3..5 top corners (sorted order).
inline constexpr std::array<std::array<int, 4>, 3> prism_tets{{{0, 1, 2, 5}, {0, 1, 5, 4}, {0, 3, 4, 5}}};

/// Top weights γ of a point of a straight prism with base weights β (sorted order, summing to 1) at
/// relative height t in [0, 1]: the point is Σ (β_k − γ_k) b_k + Σ γ_k t_k in the tetrahedron that
/// contains it (T1 when t <= β2, T2 when β2 <= t <= β1 + β2, T3 above); these are its barycentric
/// coordinates there, and applying them to the shell-space tetrahedron is the shell map. Continuous in
/// (β, t); on a side of the prism (one β_k = 0) it depends on that side's two vertices only.
inline vec3 prism_top_weights(vec3 beta, double t) noexcept {
  if (t <= beta[2]) return {0, 0, t};
  if (t <= beta[1] + beta[2]) return {0, t - beta[2], beta[2]};
  return {t - beta[1] - beta[2], beta[1], beta[2]};
}

/// Six times the signed volume of tetrahedron (a, b, c, d).
inline double tet_volume6(vec3 a, vec3 b, vec3 c, vec3 d) noexcept { return dot(cross(b - a, c - a), d - a); }

}  // namespace detail
TESSERA_NAMESPACE_END
