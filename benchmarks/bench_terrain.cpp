// Terrain synthesis (paper 003): scale field + triangle synthesis for 10^4, 10^5 and 10^6 visible
// triangles, projection, and 1920 x 1080 frames: synthesized vs plain tiled texture mapping of the
// same frame (the naive method, the same-run baseline), plus a memcpy of the frame.
//
// Counters: triangles/s (items), and for the synthesis benchmarks `vs_tiled_render`, the ratio of
// the measured time to rendering the same frame with plain tiled mapping (timed in the same run).
//
// Ground-anchored sessions (issue 18): BM_SessionFirstFrame (a fresh terrain_session's first
// update; counter caller_cpu_ms, the CPU time of the calling thread alone, next to the process's;
// with and without the relaxation of the grown regions, the same-run ratio), BM_SessionIncremental (the camera moving 1 % of its view distance per frame, back and
// forth; the overview camera with every face in view, and the grazing one) with counters stable (faces visible in consecutive frames with unchanged coordinates),
// continuous (shared edges), jump (largest level jump), resynth (faces re-synthesized per frame)
// and bytes_per_face (session memory); BM_MemcpyFaceOutput, a memcpy of the per-face corner
// coordinates (24 bytes a face), is their same-run baseline.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <tessera/image/exemplars.hpp>
#include <tessera/terrain/assign_scale_field.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/prepare_terrain_mesh.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/render_terrain_frame.hpp>
#include <tessera/terrain/render_tiled_frame.hpp>
#include <tessera/terrain/synthesize_triangles.hpp>
#include <tessera/terrain/terrain_session.hpp>

namespace {

using tessera::index_t;
constexpr index_t frame_w = 1920, frame_h = 1080, exemplar_side = 256;

struct scene {
  tessera::terrain_mesh mesh;
  tessera::screen_projection proj;
  tessera::scale_field field;
  tessera::triangle_synthesis syn;
  double tiled_ms = 0;  ///< median time of the plain tiled frame, for the ratio counters
  std::string error;    ///< why the scene could not be built (the benchmarks then skip with it)
};

/// Reports a failed status to Google Benchmark (the run shows the message instead of a figure).
bool failed(benchmark::State& state, const tessera::status& s) {
  if (s) return false;
  state.SkipWithError(s.to_string().c_str());
  return true;
}

tessera::thread_pool_executor& pool() {
  static tessera::thread_pool_executor p(2);
  return p;
}

const tessera::image_buffer<std::uint8_t, 3>& exemplar() {
  static const auto e = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::grass,
                                                                {.width = exemplar_side, .height = exemplar_side})
                            .value();
  return e;
}
const tessera::exemplar_pyramid<std::uint8_t, 3>& pyramid() {
  static const auto p = tessera::build_exemplar_pyramid(exemplar(), {.min_scale = 0.5}, pool()).value();
  return p;
}
const tessera::tiled_texture<std::uint8_t, 3>& tiled() {
  static const auto t = tessera::prepare_tiled_texture(exemplar(), pool()).value();
  return t;
}

/// A heightfield of about `triangles` faces, all visible in the overview camera.
scene& get_scene(index_t triangles) {
  static std::map<index_t, std::unique_ptr<scene>> cache;
  auto& s = cache[triangles];
  if (s) return *s;
  s = std::make_unique<scene>();
  const auto cells = static_cast<index_t>(std::llround(std::sqrt(static_cast<double>(triangles) / 2)));
  auto build = [&]() -> tessera::status {
    const auto m = tessera::make_terrain({.cells_x = cells, .cells_y = cells}, pool());
    if (!m) return m.error();
    auto mesh = tessera::prepare_terrain_mesh(*m);
    if (!mesh) return mesh.error();
    s->mesh = std::move(*mesh);
    const auto cam =
        tessera::make_camera_preset(tessera::camera_preset::overview, tessera::bounding_box(*m), frame_w, frame_h);
    if (!cam) return cam.error();
    if (auto st = tessera::project_mesh(s->mesh, *cam, s->proj, {}, pool()); !st) return st;
    if (auto st = tessera::assign_scale_field(
            s->mesh, s->proj, {.min_scale = 0.5, .max_levels = pyramid().num_levels()}, s->field, pool());
        !st)
      return st;
    if (auto st = tessera::synthesize_triangles(s->mesh, s->proj, s->field, exemplar_side, exemplar_side, {}, s->syn);
        !st)
      return st;
    tessera::image_buffer<std::uint8_t, 3> frame(frame_w, frame_h);
    std::vector<double> t;
    for (int r = 0; r < 3; ++r) {
      const auto a = std::chrono::steady_clock::now();
      if (auto st = tessera::render_tiled_frame(s->mesh, s->proj, tiled(), frame, {}, pool()); !st) return st;
      t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count());
    }
    std::sort(t.begin(), t.end());
    s->tiled_ms = t[1];
    return {};
  };
  if (auto st = build(); !st) s->error = st.to_string();
  return *s;
}

