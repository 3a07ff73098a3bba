// Benchmarks of the fabric family (paper 001). Figures read as ratios to same-run baselines:
//   BM_Memcpy            memcpy of the image (the floor for any pass over it)
//   BM_CatMapStep        one step of the paper's iteration (cat_map_step)
//   BM_CatMapJump        cat_map(image, n): n steps in one pass; goal <= 2x one step at 4096^2.
//                        Counter jump/step: its time over one cat_map_step timed in the same
//                        iterations (interleaved, so load on a shared machine hits both alike)
//   BM_CatMapSteps       n single steps, what the paper pays
//   BM_CatMapPeriod      cat_map_period(N) from the factorization; goal < 1 ms for N <= 10^12
//   BM_LifePerturbation  one generation on RGBA8; goal <= 10x memcpy at 4096^2. Counter
//                        x_memcpy: its time over a memcpy of the image timed in the same iterations
// Arguments: image side N, step count n, threads. Each ratio comes twice: of wall-clock times, and
// (suffix _cpu) of CPU times summed over all threads, the one to read on a loaded machine.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include <tessera/core/random.hpp>
#include <tessera/fabric/cat_map.hpp>
#include <tessera/fabric/cat_map_period.hpp>
#include <tessera/fabric/life_perturbation.hpp>
#include <tessera/fabric/make_fabric.hpp>

