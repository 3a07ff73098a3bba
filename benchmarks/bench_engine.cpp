// Benchmarks of engine integration (issue 19): writing into an engine's own texture and mesh types.
//
// Images: compose_tiles (1024² window, hash colouring) and synthesize (512² window) into an engine
// texture (RGBA8 packed in a uint32, adapted through image_traits) without the contiguous-memory
// trait (every pixel through image_traits::write) and with it (image_traits::view, core/image_rows.hpp),
// against an image_view over the same kind of memory: the same-run baseline.
//
// Meshes: a 64 x 64-tile geometric plane (ring tiles of size 4.0, as bench_geometry) three ways: as tessera's
// tri_mesh (double positions, int64 indices); that tri_mesh converted into float / uint32 engine
// buffers (write_mesh); and written straight into the engine buffers through a mesh_sink. Peak
// memory is the largest number of bytes live on the heap during one iteration (counted by this
// program's operator new / delete), reported as the counter peak_MB.
#include <benchmark/benchmark.h>

#include <malloc.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/image_rows.hpp>
#include <tessera/core/mesh_sink.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include "../tests/core/packed_texture_support.hpp"

// ---- heap accounting (live and peak bytes)
namespace {
std::atomic<std::int64_t> live_bytes{0}, peak_bytes{0};
void count(std::int64_t d) {
  const std::int64_t now = live_bytes.fetch_add(d) + d;
  std::int64_t peak = peak_bytes.load();
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {}
}
void reset_peak() { peak_bytes.store(live_bytes.load()); }
double peak_mb(std::int64_t base) { return double(peak_bytes.load() - base) / 1e6; }
}  // namespace
void* operator new(std::size_t n) {
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  count(std::int64_t(malloc_usable_size(p)));
  return p;
}
void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  count(-std::int64_t(malloc_usable_size(p)));
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

using namespace tessera;

// ---- the engine's texture: RGBA8 packed in uint32, with and without the contiguous trait (the
// tests' adapter, tests/core/packed_texture_support.hpp)
using texture = test_support::packed_texture;
using texture_no_trait = test_support::packed_texture_slow;
static_assert(ContiguousImage<texture> && !ContiguousImage<texture_no_trait>);

