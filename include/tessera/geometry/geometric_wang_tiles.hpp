// tessera/geometry/geometric_wang_tiles.hpp: planar geometric-texture Wang tiles, paper 000 §3.1-3.2:
// one edge strip per colour is cut out of the exemplar (§3.1; from a larger quilted texture when the
// exemplar is too small); each tile's frame is built from the halves of its four edge strips that lie
// inside it, free elements that collide where strips overlap at the corners are deformed and merged
// (or dropped) with the tile border held fixed (§3.2); the interior is filled by constrained mesh
// quilting (§3.3). The complete set has nh^2 * nv^2 tiles; every tile carrying a colour on a side has
// bit-identical border geometry there, so any valid tiling is continuous.
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
#include "../tiling/complete_tile_set.hpp"
#include "constrained_mesh_quilt.hpp"
#include "detail/edge_strips.hpp"
#include "detail/tile_frames.hpp"
#include "mesh_quilt.hpp"
#include "quilt_exemplar.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of build_geometric_wang_tiles.
struct geometric_wang_options {
  int horizontal_colors = 2;  ///< nh: colours of north/south edges
  int vertical_colors = 2;    ///< nv: colours of east/west edges
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

/// A complete planar tile set. Tile i has edges complete_tile_edges(i, nh, nv) and covers
/// [0, tile_size]^2 in XY (north = +Y, east = +X); its border vertices lie exactly on x = 0,
/// x = tile_size, y = 0, y = tile_size.
struct geometric_tile_set {
  /// Tile side w_T in world units.
  double tile_size = 0;
  /// Edge strip height h_E used.
  double edge_height = 0;
  /// nh and nv.
  int horizontal_colors = 0, vertical_colors = 0;
  /// Edge colours of each tile.
  std::vector<wang_edges> edges;
  /// The tiles' meshes.
  std::vector<tri_mesh> tiles;
  mesh_quilt_stats stats;         ///< summed over the tiles' interior synthesis
  bool quilted_source = false;    ///< the strips came from a larger quilted texture
  index_t crossing_elements = 0;  ///< elements split on an edge line, over all strips
  /// Corner merging of the frames (§3.2), over all tiles: free strip elements that collided with
  /// another strip's elements, merge_pair calls, merged into the frame, dropped.
  index_t frame_merges_attempted = 0, frame_merged = 0, frame_dropped = 0;
};

namespace detail {

/// The edge strips of a tile set (§3.1) and the figures the tiles are built from.
struct wang_strip_plan {
  strip_params sp;
  double edge_height = 0;
  std::vector<edge_strip> hs, vs;  ///< one strip per horizontal / vertical colour
  bool quilted_source = false;
  index_t crossing = 0;
};

/// Checks the options and cuts the edge strips (§3.1), from a larger quilted texture when the
/// exemplar cannot hold them. Errors: see build_geometric_wang_tiles.
template <Executor E>
result<wang_strip_plan> plan_wang_strips(const quilt_exemplar& exemplar, const geometric_wang_options& o, E&& exec) {
  if (auto s = validate_color_counts(o.horizontal_colors, o.vertical_colors); !s)
    return status::invalid_argument(detail::cat("geometric wang tiles: ", s.message()));
  const index_t n = complete_tile_count(o.horizontal_colors, o.vertical_colors);
  if (n > (index_t{1} << 26))
    return status::size_overflow(detail::cat("geometric wang tiles: ", o.horizontal_colors, " x ", o.vertical_colors,
                                             " colours make ", n, " tiles, more than tessera builds (2^26)"));
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
  status picked = status::invalid_argument("geometric wang tiles: exemplar smaller than a tile");
  if (ext.x >= need && ext.y >= need)
    picked = choose_strips(exemplar, o.horizontal_colors, o.vertical_colors, plan.sp, o.quilt.seed, plan.hs, plan.vs);
  if (!picked) {
    if (!o.quilt_larger_source)
      return status::invalid_argument(detail::cat("geometric wang tiles: the exemplar (", ext.x, " x ", ext.y,
                                                  ") cannot hold the edge strips of a ", o.tile_size, " tile (",
                                                  picked.message(), ") and quilt_larger_source is off"));
    const double size = 2 * o.tile_size + 2 * he;
    mesh_quilt_options qo = o.quilt;
    qo.progress = {};
    if (o.progress.token) qo.progress.token = o.progress.token;
    auto big = mesh_quilt(exemplar, size, size, qo, exec);
    if (!big) return big.error();
    auto bigger = prepare_quilt_exemplar(big->mesh, {.cell_size = cell});
    if (!bigger) return bigger.error();
    plan.quilted_source = true;
    plan.hs.clear();
    plan.vs.clear();
    if (auto s =
            choose_strips(*bigger, o.horizontal_colors, o.vertical_colors, plan.sp, o.quilt.seed, plan.hs, plan.vs);
        !s)
      return s;
  }
  for (const auto& s : plan.hs) plan.crossing += s.crossing;
  for (const auto& s : plan.vs) plan.crossing += s.crossing;
  return plan;
}

}  // namespace detail

/// Builds the complete planar geometric Wang tile set (nh^2 * nv^2 tiles) from a prepared exemplar,
/// as paper 000 §3.1-3.3 describe. Tiles are synthesized in parallel through `exec`; the result is
/// the same for every executor.
/// Errors: colour counts outside [1, 4096] ("zero colours"), more than 2^26 tiles, tile_size not
/// positive, edge_height larger than the exemplar or than half the tile, an exemplar smaller than a
/// tile when quilt_larger_source is false, a cell size so small that a tile has more than 2^26 grid
/// cells or the strip search more than 2^24 windows (size_overflow), no strip window avoiding the
/// tile corners, bad quilt options; cancelled through options.progress. Time: dominated by
/// nh^2 nv^2 constrained quilts of one tile.
template <Executor E = serial_executor>
result<geometric_tile_set> build_geometric_wang_tiles(const quilt_exemplar& exemplar, const geometric_wang_options& o,
                                                      E&& exec = {}) {
  auto plan = detail::plan_wang_strips(exemplar, o, exec);
  if (!plan) return plan.error();
  geometric_tile_set set;
  set.tile_size = o.tile_size;
  set.edge_height = plan->edge_height;
  set.horizontal_colors = o.horizontal_colors;
  set.vertical_colors = o.vertical_colors;
  set.quilted_source = plan->quilted_source;
  set.crossing_elements = plan->crossing;

  // §3.2-3.3: frame and interior of every tile, in parallel
  const index_t n = complete_tile_count(o.horizontal_colors, o.vertical_colors);
  set.edges.resize(detail::to_size(n));
  set.tiles.resize(detail::to_size(n));
  std::vector<mesh_quilt_stats> stats(detail::to_size(n));
  std::vector<std::array<index_t, 3>> frames(detail::to_size(n));
  std::vector<status> errors(detail::to_size(n));
  const index_t batch = 4;
  for (index_t first = 0; first < n; first += batch) {
    if (!o.progress.report(double(first) / double(n), "geometric wang tiles")) return status::cancelled();
    const index_t last = std::min(n, first + batch);
    exec.parallel_for(first, last, [&](index_t t) {
      const wang_edges e = complete_tile_edges(t, o.horizontal_colors, o.vertical_colors);
      set.edges[detail::to_size(t)] = e;
      auto fr = detail::build_frame(plan->hs, plan->vs, e, o.tile_size, plan->sp.half_height, exemplar.cell_size(),
                                    o.quilt.merge_whole);
      frames[detail::to_size(t)] = {fr.merges_attempted, fr.merged, fr.dropped};
      mesh_quilt_options qo = o.quilt;
      qo.progress = {};
      if (o.progress.token) qo.progress.token = o.progress.token;
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

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_geometric_wang_tiles.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
