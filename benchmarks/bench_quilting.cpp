// Benchmarks of image quilting (issue 4): 512² from a 128² exemplar (serial and 2 threads), against
// a same-run memcpy of the output; the overlap-error search of one L-shaped site against a naive
// per-candidate loop (the kernel the quilting time is spent in).
#include <benchmark/benchmark.h>

#include <cstring>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/image/constrained_quilt.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/quilt.hpp>

using namespace tessera;

namespace {
const image_buffer<std::uint8_t, 3>& exemplar() {
  static const auto ex =
      *make_exemplar<std::uint8_t, 3>(exemplar_kind::bricks, {.width = 128, .height = 128, .seed = 3});
  return ex;
}
}  // namespace

// Goal: under 1 s on this 2-core machine.
static void BM_quilt_512_from_128(benchmark::State& state) {
  image_buffer<std::uint8_t, 3> out(512, 512);
  thread_pool_executor pool(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto s = quilt(exemplar(), out, {.patch_size = 32}, pool);
    benchmark::DoNotOptimize(s);
  }
  state.counters["pixels/s"] =
      benchmark::Counter(512.0 * 512.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_quilt_512_from_128)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_quilt_512_seamless(benchmark::State& state) {
  image_buffer<std::uint8_t, 3> out(512, 512);
  for (auto _ : state) {
    auto s = quilt(exemplar(), out, {.patch_size = 32, .seamless = true});
    benchmark::DoNotOptimize(s);
  }
  state.counters["pixels/s"] =
      benchmark::Counter(512.0 * 512.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_quilt_512_seamless)->Unit(benchmark::kMillisecond)->UseRealTime();

// Baseline: memcpy of the 512² RGB8 output.
static void BM_memcpy_512_rgb8(benchmark::State& state) {
  std::vector<std::uint8_t> src(512 * 512 * 3, 7), dst(512 * 512 * 3);
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), dst.size());
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(512.0 * 512.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_memcpy_512_rgb8)->Unit(benchmark::kMicrosecond);

// Inpainting a 96 x 96 hole of a 256² image from the image itself.
static void BM_inpaint_96_hole(benchmark::State& state) {
  static const auto image =
      *make_exemplar<std::uint8_t, 3>(exemplar_kind::bricks, {.width = 256, .height = 256, .seed = 4});
  image_buffer<std::uint8_t, 1> mask(256, 256);
  for (index_t y = 80; y < 176; ++y)
    for (index_t x = 80; x < 176; ++x) mask.write(x, y, {255});
  image_buffer<std::uint8_t, 3> out(256, 256);
  for (auto _ : state) {
    auto s = constrained_quilt(image, mask, out, {.patch_size = 24});
    benchmark::DoNotOptimize(s);
  }
  state.counters["hole pixels/s"] =
      benchmark::Counter(96.0 * 96.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_inpaint_96_hole)->Unit(benchmark::kMillisecond)->UseRealTime();

namespace {
// an L-shaped overlap (32 x 32 patch, overlap 5) as the kernel sees it
std::vector<detail::template_element> l_shape(index_t ew, index_t eh) {
  std::vector<detail::template_element> e;
  for (index_t j = 0; j < 32; ++j)
    for (index_t i = 0; i < 32; ++i)
      if (i < 5 || j < 5)
        for (int c = 0; c < 3; ++c) e.push_back({c * ew * eh + j * ew + i, 0.25f + 0.01f * float((i + j + c) % 7)});
  return e;
}
}  // namespace

static void BM_overlap_errors_one_site(benchmark::State& state) {
  const detail::quilt_source<std::uint8_t, 3> src(exemplar());
  const auto elements = l_shape(128, 128);
  std::vector<float> err;
  serial_executor serial;
  for (auto _ : state) {
    detail::overlap_errors(src, elements, 32, err, serial);
    benchmark::DoNotOptimize(err.data());
  }
  state.counters["candidates/s"] =
      benchmark::Counter(97.0 * 97.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_overlap_errors_one_site)->Unit(benchmark::kMicrosecond);

// Baseline: the same errors, one candidate at a time.
static void BM_overlap_errors_one_site_naive(benchmark::State& state) {
  const detail::quilt_source<std::uint8_t, 3> src(exemplar());
  const auto elements = l_shape(128, 128);
  std::vector<float> err(97 * 97);
  for (auto _ : state) {
    for (index_t v = 0; v < 97; ++v)
      for (index_t u = 0; u < 97; ++u) {
        float sum = 0;
        for (const auto& e : elements) {
          const float d = src.planes[static_cast<std::size_t>(e.offset + v * 128 + u)] - e.value;
          sum += d * d;
        }
        err[static_cast<std::size_t>(v * 97 + u)] = sum;
      }
    benchmark::DoNotOptimize(err.data());
  }
  state.counters["candidates/s"] =
      benchmark::Counter(97.0 * 97.0 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_overlap_errors_one_site_naive)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