/// The scene of `triangles` faces, or nullptr after reporting why it could not be built.
scene* scene_or_skip(benchmark::State& state, index_t triangles) {
  scene& s = get_scene(triangles);
  if (s.error.empty()) return &s;
  state.SkipWithError(s.error.c_str());
  return nullptr;
}

void set_counters(benchmark::State& state, const scene& s) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * s.proj.num_visible());
  state.counters["visible"] = static_cast<double>(s.proj.num_visible());
}

// scale field + synthesis, the per-frame work of §2.2-2.3 (the goal: 10^6 under 100 ms)
template <bool Threads>
void BM_ScaleFieldAndSynthesis(benchmark::State& state) {
  scene* sp = scene_or_skip(state, state.range(0));
  if (!sp) return;
  scene& s = *sp;
  tessera::serial_executor serial;
  double total_ms = 0;
  for (auto _ : state) {
    const auto a = std::chrono::steady_clock::now();
    auto run = [&](auto& exec) {
      if (auto st = tessera::assign_scale_field(s.mesh, s.proj, {.max_levels = pyramid().num_levels()}, s.field, exec);
          !st)
        return st;
      return tessera::synthesize_triangles(s.mesh, s.proj, s.field, exemplar_side, exemplar_side, {}, s.syn, exec);
    };
    tessera::status st;
    if constexpr (Threads)
      st = run(pool());
    else
      st = run(serial);
    if (failed(state, st)) break;
    benchmark::DoNotOptimize(s.syn.offset.data());
    total_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count();
  }
  set_counters(state, s);
  state.counters["vs_tiled_render"] = total_ms / static_cast<double>(state.iterations()) / s.tiled_ms;
  state.counters["continuous_edges"] = s.syn.continuous_fraction;
}
BENCHMARK(BM_ScaleFieldAndSynthesis<false>)
    ->Name("ScaleFieldAndSynthesis/serial")
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ScaleFieldAndSynthesis<true>)
    ->Name("ScaleFieldAndSynthesis/2threads")
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ScaleField(benchmark::State& state) {
  scene* sp = scene_or_skip(state, state.range(0));
  if (!sp) return;
  scene& s = *sp;
  tessera::serial_executor serial;
  for (auto _ : state) {
    if (failed(state,
               tessera::assign_scale_field(s.mesh, s.proj, {.max_levels = pyramid().num_levels()}, s.field, serial)))
      break;
    benchmark::DoNotOptimize(s.field.level.data());
  }
  set_counters(state, s);
}
BENCHMARK(BM_ScaleField)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Synthesis(benchmark::State& state) {
  scene* sp = scene_or_skip(state, state.range(0));
  if (!sp) return;
  scene& s = *sp;
  double total_ms = 0;
  for (auto _ : state) {
    const auto a = std::chrono::steady_clock::now();
    if (failed(state, tessera::synthesize_triangles(s.mesh, s.proj, s.field, exemplar_side, exemplar_side, {}, s.syn)))
      break;
    benchmark::DoNotOptimize(s.syn.offset.data());
    total_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count();
  }
  set_counters(state, s);
  state.counters["vs_tiled_render"] = total_ms / static_cast<double>(state.iterations()) / s.tiled_ms;
}
BENCHMARK(BM_Synthesis)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Projection(benchmark::State& state) {
  scene* sp = scene_or_skip(state, state.range(0));
  if (!sp) return;
  scene& s = *sp;
  const auto cam =
      tessera::make_camera_preset(tessera::camera_preset::overview, tessera::bounding_box(s.mesh), frame_w, frame_h);
  if (failed(state, cam.error())) return;
  tessera::screen_projection p;
  for (auto _ : state) {
    if (failed(state, tessera::project_mesh(s.mesh, *cam, p, {}, pool()))) break;
    benchmark::DoNotOptimize(p.visible.data());
  }
  set_counters(state, s);
}
BENCHMARK(BM_Projection)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

