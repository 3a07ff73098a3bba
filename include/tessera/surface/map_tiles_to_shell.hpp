// tessera/surface/map_tiles_to_shell.hpp: puts geometric tiles onto a base mesh (paper 000 §4, Fig. 5).
// Every quad of the polycube map carries a tile mesh in quad-local coordinates (u, v, h); each vertex is
// located on its quad (a polycube point P), carried back to the base surface by the inverse projection
// P⁻¹ (base face + barycentric weights, polycube_projector::inverse) and placed by the shell map
// (build_shell.hpp: its barycentric coordinates in the texture-space tetrahedron, the polycube triangle
// extruded along the chart normal, applied to the shell-space one). Tile triangles that overlap several
// texture-space tetrahedra are split at edge midpoints until a chordal tolerance holds (the default,
// shell_clip::midpoint, detail/shell_refine.hpp: an approximation, nearby elements can cross) or, with
// shell_clip::exact, clipped at the tetrahedra's boundaries (detail/shell_clip.hpp: the output is the
// exact image of the tiles under the piecewise-linear shell map), and vertices on shared quad sides and
// corners, in the plane and around polycube edges, are welded from a canonical side
// (detail/shell_weld.hpp), so closed elements stay closed.
//
// Input: `tiles(q)` returns the tile mesh of quad q (or nullptr for none), valid until the call
// returns. Its vertex positions are (u, v, h): (u, v) in [0, 1]² the quad-local square, u from corner 0
// to corner 1 and v from corner 0 to corner 3 of the quad (polycube_quad: corners counter-clockwise
// seen from outside, so (u, v, h) is right-handed with h outwards), and h in [0, H] the height above the
// surface in base-mesh units (a tile of side 1 with heights z in tile units has h = z · tile_size).
// Faces counter-clockwise seen from outside the elements keep their orientation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "build_shell.hpp"
#include "detail/shell_clip.hpp"
#include "detail/shell_refine.hpp"
#include "detail/shell_weld.hpp"
#include "polycube_map.hpp"
#include "polycube_projection.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// In tile units: how far from the polycube surface the inverse projection looks first (texture
/// points lie on it up to rounding).
inline constexpr double shell_projection_radius = 1e-6;
}  // namespace detail

/// How map_tiles_to_shell makes tile triangles follow the shell.
enum class shell_clip : std::uint8_t {
  /// Clip every tile triangle at the texture-space tetrahedra it overlaps (prism sides over the base
  /// edges, the prisms' split planes): every piece is mapped affinely by its tetrahedron, the output is
  /// the exact image of the tiles under the piecewise-linear shell map (elements that do not cross in
  /// texture space do not cross after mapping, where no shell tetrahedron is inverted).
  exact,
  /// Split edges at their texture-space midpoints until each mapped midpoint lies within
  /// chordal_tolerance of its chord (the earlier approximation, kept for comparison; nearby elements
  /// can cross between split points).
  midpoint,
};

/// Options of map_tiles_to_shell. Lengths are in tile units (multiples of polycube_map::tile_size).
struct shell_map_options {
  /// Midpoint refinement (default: 7.5-15x faster on bench_surface) or exact clipping (no crossings
  /// from the approximation, 2.6-5x the faces; docs/surface.md).
  shell_clip clip = shell_clip::midpoint;
  /// exact: texture-space distance within which clip points snap onto tile triangle sides and corners
  /// and merge (pieces thinner than this are not made).
  double clip_tolerance = 3e-6;
  /// midpoint (this and the next three options apply to it only): largest distance of a mapped edge's midpoint
  /// from the straight chord between its mapped ends.
  double chordal_tolerance = 5e-3;
  /// Tile vertices within this of a quad side or corner count as on it; vertices of neighbouring quads
  /// whose edge parameter and height agree within it are welded.
  double weld_tolerance = 1e-7;
  /// Edges shorter than this in texture space are never split.
  double min_edge = 1.0 / 1024;
  /// Most split rounds (each at most halves the longest edge).
  int max_split_rounds = 10;
  /// The splitting may multiply the tiles' face count by at most this (or reach 2^20 faces, whichever
  /// is more); a shell too high for the tiles' detail (long edges bent around a small base) is refused
  /// rather than split without end.
  double max_split_growth = 32;
  /// Append the base mesh after the elements.
  bool with_base = false;
};

