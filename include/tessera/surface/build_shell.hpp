// tessera/surface/build_shell.hpp: the shell of a closed base mesh (paper 000 §4, its ref. [7]: Porumbescu
// et al. 2005, "Shell maps"): the space between the base surface and its offset by a height H along
// smooth vertex normals, cut into one prism per base face and each prism into three tetrahedra
// (detail/shell_prism.hpp). Where the offset folds (concave or strongly curved regions, where vertex
// normals converge within H) some tetrahedra invert; the repair smooths the offset directions there
// and, where that is not enough, lowers the local height, until every tetrahedron is positively
// oriented with a margin. shell_position() is the shell map itself: barycentric coordinates in the
// texture-space tetrahedron applied to the shell-space one.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "detail/shell_prism.hpp"
#include "polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN

/// A shell over a base mesh: the top of vertex v is base.position(v) + (1 - sink) * heights[v] *
/// directions[v], its bottom base.position(v) - sink * heights[v] * directions[v] (sink 0: the base).
struct shell {
  /// The base mesh (positions and faces).
  tri_mesh base;
  /// Unit offset direction of every base vertex (angle-weighted normal, smoothed where repaired).
  std::vector<vec3> directions;
  /// Local height of every base vertex, in (0, height]; below `height` where the repair lowered it.
  std::vector<double> heights;
  /// The requested height H (mesh units).
  double height = 0;
  /// Vertices whose direction or height the fold repair changed.
  index_t repaired_vertices = 0;
  /// Repair rounds run (0: the plain offset did not fold).
  int repair_rounds = 0;
  /// Share of each vertex's height below the surface, in [0, 1) (shell_options::sink).
  double sink = 0;
  /// Top (offset) position of vertex v.
  [[nodiscard]] vec3 top(index_t v) const noexcept {
    return base.position(v) + ((1 - sink) * heights[detail::to_size(v)]) * directions[detail::to_size(v)];
  }
  /// Bottom position of vertex v: the base vertex itself unless the shell is sunk.
  [[nodiscard]] vec3 bottom(index_t v) const noexcept {
    return base.position(v) - (sink * heights[detail::to_size(v)]) * directions[detail::to_size(v)];
  }
};

/// Options of build_shell.
struct shell_options {
  /// A tetrahedron counts as folded when six times its signed volume is below this fraction of
  /// 2 · face area · mean local height (the value of an upright prism's tetrahedra, which is 1).
  double min_quality = 0.05;
  /// Repair rounds that only smooth the directions before heights are lowered too.
  int smoothing_rounds = 4;
  /// Factor applied to the local height of a vertex of a folded prism per round (after smoothing_rounds).
  double height_step = 0.85;
  /// The repair may lower a vertex's height down to this fraction of H; a fold that needs less fails.
  double min_height_ratio = 0.2;
  /// Most repair rounds.
  int max_rounds = 100;
  /// Share of the height sunk below the surface, in [0, 1): the bottom of vertex v lies at base(v) -
  /// sink · h_v · d_v and its top at base(v) + (1 - sink) · h_v · d_v, so a texture mapped through the
  /// shell fills [-sink · H, (1 - sink) · H] about the surface and its elements overlap the base's volume
  /// (a union with the base is then one solid, a difference engraves them: mesh_boolean, paper 000 Fig.
  /// 7). The repair then also covers the inward offset, which folds where the surface is convex and
  /// tighter than the sunk depth. 0 (the default): the shell stands on the surface.
  double sink = 0;
};

namespace detail {
/// Below this smallest angle (degrees) a face next to a fold is called a sliver in the refusal.
inline constexpr double shell_sliver_angle = 5;
/// "" or a hint that the faces at the marked (folded) vertices are slivers (CAD output), which
/// fold any offset.
inline std::string sliver_hint(const tri_mesh& base, const std::vector<char>& marked) {
  double worst = 180;
  for (const auto& f : base.faces)
    if (marked[to_size(f[0])] != 0 || marked[to_size(f[1])] != 0 || marked[to_size(f[2])] != 0)
      worst = std::min(worst, smallest_angle_degrees(base.positions[to_size(f[0])], base.positions[to_size(f[1])],
                                                     base.positions[to_size(f[2])]));
  if (!(worst < shell_sliver_angle)) return {};
  return cat(" (its faces there include slivers, smallest angle ", worst,
             " degrees: remesh the base first, remesh_isotropic or `tessera remesh`)");
}
}  // namespace detail