namespace {
const wang_tile_set<std::uint8_t, 4>& wang() {
  static const auto set =
      *build_wang_tiles(*make_exemplar<std::uint8_t, 4>(exemplar_kind::cells, {.width = 128, .height = 128, .seed = 3}),
                        {.tile_size = 64});
  return set;
}
const hash_coloring& plane() {
  static const auto c = *hash_coloring::create(2, 2, 7);
  return c;
}
const patch_model<std::uint8_t, 4>& model() {
  static const auto m =
      *build_patch_model(*make_exemplar<std::uint8_t, 4>(exemplar_kind::rock, {.width = 128, .height = 128}));
  return m;
}
constexpr index_t compose_size = 1024, synth_size = 512;

template <class Out>
void compose_into(benchmark::State& state, Out& out) {
  thread_pool_executor pool(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    if (!compose_tiles(wang(), plane(), out, {.x = -300, .y = 77}, pool).ok()) state.SkipWithError("compose failed");
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(double(compose_size * compose_size) * double(state.iterations()), benchmark::Counter::kIsRate);
}
template <class Out>
void synthesize_into(benchmark::State& state, Out& out) {
  thread_pool_executor pool(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    if (!synthesize(model(), out, {.origin = {1000, -40}, .seed = 3}, pool).ok()) state.SkipWithError("failed");
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(double(synth_size * synth_size) * double(state.iterations()), benchmark::Counter::kIsRate);
}
}  // namespace

// Baseline: an image_view over uint32 texels.
static void BM_compose_image_view(benchmark::State& state) {
  std::vector<std::uint32_t> texels(std::size_t(compose_size * compose_size));
  auto view = *make_image_view<4>(reinterpret_cast<std::uint8_t*>(texels.data()), compose_size, compose_size);
  compose_into(state, view);
}
BENCHMARK(BM_compose_image_view)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();
static void BM_compose_adapted_no_trait(benchmark::State& state) {
  auto t = texture_no_trait::make(compose_size, compose_size);
  compose_into(state, t);
}
BENCHMARK(BM_compose_adapted_no_trait)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
static void BM_compose_adapted_trait(benchmark::State& state) {
  auto t = texture::make(compose_size, compose_size);
  compose_into(state, t);
}
BENCHMARK(BM_compose_adapted_trait)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_synthesize_image_view(benchmark::State& state) {
  std::vector<std::uint32_t> texels(std::size_t(synth_size * synth_size));
  auto view = *make_image_view<4>(reinterpret_cast<std::uint8_t*>(texels.data()), synth_size, synth_size);
  synthesize_into(state, view);
}
BENCHMARK(BM_synthesize_image_view)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();
static void BM_synthesize_adapted_no_trait(benchmark::State& state) {
  auto t = texture_no_trait::make(synth_size, synth_size);
  synthesize_into(state, t);
}
BENCHMARK(BM_synthesize_adapted_no_trait)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
static void BM_synthesize_adapted_trait(benchmark::State& state) {
  auto t = texture::make(synth_size, synth_size);
  synthesize_into(state, t);
}
BENCHMARK(BM_synthesize_adapted_trait)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// ---- 64 x 64 geometric plane
namespace {
const geometric_tile_set& ring_tiles() {
  static const auto set = [] {
    auto prepared = *prepare_quilt_exemplar(*make_ring_exemplar());
    geometric_wang_options o;
    o.tile_size = 4.0;  // as bench_geometry's BM_tile_plane_64x64/1: 4.5M triangles
    thread_pool_executor pool(2);
    return *build_geometric_wang_tiles(prepared, o, pool);
  }();
  return set;
}
const hash_coloring_window& plane_window() {
  static const auto w =
      *hash_coloring::create(ring_tiles().horizontal_colors, ring_tiles().vertical_colors, 5)->window(0, 0, 64, 64);
  return w;
}
struct engine_buffers {
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
};
mesh_sink<float, std::uint32_t> sink_into(engine_buffers& b) {
  return *make_growing_mesh_sink<float, std::uint32_t>(
      [&b](std::size_t bytes, std::size_t count, mesh_buffers<std::uint32_t>& out) {
        b.vertices.resize(bytes / sizeof(float));
        b.indices.resize(count);
        out = {b.vertices.data(), b.vertices.size() * sizeof(float), b.indices.data(), b.indices.size()};
        return status{};
      });
}
template <class F>
void plane_bench(benchmark::State& state, F&& run) {
  (void)plane_window();  // build the tile set outside the timing
  thread_pool_executor pool(static_cast<int>(state.range(0)));
  double peak = 0;
  for (auto _ : state) {
    const std::int64_t base = live_bytes.load();
    reset_peak();
    run(pool);
    peak = peak_mb(base);
  }
  state.counters["peak_MB"] = peak;
}
}  // namespace

// Baseline: tessera's tri_mesh.
static void BM_plane64_tri_mesh(benchmark::State& state) {
  plane_bench(state, [](thread_pool_executor& pool) {
    auto m = tile_geometric_plane(ring_tiles(), plane_window(), 64, 64, pool);
    benchmark::DoNotOptimize(m);
  });
}
BENCHMARK(BM_plane64_tri_mesh)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();
// The tri_mesh, then converted into float / uint32 engine buffers.
static void BM_plane64_tri_mesh_then_convert(benchmark::State& state) {
  plane_bench(state, [](thread_pool_executor& pool) {
    auto m = tile_geometric_plane(ring_tiles(), plane_window(), 64, 64, pool);
    engine_buffers b;
    auto sink = sink_into(b);
    if (!m || !write_mesh(*m, sink).ok()) std::abort();
    benchmark::DoNotOptimize(b.vertices.data());
  });
}
BENCHMARK(BM_plane64_tri_mesh_then_convert)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// Straight into the float / uint32 engine buffers.
static void BM_plane64_sink(benchmark::State& state) {
  plane_bench(state, [](thread_pool_executor& pool) {
    engine_buffers b;
    auto sink = sink_into(b);
    if (!tile_geometric_plane(ring_tiles(), plane_window(), 64, 64, sink, pool).ok()) std::abort();
    benchmark::DoNotOptimize(b.vertices.data());
  });
}
BENCHMARK(BM_plane64_sink)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
