// Core vocabulary costs: counter-based random numbers against std::mt19937_64 and a plain loop,
// mesh connectivity (flat face_adjacency vs the per-edge mesh_edges list vs a sort of the face
// indices as baseline), and thread_pool_executor overhead against a serial loop.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/random.hpp>
#include <tessera/core/tri_mesh.hpp>

namespace {

constexpr std::int64_t draws = 1 << 20;

void BM_FillBaseline(benchmark::State& state) {
  std::vector<std::uint64_t> out(draws);
  for (auto _ : state) {
    for (std::int64_t i = 0; i < draws; ++i) out[static_cast<std::size_t>(i)] = static_cast<std::uint64_t>(i) * 3;
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["values/s"] = benchmark::Counter(double(draws), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_FillBaseline);

void BM_Mt19937(benchmark::State& state) {
  std::vector<std::uint64_t> out(draws);
  std::mt19937_64 gen(1);
  for (auto _ : state) {
    for (auto& v : out) v = gen();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["values/s"] = benchmark::Counter(double(draws), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Mt19937);

void BM_CounterRngBits2Keys(benchmark::State& state) {
  std::vector<std::uint64_t> out(draws);
  const tessera::counter_rng rng(1, tessera::stream_id("bench"));
  for (auto _ : state) {
    for (std::int64_t i = 0; i < draws; ++i) out[static_cast<std::size_t>(i)] = rng.bits(i & 1023, i >> 10);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["values/s"] = benchmark::Counter(double(draws), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_CounterRngBits2Keys);

void BM_CounterRngSequence(benchmark::State& state) {
  std::vector<std::uint64_t> out(draws);
  for (auto _ : state) {
    auto seq = tessera::counter_rng(1).sequence(7);
    for (auto& v : out) v = seq();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["values/s"] = benchmark::Counter(double(draws), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_CounterRngSequence);

const tessera::tri_mesh& grid() {
  static const tessera::tri_mesh m = [] {
    tessera::tri_mesh g;
    const int n = 256;
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) g.add_vertex({double(x), double(y), 0});
    auto id = [&](int x, int y) { return tessera::index_t{y * (n + 1) + x}; };
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        g.add_face(id(x, y), id(x + 1, y), id(x + 1, y + 1));
        g.add_face(id(x, y), id(x + 1, y + 1), id(x, y + 1));
      }
    return g;
  }();
  return m;
}
void triangles(benchmark::State& state) {
  state.counters["triangles/s"] =
      benchmark::Counter(double(grid().num_faces()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_SortFacesBaseline(benchmark::State& state) {  // sorting the 3F corner keys once
  for (auto _ : state) {
    std::vector<std::uint64_t> keys;
    keys.reserve(grid().faces.size() * 3);
    for (const auto& f : grid().faces)
      for (int k = 0; k < 3; ++k)
        keys.push_back(static_cast<std::uint64_t>(std::min(f[k], f[(k + 1) % 3])) << 32 |
                       static_cast<std::uint64_t>(std::max(f[k], f[(k + 1) % 3])));
    std::sort(keys.begin(), keys.end());
    benchmark::DoNotOptimize(keys.data());
  }
  triangles(state);
}
BENCHMARK(BM_SortFacesBaseline)->Unit(benchmark::kMillisecond);

void BM_FaceAdjacency(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(tessera::face_adjacency(grid()));
  triangles(state);
}
BENCHMARK(BM_FaceAdjacency)->Unit(benchmark::kMillisecond);

void BM_MeshEdges(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(tessera::mesh_edges(grid()));
  triangles(state);
}
BENCHMARK(BM_MeshEdges)->Unit(benchmark::kMillisecond);

void BM_ConnectedComponents(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(tessera::connected_components(grid()));
  triangles(state);
}
BENCHMARK(BM_ConnectedComponents)->Unit(benchmark::kMillisecond);

// Executor overhead: many small loops (the cost a fine-grained algorithm pays per parallel_for).
template <class E>
void small_loops(benchmark::State& state, E& exec) {
  std::vector<double> out(4096);
  for (auto _ : state) {
    exec.parallel_for(0, 4096, [&](tessera::index_t i) { out[static_cast<std::size_t>(i)] = double(i) * 0.5; });
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["loops/s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}
void BM_SerialLoop(benchmark::State& state) {
  tessera::serial_executor e;
  small_loops(state, e);
}
BENCHMARK(BM_SerialLoop);
void BM_PoolLoop(benchmark::State& state) {
  tessera::thread_pool_executor e(static_cast<int>(state.range(0)));
  small_loops(state, e);
}
BENCHMARK(BM_PoolLoop)->Arg(1)->Arg(2);

}  // namespace

BENCHMARK_MAIN();
