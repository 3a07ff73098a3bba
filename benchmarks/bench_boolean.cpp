// Benchmark of the mesh Booleans (adapters/cgal_boolean.hpp, CGAL's corefinement; paper 000 Fig. 7):
// the ring elements of a one-colour three-axis set mapped onto a 4 x 4 x 4 box (96 quads, exact
// clipping), sunk and joined with the box (union, sink 0.1) or engraved into it (difference, sink 0.5).
// Same-run baseline: the mapping that made the elements (map_geometric_tiles), so the Boolean reads as
// a multiple of it. Built only with CGAL (TESSERA_HAS_CGAL).
#include <benchmark/benchmark.h>

#include <tessera/adapters/cgal_boolean.hpp>
#include <tessera/core/executor.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/map_geometric_tiles.hpp>

using namespace tessera;

namespace {
struct boolean_case {
  tri_mesh base;
  polycube_map map;
  geometric_tile_set set;
};
const boolean_case& bench_case() {
  static const boolean_case c = [] {
    boolean_case c;
    for (int i = 0; i < 8; ++i) c.base.add_vertex({(i & 1) ? 4.0 : 0.0, (i & 2) ? 4.0 : 0.0, (i & 4) ? 4.0 : 0.0});
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
      c.base.add_face(q[0], q[1], q[2]);
      c.base.add_face(q[0], q[2], q[3]);
    }
    c.map = *build_polycube_map(c.base, polycube_options{1.0});
    auto ex = prepare_quilt_exemplar(
        *make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 12, .tube_segments = 5, .seed = 3}));
    geometric_wang_options wo;
    wo.axis_colors = {1, 1, 1};
    wo.tile_size = 4.0;
    wo.quilt.seed = 5;
    thread_pool_executor pool(2);
    c.set = *build_geometric_wang_tiles(*ex, wo, pool);
    return c;
  }();
  return c;
}
map_geometric_tiles_options mapping(double sink) {
  map_geometric_tiles_options o;
  o.height = 0.3;
  o.shell.sink = sink;
  o.mapping.clip = shell_clip::exact;
  return o;
}
}  // namespace

// baseline: the mapping of the elements (one thread)
void BM_boolean_mapping_baseline(benchmark::State& st) {
  const auto& c = bench_case();
  index_t faces = 0;
  for (auto _ : st) faces = map_geometric_tiles(c.base, c.map, c.set, mapping(0.1))->element_faces;
  st.counters["element_faces"] = static_cast<double>(faces);
}
BENCHMARK(BM_boolean_mapping_baseline)->Unit(benchmark::kMillisecond);

// argument: 0 union (sink 0.1), 1 difference (sink 0.5)
void BM_mesh_boolean(benchmark::State& st) {
  const auto& c = bench_case();
  const bool unite = st.range(0) == 0;
  const tri_mesh elements = map_geometric_tiles(c.base, c.map, c.set, mapping(unite ? 0.1 : 0.5))->elements();
  index_t faces = 0;
  for (auto _ : st) {
    auto r = mesh_boolean(c.map.base, elements, unite ? boolean_op::unite : boolean_op::subtract);
    if (!r) {
      st.SkipWithError(r.error().message().c_str());
      return;
    }
    faces = r->num_faces();
  }
  st.counters["element_faces"] = static_cast<double>(elements.num_faces());
  st.counters["output_faces"] = static_cast<double>(faces);
}
BENCHMARK(BM_mesh_boolean)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
