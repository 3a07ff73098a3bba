// tessera/geometry/mesh_quilt_types.hpp: the public types of mesh quilting that its options and
// results share with the internal engine (geometry/detail/quilt_engine.hpp, element_merge.hpp): the
// element-cut rules and the run counters. The algorithm itself is geometry/mesh_quilt.hpp.
#pragma once

#include "../core/config.hpp"

TESSERA_NAMESPACE_BEGIN

/// Which SOURCE/SINK rules cut the two elements (§3.3.6).
///  - `paper`: as the paper words them. C_T: SOURCE = faces outside P_T, border triangles, fixed
///    faces; SINK = faces around a vertex whose corresponding C_in face lies in the new region, is a
///    border triangle of C_in, or is on C_in's frontier. C_in "by the same method", roles swapped.
///  - `tessera` (default; docs/geometry.md says why, with measurements): C_T's vertices whose
///    corresponding C_in face is a border triangle are not sent to SINK (C_in's border triangles
///    cross the tile border and are always removed, so C_T must stay there); C_T's corresponded faces
///    in the new region go to SINK; C_in's border triangles are hard SINK, and the rest of C_in is
///    made consistent with C_T's cut (dropped where C_T is kept, kept where it was removed).
/// Both: nothing non-fixed of C_in may cross a constrained domain's sides, and C_in's faces over old
/// output outside P_T go.
enum class merge_rules { tessera, paper };

/// Counters of one quilting run (also summed over the tiles of a tile set).
struct mesh_quilt_stats {
  index_t patches = 0;           ///< seed cells processed
  index_t elements_added = 0;    ///< exemplar elements added whole (§3.3.6)
  index_t elements_merged = 0;   ///< exemplar elements merged with corresponding output elements
  index_t elements_dropped = 0;  ///< candidates rejected (intersection, border, failed merge)
  index_t merges_attempted = 0;  ///< pairwise merges tried (one exemplar element may merge several)
  /// Of those, merges that succeeded.
  index_t merges_succeeded = 0;
  index_t icp_iterations = 0;  ///< total ICP updates (eq. 5)
  index_t icp_discarded = 0;   ///< ICP results not used (no pairs, or a move of a cell or more)
  /// Why merges failed: too few correspondences, deformation solve, graph cut (nothing to cut or
  /// an infinite cut), cut paths that could not be paired, and the final check (self-intersection,
  /// leaving the tile, open or non-manifold edges).
  index_t merge_fail_correspondence = 0, merge_fail_deform = 0, merge_fail_cut = 0, merge_fail_loops = 0,
          merge_fail_check = 0;
  /// Of the merges that succeeded, those of two thread pieces joined across a plane
  /// (mesh_quilt_options::thread_joins).
  index_t merges_plane_cut = 0;
  /// Exemplar elements left out because a whole output element already stands where they
  /// correspond (merging two copies of one closed element only deforms it; see merge_whole).
  index_t elements_skipped = 0;
  /// Cells handed back to the seed search because the element whose centre lay there was dropped
  /// (a later patch retries them with another translation instead of leaving a hole).
  index_t cells_retried = 0;
  /// Constrained quilting: elements reaching a little across a tile side, moved back inside.
  index_t elements_nudged = 0;
  /// Exemplar elements placed one by one into the holes left after the patches (fill_holes).
  index_t elements_filled = 0;
  /// Elements moved a little apart to make room for a filled one (fill_relax).
  index_t elements_relaxed = 0;
  /// Small elements removed where one larger exemplar element took their place (fill_replace).
  index_t elements_replaced = 0;
  /// Adds every counter of `o`.
  mesh_quilt_stats& operator+=(const mesh_quilt_stats& o) {
    patches += o.patches;
    elements_added += o.elements_added;
    elements_merged += o.elements_merged;
    elements_dropped += o.elements_dropped;
    merges_attempted += o.merges_attempted;
    merges_succeeded += o.merges_succeeded;
    icp_iterations += o.icp_iterations;
    icp_discarded += o.icp_discarded;
    merge_fail_correspondence += o.merge_fail_correspondence;
    merge_fail_deform += o.merge_fail_deform;
    merge_fail_cut += o.merge_fail_cut;
    merge_fail_loops += o.merge_fail_loops;
    merge_fail_check += o.merge_fail_check;
    merges_plane_cut += o.merges_plane_cut;
    elements_skipped += o.elements_skipped;
    cells_retried += o.cells_retried;
    elements_nudged += o.elements_nudged;
    elements_filled += o.elements_filled;
    elements_relaxed += o.elements_relaxed;
    elements_replaced += o.elements_replaced;
    return *this;
  }
};

TESSERA_NAMESPACE_END
