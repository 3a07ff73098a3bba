// tessera/terrain/synthesize_triangles.hpp: triangle-based texture synthesis on the screen (paper
// 003, §2.3). Every visible triangle gets texture coordinates in the exemplar shrunk to its scale
// (its "level image", width * scale x height * scale pixels), as a translation of its screen
// position: uv = screen position + offset. Being a pure translation, the mapping is congruent (no
// stretching: one screen pixel is one level pixel), and scale changes the texture's size with
// distance instead.
//
//   order    a stack over face adjacency: a seeded random start is pushed; each popped triangle is
//            synthesized and pushes its unsynthesized visible neighbours (§2.3 step 1); when the
//            stack empties, the next unsynthesized visible triangle (in visible order after the
//            start) starts a new connected region
//   first    a triangle with no synthesized neighbour gets a random congruent placement: a random
//            offset that puts it inside its level image (step 2.1)
//   next     otherwise it takes a synthesized neighbour's offset: the identity map between levels
//            (adjacent triangles are at most one level apart) plus its own screen position (step
//            2.2). Of several neighbours, the OLDEST placement that keeps the triangle inside its
//            level image wins, so placements fill their level image as compact patches instead of
//            following the stack's snake (96-99 % continuous edges on the default scenes, against
//            85-90 % for continuation_rule::first_neighbor, the paper read literally)
//   wait     if no neighbour's offset fits, the triangle first waits (once, defer_restarts): it
//            goes on a list taken up, oldest first, when the stack empties, because a neighbour
//            synthesized meanwhile often brings coordinates that fit. Restarting at once left
//            single-face placements wherever the stack reached a face from the wrong side (most
//            placements of the grazing view were one face), about 1.5 % of all shared edges
//   restart  if still no neighbour's offset fits, a new random placement ("out of bounds: choose a
//            congruent triangle at random"); by default biased so the triangle sits at the side of
//            the level image facing its synthesized neighbours, leaving the rest of the image for the
//            unsynthesized side (placement_strategy::away_from_neighbors; the paper's uniform choice
//            is placement_strategy::uniform), and keeping the offset along an axis where the
//            oldest neighbouring placement still fits (keep_fitting_axis)
//   seams    sides where a synthesized neighbour has other coordinates are marked for colour
//            blending (step 3; render_terrain_frame feathers across them)
//
// Coordinates are measured from the CENTRE of the level image (uv in [-width * scale / 2,
// width * scale / 2] x [-height * scale / 2, height * scale / 2]; exemplar pixel = (width / 2, height
// / 2) + uv / scale). The identity map carries uv unchanged between levels, so content drifts by
// |uv| * |1/s_a - 1/s_b| where two levels meet; centring halves the largest |uv| and so that drift.
//
// The paper's guidance (§3 (1)): the exemplar should be 8 to 12 times the area of the largest
// screen triangle. The result carries a warning (not an error) below 8 times, and when a triangle
// does not fit its level image at all (it is then centred on the image and its texture clamps at
// the border; counted in `oversized`).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/progress.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "assign_scale_field.hpp"
#include "detail/stack_growth.hpp"
#include "detail/triangle_placement.hpp"
#include "prepare_terrain_mesh.hpp"
#include "project_mesh.hpp"

TESSERA_NAMESPACE_BEGIN

/// How a new placement's offset is drawn.
enum class placement_strategy {
  uniform,              ///< the paper: offset uniform over all placements inside the level image
  away_from_neighbors,  ///< random, biased to leave room on the side away from synthesized neighbours
};

/// Which synthesized neighbour's coordinates a face continues.
enum class continuation_rule {
  oldest_placement,  ///< of the synthesized neighbours whose coordinates fit, the oldest placement
  first_neighbor,    ///< the paper read literally: the first synthesized neighbour (in side order) that fits
};