namespace detail {
/// The first `nv` vertices and `nf` faces of `m` (a mapping's elements, before an appended base).
inline tri_mesh leading_part(const tri_mesh& m, index_t nv, index_t nf) {
  tri_mesh e;
  e.positions.assign(m.positions.begin(), m.positions.begin() + nv);
  e.faces.assign(m.faces.begin(), m.faces.begin() + nf);
  return e;
}
}  // namespace detail
/// Output of map_tiles_to_shell.
struct shell_map_result {
  /// The mapped elements (vertices and faces first), then the base mesh when with_base.
  tri_mesh mesh;
  /// Vertices and faces of the elements (the leading part of `mesh`).
  index_t element_vertices = 0, element_faces = 0;
  /// The elements alone: a copy of the leading part of `mesh`. O(element vertices + faces).
  [[nodiscard]] tri_mesh elements() const { return detail::leading_part(mesh, element_vertices, element_faces); }
  /// Tile vertices over all quads, and how many of them were welded to a vertex of a neighbouring quad.
  index_t tile_vertices = 0, welded_vertices = 0;
  /// Tile faces dropped because welding merged two of their corners.
  index_t dropped_faces = 0;
  /// Edges split so that the elements follow the shell (exact: distinct clip points on tile triangle
  /// sides; midpoint: midpoints).
  index_t split_edges = 0;
  /// exact: tile triangles cut at tetrahedron boundaries, and clip points inside them.
  index_t clipped_faces = 0, inner_points = 0;
  /// exact: output faces of zero area in texture space (only where a tile triangle was degenerate).
  index_t flat_faces = 0;
  /// Quads that carried a non-empty tile.
  index_t quads = 0;
};

