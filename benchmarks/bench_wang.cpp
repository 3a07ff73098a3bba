// Benchmarks of Wang tiles (issue 4): building a complete 16-tile set (tile 64) from a 128² exemplar,
// composing a 4096² RGBA8 tiled image (scanline and hash colourings, serial and 2 threads) against a
// same-run memcpy of the same 64 MB output, and the per-pixel plane -> atlas mapping.
#include <benchmark/benchmark.h>

#include <cstring>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/wang_atlas.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

using namespace tessera;

namespace {
const image_buffer<std::uint8_t, 4>& exemplar() {
  static const auto ex = *make_exemplar<std::uint8_t, 4>(exemplar_kind::cells, {.width = 128, .height = 128, .seed = 3});
  return ex;
}
const wang_tile_set<std::uint8_t, 4>& tiles() {
  static const auto set = *build_wang_tiles(exemplar(), {.tile_size = 64});
  return set;
}
constexpr index_t big = 4096;
}  // namespace

// Goal: under 2 s on this 2-core machine.
static void BM_build_wang_tiles_16x64(benchmark::State& state) {
  thread_pool_executor pool(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto set = build_wang_tiles(exemplar(), {.tile_size = 64}, pool);
    benchmark::DoNotOptimize(set);
  }
  state.counters["tiles/s"] = benchmark::Counter(16.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_build_wang_tiles_16x64)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

// Baseline: memcpy of a 4096² RGBA8 image (what composing the same output cannot beat by much).
static void BM_memcpy_4096_rgba8(benchmark::State& state) {
  std::vector<std::uint8_t> src(big * big * 4, 7), dst(big * big * 4);
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), dst.size());
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] = benchmark::Counter(double(big * big) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_memcpy_4096_rgba8)->Unit(benchmark::kMillisecond)->UseRealTime();

template <class Coloring>
static void compose_bench(benchmark::State& state, const Coloring& coloring) {
  image_buffer<std::uint8_t, 4> out(big, big);
  thread_pool_executor pool(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto s = compose_tiles(tiles(), coloring, out, {}, pool);
    benchmark::DoNotOptimize(s);
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] = benchmark::Counter(double(big * big) * double(state.iterations()), benchmark::Counter::kIsRate);
}

// Goal: within 1.5x of BM_memcpy_4096_rgba8.
static void BM_compose_4096_rgba8_scanline(benchmark::State& state) {
  static const auto coloring = *scanline_coloring::create(tiles().edges(), big / 64, big / 64, 1);
  compose_bench(state, coloring);
}
BENCHMARK(BM_compose_4096_rgba8_scanline)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_compose_4096_rgba8_hash(benchmark::State& state) {
  static const auto coloring = *hash_coloring::for_set(tiles().edges(), 1);
  compose_bench(state, coloring);
}
BENCHMARK(BM_compose_4096_rgba8_hash)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

// Per-pixel texture-coordinate -> atlas mapping (what a shader does per fragment), 1024² lookups.
static void BM_atlas_lookup_per_pixel(benchmark::State& state) {
  static const auto atlas = *build_wang_atlas(tiles());
  static const auto coloring = *hash_coloring::for_set(tiles().edges(), 1);
  constexpr index_t n = 1024;
  for (auto _ : state) {
    double sum = 0;
    for (index_t y = 0; y < n; ++y)
      for (index_t x = 0; x < n; ++x) {
        const vec2 a = atlas_coordinates(atlas, coloring, double(x) * 3.7 + 0.5, double(y) * 2.3 + 0.5);
        sum += a.x + a.y;
      }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["lookups/s"] = benchmark::Counter(double(n * n) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_atlas_lookup_per_pixel)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