// 1920 x 1080 frames of the same scene: synthesized (with seam feathering) and plain tiled
template <bool Synthesized>
void BM_Render(benchmark::State& state) {
  scene* sp = scene_or_skip(state, state.range(0));
  if (!sp) return;
  scene& s = *sp;
  tessera::image_buffer<std::uint8_t, 3> frame(frame_w, frame_h);
  for (auto _ : state) {
    tessera::status st;
    if constexpr (Synthesized)
      st = tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, pyramid(), frame, {}, pool());
    else
      st = tessera::render_tiled_frame(s.mesh, s.proj, tiled(), frame, {}, pool());
    if (failed(state, st)) break;
    benchmark::DoNotOptimize(frame.data());
  }
  set_counters(state, s);
  state.counters["pixels/s"] = benchmark::Counter(
      static_cast<double>(frame_w * frame_h) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Render<true>)
    ->Name("BM_RenderSynthesized")
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Render<false>)
    ->Name("BM_RenderTiled")
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_MemcpyFrame(benchmark::State& state) {
  std::vector<std::uint8_t> a(static_cast<std::size_t>(frame_w * frame_h * 3), 7), b(a.size());
  for (auto _ : state) {
    std::memcpy(b.data(), a.data(), a.size());
    benchmark::DoNotOptimize(b.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(a.size()));
}
BENCHMARK(BM_MemcpyFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The overview camera of a grid moved by `t` view distances along x; or the grazing camera (low
/// over one edge, looking across) moved by `t` view distances along its horizontal view direction.
tessera::terrain_camera moved_camera(const tessera::terrain_mesh& mesh, double t,
                                     tessera::camera_preset preset = tessera::camera_preset::overview) {
  auto l = tessera::camera_preset_look_at(preset, tessera::bounding_box(mesh)).value();
  const tessera::vec3 dir = l.target - l.eye;
  const double d = tessera::norm(dir);
  const tessera::vec3 h = preset == tessera::camera_preset::overview
                              ? tessera::vec3{1, 0, 0}
                              : tessera::normalized(tessera::vec3{dir.x, dir.y, 0});
  l.eye = l.eye + h * (t * d);
  l.target = l.target + h * (t * d);
  return tessera::make_camera(l, frame_w, frame_h).value();
}

/// CPU time of the calling thread in milliseconds.
double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

/// Session options: level 0 up to where a texel covers a pixel of the overview camera (as the CLI);
/// `relax` false turns the relaxation of the grown regions off (relax_iterations = 0).
tessera::result<tessera::terrain_session> make_session(const tessera::terrain_mesh& mesh, bool relax = true) {
  tessera::terrain_session_options o;
  if (!relax) o.synthesis.relax_iterations = 0;
  auto s = tessera::make_terrain_session(mesh, exemplar_side, exemplar_side, o);
  if (!s) return s;
  const double focal = 0.5 * static_cast<double>(frame_h) * moved_camera(mesh, 0).projection[1][1];
  o.near_distance = std::max(s->near_distance(), focal / s->regions().texels_per_unit);
  return tessera::make_terrain_session(mesh, exemplar_side, exemplar_side, o);
}

/// Range 0: faces; range 1: 1 the default relaxation of the grown regions, 0 none.
void BM_SessionFirstFrame(benchmark::State& state) {
  scene* s = scene_or_skip(state, state.range(0));
  if (!s) return;
  const auto cam = moved_camera(s->mesh, 0);
  double caller_ms = 0;  // CPU time of the calling thread alone (the process's minus it: the worker's)
  for (auto _ : state) {
    state.PauseTiming();
    auto session = make_session(s->mesh, state.range(1) != 0);
    state.ResumeTiming();
    if (!session) return (void)failed(state, session.error());
    const double t0 = thread_cpu_ms();
    if (failed(state, session->update(s->mesh, cam, pool()))) return;
    caller_ms += thread_cpu_ms() - t0;
    state.counters["visible"] = static_cast<double>(session->stats().visible);
    state.counters["continuous"] = session->stats().continuous_fraction;
    state.counters["bytes_per_face"] =
        static_cast<double>(session->memory_bytes()) / static_cast<double>(s->mesh.num_faces());
    state.PauseTiming();
    session = tessera::status::cancelled();  // freed outside the timing
    state.ResumeTiming();
  }
  state.counters["caller_cpu_ms"] = caller_ms / static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * s->proj.num_visible());
}
BENCHMARK(BM_SessionFirstFrame)
    ->Args({100000, 0})
    ->Args({100000, 1})
    ->Args({1000000, 0})
    ->Args({1000000, 1})
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

/// Range 0: faces; range 1: 0 the overview camera (every face in view), 1 the grazing one (faces
/// entering and leaving the view and changing level every frame); range 2: 1 the default
/// relaxation of the grown regions, 0 none.
void BM_SessionIncremental(benchmark::State& state) {
  scene* s = scene_or_skip(state, state.range(0));
  if (!s) return;
  auto session = make_session(s->mesh, state.range(2) != 0);
  if (!session) return (void)failed(state, session.error());
  const auto preset = state.range(1) == 0 ? tessera::camera_preset::overview : tessera::camera_preset::grazing;
  // 40 frames moving 1 % of the view distance each, forth then back
  std::vector<tessera::terrain_camera> path;
  for (int i = 0; i < 20; ++i) path.push_back(moved_camera(s->mesh, 0.01 * i, preset));
  for (int i = 20; i > 0; --i) path.push_back(moved_camera(s->mesh, 0.01 * i, preset));
  if (failed(state, session->update(s->mesh, path[0], pool()))) return;
  std::size_t at = 1;
  double stable = 1, continuous = 1, resynth = 0, visible = 0;
  int jump = 0;
  std::int64_t frames = 0;
  for (auto _ : state) {
    if (failed(state, session->update(s->mesh, path[at], pool()))) return;
    at = (at + 1) % path.size();
    const auto& st = session->stats();
    stable = std::min(stable, st.stable_fraction);
    continuous = std::min(continuous, st.continuous_fraction);
    jump = std::max(jump, st.max_level_jump);
    resynth += static_cast<double>(st.resynthesized);
    visible += static_cast<double>(st.visible);
    ++frames;
  }
  state.counters["stable_min"] = stable;
  state.counters["continuous_min"] = continuous;
  state.counters["jump_max"] = jump;
  state.counters["resynth"] = frames > 0 ? resynth / static_cast<double>(frames) : 0;
  state.counters["visible"] = frames > 0 ? visible / static_cast<double>(frames) : 0;
  state.counters["bytes_per_face"] =
      static_cast<double>(session->memory_bytes()) / static_cast<double>(s->mesh.num_faces());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * s->proj.num_visible());
}
BENCHMARK(BM_SessionIncremental)
    ->Args({100000, 0, 1})
    ->Args({1000000, 0, 1})
    ->Args({100000, 1, 1})
    ->Args({1000000, 1, 0})
    ->Args({1000000, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_MemcpyFaceOutput(benchmark::State& state) {
  std::vector<std::array<float, 6>> a(static_cast<std::size_t>(state.range(0)), {1, 2, 3, 4, 5, 6}), b(a.size());
  for (auto _ : state) {
    std::memcpy(b.data(), a.data(), a.size() * sizeof(a[0]));
    benchmark::DoNotOptimize(b.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(a.size() * sizeof(a[0])));
}
BENCHMARK(BM_MemcpyFaceOutput)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
