// Benchmarks of the geometry family (paper 000): building blocks (BVH closest point and ray casts,
// element extraction, max-flow, Laplacian, ICP), mesh quilting per output area, geometric Wang tile
// sets per tile and per set, tiling 64 x 64 tiles. Same-run baselines: brute-force closest point and
// ray casts, a copy of the exemplar, a memcpy of the tiled plane's bytes (warm and into fresh
// memory), Edmonds-Karp.
#include <benchmark/benchmark.h>

#include <cstring>
#include <deque>
#include <map>
#include <memory>
#include <vector>

#include <tessera/geometry/bvh.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/icp.hpp>
#include <tessera/geometry/laplacian.hpp>
#include <tessera/geometry/max_flow.hpp>
#include <tessera/geometry/mesh_elements.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/tiling/hash_coloring.hpp>

using namespace tessera;

namespace {
const tri_mesh& rings() {
  static const tri_mesh m = *make_ring_exemplar();  // 4800 vertices, 9600 faces
  return m;
}
const quilt_exemplar& prepared_rings() {
  static const quilt_exemplar q = *prepare_quilt_exemplar(rings());
  return q;
}
std::vector<vec3> queries(int n) {
  counter_rng rng(3);
  std::vector<vec3> q;
  for (int i = 0; i < n; ++i) q.push_back({rng.uniform(i, 0) * 8, rng.uniform(i, 1) * 8, rng.uniform(i, 2) * 0.6});
  return q;
}
}  // namespace

