// tessera/surface/polycube_map.hpp: the polycube map of a closed triangle mesh (Tarini et al. 2004,
// "PolyCube-Maps", ref. [6] of paper 000, §4): every base vertex gets a point on the surface of a set of
// axis-aligned cubes (T³), every face a chart label (+X, -X, +Y, -Y, +Z, -Z), and the polycube surface
// is cut into tile-size squares (the quad layout) that the Wang tiles of §4 cover. This header holds the
// types, the input checks and the tile-size rule; build_polycube_map.hpp builds a map.
//
// Coordinates: polycube positions are in the base mesh's units. Every chart plane, polycube corner and
// quad corner lies on the integer grid `tile_size * Z³`; `grid` coordinates below are those integers.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// Chart label of a face: the axis-aligned direction its polycube face looks to. Axis = label / 2,
/// sign = + for even labels. Files store the integer (0..5).
enum class polycube_label : std::uint8_t { pos_x = 0, neg_x = 1, pos_y = 2, neg_y = 3, pos_z = 4, neg_z = 5 };

/// Axis (0 = X, 1 = Y, 2 = Z) of a label.
constexpr int label_axis(polycube_label l) noexcept { return static_cast<int>(l) / 2; }
/// +1 or -1: the direction of a label along its axis.
constexpr int label_sign(polycube_label l) noexcept { return static_cast<int>(l) % 2 == 0 ? 1 : -1; }
/// The label of the opposite direction (+X <-> -X, ...).
constexpr polycube_label opposite(polycube_label l) noexcept {
  return static_cast<polycube_label>(static_cast<int>(l) ^ 1);
}
/// Unit vector of a label.
constexpr vec3 label_direction(polycube_label l) noexcept {
  vec3 d;
  d[label_axis(l)] = label_sign(l);
  return d;
}

/// The colour pictures give a label's charts (unit RGB; render_face_colored_mesh_preview, `tessera
/// render --labels`): +X red, -X purple, +Y green, -Y yellow, +Z blue, -Z cyan.
constexpr std::array<float, 3> polycube_label_color(polycube_label l) noexcept {
  constexpr std::array<std::array<float, 3>, 6> colors{{{0.90f, 0.35f, 0.30f},
                                                        {0.60f, 0.20f, 0.45f},
                                                        {0.40f, 0.75f, 0.35f},
                                                        {0.85f, 0.75f, 0.25f},
                                                        {0.35f, 0.55f, 0.90f},
                                                        {0.30f, 0.75f, 0.80f}}};
  return colors[static_cast<std::size_t>(l) % 6];
}

/// An integer point of the tile grid (multiply by tile_size for mesh units).
using grid_point = std::array<std::int64_t, 3>;

/// A chart: a connected set of faces with one label, flat in the plane
/// `coordinate[axis] = plane * tile_size` of the polycube. Charts are planar regions of genus 0; the
/// top of a torus-like polycube is an annulus (see docs/surface.md).
struct polycube_chart {
  /// The chart's label (the outward axis direction of its faces).
  polycube_label label = polycube_label::pos_x;
  std::int64_t plane = 0;      ///< grid coordinate of the chart's plane along its axis
  std::vector<index_t> faces;  ///< base faces, ascending
};

/// A polycube corner: a base vertex where three or more charts meet.
struct polycube_corner {
  index_t vertex = -1;          ///< base vertex
  grid_point grid{};            ///< its grid position
  std::vector<index_t> charts;  ///< charts around it, ascending
};

/// A polycube edge: the straight boundary between two charts (of different axes) from one corner to
/// another, along `axis`.
struct polycube_edge {
  index_t chart_a = -1, chart_b = -1;    ///< chart_a < chart_b
  int axis = 0;                          ///< the axis the edge runs along
  index_t corner_a = -1, corner_b = -1;  ///< corners at its low and high end along `axis`
  std::int64_t length = 0;               ///< in tiles (>= 1)
};

/// One edge of the tile grid on the polycube surface: the segment from `origin` to origin + e_axis
/// (grid units). Ids (positions in quad_layout::edges) are sorted by (axis, origin), so they depend on
/// the polycube's geometry only, never on the order quads were found in.
struct grid_edge {
  /// The axis the edge runs along.
  int axis = 0;
  /// Its low end, in grid units.
  grid_point origin{};
  std::array<index_t, 2> quads{-1, -1};  ///< the two quads sharing it, ascending
};

/// One tile-size square of the polycube surface. Corners run counter-clockwise seen from outside
/// (along the chart's label direction); side k joins corner k to corner k + 1 (mod 4). Sides 0 and 2
/// run along the chart's first in-plane axis ((axis + 1) % 3 for + labels), sides 1 and 3 along the
/// other one.
struct polycube_quad {
  /// The chart the quad lies in.
  index_t chart = -1;
  /// Its corners in grid units, counter-clockwise seen from outside.
  std::array<grid_point, 4> corners{};
  std::array<index_t, 4> edges{};              ///< grid edge id of each side
  std::array<bool, 4> edge_forward{};          ///< side k runs along +axis of its grid edge
  std::array<index_t, 4> neighbors{};          ///< quad across each side (also around polycube edges)
  std::array<std::int8_t, 4> neighbor_side{};  ///< which side of that neighbour is the shared edge
};

