// Patch synthesis (paper 002; image/patch_synthesis.hpp): synthesis throughput from a prepared model
// against a memcpy of the same output, and preprocessing time and model size per exemplar.
//
//   synthesize/<exemplar side>/<output side>/<format 0 RGBA8, 1 RGB float>/<threads>
//     Mpix_s   output pixels per second in 10^6, MiPix_s in 2^20 (the paper's "M pixels")
//     x_memcpy synthesis time / memcpy time of the same output buffer, measured in the same run (mean
//              frame over median copy); x_memcpy_min: fastest frame over fastest copy, steadier when the
//              machine is shared
//   synthesize_overlap_fallback/...: the same with the quality fallback (fill_fallback::overlap_error)
//     instead of the paper's most-sets default, for a same-run ratio of the two
//   synthesize_estimated_fallback/...: the same with the estimated fallback (fill_fallback::estimated_error)
//   synthesize_paper_feather/...: the same with the paper's feathering over the whole overlap
//     (feather_width = 0) instead of the default narrow band
//   memcpy/<output side>/<format>: the baseline alone
//   preprocess/<exemplar side>/<kind>/<threads>/<seams>: build_patch_model (size analysis included; seams:
//     also the minimum-error seam of every compatible pair), model_bytes and model_MiB (patch_model::memory_bytes)
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <tessera/core/executor.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>

namespace {

using tessera::index_t;

template <class T, int C>
const tessera::patch_model<T, C>& model_for(index_t side) {
  static std::map<index_t, std::unique_ptr<tessera::patch_model<T, C>>> cache;
  auto& slot = cache[side];
  if (!slot) {
    const auto ex = tessera::make_exemplar<T, C>(tessera::exemplar_kind::sand, {.width = side, .height = side}).value();
    tessera::thread_pool_executor pool(2);
    slot = std::make_unique<tessera::patch_model<T, C>>(tessera::build_patch_model(ex, {}, pool).value());
  }
  return *slot;
}

/// Median and minimum seconds of a memcpy of `bytes` (source and destination distinct, both touched
/// beforehand), over 15 copies.
std::pair<double, double> memcpy_seconds(std::size_t bytes) {
  std::vector<unsigned char> src(bytes, 1), dst(bytes, 0);
  std::vector<double> t;
  for (int i = 0; i < 15; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    std::memcpy(dst.data(), src.data(), bytes);
    benchmark::DoNotOptimize(dst.data());
    benchmark::ClobberMemory();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return {t[t.size() / 2], t.front()};
}

template <class T, int C>
void run_synthesis(benchmark::State& state,
                   tessera::fill_fallback fallback = tessera::patch_synthesis_options{}.fallback,
                   index_t feather_width = tessera::patch_synthesis_options{}.feather_width) {
  const index_t ex_side = state.range(0), side = state.range(1);
  const int threads = static_cast<int>(state.range(3));
  const auto& model = model_for<T, C>(ex_side);
  tessera::image_buffer<T, C> out(side, side);
  tessera::thread_pool_executor pool(threads);
  const auto [copy, copy_min] = memcpy_seconds(out.size_bytes());
  std::int64_t frames = 0;
  double fastest = 1e300;
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    const auto f0 = std::chrono::steady_clock::now();
    const tessera::patch_synthesis_options o{
        .seed = static_cast<std::uint64_t>(frames), .feather_width = feather_width, .fallback = fallback};
    auto s = threads == 1 ? tessera::synthesize(model, out, o) : tessera::synthesize(model, out, o, pool);
    if (!s) state.SkipWithError(s.error().message().c_str());
    benchmark::DoNotOptimize(out.data());
    fastest = std::min(fastest, std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count());
    ++frames;
  }
  const double per_frame =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / static_cast<double>(frames);
  const double pixels = static_cast<double>(side * side);
  state.counters["Mpix_s"] =
      benchmark::Counter(pixels * static_cast<double>(frames) / 1e6, benchmark::Counter::kIsRate);
  state.counters["MiPix_s"] =
      benchmark::Counter(pixels * static_cast<double>(frames) / 1048576.0, benchmark::Counter::kIsRate);
  state.counters["x_memcpy"] = per_frame / copy;
  state.counters["x_memcpy_min"] = fastest / copy_min;  // fastest frame over fastest copy: steadier on a loaded machine
  state.counters["patch"] = static_cast<double>(model.patch_width());
  state.SetBytesProcessed(static_cast<std::int64_t>(out.size_bytes()) * frames);
}

void BM_synthesize(benchmark::State& state) {
  if (state.range(2) == 0)
    run_synthesis<std::uint8_t, 4>(state);
  else
    run_synthesis<float, 3>(state);
}

void BM_synthesize_overlap_fallback(benchmark::State& state) {
  run_synthesis<std::uint8_t, 4>(state, tessera::fill_fallback::overlap_error);
}

void BM_synthesize_paper_feather(benchmark::State& state) {
  run_synthesis<std::uint8_t, 4>(state, tessera::patch_synthesis_options{}.fallback, 0);
}

void BM_synthesize_estimated_fallback(benchmark::State& state) {
  run_synthesis<std::uint8_t, 4>(state, tessera::fill_fallback::estimated_error);
}

void BM_memcpy(benchmark::State& state) {
  const index_t side = state.range(0);
  const std::size_t bytes = static_cast<std::size_t>(side * side) * (state.range(1) == 0 ? 4 : 12);
  std::vector<unsigned char> src(bytes, 1), dst(bytes, 0);
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), bytes);
    benchmark::DoNotOptimize(dst.data());
    benchmark::ClobberMemory();
  }
  state.counters["Mpix_s"] = benchmark::Counter(
      static_cast<double>(side * side) * static_cast<double>(state.iterations()) / 1e6, benchmark::Counter::kIsRate);
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes) * state.iterations());
}

void BM_preprocess(benchmark::State& state) {
  const index_t side = state.range(0);
  const auto kind = static_cast<tessera::exemplar_kind>(state.range(1));
  const int threads = static_cast<int>(state.range(2));
  const tessera::patch_model_options opts{.seams = state.range(3) != 0};
  const auto ex = tessera::make_exemplar<std::uint8_t, 4>(kind, {.width = side, .height = side}).value();
  tessera::thread_pool_executor pool(threads);
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto m = threads == 1 ? tessera::build_patch_model(ex, opts) : tessera::build_patch_model(ex, opts, pool);
    if (!m)
      state.SkipWithError(m.error().message().c_str());
    else
      bytes = m->memory_bytes();
  }
  state.counters["model_bytes"] = static_cast<double>(bytes);
  state.counters["model_MiB"] = static_cast<double>(bytes) / 1048576.0;
  state.SetLabel(std::string(tessera::to_string(kind)));
}

void synthesis_args(benchmark::internal::Benchmark* b) {
  for (index_t ex : {64, 128})
    for (index_t side : {256, 512, 1024, 2048, 4096})
      for (int format : {0, 1})
        for (int threads : {1, 2}) b->Args({ex, side, format, threads});
}

}  // namespace

BENCHMARK(BM_memcpy)->ArgsProduct({{256, 512, 1024, 2048, 4096}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_synthesize)->Apply(synthesis_args)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_synthesize_overlap_fallback)
    ->ArgsProduct({{64, 128}, {1024}, {0}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_synthesize_estimated_fallback)
    ->ArgsProduct({{64, 128}, {1024}, {0}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_synthesize_paper_feather)
    ->ArgsProduct({{64, 128}, {1024}, {0}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_preprocess)
    ->ArgsProduct({{64, 128}, {0, 1, 2, 3, 4, 5, 6}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

BENCHMARK_MAIN();
