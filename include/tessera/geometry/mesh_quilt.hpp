// tessera/geometry/mesh_quilt.hpp: mesh quilting (Zhou et al., "Mesh Quilting for Geometric Texture
// Synthesis", SIGGRAPH 2006), with the refinements of paper 000 §3.3: grows a geometric texture of
// any XY size from a small exemplar, patch by patch, placing the exemplar at the translation that
// best matches what is already there (eq. 1-4, refined by ICP eq. 5) and merging corresponding
// elements (deformation eq. 6-7, graph cut eq. 8, seam join). Note: mesh quilting is the subject of
// US patent US7800627B2; judge for yourself whether it concerns your use.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/mesh.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "detail/quilt_engine.hpp"
#include "mesh_elements.hpp"
#include "quilt_exemplar.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of mesh_quilt (paper 000 §3.3).
struct mesh_quilt_options {
  int patch_cells = 0;      ///< side of the patch P_T in grid cells; 0 = half the exemplar
  double lambda = 1.0;      ///< weight of the normal term of eq. 1
  int max_samples = 160;    ///< M_T vertices of P_T used for the matching cost (evenly thinned)
  double tolerance = 0.05;  ///< pick randomly among translations within (1 + tolerance) of the best cost
  bool icp = true;          ///< refine the grid translation by ICP (eq. 5, §3.3.3)
  /// At most this many ICP updates per patch.
  int icp_iterations = 30;
  double correspondence_distance = 0;        ///< §3.3.4 search radius; 0 = half a grid cell
  double deform_weight = 1.0;                ///< mu of eq. 6-7
  bool merge = true;                         ///< merge corresponding elements (§3.3.6); false drops overlapping ones
  int smooth_rings = 2;                      ///< vertex rings relaxed around each merge seam
  merge_rules rules = merge_rules::tessera;  ///< SOURCE/SINK rules of the element cuts (§3.3.6; see merge_rules)
  /// Merge an exemplar element that is not long with its corresponding output element, as the paper
  /// does. false (default): the exemplar element is left out, since the output element already
  /// stands there whole (or as a tile border half, whole across the border); merging two copies of
  /// one closed element only deforms it (docs/geometry.md, quality table). Long elements (threads)
  /// are merged either way: that is how a clipped thread continues.
  bool merge_whole = false;
  /// Threads (long elements narrower than half their length): a patch cuts them only across their
  /// length (its sides along a thread would slice it lengthwise into a ribbon; a thread belongs to
  /// the patch that holds its middle line), and two pieces of one thread are joined across a plane
  /// in their overlap, tried at up to five places, before the graph-cut merge of §3.3.6, whose
  /// correspondences then leave out the pieces' flat caps (`stats.merges_plane_cut`; docs/geometry.md,
  /// "Woven threads"). false: as before (the weave's quilts and planes covered 0.66-0.68 of the
  /// exemplar's area).
  bool thread_joins = true;
  /// How many times a cell whose element was dropped (it hit another element or a tile side) is
  /// handed back to the seed search, to be tried with another translation (0 = never).
  int cell_retries = 1;
  /// Constrained quilting (tiles): move an element that reaches a little (at most 0.35 element
  /// diameters) across a tile side back inside instead of dropping it (false: drop it, as before).
  bool nudge_inside = true;
  /// Occupancy term of the translation search (§3.3.3): among the translations within three times
  /// `tolerance` of the best eq. 4 cost, take those that would drop the fewest exemplar elements
  /// (colliding with what stands, or across a tile side). Off by default: measured, it helped the
  /// stone and pebble tiles (covered area 0.82 -> 0.87 of the exemplar's) but hurt the ring and
  /// chain-mail quilts (0.94 -> 0.88, 1.00 -> 0.91) and took longer (docs/geometry.md).
  bool occupancy_aware = false;
  /// After the patches, place single exemplar elements into the holes left where elements were
  /// dropped (an extension of §3.3; docs/geometry.md measures it): each hole, largest first, gets an
  /// element whose footprint fits with the exemplar's clearance, never intersecting or leaving a tile.
  /// Three-axis geometric tile sets turn it off (their tiles go onto surfaces; docs/geometry.md).
  bool fill_holes = true;
  /// Hole filling follows the exemplar's element sizes and density (docs/geometry.md): a hole gets an
  /// element of the largest size class the output lacks against the exemplar's, its free neighbours
  /// (not frame elements, not elements merged across a patch seam, none in a tile's border band)
  /// pushed apart by at most a quarter of an element diameter when it does not fit as it stands
  /// (only when the exemplar's element sizes vary: a lattice keeps its spacing); once the output
  /// holds the exemplar's element density, only holes that would leave an empty cell are filled.
  /// false: elements are drawn from the larger half of those that fit a hole as it stands, until the
  /// exemplar's covered share is reached.
  bool fill_relax = true;
  /// With fill_relax, where the output still holds more elements than the exemplar's density once
  /// the holes are filled (the patches drop large elements more often than small ones), one element
  /// of the exemplar's largest size class takes the place of two or more smaller free ones (added
  /// whole or filled; never frame elements, elements merged across a patch seam or any in a tile's
  /// border band), when it intersects nothing and the covered area moves towards the exemplar's
  /// (`stats.elements_replaced`; docs/geometry.md). A tile set's strip source is quilted without it
  /// (large elements leave fewer strip windows clear of the tile corners). false: filling only adds,
  /// as before.
  bool fill_replace = true;
  /// Constrained quilting: holes are not filled by elements reaching within this distance of the
  /// domain's sides. Geometric tile sets use half the edge strip height (h_E / 2): there a tile's
  /// elements must agree with the strip the neighbouring tile shares, and on a surface two tiles meet
  /// at an angle across it (docs/geometry.md).
  double fill_border_margin = 0;
  /// Seed of the patch choices.
  std::uint64_t seed = 0;
  /// Progress callback and cancellation token.
  tessera::progress progress = {};
};

