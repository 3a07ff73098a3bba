// tessera/geometry/geometric_wang_tiles.hpp: planar geometric-texture Wang tiles, paper 000 §3.1-3.2:
// one edge strip per colour is cut out of the exemplar (§3.1; from a larger quilted texture when the
// exemplar is too small); each tile's frame is built from the halves of its four edge strips that lie
// inside it, free elements that collide where strips overlap at the corners are deformed and merged
// (or dropped) with the tile border held fixed (§3.2); the interior is filled by constrained mesh
// quilting (§3.3). The complete planar set has nh^2 * nv^2 tiles; the complete three-axis set, which
// covers polycube surfaces (§3.1 Fig. 2-3, §5), 2 (nX^2 nY^2 + nX^2 nZ^2 + nY^2 nZ^2) (96 for two colours
// per axis). Every tile carrying a colour on a side has bit-identical border geometry there, so any
// valid tiling is continuous, in the plane and around convex and concave polycube edges.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/tri_mesh.hpp"
#include "../tiling/axis_tile_set.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "constrained_mesh_quilt.hpp"
#include "detail/axis_strips.hpp"
#include "detail/edge_strips.hpp"
#include "detail/tile_frames.hpp"
#include "mesh_quilt.hpp"
#include "quilt_exemplar.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of build_geometric_wang_tiles.
struct geometric_wang_options {
  int horizontal_colors = 2;  ///< nh: colours of north/south edges (planar sets)
  int vertical_colors = 2;    ///< nv: colours of east/west edges (planar sets)
  /// {nX, nY, nZ}: when set (all >= 1), a three-axis set for polycube surfaces is built instead of a
  /// planar one, and horizontal_colors / vertical_colors are not used. {0, 0, 0} (default): planar.
  axis_color_counts axis_colors = {0, 0, 0};
  double tile_size = 0;       ///< w_T (required)
  double edge_height = 0;     ///< h_E, strip height across an edge; 0 = 1.5 x the exemplar's element size
  double corner_margin = -1;  ///< crossing elements keep this far from the tile corners; < 0 = 0.15 x element size
  /// When the exemplar cannot hold a strip (smaller than w_T + ...), quilt a larger texture first and
  /// cut the strips from it (§3.1). When false, such exemplars are rejected.
  bool quilt_larger_source = true;
  /// Free strip elements (on one side of the edge line) are kept when they start inside the strip,
  /// even where they reach past it into the tile (true, default), or only when they lie wholly inside
  /// one half of the strip (false: the earlier rule, which kept next to none and left a band along
  /// every tile border that the interior synthesis cannot fill without crossing the border).
  bool deep_free_elements = true;
  mesh_quilt_options quilt = {};  ///< interior synthesis (and the larger source); its seed seeds everything
  /// Progress callback and cancellation token.
  tessera::progress progress = {};
};

