// Benchmarks of Wang tiles (issue 4): building a complete 16-tile set (tile 64) from a 128² exemplar,
// composing a 4096² RGBA8 tiled image (scanline and hash colourings, serial and 2 threads) against
// three same-run baselines writing the same 64 MB output, and the per-pixel plane -> atlas mapping.
// Baselines: a memcpy from a cold 64 MB source (reads 64 MB from memory), a row-wise memcpy from a
// 1 MB source that stays in cache (what composing does: its 16 tiles are 256 KB), and a memset of
// the output (the write bandwidth alone).
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
  static const auto ex =
      *make_exemplar<std::uint8_t, 4>(exemplar_kind::cells, {.width = 128, .height = 128, .seed = 3});
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

// Baseline 1: memcpy of a 4096² RGBA8 image from a 64 MB source (the source is cold: it is read
// from memory, which composing never does, so this baseline flatters composing).
static void BM_memcpy_4096_rgba8(benchmark::State& state) {
  std::vector<std::uint8_t> src(big * big * 4, 7), dst(big * big * 4);
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), dst.size());
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(double(big * big) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_memcpy_4096_rgba8)->Unit(benchmark::kMillisecond)->UseRealTime();

// Baseline 2: the same 64 MB output written row by row from a 1 MB source that stays in cache (64
// rows of 16 KB, reused): the fair comparison, since composing reads ~1 MB of cached tiles.
static void BM_memcpy_4096_rgba8_cached_source(benchmark::State& state) {
  constexpr index_t row = big * 4, src_rows = 64;
  std::vector<std::uint8_t> src(static_cast<std::size_t>(row * src_rows), 7), dst(big * big * 4);
  for (auto _ : state) {
    for (index_t y = 0; y < big; ++y)
      std::memcpy(dst.data() + y * row, src.data() + (y % src_rows) * row, static_cast<std::size_t>(row));
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(double(big * big) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_memcpy_4096_rgba8_cached_source)->Unit(benchmark::kMillisecond)->UseRealTime();

// Baseline 3: memset of the 64 MB output (writes only).
static void BM_memset_4096_rgba8(benchmark::State& state) {
  std::vector<std::uint8_t> dst(big * big * 4);
  std::uint8_t value = 0;
  for (auto _ : state) {
    std::memset(dst.data(), ++value, dst.size());
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(double(big * big) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_memset_4096_rgba8)->Unit(benchmark::kMillisecond)->UseRealTime();

template <class Coloring>
static void compose_bench(benchmark::State& state, const Coloring& coloring) {
  image_buffer<std::uint8_t, 4> out(big, big);
  thread_pool_executor pool(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto s = compose_tiles(tiles(), coloring, out, {}, pool);
    benchmark::DoNotOptimize(s);
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(double(big * big) * double(state.iterations()), benchmark::Counter::kIsRate);
}

// Goal: within 1.5x of a memcpy of the output; compare with all three baselines above.
static void BM_compose_4096_rgba8_scanline(benchmark::State& state) {
  static const auto coloring = *scanline_coloring::create(tiles().edges(), big / 64, big / 64, 1);
  compose_bench(state, coloring);
}
BENCHMARK(BM_compose_4096_rgba8_scanline)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

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
  state.counters["lookups/s"] =
      benchmark::Counter(double(n * n) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_atlas_lookup_per_pixel)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
