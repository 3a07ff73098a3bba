// Example 53: do quilts and tiled planes of geometric Wang tiles look like their exemplar? For each
// exemplar kind, a 24 x 24 quilt and a 6 x 6 plane of a 16-tile set are measured against the exemplar
// (geometry/texture_quality.hpp) and rendered; one markdown row per output goes to stdout (the
// quality table of docs/geometry.md).
//   example_53_geometric_quality [OUT_DIR] [KIND|all] [before|nofill|nothreads|norelax|noreplace]   KIND: rings (default), chain_mail,
//                                                                 beads, stones, pebbles, weave
// `before` runs the earlier rules (every corresponding pair merged, no cell retried, nothing moved
// back inside a tile, eq. 4 alone, free strip elements only wholly inside the strip), for the before/after table and its same-run speed ratio.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/texture_quality.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/tiling/hash_coloring.hpp>

namespace {
using namespace tessera;

// a regular square lattice of flattened beads (icospheres), 1.6 apart: a lattice of another shape
tri_mesh bead_lattice(double size) {
  tri_mesh m;
  const tri_mesh ball = detail::icosphere(2);
  for (double y = 0.8; y < size; y += 1.6)
    for (double x = 0.8; x < size; x += 1.6) {
      tri_mesh b = ball;
      for (auto& p : b.positions) p = vec3{x + 0.55 * p.x, y + 0.4 * p.y, 0.25 + 0.22 * p.z};
      m.append(b);
    }
  return m;
}

result<tri_mesh> make_kind(const std::string& kind) {
  if (kind == "chain_mail") return make_ring_exemplar({.size = 8, .minor_radius = 0.08, .chain_mail = true});
  if (kind == "beads") return bead_lattice(9.6);
  if (kind == "stones") return make_stone_exemplar({.seed = 7});
  if (kind == "pebbles") return make_stone_exemplar({.min_radius = 0.2, .max_radius = 0.8, .coverage = 0.5, .seed = 3});
  if (kind == "weave") return make_weave_exemplar();
  return make_ring_exemplar({.size = 9.6});
}

void row(const char* what, const std::string& kind, const texture_quality_comparison& c, bool tiled,
         const geometric_texture_report& v, double ms) {
  auto pct = [](double x) { return 100.0 * x; };
  std::printf(
      "| %s | %s | %.2f | %.2f | %.1f (%.1f) | %s | %.1f (%.1f) | %.1f (%.1f) | %lld/%lld/%lld | %.0f |\n",
      kind.c_str(), what, c.density_ratio, c.coverage_ratio, pct(c.output.partial_rate), pct(c.exemplar.partial_rate),
      tiled ? (std::to_string(c.band_ratio).substr(0, 4) + " / " + std::to_string(c.corner_ratio).substr(0, 4)).c_str()
            : "-",
      pct(c.output.empty_cell_rate), pct(c.exemplar.empty_cell_rate), pct(c.output.nn_outside),
      pct(c.exemplar.nn_outside), static_cast<long long>(v.open_edges_inside),
      static_cast<long long>(v.nonmanifold_edges), static_cast<long long>(v.intersecting_pairs), ms);
}

int run_kind(const std::string& dir, const std::string& kind, bool before, bool no_fill, bool no_threads, bool no_relax,
             bool no_replace, thread_pool_executor& pool) {
  const auto exemplar = make_kind(kind);
  if (!exemplar) return std::fprintf(stderr, "%s\n", exemplar.error().to_string().c_str()), 1;
  const auto prepared = prepare_quilt_exemplar(*exemplar);
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().to_string().c_str()), 1;
  mesh_preview_options view{.width = 480, .height = 480, .azimuth_degrees = 0, .elevation_degrees = 90};
  if (auto s = write_mesh_preview(dir + "/quality_" + kind + "_exemplar.png", *exemplar, view, pool); !s) return 1;