/// Options of synthesize_triangles (§2.3).
struct triangle_synthesis_options {
  /// Seed of the placements.
  std::uint64_t seed = 1;
  /// How new placements are drawn.
  placement_strategy placement = placement_strategy::away_from_neighbors;
  /// Which neighbour a face continues.
  continuation_rule continuation = continuation_rule::oldest_placement;
  double margin = 1.0;  ///< pixels kept free at the level image border (the bilinear footprint), >= 0
  /// A face whose synthesized neighbours' coordinates all leave its level image waits (once) until
  /// the stack empties, in case a neighbour synthesized later brings coordinates that fit; only
  /// then is it given a new placement. False: the paper's immediate restart.
  bool defer_restarts = true;
  /// A new placement next to a synthesized placement that still fits the face along one axis keeps
  /// that axis's offset and draws only the other: the seam becomes a one-dimensional shift, which
  /// textures with a direction (grass blades) carry across almost unseen. False: both at random.
  bool keep_fitting_axis = true;
  /// Progress callback and cancellation token.
  tessera::progress progress = {};
};

/// Per-face results (indexed like the mesh; culled faces have region -1) and statistics.
struct triangle_synthesis {
  std::vector<vec2> offset;          ///< uv = screen position + offset (level-image pixels from its centre)
  std::vector<std::int32_t> region;  ///< placement id; equal ids share one offset
  std::vector<std::uint8_t> seam;    ///< bit k: side k borders a visible face with other coordinates
  std::vector<std::int32_t> order;   ///< visible faces in synthesis (stack) order
  /// Faces not culled.
  index_t visible = 0;
  index_t regions = 0;             ///< placements made (components + restarts)
  index_t components = 0;          ///< connected regions of visible faces (each starts with a placement)
  index_t restarts = 0;            ///< placements because no neighbour's coordinates fitted (out of bounds)
  index_t deferred = 0;            ///< faces that waited for more synthesized neighbours (defer_restarts)
  index_t oversized = 0;           ///< faces larger than their level image (texture clamps at its border)
  index_t shared_edges = 0;        ///< edges between two visible faces
  index_t continuous_edges = 0;    ///< of those, edges whose two faces have equal coordinates
  double continuous_fraction = 1;  ///< continuous_edges / shared_edges (1 when there are none)
  double min_area_ratio =
      std::numeric_limits<double>::infinity();  ///< min over faces of level-image area / screen area
  /// The face with min_area_ratio (-1 when none).
  index_t min_area_face = -1;
  index_t exemplar_width = 0, exemplar_height = 0;  ///< the exemplar size synthesized for (level 0 of the pyramid)
  status warning;  ///< ok, or out_of_range describing an exemplar too small for the triangles (§3 (1))
};