/// What mesh_quilt returns.
struct mesh_quilt_result {
  std::vector<texture_element> elements;  ///< the synthesized elements (with bookkeeping)
  tri_mesh mesh;                          ///< the same, as one mesh
  /// What the synthesis did.
  mesh_quilt_stats stats;
};

namespace detail {
inline status check_quilt_options(const mesh_quilt_options& o) {
  if (o.patch_cells < 0)
    return status::invalid_argument(detail::cat("mesh_quilt: patch_cells must be >= 0, got ", o.patch_cells));
  if (!(o.lambda >= 0) || !std::isfinite(o.lambda))
    return status::invalid_argument(detail::cat("mesh_quilt: lambda must be >= 0, got ", o.lambda));
  if (o.max_samples < 1)
    return status::invalid_argument(detail::cat("mesh_quilt: max_samples must be >= 1, got ", o.max_samples));
  if (!(o.tolerance >= 0))
    return status::invalid_argument(detail::cat("mesh_quilt: tolerance must be >= 0, got ", o.tolerance));
  if (o.icp_iterations < 1)
    return status::invalid_argument(detail::cat("mesh_quilt: icp_iterations must be >= 1, got ", o.icp_iterations));
  if (!(o.correspondence_distance >= 0) || !std::isfinite(o.correspondence_distance))
    return status::invalid_argument(
        detail::cat("mesh_quilt: correspondence_distance must be >= 0, got ", o.correspondence_distance));
  if (!(o.deform_weight > 0) || !std::isfinite(o.deform_weight))
    return status::invalid_argument(detail::cat("mesh_quilt: deform_weight must be > 0, got ", o.deform_weight));
  if (o.cell_retries < 0 || o.cell_retries > 16)
    return status::invalid_argument(detail::cat("mesh_quilt: cell_retries must be in [0, 16], got ", o.cell_retries));
  if (!(o.fill_border_margin >= 0) || !std::isfinite(o.fill_border_margin))
    return status::invalid_argument(
        detail::cat("mesh_quilt: fill_border_margin must be finite and >= 0, got ", o.fill_border_margin));
  if (o.smooth_rings < 0)
    return status::invalid_argument(detail::cat("mesh_quilt: smooth_rings must be >= 0, got ", o.smooth_rings));
  return validate_enum(o.rules, {"tessera", "paper"}, "mesh_quilt: options.rules");
}
template <class Engine>
mesh_quilt_result finish_quilt(Engine& engine) {
  mesh_quilt_result r;
  r.stats = engine.stats();
  r.elements = engine.take_elements();
  r.mesh = combine_elements(r.elements);
  return r;
}
// Each field by name (a positional aggregate would silently accept two swapped doubles).
inline mesh_quilt_params to_params(const mesh_quilt_options& o, bool constrained, std::uint64_t stream) {
  return {.patch_cells = o.patch_cells,
          .lambda = o.lambda,
          .max_samples = o.max_samples,
          .tolerance = o.tolerance,
          .icp = o.icp,
          .icp_iterations = o.icp_iterations,
          .correspondence_distance = o.correspondence_distance,
          .deform_weight = o.deform_weight,
          .merge = o.merge,
          .smooth_rings = o.smooth_rings,
          .seed = o.seed,
          .stream = stream,
          .constrained = constrained,
          .rules = o.rules,
          .merge_whole = o.merge_whole,
          .thread_joins = o.thread_joins,
          .cell_retries = o.cell_retries,
          .nudge_inside = o.nudge_inside,
          .occupancy_aware = o.occupancy_aware,
          .fill_holes = o.fill_holes,
          .fill_relax = o.fill_relax,
          .fill_replace = o.fill_replace,
          .fill_border_margin = o.fill_border_margin};
}
}  // namespace detail