  // a quilt of 24 x 24
  const double size = 24;
  const auto t0 = std::chrono::steady_clock::now();
  mesh_quilt_options qo{.seed = 7};
  if (before) qo.merge_whole = true, qo.cell_retries = 0, qo.nudge_inside = false;
  if (before || no_fill) qo.fill_holes = false;
  if (no_relax) qo.fill_relax = false;
  if (no_relax || no_replace) qo.fill_replace = false;
  if (before || no_threads) qo.thread_joins = false;
  const auto q = mesh_quilt(*prepared, size, size, qo, pool);
  const double quilt_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!q) return std::fprintf(stderr, "%s\n", q.error().to_string().c_str()), 1;
  const auto qc = compare_texture_quality(*exemplar, q->mesh, {0, 0, size, size});
  const auto qv = check_geometric_texture(q->mesh);
  if (!qc || !qv) return std::fprintf(stderr, "quilt: measuring failed\n"), 1;
  row("quilt 24 x 24", kind, *qc, false, *qv, quilt_ms);
  if (auto s = write_mesh_preview(dir + "/quality_" + kind +
                                      (before       ? "_before"
                                       : no_fill    ? "_nofill"
                                       : no_threads ? "_nothreads"
                                       : no_relax   ? "_norelax"
                                       : no_replace ? "_noreplace"
                                                    : "") +
                                      "_quilt.png",
                                  q->mesh, view, pool);
      !s)
    return 1;

  // a 16-tile set and a 6 x 6 plane of it
  geometric_wang_options o;
  o.tile_size = kind == "weave" ? 6.0 : (kind == "chain_mail" ? 6.5 : 6.4);
  o.quilt = qo;
  o.quilt.seed = 3;
  o.deep_free_elements = !before;
  const auto t1 = std::chrono::steady_clock::now();
  const auto set = build_geometric_wang_tiles(*prepared, o, pool);
  const double set_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
  if (!set) {  // chain mail: every edge line crosses linked rings near the corners
    std::printf("| %s | tiles | no tile set: %s |\n", kind.c_str(), set.error().message().c_str());
    return 0;
  }
  const auto hash = hash_coloring::create(set->horizontal_colors, set->vertical_colors, 5);
  if (!hash) return 1;
  const auto coloring = hash->window(0, 0, 6, 6);
  if (!coloring) return 1;
  const auto plane = tile_geometric_plane(*set, *coloring, 6, 6, pool);
  if (!plane) return std::fprintf(stderr, "%s\n", plane.error().to_string().c_str()), 1;
  const double w = set->tile_size;
  const auto pc = compare_texture_quality(*exemplar, *plane, {0, 0, 6 * w, 6 * w}, {.tile_size = w});
  const auto pv = check_geometric_texture(*plane, {0, 0, 6 * w, 6 * w});
  if (!pc || !pv) return std::fprintf(stderr, "plane: measuring failed\n"), 1;
  row("tiles 6 x 6", kind, *pc, true, *pv, set_ms);
  view.grid_spacing = w;
  if (auto s = write_mesh_preview(dir + "/quality_" + kind +
                                      (before       ? "_before"
                                       : no_fill    ? "_nofill"
                                       : no_threads ? "_nothreads"
                                       : no_relax   ? "_norelax"
                                       : no_replace ? "_noreplace"
                                                    : "") +
                                      "_plane.png",
                                  *plane, view, pool);
      !s)
    return 1;
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  const std::string which = argc > 2 ? argv[2] : "rings";
  // "before": the rules of the first quality table; "nofill": today's rules without hole filling
  const bool before = argc > 3 && std::string(argv[3]) == "before";
  const bool no_fill = argc > 3 && std::string(argv[3]) == "nofill";
  // "nothreads": today's rules without the thread joins (mesh_quilt_options::thread_joins)
  const bool no_threads = argc > 3 && std::string(argv[3]) == "nothreads";
  // "norelax": hole filling without the relaxation and size classes (mesh_quilt_options::fill_relax)
  const bool no_relax = argc > 3 && std::string(argv[3]) == "norelax";
  // "noreplace": hole filling that only adds (mesh_quilt_options::fill_replace off)
  const bool no_replace = argc > 3 && std::string(argv[3]) == "noreplace";
  std::vector<std::string> kinds{which};
  if (which == "all") kinds = {"rings", "chain_mail", "beads", "stones", "pebbles", "weave"};
  tessera::thread_pool_executor pool;
  std::printf(
      "| exemplar | output | density | covered area | partial %% (exemplar) | band / corner | empty cells %% "
      "(exemplar) | spacing outside spread %% (exemplar) | open/non-manifold/intersecting | ms |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& k : kinds)
    if (run_kind(dir, k, before, no_fill, no_threads, no_relax, no_replace, pool) != 0) return 1;
  return 0;
}
