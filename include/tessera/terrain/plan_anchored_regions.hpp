// tessera/terrain/plan_anchored_regions.hpp: the world-anchored regions of ground-anchored terrain
// synthesis (an extension of paper 003; see docs/terrain.md, "Ground-anchored mode").
//
// The paper grows its placements over the faces in screen (stack) order from a random start among
// the visible faces, so every placement depends on the view. The anchored mode makes the growth a
// pure function of the mesh: the mesh is cut into square cells of a fixed world grid (in the plane
// of its two longest bounding-box axes, x and y for a z-up terrain); the faces whose centroids lie
// in one cell form a REGION, grown on its own (synthesize_anchored_region.hpp) from its SEED face,
// the face whose centroid is nearest the cell centre (ties: smallest face id). Which faces are
// visible only decides which regions get grown, never how.
//
// The cell side is `region_size` times the exemplar's world width (exemplar pixels divided by
// `texels_per_unit`), so a region's unfolded faces usually fit one exemplar and a region needs few
// restarts; the texture density `texels_per_unit` defaults to an exemplar width per
// `auto_edges_per_exemplar` mean edge lengths.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "prepare_terrain_mesh.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of ground-anchored synthesis (regions and growth).
struct anchored_synthesis_options {
  /// Seed of the placements.
  std::uint64_t seed = 1;
  /// Exemplar pixels per world unit at level 0 (scale 1); 0: automatic (see the file comment).
  double texels_per_unit = 0;
  /// Region cell side as a fraction of the exemplar's world width, in [0.05, 4].
  double region_size = 0.8;
  /// Exemplar pixels kept free at the exemplar border (the bilinear footprint of the coarsest level), >= 0.
  double margin = 2.0;
  /// A face whose neighbours' unfolded coordinates all leave the exemplar waits once for more
  /// placed neighbours before it starts a new placement (as synthesize_triangles' defer_restarts).
  bool defer_restarts = true;
  /// A new placement keeps the unfolded coordinate along an axis that still fits (a one-dimensional seam).
  bool keep_fitting_axis = true;
  /// A face joins a neighbour's placement only if its texture there is stretched by at most this
  /// (texture_stretch.hpp: 1 is congruent), in [1, 2]; with the relaxation on (the default) the
  /// growth joins up to relax_join_stretch instead and this bounds every face at the end, with
  /// relaxed_max_stretch. Faces are unfolded congruently across their
  /// neighbours; only a face closing a loop whose corners a placement already holds can be stretched.
  /// The default is the smallest bound that keeps, without the relaxation, 95 % of the shared edges continuous on the
  /// default relief, the 10^6-face grid and the real DEM of docs/terrain.md (a smaller one gives
  /// less stretch and more seams: 1.05 gives 78 to 91 % continuous edges; table there).
  double max_stretch = 1.55;
  /// Grow each region breadth first (a queue) instead of by the paper's stack: the unfolding then
  /// closes each loop of faces next to where it opened, where its mismatch is small (more faces
  /// stay in their placement: 85 instead of 78 % continuous edges on the real DEM of docs/terrain.md
  /// with max_stretch 1.05).
  bool breadth_first = true;
  /// Rounds of as-rigid-as-possible relaxation per pass, after a region has grown, round the
  /// faces it left stretched by more than relax_above (detail/relax_anchored_region.hpp: every
  /// placement's coordinate of a vertex moves alike, so no edge's continuity changes), then the
  /// settling of relaxed_max_stretch; 0 to 64, 0: neither (the growth alone, within max_stretch).
  /// The defaults (3 rounds, 1 ring, 3 passes, 1.2, joining up to 2, settling beyond 1.3) were
  /// measured in docs/terrain.md, "Slope stretch".
  int relax_iterations = 3;
  /// Faces stretched by more than this are relaxed, in [1, 2].
  double relax_above = 1.2;
  /// The vertices within this many side-steps of such a face move, 1 to 16.
  int relax_rings = 1;
  /// Passes round the faces still stretched beyond relax_above, each with wider rings, 1 to 8.
  int relax_passes = 3;
  /// With the relaxation (relax_iterations > 0), the growth joins a face to a placement up to this
  /// stretch (if more than max_stretch), in [1, 2]: more loops close (more continuous edges), the
  /// relaxation spreads their mismatch and the settling cuts what is left beyond the final bound.
  double relax_join_stretch = 2;
  /// After the relaxation, a face still stretched by more than min(max_stretch, this) becomes a
  /// placement of its own (a congruent copy; seams round it), in [1, 2]: no face ends beyond it.
  double relaxed_max_stretch = 1.3;
};