namespace detail {
/// Visible screen area of face f: the triangle's area, at most its bounds' area (partly visible).
inline double visible_screen_area(const terrain_mesh& mesh, const screen_projection& proj, std::int32_t f) {
  const auto& b = proj.bounds[to_size(f)];
  const double box = static_cast<double>(b[2] - b[0]) * static_cast<double>(b[3] - b[1]);
  if (proj.state[to_size(f)] != static_cast<std::uint8_t>(face_visibility::inside)) return box;
  const auto& face = mesh.faces[to_size(f)];
  for (const std::int32_t v : face)
    if (v < 0 || to_size(v) >= proj.screen.size()) return box;
  const vec2 a = proj.screen[to_size(face[0])], p = proj.screen[to_size(face[1])], q = proj.screen[to_size(face[2])];
  return std::min(box, 0.5 * std::abs(cross(p - a, q - a)));
}
/// Faces a synthesize_triangles block handles at once (the parallel reset and measure steps).
inline constexpr index_t synthesis_block = 16384;
/// The serial loop reports progress once every progress_interval + 1 faces (a power of two, less 1).
inline constexpr index_t progress_interval = 0xffff;
/// Paper 003 §3 (1): the exemplar should be 8 to 12 times the area of the largest screen triangle;
/// below the lower bound the result carries a warning.
inline constexpr double min_exemplar_area_ratio = 8;
/// Floor of a face's screen area in the area ratio (a degenerate face must not divide by zero).
inline constexpr double min_screen_area = 1e-300;

/// §2.3 step (3) of paper 003 and the figures of the result: each visible face's offset from its
/// placement, the sides where a synthesized neighbour has other coordinates (marked for the colour
/// blending of step 3), continuity counts and the exemplar-size check of §3 (1). Independent per
/// face, in chunks whose partial results combine in chunk order (so ties resolve to the smallest
/// face, for any executor).
template <Executor E>
void measure_synthesis(const terrain_mesh& mesh, const screen_projection& proj, const scale_field& field,
                       const std::vector<vec2>& placements, index_t exemplar_width, index_t exemplar_height,
                       triangle_synthesis& out, E&& exec) {
  struct partial {
    index_t shared = 0, same = 0;
    double ratio = std::numeric_limits<double>::infinity();
    std::int32_t face = -1;
  };
  const index_t nf = mesh.num_faces(), nvis = proj.num_visible();
  const double W = static_cast<double>(exemplar_width), H = static_cast<double>(exemplar_height);
  const index_t chunks = (nvis + synthesis_block - 1) / synthesis_block;
  std::vector<partial> part(to_size(chunks));
  exec.parallel_for(0, chunks, [&](index_t c) {
    partial& p = part[to_size(c)];
    for (index_t i = c * synthesis_block; i < std::min(nvis, (c + 1) * synthesis_block); ++i) {
      const std::int32_t f = proj.visible[to_size(i)];
      const vec2 own = placements[to_size(out.region[to_size(f)])];
      out.offset[to_size(f)] = own;
      const auto& nb = mesh.neighbors[to_size(f)];
      std::uint8_t bits = 0;
      for (int k = 0; k < 3; ++k) {
        const std::int32_t n = nb[to_size(k)];
        if (!is_face_index(n, nf) || out.region[to_size(n)] < 0) continue;
        const bool same = placements[to_size(out.region[to_size(n)])] == own;
        bits = static_cast<std::uint8_t>(bits | (same ? 0 : 1 << k));
        if (n > f) {
          p.shared += 1;
          p.same += same ? 1 : 0;
        }
      }
      out.seam[to_size(f)] = bits;
      const double s = field.scale[to_size(f)];
      const double ratio = W * H * s * s / std::max(visible_screen_area(mesh, proj, f), min_screen_area);
      if (ratio < p.ratio) {
        p.ratio = ratio;
        p.face = f;
      }
    }
  });
  for (const partial& p : part) {
    out.shared_edges += p.shared;
    out.continuous_edges += p.same;
    if (p.ratio < out.min_area_ratio) {
      out.min_area_ratio = p.ratio;
      out.min_area_face = p.face;
    }
  }
  out.continuous_fraction =
      out.shared_edges > 0 ? static_cast<double>(out.continuous_edges) / static_cast<double>(out.shared_edges) : 1.0;
  if (out.min_area_ratio < min_exemplar_area_ratio || out.oversized > 0)
    out.warning = status::out_of_range(detail::cat(
        "the exemplar (", exemplar_width, " x ", exemplar_height, ") is only ", out.min_area_ratio,
        " times the screen area of face ", out.min_area_face, " at its scale; paper 003 advises 8 to 12 times (",
        out.oversized,
        " faces do not fit their level image at all and clamp at its border): use a larger exemplar, a larger "
        "min_scale or a finer mesh"));
}
}  // namespace detail