/// A complete tile set, planar or three-axis. Every tile covers [0, tile_size]^2 in XY (north = +Y,
/// east = +X, height +Z); its border vertices lie exactly on x = 0, x = tile_size, y = 0, y = tile_size.
/// Planar: tile i has edges complete_tile_edges(i, nh, nv). Three-axis (three_axis()): tile i is
/// axis_tile_at(i, axis_colors) (tiling/axis_tile_set.hpp): it covers quads facing `faces[i]`, its
/// local x, y, z are that face's tile frame (x along the face's first in-plane axis, y along the
/// second, z outward), and `edges[i]` are its colours in that frame (north / south from the first
/// axis' colours, east / west from the second's); horizontal_colors and vertical_colors are 0.
struct geometric_tile_set {
  /// Tile side w_T in world units.
  double tile_size = 0;
  /// Edge strip height h_E used.
  double edge_height = 0;
  /// nh and nv.
  int horizontal_colors = 0, vertical_colors = 0;
  /// Three-axis sets: {nX, nY, nZ}; {0, 0, 0} for a planar set.
  axis_color_counts axis_colors = {0, 0, 0};
  /// Edge colours of each tile.
  std::vector<wang_edges> edges;
  /// Three-axis sets: the cube face of each tile (0..5: +X, -X, +Y, -Y, +Z, -Z, polycube_label's
  /// numbering); empty for a planar set.
  std::vector<int> faces;
  /// The tiles' meshes.
  std::vector<tri_mesh> tiles;
  mesh_quilt_stats stats;         ///< summed over the tiles' interior synthesis
  bool quilted_source = false;    ///< the strips came from a larger quilted texture
  index_t crossing_elements = 0;  ///< elements split on an edge line, over all strips
  /// Corner merging of the frames (§3.2), over all tiles: free strip elements that collided with
  /// another strip's elements, merge_pair calls, merged into the frame, dropped.
  index_t frame_merges_attempted = 0, frame_merged = 0, frame_dropped = 0;
  /// True for a three-axis set (axis_colors set).
  [[nodiscard]] bool three_axis() const noexcept { return axis_colors[0] > 0; }
  /// The axis (0 X, 1 Y, 2 Z) side `side` of tile `t` runs along in a three-axis set; for a planar set
  /// 0 for north / south, 1 for east / west (the colour class a side draws from either way).
  /// Precondition: t < tiles; faces filled for a three-axis set.
  [[nodiscard]] int side_class(index_t t, int side) const noexcept {
    return three_axis() ? cube_face_side_axis(faces[detail::to_size(t)], side) : (is_horizontal_side(side) ? 0 : 1);
  }
};