/// Mean edge lengths covered by one exemplar width when texels_per_unit is automatic.
inline constexpr double auto_edges_per_exemplar = 48;

/// The regions of a mesh (plain data, a pure function of the mesh, the exemplar size and the options).
struct anchored_regions {
  double texels_per_unit = 0;  ///< resolved density (exemplar pixels per world unit)
  double cell = 0;             ///< cell side in world units
  int axis_a = 0, axis_b = 1;  ///< the two world axes spanning the cells
  /// World coordinates of the cell grid's corner along axis_a and axis_b.
  double origin_a = 0, origin_b = 0;
  /// Cells along axis_a and axis_b.
  index_t cells_a = 0, cells_b = 0;
  std::vector<std::int32_t> region;  ///< per face: its region (cell id, cells_a * b + a)
  std::vector<std::int32_t> first;   ///< per region r: its faces are faces[first[r] .. first[r + 1]), ascending
  std::vector<std::int32_t> faces;   ///< faces grouped by region
  std::vector<std::int32_t> seed;    ///< per region: the face nearest the cell centre (-1: empty region)
  double max_neighbor_distance = 0;  ///< largest distance between the centroids of adjacent faces
  /// Number of regions (cells_a * cells_b).
  [[nodiscard]] index_t num_regions() const noexcept { return static_cast<index_t>(seed.size()); }
  /// Bytes held.
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    return 4 * (region.size() + first.size() + faces.size() + seed.size());
  }
};