static void BM_bvh_build(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(triangle_bvh(rings()));
  state.counters["triangles/s"] =
      benchmark::Counter(double(rings().num_faces()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_bvh_build)->Unit(benchmark::kMillisecond);

static void BM_bvh_closest_point(benchmark::State& state) {
  const triangle_bvh bvh(rings());
  const auto q = queries(1000);
  for (auto _ : state)
    for (const vec3& p : q) benchmark::DoNotOptimize(bvh.closest_point(p));
  state.counters["queries/s"] = benchmark::Counter(1000.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_bvh_closest_point)->Unit(benchmark::kMicrosecond);

// baseline: the same queries by brute force over every triangle
static void BM_baseline_brute_closest_point(benchmark::State& state) {
  const tri_mesh& m = rings();
  const auto q = queries(10);
  for (auto _ : state)
    for (const vec3& p : q) {
      double best = 1e300;
      for (const auto& f : m.faces) {
        const auto c = detail::closest_point_on_triangle(
            p, m.positions[std::size_t(f[0])], m.positions[std::size_t(f[1])], m.positions[std::size_t(f[2])]);
        best = std::min(best, squared_norm(c.point - p));
      }
      benchmark::DoNotOptimize(best);
    }
  state.counters["queries/s"] = benchmark::Counter(10.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_baseline_brute_closest_point)->Unit(benchmark::kMicrosecond);

// BVH ray casts: rays from above the texture straight down and slanted, over the ring exemplar (what
// the preview renderer and shell mapping ask); baseline: the same rays against every triangle
namespace {
std::vector<std::pair<vec3, vec3>> rays(int n) {
  counter_rng rng(5);
  std::vector<std::pair<vec3, vec3>> r;
  for (int i = 0; i < n; ++i) {
    const vec3 o{rng.uniform(i, 0) * 8, rng.uniform(i, 1) * 8, 2};
    r.push_back({o, normalized(vec3{rng.uniform(i, 2) - 0.5, rng.uniform(i, 3) - 0.5, -1})});
  }
  return r;
}
}  // namespace

static void BM_bvh_raycast(benchmark::State& state) {
  const triangle_bvh bvh(rings());
  const auto r = rays(1000);
  index_t hits = 0;
  for (auto _ : state)
    for (const auto& [o, d] : r) hits += bvh.raycast(o, d).face >= 0;
  benchmark::DoNotOptimize(hits);
  state.counters["rays/s"] = benchmark::Counter(1000.0 * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["hit_fraction"] = double(hits) / (1000.0 * double(state.iterations()));
}
BENCHMARK(BM_bvh_raycast)->Unit(benchmark::kMicrosecond);

static void BM_baseline_brute_raycast(benchmark::State& state) {
  const tri_mesh& m = rings();
  std::vector<std::array<vec3, 3>> tris;
  for (const auto& f : m.faces)
    tris.push_back({m.positions[std::size_t(f[0])], m.positions[std::size_t(f[1])], m.positions[std::size_t(f[2])]});
  const auto r = rays(10);
  for (auto _ : state)
    for (const auto& [o, d] : r) {
      double best = 1e300;
      for (const auto& t : tris) {  // Moller-Trumbore
        const vec3 e1 = t[1] - t[0], e2 = t[2] - t[0], pv = cross(d, e2);
        const double det = dot(e1, pv);
        if (std::abs(det) < 1e-14) continue;
        const vec3 tv = o - t[0];
        const double u = dot(tv, pv) / det;
        if (u < 0 || u > 1) continue;
        const vec3 qv = cross(tv, e1);
        const double v = dot(d, qv) / det;
        if (v < 0 || u + v > 1) continue;
        const double tt = dot(e2, qv) / det;
        if (tt >= 0 && tt < best) best = tt;
      }
      benchmark::DoNotOptimize(best);
    }
  state.counters["rays/s"] = benchmark::Counter(10.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_baseline_brute_raycast)->Unit(benchmark::kMicrosecond);

// element extraction (connected components into per-element meshes, closed/manifold checks) and the
// whole exemplar preparation it is part of; baseline: copying the exemplar's arrays once
static void BM_extract_elements(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(extract_elements(rings()));
  state.counters["triangles/s"] =
      benchmark::Counter(double(rings().num_faces()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_extract_elements)->Unit(benchmark::kMillisecond);

static void BM_prepare_quilt_exemplar(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(prepare_quilt_exemplar(rings()));
  state.counters["triangles/s"] =
      benchmark::Counter(double(rings().num_faces()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_prepare_quilt_exemplar)->Unit(benchmark::kMillisecond);

static void BM_baseline_copy_exemplar(benchmark::State& state) {
  for (auto _ : state) {
    tri_mesh copy = rings();
    benchmark::DoNotOptimize(copy.positions.data());
  }
  state.counters["triangles/s"] =
      benchmark::Counter(double(rings().num_faces()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_baseline_copy_exemplar)->Unit(benchmark::kMillisecond);

namespace {
// a w x w 4-connected grid with seeds on the left (source) and right (sink), random capacities
template <class AddT, class AddE>
void grid_graph(int w, AddT&& add_t, AddE&& add_e) {
  counter_rng rng(9);
  for (int y = 0; y < w; ++y) {
    add_t(y * w, 1e9, 0.0);
    add_t(y * w + w - 1, 0.0, 1e9);
    for (int x = 0; x < w; ++x) {
      if (x + 1 < w) add_e(y * w + x, y * w + x + 1, 1 + rng.uniform(x, y, 0) * 9);
      if (y + 1 < w) add_e(y * w + x, (y + 1) * w + x, 1 + rng.uniform(x, y, 1) * 9);
    }
  }
}
}  // namespace

static void BM_max_flow_boykov_kolmogorov(benchmark::State& state) {
  const int w = int(state.range(0));
  for (auto _ : state) {
    max_flow_graph g(w * w);
    grid_graph(
        w, [&](int n, double s, double t) { g.add_terminal(n, s, t); },
        [&](int a, int b, double c) { g.add_edge(a, b, c, c); });
    benchmark::DoNotOptimize(*g.solve());
  }
  state.counters["nodes/s"] =
      benchmark::Counter(double(w * w) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_max_flow_boykov_kolmogorov)->Arg(64)->Unit(benchmark::kMillisecond);

// baseline: Edmonds-Karp (BFS augmenting paths) on the same graph
static void BM_baseline_max_flow_edmonds_karp(benchmark::State& state) {
  const int w = int(state.range(0));
  for (auto _ : state) {
    const int n = w * w + 2, s = w * w, t = w * w + 1;
    struct arc {
      int to, rev;
      double cap;
    };
    std::vector<std::vector<arc>> g(static_cast<std::size_t>(n));
    auto add = [&](int a, int b, double ab, double ba) {
      g[std::size_t(a)].push_back({b, int(g[std::size_t(b)].size()), ab});
      g[std::size_t(b)].push_back({a, int(g[std::size_t(a)].size()) - 1, ba});
    };
    grid_graph(
        w,
        [&](int v, double cs, double ct) {
          if (cs > 0) add(s, v, cs, 0);
          if (ct > 0) add(v, t, ct, 0);
        },
        [&](int a, int b, double c) { add(a, b, c, c); });
    double flow = 0;
    for (;;) {
      std::vector<std::pair<int, int>> prev(std::size_t(n), {-1, -1});
      std::deque<int> q{s};
      prev[std::size_t(s)] = {s, -1};
      while (!q.empty() && prev[std::size_t(t)].first < 0) {
        const int u = q.front();
        q.pop_front();
        for (int i = 0; i < int(g[std::size_t(u)].size()); ++i) {
          const arc& a = g[std::size_t(u)][std::size_t(i)];
          if (a.cap > 1e-12 && prev[std::size_t(a.to)].first < 0) prev[std::size_t(a.to)] = {u, i}, q.push_back(a.to);
        }
      }
      if (prev[std::size_t(t)].first < 0) break;
      double b = 1e300;
      for (int v = t; v != s; v = prev[std::size_t(v)].first)
        b = std::min(b, g[std::size_t(prev[std::size_t(v)].first)][std::size_t(prev[std::size_t(v)].second)].cap);
      for (int v = t; v != s; v = prev[std::size_t(v)].first) {
        arc& a = g[std::size_t(prev[std::size_t(v)].first)][std::size_t(prev[std::size_t(v)].second)];
        a.cap -= b;
        g[std::size_t(a.to)][std::size_t(a.rev)].cap += b;
      }
      flow += b;
    }
    benchmark::DoNotOptimize(flow);
  }
  state.counters["nodes/s"] =
      benchmark::Counter(double(w * w) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_baseline_max_flow_edmonds_karp)->Arg(64)->Unit(benchmark::kMillisecond);

static void BM_laplacian_deform(benchmark::State& state) {
  tri_mesh m;
  detail::add_torus(m, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0, 0.3, int(state.range(0)),
                    int(state.range(0)) / 3);
  std::vector<laplacian_constraint> cs;
  for (index_t v = 0; v < m.num_vertices(); v += 17)
    cs.push_back({{v, -1, -1}, {1, 0, 0}, m.positions[std::size_t(v)] + vec3{0, 0, 0.05}});
  for (auto _ : state) benchmark::DoNotOptimize(laplacian_deform(m, {}, cs));
  state.counters["vertices/s"] =
      benchmark::Counter(double(m.num_vertices()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_laplacian_deform)->Arg(48)->Unit(benchmark::kMillisecond);

static void BM_icp_translation(benchmark::State& state) {
  const triangle_bvh bvh(rings());
  std::vector<vec3> pts;
  for (index_t v = 0; v < rings().num_vertices(); v += 30)
    pts.push_back(rings().positions[std::size_t(v)] + vec3{0.08, -0.05, 0});
  for (auto _ : state)
    benchmark::DoNotOptimize(icp_translation(pts, bvh, {}, {.max_iterations = 30, .free_axes = {true, true, false}}));
  state.counters["points/s"] =
      benchmark::Counter(double(pts.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_icp_translation)->Unit(benchmark::kMillisecond);

static void BM_mesh_quilt_per_area(benchmark::State& state) {
  const double side = double(state.range(0));
  thread_pool_executor pool(2);
  for (auto _ : state) benchmark::DoNotOptimize(mesh_quilt(prepared_rings(), side, side, {.seed = 1}, pool));
  state.counters["area/s"] = benchmark::Counter(side * side * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_mesh_quilt_per_area)->Arg(12)->Unit(benchmark::kMillisecond)->Iterations(1);

// same-run baseline of the quality fixes (issue 17): the earlier rules, every corresponding pair
// merged and no dropped element's cell retried
static void BM_baseline_mesh_quilt_merge_all(benchmark::State& state) {
  const double side = double(state.range(0));
  thread_pool_executor pool(2);
  for (auto _ : state)
    benchmark::DoNotOptimize(mesh_quilt(prepared_rings(), side, side,
                                        {.merge_whole = true, .cell_retries = 0, .occupancy_aware = false, .seed = 1},
                                        pool));
  state.counters["area/s"] = benchmark::Counter(side * side * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_baseline_mesh_quilt_merge_all)->Arg(12)->Unit(benchmark::kMillisecond)->Iterations(1);

namespace {
// Tile sets of the ring exemplar: arg 0 = tile 6.4 (about 5.7k triangles a tile), arg 1 = tile 4.0
// (the smallest the default edge height allows, about 2.2k triangles a tile: the size of the paper's
// tiles, Table 1 of paper 000 has 0.5k-2.6k).
const geometric_tile_set& ring_tiles(std::int64_t which) {
  static std::map<std::int64_t, geometric_tile_set> sets;
  auto it = sets.find(which);
  if (it == sets.end()) {
    geometric_wang_options o;
    o.tile_size = which == 0 ? 6.4 : 4.0;
    thread_pool_executor pool(2);
    it = sets.emplace(which, *build_geometric_wang_tiles(prepared_rings(), o, pool)).first;
  }
  return it->second;
}
const stored_tile_coloring& coloring_64() {
  static const stored_tile_coloring c = store_coloring(*hash_coloring::create(2, 2, 3)->window(0, 0, 64, 64));
  return c;
}
std::size_t plane_bytes(const geometric_plane_layout& l) {
  return std::size_t(l.num_vertices()) * sizeof(vec3) + std::size_t(l.num_faces()) * sizeof(std::array<index_t, 3>);
}
void plane_counters(benchmark::State& state, const geometric_plane_layout& l) {
  state.counters["triangles/s"] =
      benchmark::Counter(double(l.num_faces()) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["triangles"] = double(l.num_faces());
  state.counters["tri_per_tile"] = double(l.num_faces()) / (64.0 * 64.0);
  state.counters["bytes/s"] =
      benchmark::Counter(double(plane_bytes(l)) * double(state.iterations()), benchmark::Counter::kIsRate);
}
}  // namespace

// the goal: a complete 16-tile set from a ~5k-vertex exemplar in under 30 s (2 threads)
static void BM_geometric_wang_tile_set_16(benchmark::State& state) {
  thread_pool_executor pool(2);
  geometric_wang_options o;
  o.tile_size = 6.4;
  for (auto _ : state) benchmark::DoNotOptimize(build_geometric_wang_tiles(prepared_rings(), o, pool));
  state.counters["tiles/s"] = benchmark::Counter(16.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_geometric_wang_tile_set_16)->Unit(benchmark::kMillisecond)->Iterations(1);

// the goal of issue 15: the complete three-axis set for two colours per axis (96 tiles, paper 000 §5)
// from the same ~5k-vertex exemplar in under 30 s (2 threads); same-run baseline: the planar 16-tile set
// above (96 / 16 = 6 times the tiles, so a ratio near 6 means the three-axis strips cost nothing extra)
static void BM_geometric_wang_tile_set_96_three_axis(benchmark::State& state) {
  thread_pool_executor pool(2);
  geometric_wang_options o;
  o.tile_size = 6.4;
  o.axis_colors = {2, 2, 2};
  for (auto _ : state) benchmark::DoNotOptimize(build_geometric_wang_tiles(prepared_rings(), o, pool));
  state.counters["tiles/s"] = benchmark::Counter(96.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_geometric_wang_tile_set_96_three_axis)->Unit(benchmark::kMillisecond)->Iterations(1);

// same-run baseline of the quality fixes (issue 17): the earlier rules (every corresponding pair
// merged, no cell retried, nothing moved back inside a tile, free strip elements only wholly inside
// the strip)
static void BM_baseline_geometric_wang_tile_set_16_merge_all(benchmark::State& state) {
  thread_pool_executor pool(2);
  geometric_wang_options o;
  o.tile_size = 6.4;
  o.quilt.merge_whole = true;
  o.quilt.cell_retries = 0;
  o.quilt.nudge_inside = false;
  o.quilt.occupancy_aware = false;
  o.deep_free_elements = false;
  for (auto _ : state) benchmark::DoNotOptimize(build_geometric_wang_tiles(prepared_rings(), o, pool));
  state.counters["tiles/s"] = benchmark::Counter(16.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_baseline_geometric_wang_tile_set_16_merge_all)->Unit(benchmark::kMillisecond)->Iterations(1);

// the goal: 64 x 64 tiles welded into one mesh in under 1 s (returned as a tri_mesh: allocation and
// the vectors' zero fill included)
static void BM_tile_plane_64x64(benchmark::State& state) {
  const auto& set = ring_tiles(state.range(0));
  thread_pool_executor pool(2);
  for (auto _ : state) {
    auto plane = tile_geometric_plane(set, coloring_64(), 64, 64, pool);
    benchmark::DoNotOptimize(plane->positions.data());
  }
  plane_counters(state, *plan_geometric_plane(set, coloring_64(), 64, 64));
}
BENCHMARK(BM_tile_plane_64x64)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// the same, planned and written into fresh uninitialised caller storage (engine vertex buffers)
static void BM_tile_plane_64x64_into_storage(benchmark::State& state) {
  const auto& set = ring_tiles(state.range(0));
  thread_pool_executor pool(2);
  for (auto _ : state) {
    const auto l = plan_geometric_plane(set, coloring_64(), 64, 64);
    std::allocator<vec3> av;
    std::allocator<std::array<index_t, 3>> af;
    const std::size_t nv = std::size_t(l->num_vertices()), nf = std::size_t(l->num_faces());
    vec3* p = av.allocate(nv);
    std::array<index_t, 3>* f = af.allocate(nf);
    benchmark::DoNotOptimize(l->write({p, nv}, {f, nf}, pool));
    benchmark::DoNotOptimize(p);
    av.deallocate(p, nv), af.deallocate(f, nf);
  }
  plane_counters(state, *plan_geometric_plane(set, coloring_64(), 64, 64));
}
BENCHMARK(BM_tile_plane_64x64_into_storage)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// baselines: one memcpy of the welded plane's bytes (vertices + faces), into a buffer already in
// memory, and into a freshly allocated one (page faults included, as for a new mesh)
static void BM_baseline_memcpy_plane_bytes(benchmark::State& state) {
  const auto l = plan_geometric_plane(ring_tiles(state.range(0)), coloring_64(), 64, 64);
  const std::size_t bytes = plane_bytes(*l);
  std::vector<char> src(bytes, 1), dst(bytes, 0);
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), bytes);
    benchmark::DoNotOptimize(dst.data());
  }
  plane_counters(state, *l);
}
BENCHMARK(BM_baseline_memcpy_plane_bytes)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_baseline_alloc_memcpy_plane_bytes(benchmark::State& state) {
  const auto l = plan_geometric_plane(ring_tiles(state.range(0)), coloring_64(), 64, 64);
  const std::size_t bytes = plane_bytes(*l);
  std::vector<char> src(bytes, 1);
  for (auto _ : state) {
    std::unique_ptr<char[]> dst(new char[bytes]);
    std::memcpy(dst.get(), src.data(), bytes);
    benchmark::DoNotOptimize(dst.get());
  }
  plane_counters(state, *l);
}
BENCHMARK(BM_baseline_alloc_memcpy_plane_bytes)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