namespace detail {

/// The edge strips of a tile set (§3.1) and the figures the tiles are built from.
struct wang_strip_plan {
  strip_params sp;
  double edge_height = 0;
  std::vector<edge_strip> hs, vs;  ///< planar sets: one strip per horizontal / vertical colour
  axis_strip_set axis;             ///< three-axis sets: the strips of each axis
  bool quilted_source = false;
  index_t crossing = 0;
};

/// Checks the options and cuts the edge strips (§3.1), from a larger quilted texture when the
/// exemplar cannot hold them. Errors: see build_geometric_wang_tiles.
template <Executor E>
result<wang_strip_plan> plan_wang_strips(const quilt_exemplar& exemplar, const geometric_wang_options& o, E&& exec) {
  const bool three = o.axis_colors != axis_color_counts{0, 0, 0};
  if (three) {
    if (auto s = validate_axis_color_counts(o.axis_colors); !s)
      return status::invalid_argument(detail::cat("geometric wang tiles: ", s.message()));
  } else if (auto s = validate_color_counts(o.horizontal_colors, o.vertical_colors); !s) {
    return status::invalid_argument(detail::cat("geometric wang tiles: ", s.message()));
  }
  const index_t n =
      three ? axis_tile_count(o.axis_colors) : complete_tile_count(o.horizontal_colors, o.vertical_colors);
  if (n > (index_t{1} << 26))
    return status::size_overflow(
        detail::cat("geometric wang tiles: the colours make ", n, " tiles, more than tessera builds (2^26)"));
  if (!(o.tile_size > 0) || !std::isfinite(o.tile_size))
    return status::invalid_argument(detail::cat("geometric wang tiles: tile_size must be > 0, got ", o.tile_size));
  if (exemplar.num_elements() == 0)
    return status::invalid_argument("geometric wang tiles: the exemplar is empty (not prepared)");
  if (auto s = detail::check_quilt_options(o.quilt); !s) return s;
  if (!(o.edge_height >= 0) || !std::isfinite(o.edge_height))
    return status::invalid_argument(detail::cat("geometric wang tiles: edge_height must be >= 0, got ", o.edge_height));
  const double he = o.edge_height > 0 ? o.edge_height : 1.5 * exemplar.element_diameter();
  const vec3 ext = exemplar.bounds().extent();
  if (he > std::min(ext.x, ext.y))
    return status::invalid_argument(detail::cat("geometric wang tiles: edge_height ", he,
                                                " is larger than the exemplar (", ext.x, " x ", ext.y, ")"));
  if (he > 0.5 * o.tile_size)
    return status::invalid_argument(detail::cat("geometric wang tiles: edge_height ", he,
                                                " leaves no interior in a tile of size ", o.tile_size,
                                                "; it must be at most half the tile"));
  const double margin = o.corner_margin >= 0 ? o.corner_margin : 0.15 * exemplar.element_diameter();
  if (!std::isfinite(margin) || margin * 2 >= o.tile_size)
    return status::invalid_argument(
        detail::cat("geometric wang tiles: corner_margin ", margin, " does not fit a tile of size ", o.tile_size));
  // grid sizes before any loop over them: a tile's quilting grid, the strip windows (step half a
  // cell over the exemplar or the larger source of 2 w_T + 2 h_E) and the larger source's grid
  const double cell = exemplar.cell_size(), src_side = std::max({ext.x, ext.y, 2 * o.tile_size + 2 * he});
  const double tile_cells = (o.tile_size / cell) * (o.tile_size / cell),
               windows = (2 * src_side / cell + 1) * (2 * src_side / cell + 1);
  if (tile_cells > double(1 << 26) || windows > double(1 << 24))
    return status::size_overflow(detail::cat("geometric wang tiles: the exemplar's cell_size ", cell, " gives ",
                                             tile_cells, " grid cells a tile and ", windows,
                                             " strip windows (at most 2^26 and 2^24); use a larger cell_size"));
  wang_strip_plan plan;
  plan.edge_height = he;
  plan.sp = {.tile_size = o.tile_size,
             .half_height = 0.5 * he,
             .corner_margin = margin,
             .snap = detail::clip_snap_fraction * o.tile_size,
             .deep_free_elements = o.deep_free_elements};
  const double need = o.tile_size + 2 * cell;
  const auto choose = [&](const quilt_exemplar& src) {
    plan.hs.clear();
    plan.vs.clear();
    return three ? choose_axis_strips(src, o.axis_colors, plan.sp, o.quilt.seed, plan.axis)
                 : choose_strips(src, o.horizontal_colors, o.vertical_colors, plan.sp, o.quilt.seed, plan.hs, plan.vs);
  };
  status picked = status::invalid_argument("geometric wang tiles: exemplar smaller than a tile");
  if (ext.x >= need && ext.y >= need) picked = choose(exemplar);
  if (!picked) {
    if (!o.quilt_larger_source)
      return status::invalid_argument(detail::cat("geometric wang tiles: the exemplar (", ext.x, " x ", ext.y,
                                                  ") cannot hold the edge strips of a ", o.tile_size, " tile (",
                                                  picked.message(), ") and quilt_larger_source is off"));
    const double size = 2 * o.tile_size + 2 * he;
    mesh_quilt_options qo = o.quilt;
    if (three) qo.fill_holes = false;  // as the tiles' quilts of a three-axis set (below)
    // the strips' source keeps its small elements: large ones in their place leave fewer strip windows
    // that avoid elements across the tile corners (the pebbles' 16-tile set had none; docs/geometry.md)
    qo.fill_replace = false;
    qo.progress = {};
    if (o.progress.token) qo.progress.token = o.progress.token;
    auto big = mesh_quilt(exemplar, size, size, qo, exec);
    if (!big) return big.error();
    auto bigger = prepare_quilt_exemplar(big->mesh, {.cell_size = cell});
    if (!bigger) return bigger.error();
    plan.quilted_source = true;
    if (auto s = choose(*bigger); !s) return s;
  }
  for (const auto& s : plan.hs) plan.crossing += s.crossing;
  for (const auto& s : plan.vs) plan.crossing += s.crossing;
  for (const auto& strips : plan.axis.horizontal)
    for (const auto& s : strips) plan.crossing += s.crossing;
  return plan;
}

}  // namespace detail