/// The polycube surface cut into tile-size squares, with the grid edges they share.
struct quad_layout {
  /// The quads.
  std::vector<polycube_quad> quads;
  /// The grid edges, sorted by (axis, origin).
  std::vector<grid_edge> edges;
  /// Per chart: the quads of its plane as a dense grid over the chart's bounding rectangle in
  /// (first in-plane axis, second in-plane axis) grid units: origin, size, and quad id or -1.
  struct chart_grid {
    /// Grid coordinates of the rectangle's low corner.
    std::array<std::int64_t, 2> origin{};
    /// Its size in grid units.
    std::array<std::int64_t, 2> size{};
    /// Quad id of each grid cell, row by row, or -1.
    std::vector<index_t> quad;
  };
  /// One grid per chart.
  std::vector<chart_grid> chart_grids;
};

/// A polycube map: see the file comment. `polycube` and `labels` follow the base mesh's vertex and face
/// order. Every field is consistent once build_polycube_map (or load_polycube_map) returned it.
struct polycube_map {
  tri_mesh base;                       ///< the base mesh (positions and faces only)
  std::vector<vec3> polycube;          ///< polycube position of every base vertex
  std::vector<polycube_label> labels;  ///< chart label of every base face
  std::vector<index_t> face_chart;     ///< chart of every base face
  /// The charts.
  std::vector<polycube_chart> charts;
  /// The corners.
  std::vector<polycube_corner> corners;
  /// The polycube edges.
  std::vector<polycube_edge> edges;
  /// The surface cut into tile-size quads.
  quad_layout layout;
  /// Side of a grid square in mesh units.
  double tile_size = 1;
  /// When the construction refined the input (polycube_options::refine): the input face of every
  /// base face (input vertices and faces keep their indices, new ones follow). Empty: base is the input.
  std::vector<index_t> face_origin;
  /// Whether the base mesh is a refinement of the input.
  [[nodiscard]] bool refined() const noexcept { return !face_origin.empty(); }
  /// The polycube-deformed mesh: base connectivity, polycube positions.
  [[nodiscard]] tri_mesh deformed_mesh() const {
    tri_mesh m;
    m.positions = polycube;
    m.faces = base.faces;
    return m;
  }
};

/// Options of build_polycube_map.
struct polycube_options {
  double tile_size = 0;             ///< tile edge length in mesh units; 0: use tiles_across
  index_t tiles_across = 8;         ///< when tile_size is 0: tiles across the largest bounding-box extent
  double compactness = 1.0;         ///< weight of the dihedral-weighted compactness term against fidelity
  double opposite_penalty = 2;      ///< compactness cost factor between opposite labels (<= 2 keeps it metric)
  int max_expansion_cycles = 6;     ///< α-expansion sweeps over the six labels
  int max_repair_iterations = 200;  ///< relabelling steps of the validity repair
  int untangle_iterations = 300;    ///< smoothing rounds that unflip faces after the final solve
  int max_relabel_rounds = 24;      ///< relabellings of a chart whose deformation fails, then a new solve
  int max_compactness_retries = 5;  ///< further attempts at other compactness multiples (x4, x3, x8, x2, x0.5)
  /// After the first valid map, up to this many further compactness multiples (within
  /// max_compactness_retries) are tried as well and the least distorted valid map (smallest sum of
  /// area and angle distortion, polycube_distortion.hpp) is returned: slower, often less distorted.
  int distortion_retries = 0;
  /// Degeneracy bound of the verification: a face whose normalized area ratio (its share of the polycube
  /// area over its share of the base area) is below this counts as collapsed and the map is refused
  /// (0 accepts any positive area).
  double min_area_ratio = 1e-4;
  /// Split chart chords (edges inside a chart with both ends on its boundary with one other chart,
  /// which would collapse onto a polycube edge) by a new vertex, and when an attempt fails, repeat it
  /// with the chords of the graph cut's labels split before the repair: the map's base is then refined.
  bool refine = true;
};

namespace detail {
/// Relative threshold under which a face counts as having zero area.
inline constexpr double polycube_area_eps = 1e-14;
}  // namespace detail

