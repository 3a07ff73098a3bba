// tessera/surface/map_geometric_tiles.hpp: covers a closed base mesh with a geometric texture from one
// precomputed three-axis Wang tile set (paper 000 §4, Fig. 5-6): the base is parameterized over a
// polycube (build_polycube_map.hpp), the polycube's grid edges are coloured per axis and every quad gets
// the tile whose edge colours match (polycube_tiling.hpp), each tile is carried from tile-local (x, y, z)
// into its quad's (u, v, h) by its placement (quad_tile_placement::tile_to_quad), its height scaled to
// the shell height H, and the shell map places every vertex between the base and its offset by H
// (build_shell.hpp, map_tiles_to_shell.hpp), welding vertices on shared quad sides so that elements cut
// by tile borders, also around polycube edges, close again.
//
// Heights: the tile set's texture occupies z in [z0, z1] over its tiles (z0 = min(0, lowest z), z = 0
// being the tile's base plane, z1 its highest vertex). That range fills [0, H] of the shell: a vertex at
// tile height z is placed at h = (z - z0) · H / (z1 - z0). With options.height = 0, H keeps the tiles'
// proportions: H = (z1 - z0) · T / w_T (T the polycube's tile size in base-mesh units, w_T the set's).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <type_traits>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/mesh.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "../geometry/geometric_wang_tiles.hpp"
#include "build_polycube_map.hpp"
#include "build_shell.hpp"
#include "map_tiles_to_shell.hpp"
#include "polycube_map.hpp"
#include "polycube_projection.hpp"
#include "polycube_tiling.hpp"

TESSERA_NAMESPACE_BEGIN

/// Factor by which map_geometric_tiles lowers its default shell height when the shell folds there.
inline constexpr double auto_height_step = 0.8;
/// Most times map_geometric_tiles lowers its default shell height (0.8^6 = 0.26 of the tiles' own).
inline constexpr int auto_height_tries = 6;

/// Options of map_geometric_tiles.
struct map_geometric_tiles_options {
  /// Shell height H in base-mesh units, > 0; 0 (the default): keep the tiles' proportions (see the
  /// file comment), lowered in steps of auto_height_step (at most auto_height_tries times) where the
  /// shell folds beyond its repair at that height. The texture's height range always fills [0, H].
  double height = 0;
  /// Seed of the grid-edge colouring (color_polycube_edges); unused when a colouring is passed.
  std::uint64_t seed = 0;
  /// Append the base mesh (the polycube map's base, refined or not) after the elements.
  bool with_base = false;
  /// Fold repair of the shell (build_shell), and its sink: shell.sink > 0 sinks the texture that share
  /// of H into the base, so that its elements overlap the base's volume (for mesh_boolean, Fig. 7).
  shell_options shell = {};
  /// Splitting and welding of the mapping (map_tiles_to_shell); its with_base is ignored (see above).
  shell_map_options mapping = {};
  /// Progress (stages "polycube", "shell", "tiles", "mapping") and cancellation, reported from the
  /// calling thread between stages.
  tessera::progress progress = {};
};

/// Output of map_geometric_tiles.
struct map_geometric_tiles_result {
  /// The texture elements (vertices and faces first), then the base mesh when with_base.
  tri_mesh mesh;
  /// Vertices and faces of the elements (the leading part of `mesh`).
  index_t element_vertices = 0, element_faces = 0;
  /// The elements alone: a copy of the leading part of `mesh`. O(element vertices + faces).
  [[nodiscard]] tri_mesh elements() const { return detail::leading_part(mesh, element_vertices, element_faces); }
  /// H used, in base-mesh units.
  double height = 0;
  /// Times the default height (options.height 0) was lowered because the shell folded (0: the tiles'
  /// own proportions were kept).
  int height_lowered = 0;
  /// The polycube's tile size T in base-mesh units.
  double tile_size = 0;
  /// Which tile each quad carries (and how it is placed); tiling.tiles_used counts distinct tiles.
  polycube_tiling tiling;
  /// Quads that carried a non-empty tile.
  index_t quads = 0;
  /// Base vertices whose offset direction or height the shell's fold repair changed.
  index_t shell_repairs = 0;
  /// Tile vertices over all quads, how many were welded to a neighbouring quad's, tile faces dropped by
  /// the weld, edges split so that the elements follow the shell (map_tiles_to_shell).
  index_t tile_vertices = 0, welded_vertices = 0, dropped_faces = 0, split_edges = 0;
};