/// Builds the complete geometric Wang tile set from a prepared exemplar, as paper 000 §3.1-3.3
/// describe: planar (nh^2 * nv^2 tiles) or, when options.axis_colors is set, three-axis for polycube
/// surfaces (2 (nX^2 nY^2 + nX^2 nZ^2 + nY^2 nZ^2) tiles from nX + nY + nZ strips; each face direction's
/// tiles are built like a planar set whose horizontal strips are those of its first in-plane axis and
/// vertical strips those of its second, turned a quarter). Tiles are synthesized in parallel through
/// `exec`; the result is the same for every executor.
/// Errors: colour counts outside [1, 4096] ("zero colours"), more than 2^26 tiles, tile_size not
/// positive, edge_height larger than the exemplar or than half the tile, an exemplar smaller than a
/// tile when quilt_larger_source is false, a cell size so small that a tile has more than 2^26 grid
/// cells or the strip search more than 2^24 windows (size_overflow), no strip window avoiding the
/// tile corners (and, three-axis, fitting the other axes' strips there), bad quilt options; cancelled
/// through options.progress. Time: dominated by one constrained quilt of one tile per tile.
template <Executor E = serial_executor>
result<geometric_tile_set> build_geometric_wang_tiles(const quilt_exemplar& exemplar, const geometric_wang_options& o,
                                                      E&& exec = {}) {
  auto plan = detail::plan_wang_strips(exemplar, o, exec);
  if (!plan) return plan.error();
  geometric_tile_set set;
  set.tile_size = o.tile_size;
  set.edge_height = plan->edge_height;
  const bool three = o.axis_colors != axis_color_counts{0, 0, 0};
  set.horizontal_colors = three ? 0 : o.horizontal_colors;
  set.vertical_colors = three ? 0 : o.vertical_colors;
  set.axis_colors = o.axis_colors;
  set.quilted_source = plan->quilted_source;
  set.crossing_elements = plan->crossing;

  // §3.2-3.3: frame and interior of every tile, in parallel
  const index_t n =
      three ? axis_tile_count(o.axis_colors) : complete_tile_count(o.horizontal_colors, o.vertical_colors);
  set.edges.resize(detail::to_size(n));
  set.tiles.resize(detail::to_size(n));
  if (three) set.faces.resize(detail::to_size(n));
  std::vector<mesh_quilt_stats> stats(detail::to_size(n));
  std::vector<std::array<index_t, 3>> frames(detail::to_size(n));
  std::vector<status> errors(detail::to_size(n));
  const index_t batch = 4;
  for (index_t first = 0; first < n; first += batch) {
    if (!o.progress.report(double(first) / double(n), "geometric wang tiles")) return status::cancelled();
    const index_t last = std::min(n, first + batch);
    exec.parallel_for(first, last, [&](index_t t) {
      // a three-axis tile is the planar tile of its face: horizontal strips from the face's first
      // in-plane axis, vertical strips (turned a quarter) from its second
      const axis_tile at = three ? axis_tile_at(t, o.axis_colors) : axis_tile{};
      const wang_edges e = three ? at.edges : complete_tile_edges(t, o.horizontal_colors, o.vertical_colors);
      const auto ax = cube_face_axes(at.face);
      const auto& hs = three ? plan->axis.horizontal[detail::to_size(ax[0])] : plan->hs;
      const auto& vs = three ? plan->axis.vertical[detail::to_size(ax[1])] : plan->vs;
      set.edges[detail::to_size(t)] = e;
      if (three) set.faces[detail::to_size(t)] = at.face;
      auto fr =
          detail::build_frame(hs, vs, e, o.tile_size, plan->sp.half_height, exemplar.cell_size(), o.quilt.merge_whole);
      frames[detail::to_size(t)] = {fr.merges_attempted, fr.merged, fr.dropped};
      mesh_quilt_options qo = o.quilt;
      qo.progress = {};
      if (o.progress.token) qo.progress.token = o.progress.token;
      qo.fill_border_margin = std::max(qo.fill_border_margin, plan->sp.half_height);
      // three-axis sets go onto surfaces, whose shell map follows a tile only within its chordal
      // tolerance: the tighter gaps of filled holes made elements cross there (the test sphere: 0 ->
      // 23 crossing face pairs), so they are quilted without hole filling (docs/surface.md)
      if (three) qo.fill_holes = false;
      auto q = constrained_mesh_quilt(exemplar, {0, 0, o.tile_size, o.tile_size}, std::move(fr.frame), qo,
                                      static_cast<std::uint64_t>(t) + 1);
      if (!q) {
        errors[detail::to_size(t)] = q.error();
        return;
      }
      stats[detail::to_size(t)] = q->stats;
      set.tiles[detail::to_size(t)] = std::move(q->mesh);
    });
    for (index_t t = first; t < last; ++t)
      if (!errors[detail::to_size(t)]) return errors[detail::to_size(t)];
  }
  for (const auto& s : stats) set.stats += s;
  for (const auto& f : frames) {
    set.frame_merges_attempted += f[0];
    set.frame_merged += f[1];
    set.frame_dropped += f[2];
  }
  o.progress.report(1.0, "geometric wang tiles");
  return set;
}