namespace {

using tessera::index_t;
using rgba8 = tessera::image_buffer<std::uint8_t, 4>;

// A fabric-like RGBA8 image: the tweed preset's cat-mapped wool tones (tiled from 400^2).
const rgba8& fabric_image(index_t n) {
  static std::vector<std::pair<index_t, std::unique_ptr<rgba8>>> cache;
  for (auto& c : cache)
    if (c.first == n) return *c.second;
  auto img = std::make_unique<rgba8>(n, n);
  auto recipe = tessera::fabric_preset_recipe(tessera::fabric_preset::tweed);
  recipe.options.perturbation.generations = 0;
  recipe.options.tile_size = 400;
  if (!tessera::make_fabric(recipe.tones, recipe.source, *img, recipe.options)) std::abort();
  cache.emplace_back(n, std::move(img));
  return *cache.back().second;
}

tessera::thread_pool_executor& pool(int threads) {
  static tessera::thread_pool_executor one(1), two(2);
  return threads == 1 ? one : two;
}

void set_pixels(benchmark::State& state, index_t n) {
  state.SetItemsProcessed(state.iterations() * n * n);
  state.counters["Mpix/s"] =
      benchmark::Counter(static_cast<double>(n * n) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// Wall-clock and process CPU seconds (all threads) of one call.
struct elapsed {
  double wall = 0, cpu = 0;
  elapsed& operator+=(const elapsed& e) {
    wall += e.wall, cpu += e.cpu;
    return *this;
  }
};
template <class F>
elapsed seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  f();
  const std::clock_t c1 = std::clock();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          static_cast<double>(c1 - c0) / CLOCKS_PER_SEC};
}

// Runs `baseline` with the benchmark's timer paused, so a benchmark can report its own time as a
// ratio to a baseline measured in the same iterations (interleaved: load hits both alike).
template <class F>
elapsed paused_seconds(benchmark::State& state, F&& baseline) {
  state.PauseTiming();
  const elapsed e = seconds(baseline);
  state.ResumeTiming();
  return e;
}

// Counters `name` (wall-clock ratio) and `name`_cpu (ratio of CPU time summed over all threads).
void set_ratio(benchmark::State& state, const char* name, const elapsed& a, const elapsed& b) {
  state.counters[name] = a.wall / b.wall;
  state.counters[std::string(name) + "_cpu"] = a.cpu / b.cpu;
}

void BM_Memcpy(benchmark::State& state) {
  const index_t n = state.range(0);
  const rgba8& in = fabric_image(n);
  rgba8 out(n, n);
  for (auto _ : state) {
    std::memcpy(out.data(), in.data(), in.size_bytes());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_pixels(state, n);
}

void BM_CatMapStep(benchmark::State& state) {
  const index_t n = state.range(0);
  const rgba8& in = fabric_image(n);
  rgba8 out(n, n);
  auto& exec = pool(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    if (!tessera::cat_map_step(in, out, {}, exec)) state.SkipWithError("cat_map_step failed");
    benchmark::ClobberMemory();
  }
  set_pixels(state, n);
}

void BM_CatMapJump(benchmark::State& state) {
  const index_t n = state.range(0);
  const std::int64_t steps = state.range(1);
  const rgba8& in = fabric_image(n);
  rgba8 out(n, n), stepped(n, n);
  auto& exec = pool(static_cast<int>(state.range(2)));
  elapsed jump, step;
  for (auto _ : state) {
    step += paused_seconds(state, [&] {
      if (!tessera::cat_map_step(in, stepped, {}, exec)) state.SkipWithError("cat_map_step failed");
    });
    jump += seconds([&] {
      if (!tessera::cat_map(in, out, steps, {}, exec)) state.SkipWithError("cat_map failed");
      benchmark::ClobberMemory();
    });
  }
  set_ratio(state, "jump/step", jump, step);
  set_pixels(state, n);
}

void BM_CatMapSteps(benchmark::State& state) {
  const index_t n = state.range(0);
  const std::int64_t steps = state.range(1);
  const rgba8& in = fabric_image(n);
  rgba8 a(n, n), b(n, n);
  auto& exec = pool(static_cast<int>(state.range(2)));
  for (auto _ : state) {
    std::memcpy(a.data(), in.data(), in.size_bytes());
    for (std::int64_t k = 0; k < steps; ++k) {
      if (!tessera::cat_map_step(a, b, {}, exec)) state.SkipWithError("cat_map_step failed");
      std::swap(a, b);
    }
    benchmark::ClobberMemory();
  }
  set_pixels(state, n);
}

void BM_CatMapPeriod(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  for (auto _ : state) benchmark::DoNotOptimize(tessera::cat_map_period(n));
  state.counters["period"] = static_cast<double>(*tessera::cat_map_period(n));
}

// Random N in [1, 10^12]: the mean cost over many factorization shapes.
void BM_CatMapPeriodRandom(benchmark::State& state) {
  std::uint64_t i = 0;
  for (auto _ : state) {
    const auto n = static_cast<std::int64_t>(1 + tessera::mix64(++i) % 1000000000000ULL);
    benchmark::DoNotOptimize(tessera::cat_map_period(n));
  }
}

void BM_LifePerturbation(benchmark::State& state) {
  const index_t n = state.range(0);
  const rgba8& in = fabric_image(n);
  rgba8 out(n, n), copy(n, n);
  auto& exec = pool(static_cast<int>(state.range(1)));
  elapsed life, copied;
  for (auto _ : state) {
    copied += paused_seconds(state, [&] {
      std::memcpy(copy.data(), in.data(), in.size_bytes());
      benchmark::ClobberMemory();
    });
    life += seconds([&] {
      if (!tessera::life_perturbation(in, out, {.generations = 1}, exec))
        state.SkipWithError("life_perturbation failed");
      benchmark::ClobberMemory();
    });
  }
  set_ratio(state, "x_memcpy", life, copied);
  set_pixels(state, n);
}

}  // namespace

BENCHMARK(BM_Memcpy)->Arg(400)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CatMapStep)->ArgsProduct({{400, 4096}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CatMapJump)
    ->ArgsProduct({{400, 4096}, {1, 31, 60, 300}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_CatMapSteps)->ArgsProduct({{400}, {1, 31, 60, 300}, {2}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CatMapSteps)
    ->ArgsProduct({{4096}, {1, 31, 60, 300}, {2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_CatMapPeriod)
    ->Arg(400)
    ->Arg(4096)
    ->Arg(1000003)              // a prime near 10^6
    ->Arg(999999999989LL)       // the largest prime below 10^12
    ->Arg(999983LL * 999979LL)  // two primes near 10^6 (hardest for Pollard's rho)
    ->Arg(1000000000000LL)      // 2^12 5^12
    ->Arg(1099511627776LL)      // 2^40
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CatMapPeriodRandom)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LifePerturbation)->ArgsProduct({{400, 4096}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