/// Maps the tiles of every quad of `map` onto its base mesh through `sh` (see the file comment).
/// `pj` must be a projector of `map`; `sh` a shell of map.base (build_shell). Deterministic: the
/// output is the same for any executor and thread count (the per-point projections run through
/// `exec`, all choices are functions of the points). Output vertices lie within H of the base surface
/// (the shell map moves a point at most t · H off its base triangle). Errors (invalid_argument): a
/// shell built over another mesh than map.base, bad options, an invalid tile mesh or a tile vertex
/// outside [0, 1]² x [0, H] (naming the quad and vertex), a shell too high for the tiles' detail (the
/// splitting would multiply the faces by more than max_split_growth); size_overflow beyond 2^31
/// vertices.
/// O(tile vertices · log F) plus the splits.
template <class Tiles, Executor E = serial_executor>
requires std::is_invocable_r_v<const tri_mesh*, const Tiles&, index_t> result<shell_map_result> map_tiles_to_shell(
    const polycube_map& map, const polycube_projector& pj, const shell& sh, const Tiles& tiles,
    const shell_map_options& o = {}, E&& exec = {}) {
  if (sh.base.positions != map.base.positions || sh.base.faces != map.base.faces)
    return status::invalid_argument(detail::cat("map_tiles_to_shell: the shell (", sh.base.num_vertices(),
                                                " vertices, ", sh.base.num_faces(),
                                                " faces) is not built over the polycube map's base mesh (",
                                                map.base.num_vertices(), " vertices, ", map.base.num_faces(), ")"));
  if (!(o.chordal_tolerance > 0) || !(o.weld_tolerance >= 0 && o.weld_tolerance < 0.01) || !(o.min_edge > 0) ||
      !std::isfinite(o.chordal_tolerance) || !std::isfinite(o.min_edge) || o.max_split_rounds < 0 ||
      o.max_split_rounds > 30 || !(o.max_split_growth >= 1) || !(o.max_split_growth <= 1e6) ||
      !(o.clip_tolerance > 0 && o.clip_tolerance < 0.01) ||
      (o.clip != shell_clip::exact && o.clip != shell_clip::midpoint))
    return status::invalid_argument(
        "shell_map_options: need chordal_tolerance > 0, 0 <= weld_tolerance < 0.01, min_edge > 0, "
        "0 <= max_split_rounds <= 30, 1 <= max_split_growth <= 1e6, 0 < clip_tolerance < 0.01, clip exact or "
        "midpoint");
  if (!(sh.height > 0) || sh.heights.size() != sh.base.positions.size() ||
      sh.directions.size() != sh.base.positions.size() || !(sh.sink >= 0 && sh.sink < 1))
    return status::invalid_argument(
        "map_tiles_to_shell: the shell is empty or inconsistent, or its sink outside [0, 1) (use build_shell)");
  const double H = sh.height, T = map.tile_size;
  auto gathered = detail::gather_shell_tiles(map, tiles, H, o.weld_tolerance);
  if (!gathered) return gathered.error();
  auto& tex = *gathered;
  shell_map_result res;
  res.tile_vertices = tex.input_vertices;
  res.welded_vertices = tex.welded;
  res.dropped_faces = tex.dropped_faces;
  res.quads = tex.quads;
  // P⁻¹ then the shell map, one texture point at a time
  auto map_in_face = [&](index_t face, vec3 bary, double h) {
    detail::shell_mapped_point m;
    m.face = face;
    m.bary = bary;
    m.x = detail::shell_position_in_tet(sh, face, bary, std::clamp(h / H, 0.0, 1.0), m.tet);
    return m;
  };
  // texture points lie on the polycube surface: a small search radius prunes the BVH walk
  const double radius = detail::shell_projection_radius * T;
  auto map_point = [&](const detail::shell_texture_point& tp, index_t hint_a, index_t hint_b) {
    // a midpoint usually lies in the polycube triangle of one of its edge's ends: try those first
    for (const index_t f : {hint_a, hint_b}) {
      if (f < 0) continue;
      const auto& fv = map.base.faces[detail::to_size(f)];
      const vec3 q0 = map.polycube[detail::to_size(fv[0])], q1 = map.polycube[detail::to_size(fv[1])],
                 q2 = map.polycube[detail::to_size(fv[2])];
      const vec3 n = cross(q1 - q0, q2 - q0);
      const double nn = dot(n, n);
      if (!(nn > 0) || std::abs(dot(tp.p - q0, n)) > radius * std::sqrt(nn)) continue;
      const vec3 b{dot(cross(q1 - tp.p, q2 - tp.p), n) / nn, dot(cross(q2 - tp.p, q0 - tp.p), n) / nn,
                   dot(cross(q0 - tp.p, q1 - tp.p), n) / nn};
      if (b.x >= 0 && b.y >= 0 && b.z >= 0) return map_in_face(f, b / (b.x + b.y + b.z), tp.h);
    }
    const base_surface_point b = pj.inverse(tp.p, radius);
    if (b.face < 0) return detail::shell_mapped_point{};
    return map_in_face(b.face, b.bary, tp.h);
  };
  std::vector<detail::shell_mapped_point> mapped(tex.points.size());
  exec.parallel_for(0, static_cast<index_t>(tex.points.size()),
                    [&](index_t i) { mapped[detail::to_size(i)] = map_point(tex.points[detail::to_size(i)], -1, -1); });
  if (o.clip == shell_clip::exact) {
    std::vector<index_t> chart(tex.face_quad.size());
    for (std::size_t i = 0; i < chart.size(); ++i) chart[i] = map.layout.quads[detail::to_size(tex.face_quad[i])].chart;
    const auto st =
        detail::clip_shell_mesh(tex.points, mapped, tex.faces, chart, map, H, o.clip_tolerance * T, map_in_face, exec);
    res.split_edges = st.side_points;
    res.clipped_faces = st.clipped_faces;
    res.inner_points = st.inner_points;
    res.flat_faces = st.flat_faces;
  } else {
    const double budget = std::max(o.max_split_growth * static_cast<double>(tex.faces.size()), double(1 << 20));
    detail::shell_refine_limits lim{o.chordal_tolerance * T, o.min_edge * T, o.max_split_rounds,
                                    static_cast<std::size_t>(std::min(budget, 1e12))};
    const std::size_t input_faces = tex.faces.size();
    res.split_edges =
        detail::refine_shell_mesh(tex.points, mapped, tex.faces, map.base.faces, lim, map_point, map_in_face, exec);
    if (res.split_edges < 0)
      return status::invalid_argument(detail::cat(
          "map_tiles_to_shell: following the shell within the chordal tolerance would split the tiles' ", input_faces,
          " faces into more than ", lim.max_triangles, " (max_split_growth): the shell height H = ", H,
          " is too large for the tiles' detail; lower H or raise chordal_tolerance"));
  }
  if (tex.points.size() >= (std::size_t{1} << 31))
    return status::size_overflow("map_tiles_to_shell: more than 2^31 output vertices");
  // keep the vertices that faces use, in vertex order
  std::vector<index_t> id(tex.points.size(), -1);
  for (const auto& f : tex.faces)
    for (index_t v : f) id[detail::to_size(v)] = 0;
  for (std::size_t v = 0; v < id.size(); ++v)
    if (id[v] == 0) { id[v] = res.mesh.add_vertex(mapped[v].x); }
  res.mesh.faces.reserve(tex.faces.size() + (o.with_base ? sh.base.faces.size() : 0));
  for (const auto& f : tex.faces)
    res.mesh.add_face(id[detail::to_size(f[0])], id[detail::to_size(f[1])], id[detail::to_size(f[2])]);
  res.element_vertices = res.mesh.num_vertices();
  res.element_faces = res.mesh.num_faces();
  if (o.with_base) res.mesh.append(sh.base);
  return res;
}

TESSERA_NAMESPACE_END