/// Synthesizes texture coordinates for every visible face (paper 003, §2.3; see the file comment)
/// into `out`, reusing its storage. `exemplar_width` x `exemplar_height` is the exemplar's size
/// (level 0 of the pyramid). Errors: non-positive exemplar size, negative margin, a projection or
/// field that does not belong to `mesh`, cancelled. Nothing visible is not an error (all counts 0).
/// O(F) time, O(1) work per face; the stack order is inherently serial, the per-face statistics
/// afterwards run through `exec`. The output is a pure function of the inputs and opts.seed (random
/// choices are keyed by face index), the same for any executor.
template <Executor E = serial_executor>
status synthesize_triangles(const terrain_mesh& mesh, const screen_projection& proj, const scale_field& field,
                            index_t exemplar_width, index_t exemplar_height, const triangle_synthesis_options& opts,
                            triangle_synthesis& out, E&& exec = {}) {
  if (exemplar_width <= 0 || exemplar_height <= 0)
    return status::invalid_argument(
        detail::cat("exemplar size must be positive, got ", exemplar_width, " x ", exemplar_height));
  if (!(opts.margin >= 0) || !std::isfinite(opts.margin))
    return status::invalid_argument(detail::cat("margin must be >= 0, got ", opts.margin));
  if (auto s = validate_enum(opts.placement, {"uniform", "away_from_neighbors"}, "options.placement"); !s) return s;
  if (auto s = validate_enum(opts.continuation, {"oldest_placement", "first_neighbor"}, "options.continuation"); !s)
    return s;
  if (auto s = detail::check_projection(mesh, proj, "synthesize_triangles"); !s) return s;
  const index_t nf = mesh.num_faces();
  if (static_cast<index_t>(field.level.size()) != nf || static_cast<index_t>(field.scale.size()) != nf)
    return status::invalid_argument(detail::cat("synthesize_triangles: the scale field (", field.level.size(),
                                                " faces) must belong to the mesh (", nf, " faces)"));
  {
    triangle_synthesis fresh;  // statistics reset, storage reused
    fresh.offset = std::move(out.offset);
    fresh.region = std::move(out.region);
    fresh.seam = std::move(out.seam);
    fresh.order = std::move(out.order);
    out = std::move(fresh);
  }
  constexpr index_t block = detail::synthesis_block;
  out.offset.resize(detail::to_size(nf));
  out.region.resize(detail::to_size(nf));
  out.seam.resize(detail::to_size(nf));
  exec.parallel_for(0, (nf + block - 1) / block, [&](index_t c) {  // culled faces: offset 0, region -1, no seam
    const auto a = static_cast<std::ptrdiff_t>(c * block),
               b = static_cast<std::ptrdiff_t>(std::min(nf, (c + 1) * block));
    std::fill(out.offset.begin() + a, out.offset.begin() + b, vec2{});
    std::fill(out.region.begin() + a, out.region.begin() + b, -1);
    std::fill(out.seam.begin() + a, out.seam.begin() + b, std::uint8_t{0});
  });
  out.order.clear();
  out.exemplar_width = exemplar_width;
  out.exemplar_height = exemplar_height;
  const index_t nvis = proj.num_visible();
  out.visible = nvis;
  if (nvis == 0) return {};
  out.order.reserve(detail::to_size(nvis));
  const counter_rng rng(opts.seed, stream_id("terrain.synthesize_triangles"));
  const double W = static_cast<double>(exemplar_width), H = static_cast<double>(exemplar_height), m = opts.margin;
  // the offset of each placement: faces of one region share it, so the serial loop below reads and
  // writes 4-byte region ids (and this small table) instead of a 16-byte offset per face
  std::vector<vec2> placements;
  std::vector<std::int32_t> stack, deferred;
  stack.reserve(detail::to_size(std::min<index_t>(3 * nvis + 1, 1 << 20)));
  index_t done = 0;
  status stopped;  // why a face stopped the growth
  // §2.3 step (2) for the popped face f: continue a neighbour's placement, wait, or place anew
  auto synthesize_face = [&](std::int32_t f, bool forced) {
    const auto fi = detail::to_size(f);
    if (out.region[fi] >= 0) return true;
    const double s = field.scale[fi];
    if (!(s > 0 && s <= 1)) {  // e.g. 0 for a face the field's projection culled
      stopped = status::invalid_argument(detail::cat("synthesize_triangles: visible face ", f, " has scale ", s,
                                                     " and level ", field.level[fi],
                                                     " in the scale field: compute the field from this projection"));
      return false;
    }
    const auto& nb = mesh.neighbors[fi];
    const auto& b = proj.bounds[fi];
    const double hw = 0.5 * W * s - m, hh = 0.5 * H * s - m;  // half the level image, less the margin
    int synthesized = 0;
    const std::int32_t continued =
        detail::continue_neighbour_placement(nb, nf, out.region, placements, b, hw, hh,
                                             opts.continuation == continuation_rule::oldest_placement, synthesized);
    if (continued >= 0) {
      out.region[fi] = continued;  // step 2.2: the identity map between adjacent levels
    } else if (opts.defer_restarts && synthesized > 0 && !forced) {
      if (out.region[fi] == -1) {  // wait: region -2 marks a face on the deferred list (unsynthesized)
        out.region[fi] = -2;
        deferred.push_back(f);
        ++out.deferred;
      }
      return true;
    } else {
      // step 2.1, or "out of bounds: choose a congruent triangle at random": a new placement inside
      // the level image, biased away from the synthesized neighbours, keeping a fitting axis
      const vec2 toward = opts.placement == placement_strategy::uniform
                              ? vec2{0.5, 0.5}
                              : detail::placement_preference(nb, nf, out.region, proj.bounds, b, synthesized);
      vec2 kept{};
      const int keep =
          opts.keep_fitting_axis ? detail::fitting_axis(nb, nf, out.region, placements, b, hw, hh, kept) : -1;
      const bool uniform = opts.placement == placement_strategy::uniform;
      bool big = false;
      const vec2 o{
          keep == 0 ? kept.x : detail::place_axis(-hw - b[0], hw - b[2], rng.uniform(f, 1), toward.x, uniform, big),
          keep == 1 ? kept.y : detail::place_axis(-hh - b[1], hh - b[3], rng.uniform(f, 2), toward.y, uniform, big)};
      placements.push_back(o);
      out.region[fi] = static_cast<std::int32_t>(out.regions++);
      out.oversized += big ? 1 : 0;
      out.restarts += synthesized > 0 ? 1 : 0;
    }
    out.order.push_back(f);
    for (int k = 0; k < 3; ++k) {  // step 1: push the unsynthesized visible neighbours
      const std::int32_t n = nb[detail::to_size(k)];
      if (detail::is_face_index(n, nf) && proj.state[detail::to_size(n)] != 0 && out.region[detail::to_size(n)] < 0)
        stack.push_back(n);
    }
    if ((++done & detail::progress_interval) == 0 &&
        !opts.progress.report(static_cast<double>(done) / static_cast<double>(nvis), "synthesize triangles")) {
      stopped = status::cancelled();
      return false;
    }
    return true;
  };
  // §2.3 step (1): a seeded random start; each connected region of visible faces grows by the stack
  // from its first unsynthesized face in visible order after the start
  const auto start = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(nvis), 0));
  for (index_t idx = 0; idx < nvis; ++idx) {
    const index_t at = (start + idx) % nvis;
    const std::int32_t seed_face = proj.visible[detail::to_size(at)];
    if (!detail::is_visible_face(proj, seed_face))
      return detail::bad_visible_entry("synthesize_triangles", at, seed_face);
    if (out.region[detail::to_size(seed_face)] >= 0) continue;
    ++out.components;
    stack.push_back(seed_face);
    if (!detail::grow_by_stack(stack, deferred, synthesize_face)) return stopped;
  }
  if (static_cast<index_t>(out.order.size()) !=
      nvis)  // a face marked visible but missing from proj.visible was reached
    return status::invalid_argument(detail::cat("synthesize_triangles: the projection marks ", out.order.size(),
                                                " reachable faces visible but lists ", nvis,
                                                ": project this mesh first"));
  detail::measure_synthesis(mesh, proj, field, placements, exemplar_width, exemplar_height, out, exec);
  return opts.progress.report(1.0, "synthesize triangles") ? status{} : status::cancelled();
}

/// As above, returning a new triangle_synthesis.
template <Executor E = serial_executor>
result<triangle_synthesis> synthesize_triangles(const terrain_mesh& mesh, const screen_projection& proj,
                                                const scale_field& field, index_t exemplar_width,
                                                index_t exemplar_height, const triangle_synthesis_options& opts = {},
                                                E&& exec = {}) {
  triangle_synthesis out;
  if (auto s = synthesize_triangles(mesh, proj, field, exemplar_width, exemplar_height, opts, out, exec); !s) return s;
  return out;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_synthesize_triangles.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