/// Lowest quality of the three tetrahedra of the prism over face f of `s` (1 for an upright prism,
/// <= 0 when one is inverted). Precondition: f in [0, F).
/// Used by the fold repair of build_shell (shell_options::min_quality).
inline double shell_prism_quality(const shell& s, index_t f) {
  const auto& fv = s.base.faces[detail::to_size(f)];
  const detail::prism_order o = detail::sorted_prism_order(fv);
  std::array<vec3, 6> c;
  double hbar = 0;
  for (int k = 0; k < 3; ++k) {
    const index_t v = fv[detail::to_size(o.corner[detail::to_size(k)])];
    const double h = s.heights[detail::to_size(v)];
    c[detail::to_size(k)] = s.bottom(v);
    c[detail::to_size(k + 3)] = c[detail::to_size(k)] + h * s.directions[detail::to_size(v)];
    hbar += h / 3;
  }
  const double ref = norm(cross(c[1] - c[0], c[2] - c[0])) * hbar;
  if (!(ref > 0)) return 0;
  double q = 1e300;
  for (const auto& t : detail::prism_tets) {
    const double v6 = detail::tet_volume6(c[detail::to_size(t[0])], c[detail::to_size(t[1])], c[detail::to_size(t[2])],
                                          c[detail::to_size(t[3])]);
    q = std::min(q, (o.even ? v6 : -v6) / ref);
  }
  return q;
}

namespace detail {
/// shell_position() and the tetrahedron (0..2, detail::prism_tets) of the prism the point lies in.
inline vec3 shell_position_in_tet(const shell& s, index_t f, vec3 bary, double t, int& tet) {
  const auto& fv = s.base.faces[to_size(f)];
  const prism_order o = sorted_prism_order(fv);
  const vec3 beta{bary[o.corner[0]], bary[o.corner[1]], bary[o.corner[2]]};
  const vec3 g = prism_top_weights(beta, t);
  tet = g[1] == 0 ? 0 : g[0] == 0 ? 1 : 2;
  vec3 p = bary[0] * s.bottom(fv[0]) + bary[1] * s.bottom(fv[1]) + bary[2] * s.bottom(fv[2]);
  for (int k = 0; k < 3; ++k) {
    const auto v = to_size(fv[to_size(o.corner[to_size(k)])]);
    p += (g[k] * s.heights[v]) * s.directions[v];
  }
  return p;
}
}  // namespace detail

/// The shell map (Porumbescu et al. 2005): the point of the texture-space prism over base face f with
/// barycentric weights `bary` (of the face's corners 0, 1, 2) at relative height t = h / H in [0, 1],
/// carried to shell space by its barycentric coordinates in its texture-space tetrahedron. Equals
/// Σ bary_k b_k + Σ γ_k heights_k directions_k with γ from detail::prism_top_weights and b_k the
/// bottoms (shell::bottom), so its distance to the base triangle is at most t · H (|t - sink| · H
/// about, for a sunk shell). Continuous across prism sides. Precondition: f in [0, F). O(1).
inline vec3 shell_position(const shell& s, index_t f, vec3 bary, double t) {
  int tet = 0;
  return detail::shell_position_in_tet(s, f, bary, t, tet);
}

