// File I/O throughput: PNG encode/decode (pixels/s) and mesh formats (triangles/s, bytes/s), each
// against a same-run memcpy of the same bytes, so figures read as ratios.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <tessera/image/exemplars.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/io/off.hpp>
#include <tessera/io/ply.hpp>
#include <tessera/io/png.hpp>

namespace {

const tessera::image_buffer<std::uint8_t, 3>& exemplar() {
  static const auto img =
      *tessera::make_exemplar(tessera::exemplar_kind::rock, {.width = 512, .height = 512, .seed = 1});
  return img;
}

// A 256 x 256-quad grid (131072 triangles) with uvs.
const tessera::tri_mesh& grid() {
  static const tessera::tri_mesh m = [] {
    tessera::tri_mesh g;
    const int n = 256;
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) g.add_vertex({x * 0.01, y * 0.01, 0.001 * ((x * 7 + y * 13) % 17)});
    auto id = [&](int x, int y) { return tessera::index_t{y * (n + 1) + x}; };
    auto uv = [&](int x, int y) { return tessera::vec2{x / double(n), y / double(n)}; };
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        g.add_face(id(x, y), id(x + 1, y), id(x + 1, y + 1), {uv(x, y), uv(x + 1, y), uv(x + 1, y + 1)});
        g.add_face(id(x, y), id(x + 1, y + 1), id(x, y + 1), {uv(x, y), uv(x + 1, y + 1), uv(x, y + 1)});
      }
    return g;
  }();
  return m;
}

void set_bytes(benchmark::State& state, std::size_t bytes) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}

void BM_Memcpy(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<char> a(n, 1), b(n);
  for (auto _ : state) {
    std::memcpy(b.data(), a.data(), n);
    benchmark::DoNotOptimize(b.data());
    benchmark::ClobberMemory();
  }
  set_bytes(state, n);
}
BENCHMARK(BM_Memcpy)->Arg(512 * 512 * 3)->Arg(8 << 20);

void BM_PngEncode(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(tessera::encode_png(exemplar()));
  state.counters["pixels/s"] = benchmark::Counter(512.0 * 512, benchmark::Counter::kIsIterationInvariantRate);
  set_bytes(state, 512 * 512 * 3);
}
BENCHMARK(BM_PngEncode)->Unit(benchmark::kMillisecond);

void BM_PngDecode(benchmark::State& state) {
  const auto png = *tessera::encode_png(exemplar());
  for (auto _ : state) benchmark::DoNotOptimize(tessera::decode_png<std::uint8_t, 3>(png.data(), png.size()));
  state.counters["pixels/s"] = benchmark::Counter(512.0 * 512, benchmark::Counter::kIsIterationInvariantRate);
  set_bytes(state, 512 * 512 * 3);
}
BENCHMARK(BM_PngDecode)->Unit(benchmark::kMillisecond);

template <int Format>
std::string format_mesh(const tessera::tri_mesh& m) {
  if constexpr (Format == 0)
    return tessera::format_obj(m);
  else if constexpr (Format == 1)
    return tessera::format_off(m);
  else if constexpr (Format == 2)
    return tessera::format_ply(m);
  else
    return tessera::format_ply(m, {.binary = true});
}
template <int Format>
tessera::result<tessera::tri_mesh> parse_mesh(std::string_view text) {
  if constexpr (Format == 0)
    return tessera::parse_obj(text);
  else if constexpr (Format == 1)
    return tessera::parse_off(text);
  else
    return tessera::parse_ply(text);
}

template <int Format>
void BM_MeshWrite(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string s = format_mesh<Format>(grid());
    bytes = s.size();
    benchmark::DoNotOptimize(s.data());
  }
  state.counters["triangles/s"] =
      benchmark::Counter(static_cast<double>(grid().num_faces()), benchmark::Counter::kIsIterationInvariantRate);
  set_bytes(state, bytes);
}
template <int Format>
void BM_MeshRead(benchmark::State& state) {
  const std::string s = format_mesh<Format>(grid());
  for (auto _ : state) {
    auto m = parse_mesh<Format>(s);
    if (!m) state.SkipWithError(m.error().to_string().c_str());
    benchmark::DoNotOptimize(m);
  }
  state.counters["triangles/s"] =
      benchmark::Counter(static_cast<double>(grid().num_faces()), benchmark::Counter::kIsIterationInvariantRate);
  set_bytes(state, s.size());
}
BENCHMARK_TEMPLATE(BM_MeshWrite, 0)->Name("BM_MeshWrite/obj")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_MeshWrite, 1)->Name("BM_MeshWrite/off")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_MeshWrite, 2)->Name("BM_MeshWrite/ply_ascii")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_MeshWrite, 3)->Name("BM_MeshWrite/ply_binary")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_MeshRead, 0)->Name("BM_MeshRead/obj")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_MeshRead, 1)->Name("BM_MeshRead/off")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_MeshRead, 2)->Name("BM_MeshRead/ply_ascii")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_MeshRead, 3)->Name("BM_MeshRead/ply_binary")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