/// Unconstrained mesh quilting: synthesizes a geometric texture over [0, width] x [0, height] from a
/// prepared exemplar. Elements whose centre lies in the rectangle are kept whole (they may stick out
/// of it); long elements (threads) are clipped at the rectangle and capped. Every output element is
/// closed, manifold and intersects no other.
/// Errors: width or height not positive or not finite, a grid of more than 2^26 cells, bad options;
/// cancelled when `options.progress` says so. Deterministic for a given seed, whatever `exec` (the
/// translation candidates of each patch are scored through it). Time: about (area / patch area)
/// patches, each O(candidates * samples * log F) plus the merges.
template <Executor E = serial_executor>
result<mesh_quilt_result> mesh_quilt(const quilt_exemplar& exemplar, double width, double height,
                                     const mesh_quilt_options& options = {}, E&& exec = {}) {
  if (!(width > 0) || !(height > 0) || !std::isfinite(width) || !std::isfinite(height))
    return status::invalid_argument(detail::cat("mesh_quilt: size must be positive, got ", width, " x ", height));
  if (exemplar.num_elements() == 0) return status::invalid_argument("mesh_quilt: the exemplar is empty (not prepared)");
  if (auto s = detail::check_quilt_options(options); !s) return s;
  const double cells = (width / exemplar.cell_size()) * (height / exemplar.cell_size());
  if (cells > double(1 << 26))
    return status::size_overflow(detail::cat("mesh_quilt: ", width, " x ", height, " is ", cells, " grid cells of ",
                                             exemplar.cell_size(), "; at most 2^26"));
  detail::quilt_engine engine(
      exemplar, {0, 0, width, height}, detail::to_params(options, false, 0),
      [&exec](index_t n, const std::function<void(index_t)>& fn) { exec.parallel_for(0, n, fn); });
  if (auto s = engine.run(options.progress); !s) return s;
  if (auto s = engine.fill_holes(options.progress); !s) return s;
  return detail::finish_quilt(engine);
}

/// mesh_quilt for any Mesh exemplar (prepared with default quilt_exemplar_options). Also rejects
/// open or non-manifold exemplars (see prepare_quilt_exemplar).
template <Mesh M, Executor E = serial_executor>
result<mesh_quilt_result> mesh_quilt(const M& exemplar, double width, double height,
                                     const mesh_quilt_options& options = {}, E&& exec = {}) {
  auto ex = prepare_quilt_exemplar(exemplar);
  if (!ex) return ex.error();
  return mesh_quilt(*ex, width, height, options, exec);
}

TESSERA_NAMESPACE_END