/// build_geometric_wang_tiles for any Mesh exemplar (prepared with default options); rejects open or
/// non-manifold exemplars and NaN vertices (see prepare_quilt_exemplar).
template <Mesh M, Executor E = serial_executor>
result<geometric_tile_set> build_geometric_wang_tiles(const M& exemplar, const geometric_wang_options& o,
                                                      E&& exec = {}) {
  auto ex = prepare_quilt_exemplar(exemplar);
  if (!ex) return ex.error();
  return build_geometric_wang_tiles(*ex, o, exec);
}

/// The tiles of one face of a three-axis set as a complete planar set (the special case): nh = colours
/// of the face's first in-plane axis, nv = of its second, tile i = the face's i-th tile, in the face's
/// tile frame; tile_geometric_plane tiles a plane with it. Errors: `set` is not three-axis, `face`
/// outside [0, 6), a set whose faces do not hold that face's complete block in order. O(size of the
/// face's tiles) (they are copied).
inline result<geometric_tile_set> face_tile_set(const geometric_tile_set& set, int face) {
  if (!set.three_axis()) return status::invalid_argument("face_tile_set: the tile set is planar, not three-axis");
  if (face < 0 || face >= cube_faces)
    return status::out_of_range(detail::cat("face_tile_set: face ", face, " is outside [0, 6)"));
  if (auto s = validate_axis_color_counts(set.axis_colors); !s)
    return status(s.code(), detail::cat("face_tile_set: ", s.message()));
  const index_t first = axis_face_first_tile(face, set.axis_colors), n = axis_face_tile_count(face, set.axis_colors);
  if (set.tiles.size() != set.edges.size() || set.faces.size() != set.tiles.size() ||
      static_cast<index_t>(set.tiles.size()) != axis_tile_count(set.axis_colors))
    return status::invalid_argument("face_tile_set: the set is not a complete three-axis set");
  geometric_tile_set out;
  out.tile_size = set.tile_size;
  out.edge_height = set.edge_height;
  const auto ax = cube_face_axes(face);
  out.horizontal_colors = set.axis_colors[detail::to_size(ax[0])];
  out.vertical_colors = set.axis_colors[detail::to_size(ax[1])];
  for (index_t i = 0; i < n; ++i) {
    const auto t = detail::to_size(first + i);
    if (set.faces[t] != face || set.edges[t] != complete_tile_edges(i, out.horizontal_colors, out.vertical_colors))
      return status::invalid_argument(
          detail::cat("face_tile_set: tile ", first + i, " is not tile ", i, " of face ", cube_face_name(face)));
    out.edges.push_back(set.edges[t]);
    out.tiles.push_back(set.tiles[t]);
  }
  out.quilted_source = set.quilted_source;
  return out;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_geometric_wang_tiles.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