/// Checks that `m` can carry a polycube map: a valid mesh (validate_mesh) with at least 4 faces,
/// closed (no boundary edge), edge- and vertex-manifold, consistently oriented, without zero-area or
/// duplicate faces. `what` names the mesh in messages; the message names the first offending face,
/// edge or vertex. Returns invalid_argument (out_of_range for a bad index). O(F log F).
template <Mesh M>
status validate_polycube_input(const M& m, std::string_view what = "mesh") {
  if (auto s = validate_mesh(m, what); !s) return s;
  const index_t nv = num_vertices(m), nf = num_faces(m);
  if (nf < 4) return status::invalid_argument(detail::cat(what, ": a closed mesh needs at least 4 faces, got ", nf));
  const aabb box = bounding_box(m);
  const double diag2 = squared_norm(box.extent());
  for (index_t f = 0; f < nf; ++f)
    if (!(squared_norm(face_area_normal(m, f)) > detail::polycube_area_eps * detail::polycube_area_eps * diag2 * diag2))
      return status::invalid_argument(detail::cat(what, ": face ", f, " has zero area (degenerate)"));
  const auto hs = detail::sorted_half_edges(m);
  status bad;
  detail::for_each_edge_group(hs, [&](std::size_t first, std::size_t count) {
    if (!bad.ok()) return;
    const auto& h = hs[first];
    if (count == 1) {
      bad = status::invalid_argument(
          detail::cat(what, ": is not closed: edge (", h.a, ", ", h.b, ") of face ", h.f, " is a boundary edge"));
    } else if (count > 2) {
      bad = status::invalid_argument(
          detail::cat(what, ": is not manifold: edge (", h.a, ", ", h.b, ") is shared by ", count, " faces"));
    } else {
      const auto& g = hs[first + 1];
      const bool hf = face_vertex(m, h.f, h.k) == h.a, gf = face_vertex(m, g.f, g.k) == g.a;
      if (hf == gf)
        bad = status::invalid_argument(detail::cat(what, ": is not consistently oriented: faces ", h.f, " and ", g.f,
                                                   " traverse edge (", h.a, ", ", h.b, ") in the same direction"));
    }
  });
  if (!bad) return bad;
  // duplicate faces (same vertex set)
  std::vector<std::array<index_t, 4>> keys(detail::to_size(nf));
  for (index_t f = 0; f < nf; ++f) {
    std::array<index_t, 3> v{face_vertex(m, f, 0), face_vertex(m, f, 1), face_vertex(m, f, 2)};
    std::sort(v.begin(), v.end());
    keys[detail::to_size(f)] = {v[0], v[1], v[2], f};
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i][0] == keys[i - 1][0] && keys[i][1] == keys[i - 1][1] && keys[i][2] == keys[i - 1][2])
      return status::invalid_argument(
          detail::cat(what, ": faces ", keys[i - 1][3], " and ", keys[i][3], " are duplicates (same three vertices)"));
  // vertex manifoldness: the faces around each vertex form a single fan
  const auto adj = face_adjacency(m);
  std::vector<index_t> count(detail::to_size(nv), 0), first_face(detail::to_size(nv), -1);
  for (index_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const auto v = detail::to_size(face_vertex(m, f, k));
      if (count[v]++ == 0) first_face[v] = f;
    }
  for (index_t v = 0; v < nv; ++v) {
    const index_t f0 = first_face[detail::to_size(v)];
    if (f0 < 0) return status::invalid_argument(detail::cat(what, ": vertex ", v, " is used by no face"));
    index_t f = f0, walked = 0;
    do {
      int k = 0;
      while (face_vertex(m, f, k) != v) ++k;
      f = adj.neighbor[detail::to_size(f)][detail::to_size(k)];  // across the side leaving v
      ++walked;
    } while (f != f0 && f >= 0 && walked <= count[detail::to_size(v)]);
    if (walked != count[detail::to_size(v)])
      return status::invalid_argument(
          detail::cat(what, ": is not manifold at vertex ", v, " (its faces form more than one fan)"));
  }
  return {};
}

/// The tile size a polycube of mesh `m` uses under `o`: o.tile_size when positive, else the largest
/// bounding-box extent / o.tiles_across. Errors (invalid_argument): a negative or non-finite
/// tile_size, tiles_across < 1 when tile_size is 0, a tile larger than the mesh's largest extent.
template <Mesh M>
result<double> polycube_tile_size(const M& m, const polycube_options& o) {
  const vec3 e = bounding_box(m).extent();
  const double largest = std::max({e.x, e.y, e.z});
  double t = o.tile_size;
  if (!(t >= 0) || !std::isfinite(t))
    return status::invalid_argument(
        detail::cat("polycube_options::tile_size must be > 0 (or 0 to use tiles_across), got ", t));
  if (t == 0) {
    if (o.tiles_across < 1)
      return status::invalid_argument(detail::cat("polycube_options::tiles_across must be >= 1, got ", o.tiles_across));
    t = largest / static_cast<double>(o.tiles_across);
  }
  if (!(t > 0)) return status::invalid_argument("polycube: the mesh has an empty bounding box");
  if (t > largest)
    return status::invalid_argument(
        detail::cat("polycube_options::tile_size ", t, " is larger than the mesh (largest extent ", largest, ")"));
  return t;
}

TESSERA_NAMESPACE_END