namespace detail {
inline double axis_value(const vec3& p, int a) noexcept { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
}  // namespace detail

/// Plans the world-anchored regions of `mesh` for an exemplar of `exemplar_width` x
/// `exemplar_height` pixels (see the file comment). Errors (invalid_argument naming the value):
/// non-positive exemplar size, texels_per_unit negative or not finite, region_size outside
/// [0.05, 4], negative margin, max_stretch outside [1, 2], a mesh failing validate_terrain_mesh. An empty mesh gives no
/// regions. O(F) time and memory; serial, deterministic.
inline result<anchored_regions> plan_anchored_regions(const terrain_mesh& mesh, index_t exemplar_width,
                                                      index_t exemplar_height, const anchored_synthesis_options& opts) {
  if (exemplar_width <= 0 || exemplar_height <= 0)
    return status::invalid_argument(
        detail::cat("exemplar size must be positive, got ", exemplar_width, " x ", exemplar_height));
  if (!(opts.texels_per_unit >= 0) || !std::isfinite(opts.texels_per_unit))
    return status::invalid_argument(
        detail::cat("texels_per_unit must be >= 0 (0: automatic), got ", opts.texels_per_unit));
  if (!(opts.region_size >= 0.05 && opts.region_size <= 4))
    return status::invalid_argument(detail::cat("region_size must be in [0.05, 4], got ", opts.region_size));
  if (!(opts.margin >= 0) || !std::isfinite(opts.margin))
    return status::invalid_argument(detail::cat("margin must be >= 0, got ", opts.margin));
  if (!(opts.max_stretch >= 1 && opts.max_stretch <= 2))
    return status::invalid_argument(detail::cat("max_stretch must be in [1, 2], got ", opts.max_stretch));
  if (!(opts.relax_iterations >= 0 && opts.relax_iterations <= 64))
    return status::invalid_argument(
        detail::cat("relax_iterations must be 0 (no relaxation) to 64, got ", opts.relax_iterations));
  if (!(opts.relax_above >= 1 && opts.relax_above <= 2))
    return status::invalid_argument(detail::cat("relax_above must be in [1, 2], got ", opts.relax_above));
  if (!(opts.relax_passes >= 1 && opts.relax_passes <= 8))
    return status::invalid_argument(detail::cat("relax_passes must be 1 to 8, got ", opts.relax_passes));
  if (!(opts.relax_join_stretch >= 1 && opts.relax_join_stretch <= 2))
    return status::invalid_argument(detail::cat("relax_join_stretch must be in [1, 2], got ", opts.relax_join_stretch));
  if (!(opts.relaxed_max_stretch >= 1 && opts.relaxed_max_stretch <= 2))
    return status::invalid_argument(
        detail::cat("relaxed_max_stretch must be in [1, 2], got ", opts.relaxed_max_stretch));
  if (!(opts.relax_rings >= 1 && opts.relax_rings <= 16))
    return status::invalid_argument(detail::cat("relax_rings must be 1 to 16, got ", opts.relax_rings));
  if (auto s = validate_terrain_mesh(mesh); !s) return s;
  anchored_regions p;
  const index_t nf = mesh.num_faces();
  if (nf == 0) {
    p.first.assign(1, 0);
    p.texels_per_unit = opts.texels_per_unit > 0 ? opts.texels_per_unit : 1;
    return p;
  }
  vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  vec3 hi = -lo;
  double edges = 0, maxd = 0;
  for (index_t f = 0; f < nf; ++f) {
    const auto& fv = mesh.faces[detail::to_size(f)];
    for (int k = 0; k < 3; ++k) {
      const vec3& q = mesh.position(fv[detail::to_size(k)]);
      lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
      hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
      edges += norm(mesh.position(fv[detail::to_size((k + 1) % 3)]) - q);
    }
    for (const std::int32_t n : mesh.neighbors[detail::to_size(f)])
      if (n > f) maxd = std::max(maxd, norm(mesh.centroids[detail::to_size(n)] - mesh.centroids[detail::to_size(f)]));
  }
  p.max_neighbor_distance = maxd;
  const double mean_edge = edges / (3.0 * static_cast<double>(nf));
  const double W = static_cast<double>(std::min(exemplar_width, exemplar_height));
  p.texels_per_unit = opts.texels_per_unit > 0 ? opts.texels_per_unit
                                               : (mean_edge > 0 ? W / (auto_edges_per_exemplar * mean_edge) : 1.0);
  // the two longest axes, ties to the smaller axis
  const vec3 e = hi - lo;
  std::array<int, 3> ax = {0, 1, 2};
  std::stable_sort(ax.begin(), ax.end(),
                   [&](int a, int b) { return detail::axis_value(e, a) > detail::axis_value(e, b); });
  p.axis_a = std::min(ax[0], ax[1]);
  p.axis_b = std::max(ax[0], ax[1]);
  p.origin_a = detail::axis_value(lo, p.axis_a);
  p.origin_b = detail::axis_value(lo, p.axis_b);
  const double ea = detail::axis_value(e, p.axis_a), eb = detail::axis_value(e, p.axis_b);
  double cell = opts.region_size * W / p.texels_per_unit;
  // at most about one cell per face (and 2^24 cells): wider cells for tiny textures on huge meshes
  const double max_cells = std::min(static_cast<double>(nf), 16777216.0);
  while ((std::floor(ea / cell) + 1) * (std::floor(eb / cell) + 1) > max_cells) cell *= 2;
  p.cell = cell;
  p.cells_a = static_cast<index_t>(std::floor(ea / cell)) + 1;
  p.cells_b = static_cast<index_t>(std::floor(eb / cell)) + 1;
  const auto nr = detail::to_size(p.cells_a * p.cells_b);
  p.region.resize(detail::to_size(nf));
  p.first.assign(nr + 1, 0);
  p.seed.assign(nr, -1);
  std::vector<double> best(nr, std::numeric_limits<double>::infinity());
  for (index_t f = 0; f < nf; ++f) {
    const vec3& c = mesh.centroids[detail::to_size(f)];
    const double a = (detail::axis_value(c, p.axis_a) - p.origin_a) / cell,
                 b = (detail::axis_value(c, p.axis_b) - p.origin_b) / cell;
    const index_t ia = std::clamp<index_t>(static_cast<index_t>(std::floor(a)), 0, p.cells_a - 1),
                  ib = std::clamp<index_t>(static_cast<index_t>(std::floor(b)), 0, p.cells_b - 1);
    const auto r = detail::to_size(ib * p.cells_a + ia);
    p.region[detail::to_size(f)] = static_cast<std::int32_t>(r);
    ++p.first[r + 1];
    const double da = a - (static_cast<double>(ia) + 0.5), db = b - (static_cast<double>(ib) + 0.5);
    const double d = da * da + db * db;
    if (d < best[r]) {
      best[r] = d;
      p.seed[r] = static_cast<std::int32_t>(f);
    }
  }
  for (std::size_t r = 0; r < nr; ++r) p.first[r + 1] += p.first[r];
  p.faces.resize(detail::to_size(nf));
  std::vector<std::int32_t> fill(p.first.begin(), p.first.end() - 1);
  for (index_t f = 0; f < nf; ++f)
    p.faces[detail::to_size(fill[detail::to_size(p.region[detail::to_size(f)])]++)] = static_cast<std::int32_t>(f);
  return p;
}

TESSERA_NAMESPACE_END