namespace detail {

/// The map's base must be `mesh` (same positions and faces) or its refinement (mesh's vertices first
/// in the same order, face_origin naming an input face for every base face).
inline status check_map_of_mesh(const tri_mesh& mesh, const polycube_map& map) {
  const auto nv = mesh.positions.size(), nf = mesh.faces.size();
  const char* what = "map_geometric_tiles: the polycube map belongs to another mesh";
  if (map.base.positions.size() < nv ||
      !std::equal(mesh.positions.begin(), mesh.positions.end(), map.base.positions.begin()))
    return status::invalid_argument(cat(what, " (its base has ", map.base.num_vertices(), " vertices, the mesh ", nv,
                                        ", or their positions differ)"));
  if (!map.refined()) {
    if (map.base.faces != mesh.faces)
      return status::invalid_argument(
          cat(what, " (", map.base.num_faces(), " faces against ", nf, ", or other vertices per face)"));
    return {};
  }
  if (map.face_origin.size() != map.base.faces.size() || map.base.faces.size() < nf)
    return status::invalid_argument(cat(what, " (an inconsistent refinement)"));
  for (const index_t o : map.face_origin)
    if (o < 0 || to_size(o) >= nf)
      return status::invalid_argument(cat(what, " (its refinement names input face ", o, ", the mesh has ", nf, ")"));
  return {};
}

/// Six times the signed volume a closed, consistently oriented mesh encloses (< 0: inside out).
inline double enclosed_volume6(const tri_mesh& m) {
  double v = 0;
  for (const auto& f : m.faces) v += dot(m.position(f[0]), cross(m.position(f[1]), m.position(f[2])));
  return v;
}

/// The lowest base-plane height z0 = min(0, lowest z) and the highest z1 over every tile of `set`.
inline std::pair<double, double> tile_set_height_range(const geometric_tile_set& set) {
  double z0 = 0, z1 = -1e300;
  for (const auto& t : set.tiles)
    for (const vec3& p : t.positions) {
      z0 = std::min(z0, p.z);
      z1 = std::max(z1, p.z);
    }
  return {z0, z1};
}

}  // namespace detail