/// Builds the shell of `base` at height `height` (mesh units): angle-weighted vertex normals as offset
/// directions, then the fold repair (see the file comment): each round finds the prisms with a
/// tetrahedron below `min_quality`; their vertices get their direction replaced by the normalized mean
/// of their own and their neighbours' directions, and after `smoothing_rounds` rounds also their height
/// multiplied by `height_step`. Deterministic (the per-face checks run through `exec`, the updates in
/// vertex order). Errors (invalid_argument): a base that validate_polycube_input refuses (open,
/// non-manifold, inconsistently oriented, degenerate faces), a height that is not finite and > 0, bad
/// options; a height at which the offset folds at every vertex or needs a vertex lowered below
/// min_height_ratio · H ("height too large for the shell"); not_converged after max_rounds.
/// O(rounds · F).
template <Mesh M, Executor E = serial_executor>
result<shell> build_shell(const M& base, double height, const shell_options& o = {}, E&& exec = {}) {
  if (auto s = validate_polycube_input(base, "shell base"); !s) return s;
  if (!(height > 0) || !std::isfinite(height))
    return status::invalid_argument(detail::cat("shell: height must be finite and > 0, got ", height));
  if (!(o.min_quality > 0 && o.min_quality < 1) || !(o.height_step > 0 && o.height_step < 1) ||
      !(o.min_height_ratio > 0 && o.min_height_ratio <= 1) || o.max_rounds < 0 || o.smoothing_rounds < 0 ||
      !(o.sink >= 0 && o.sink < 1))
    return status::invalid_argument(
        detail::cat("shell_options: need 0 < min_quality < 1, 0 < height_step < 1, 0 < "
                    "min_height_ratio <= 1, rounds >= 0, sink in [0, 1); sink is ",
                    o.sink));
  auto mesh = to_tri_mesh(base, "shell base");
  if (!mesh) return mesh.error();
  shell s;
  s.base = std::move(*mesh);
  s.height = height;
  s.sink = o.sink;
  const auto nv = s.base.positions.size(), nf = s.base.faces.size();
  // angle-weighted vertex normals (Thürmer & Wüthrich 1998)
  s.directions.assign(nv, vec3{});
  std::vector<std::vector<index_t>> ring(nv);
  for (const auto& f : s.base.faces) {
    const vec3 n =
        normalized(cross(s.base.position(f[1]) - s.base.position(f[0]), s.base.position(f[2]) - s.base.position(f[0])));
    for (int k = 0; k < 3; ++k) {
      const index_t a = f[detail::to_size(k)], b = f[detail::to_size((k + 1) % 3)], c = f[detail::to_size((k + 2) % 3)];
      const vec3 e1 = normalized(s.base.position(b) - s.base.position(a));
      const vec3 e2 = normalized(s.base.position(c) - s.base.position(a));
      s.directions[detail::to_size(a)] += std::acos(std::clamp(dot(e1, e2), -1.0, 1.0)) * n;
      ring[detail::to_size(a)].push_back(b);
      ring[detail::to_size(a)].push_back(c);
    }
  }
  for (auto& r : ring) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
  }
  for (auto& d : s.directions) d = normalized(d);
  s.heights.assign(nv, height);
  std::vector<double> quality(nf);
  std::vector<char> repaired(nv, 0), marked(nv);
  std::vector<vec3> next;
  for (int round = 0;; ++round) {
    exec.parallel_for(0, static_cast<index_t>(nf),
                      [&](index_t f) { quality[detail::to_size(f)] = shell_prism_quality(s, f); });
    std::fill(marked.begin(), marked.end(), 0);
    bool any = false;
    for (std::size_t f = 0; f < nf; ++f)
      if (quality[f] < o.min_quality) {
        any = true;
        for (index_t v : s.base.faces[f]) marked[detail::to_size(v)] = 1;
      }
    if (!any) break;
    if (round >= o.max_rounds)
      return status::not_converged(detail::cat("shell: folded prisms remain after ", o.max_rounds,
                                               " repair rounds; use a smaller height than ", height));
    s.repair_rounds = round + 1;
    next = s.directions;
    for (std::size_t v = 0; v < nv; ++v) {
      if (!marked[v]) continue;
      repaired[v] = 1;
      vec3 sum = s.directions[v];
      for (index_t u : ring[v]) sum += s.directions[detail::to_size(u)];
      if (const vec3 d = normalized(sum); norm(d) > 0) next[v] = d;
      if (round >= o.smoothing_rounds) {
        s.heights[v] *= o.height_step;
        if (s.heights[v] < o.min_height_ratio * height)
          return status::invalid_argument(
              detail::cat("shell: height ", height, " is too large for the shell: the offset folds near vertex ", v,
                          " (a concave or strongly curved region) even at ", o.min_height_ratio,
                          " of that height; use a smaller height", detail::sliver_hint(s.base, marked)));
      }
    }
    s.directions.swap(next);
  }
  s.repaired_vertices = static_cast<index_t>(std::count(repaired.begin(), repaired.end(), 1));
  if (s.repaired_vertices == static_cast<index_t>(nv))
    return status::invalid_argument(
        detail::cat("shell: height ", height, " is too large for the shell: the offset folded at every vertex"));
  return s;
}

TESSERA_NAMESPACE_END
