// Benchmarks of the surface family (paper 000 §4): automatic polycube construction against mesh size
// (tori of 2k to 80k faces, 8 tiles across, 1 and 2 threads), the projection round trip, and the
// distortion figures. Same-run baseline: face adjacency of the same mesh (one sort of its 3F sides),
// so the construction reads as a multiple of the cheapest whole-mesh pass.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_distortion.hpp>
#include <tessera/surface/polycube_projection.hpp>

using namespace tessera;

namespace {
// torus with about `faces` faces (nu = 3 nv)
const tri_mesh& torus(int faces) {
  static std::map<int, tri_mesh> cache;
  auto it = cache.find(faces);
  if (it != cache.end()) return it->second;
  const int nv = static_cast<int>(std::lround(std::sqrt(faces / 6.0))), nu = 3 * nv;
  tri_mesh m;
  const double pi = 3.14159265358979323846, R = 2, r = 0.8;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      m.add_vertex({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto at = [&](int i, int j) { return static_cast<index_t>(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return cache.emplace(faces, std::move(m)).first->second;
}

void BM_face_adjacency_baseline(benchmark::State& st) {
  const auto& m = torus(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(face_adjacency(m));
  st.counters["faces"] = static_cast<double>(m.num_faces());
}
BENCHMARK(BM_face_adjacency_baseline)->Arg(2000)->Arg(10000)->Arg(40000)->Arg(80000)->Unit(benchmark::kMillisecond);

void BM_build_polycube(benchmark::State& st) {
  const auto& m = torus(static_cast<int>(st.range(0)));
  thread_pool_executor pool(static_cast<int>(st.range(1)));
  polycube_options o;
  o.tiles_across = 8;
  index_t quads = 0;
  for (auto _ : st) {
    auto r = build_polycube_map(m, o, pool);
    if (!r)
      st.SkipWithError(r.error().to_string().c_str());
    else
      quads = static_cast<index_t>(r->layout.quads.size());
  }
  st.counters["faces"] = static_cast<double>(m.num_faces());
  st.counters["quads"] = static_cast<double>(quads);
}
BENCHMARK(BM_build_polycube)
    ->Args({2000, 1})
    ->Args({10000, 1})
    ->Args({10000, 2})
    ->Args({40000, 2})
    ->Args({80000, 2})
    ->Unit(benchmark::kMillisecond);

void BM_projection_round_trip(benchmark::State& st) {
  static const polycube_map map = *build_polycube_map(torus(10000), polycube_options{0, 8});
  const polycube_projector pj(map);
  index_t f = 0;
  for (auto _ : st) {
    auto p = pj.forward(f, {0.2, 0.3, 0.5});
    benchmark::DoNotOptimize(pj.inverse(p->quad, p->u, p->v));
    f = (f + 7919) % map.base.num_faces();
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_projection_round_trip);

void BM_distortion(benchmark::State& st) {
  static const polycube_map map = *build_polycube_map(torus(10000), polycube_options{0, 8});
  for (auto _ : st) benchmark::DoNotOptimize(polycube_distortion(map));
}
BENCHMARK(BM_distortion)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