/// Covers `mesh` with the geometric texture of the three-axis tile set `set` over the polycube map
/// `map` of that mesh (paper 000 §4): colours the grid edges by `coloring` (any TileColoring over the
/// quads, polycube_coloring.hpp conventions: side 0 north = quad side 2, ...), assigns each quad its
/// matching tile (assign_polycube_tiles), transforms each tile into its quad's (u, v, h) through its
/// placement with heights scaled to H (file comment), builds the shell of map.base at H and maps every
/// tile through it (map_tiles_to_shell). Output elements from a closed-element set are closed, also
/// across quad borders and polycube edges; every output vertex lies within H of the base; the result
/// is the same for every executor and thread count.
///
/// Errors: `mesh` refused by validate_polycube_input (open, non-manifold, degenerate) or inside out
/// (negative enclosed volume); `map` built over another mesh; options.height negative or not finite;
/// a set without height (all tiles flat) or without vertices; the errors of assign_polycube_tiles (a
/// planar set, an incomplete one, colours that do not fit its axes), build_shell (H too large for the
/// shell; with the default height, after lowering it auto_height_tries times), map_tiles_to_shell (tile vertices outside their square); cancelled by the progress.
/// O(tile vertices · log F + F · repair rounds).
template <Mesh M, TileColoring C, Executor E = serial_executor>
result<map_geometric_tiles_result> map_geometric_tiles(const M& mesh, const polycube_map& map,
                                                       const geometric_tile_set& set, const C& coloring,
                                                       const map_geometric_tiles_options& o = {}, E&& exec = {}) {
  if (auto s = validate_polycube_input(mesh, "base mesh"); !s) return s;
  auto base = to_tri_mesh(mesh, "base mesh");
  if (!base) return base.error();
  if (!(detail::enclosed_volume6(*base) > 0))
    return status::invalid_argument(
        "map_geometric_tiles: the base mesh is inside out (its faces enclose a negative volume): flip its faces so "
        "that they are counter-clockwise seen from outside");
  if (auto s = detail::check_map_of_mesh(*base, map); !s) return s;
  if (!(o.height >= 0) || !std::isfinite(o.height))
    return status::invalid_argument(
        detail::cat("map_geometric_tiles: height must be > 0 (or 0 for the tiles' own proportions), got ", o.height));
  const auto z_range = detail::tile_set_height_range(set);  // not a structured binding: a lambda below uses both
  const double z0 = z_range.first, z1 = z_range.second;
  if (!(z1 > z0) || !(set.tile_size > 0) || !std::isfinite(set.tile_size))
    return status::invalid_argument(
        "map_geometric_tiles: the tile set has no height (no vertex above its base plane) or no tile size");
  if (!o.progress.report(0, "tiles")) return status::cancelled();
  auto tiling = assign_polycube_tiles(map, set, coloring);
  if (!tiling) return tiling.error();
  const double T = map.tile_size;
  const double requested = o.height > 0 ? o.height : (z1 - z0) / set.tile_size * T;
  double H = requested;
  if (!o.progress.report(0, "shell")) return status::cancelled();
  auto sh = build_shell(map.base, H, o.shell, exec);
  // the tiles' own proportions are a default, not a request: where the shell folds beyond repair
  // (a sharp concave edge closer than H), a lower shell is tried; a height the caller asked for is not
  int lowered = 0;
  for (; !sh && o.height == 0 && sh.error().code() == status_code::invalid_argument && lowered < auto_height_tries;
       ++lowered) {
    if (!o.progress.report(0, "shell")) return status::cancelled();
    H *= auto_height_step;
    sh = build_shell(map.base, H, o.shell, exec);
  }
  if (!sh)
    return lowered > 0 ? status(sh.error().code(), detail::cat(sh.error().message(), " (the tiles' own height ",
                                                               requested, " lowered ", lowered, " times)"))
                       : sh.error();
  if (!o.progress.report(0, "mapping")) return status::cancelled();
  // each (tile, placement) transformed once: quad-local (u, v) from the placement, h in mesh units
  const auto& Q = tiling->quads;
  std::map<std::pair<index_t, std::array<std::array<double, 4>, 3>>, std::size_t> distinct;
  std::vector<std::size_t> quad_mesh(Q.size());
  std::vector<std::size_t> first_quad;
  for (std::size_t q = 0; q < Q.size(); ++q) {
    auto [it, fresh] = distinct.emplace(std::pair{Q[q].tile, Q[q].tile_to_quad}, first_quad.size());
    if (fresh) first_quad.push_back(q);
    quad_mesh[q] = it->second;
  }
  std::vector<tri_mesh> placed(first_quad.size());
  exec.parallel_for(0, static_cast<index_t>(first_quad.size()), [&](index_t i) {
    const quad_tile_placement& p = Q[first_quad[detail::to_size(i)]];
    tri_mesh& m = placed[detail::to_size(i)];
    m = set.tiles[detail::to_size(p.tile)];
    // the placement's h of the texture's lowest level, and mesh units per quad-local h unit
    const double h0 = p.to_quad({0, 0, z0}).z, scale = H / (p.to_quad({0, 0, z1}).z - h0);
    for (vec3& x : m.positions) {
      const vec3 uvh = p.to_quad(x);
      x = {uvh.x, uvh.y, std::clamp((uvh.z - h0) * scale, 0.0, H)};
    }
  });
  const polycube_projector pj(map);
  shell_map_options mo = o.mapping;
  mo.with_base = o.with_base;
  auto mapped = map_tiles_to_shell(
      map, pj, *sh,
      [&](index_t q) {
        const tri_mesh& m = placed[quad_mesh[detail::to_size(q)]];
        return m.faces.empty() ? nullptr : &m;
      },
      mo, exec);
  if (!mapped) return mapped.error();
  o.progress.report(1, "mapping");
  map_geometric_tiles_result r;
  r.mesh = std::move(mapped->mesh);
  r.element_vertices = mapped->element_vertices;
  r.element_faces = mapped->element_faces;
  r.height = H;
  r.height_lowered = lowered;
  r.tile_size = T;
  r.tiling = std::move(*tiling);
  r.quads = mapped->quads;
  r.shell_repairs = sh->repaired_vertices;
  r.tile_vertices = mapped->tile_vertices;
  r.welded_vertices = mapped->welded_vertices;
  r.dropped_faces = mapped->dropped_faces;
  r.split_edges = mapped->split_edges;
  return r;
}

/// As above, the grid edges coloured by color_polycube_edges(map, set.axis_colors, options.seed):
/// the result is a pure function of (mesh, map, set, options).
template <Mesh M, Executor E = serial_executor>
result<map_geometric_tiles_result> map_geometric_tiles(const M& mesh, const polycube_map& map,
                                                       const geometric_tile_set& set,
                                                       const map_geometric_tiles_options& o = {}, E&& exec = {}) {
  if (!set.three_axis())
    return status::invalid_argument(
        "map_geometric_tiles: the tile set is planar; a surface needs a three-axis set (geo-wang build --colors "
        "NX,NY,NZ, geometric_wang_options::axis_colors)");
  auto coloring = color_polycube_edges(map, set.axis_colors, o.seed, exec);
  if (!coloring) return coloring.error();
  return map_geometric_tiles(mesh, map, set, *coloring, o, exec);
}

/// As above, the polycube map built first by build_polycube_map(mesh, polycube, exec) (its tile size
/// polycube.tile_size, or polycube.tiles_across). Errors: those of build_polycube_map, then as above.
template <Mesh M, Executor E = serial_executor>
result<map_geometric_tiles_result> map_geometric_tiles(const M& mesh, const polycube_options& polycube,
                                                       const geometric_tile_set& set,
                                                       const map_geometric_tiles_options& o = {}, E&& exec = {}) {
  if (!o.progress.report(0, "polycube")) return status::cancelled();
  auto map = build_polycube_map(mesh, polycube, exec);
  if (!map) return map.error();
  return map_geometric_tiles(mesh, *map, set, o, exec);
}

TESSERA_NAMESPACE_END
