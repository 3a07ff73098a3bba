// 12_engine: tessera as an engine meets it. The engine brings its own texture type (RGBA8 packed in
// a uint32, R in the low byte), its own mesh type (interleaved float xyz + colour, uint16 indices)
// and its own job system; tessera reaches all three through traits and concepts, and writes into
// the engine's memory directly:
//
//  - the texture's image_traits also expose its texels as an image_view (image_traits::view,
//    core/image_rows.hpp), so compose_tiles and synthesize write whole rows into it, as fast as into
//    an image_view;
//  - a camera moves over the ground; a streaming texture cache keeps the 128 x 128 pages around it,
//    rendering the missing ones as it goes: Wang-tile windows (compose_tiles with the infinite hash
//    colouring, west of x = 0) and patch-synthesis windows (east of it), both with progress reports;
//    a request the camera has moved away from is cancelled through a cancellation_token;
//  - geometric Wang tiles are written straight into the engine's vertex and index buffers through a
//    growing mesh_sink<float, uint16_t> (16-byte vertex records), chunk by chunk; a chunk too large
//    for 16-bit indices is refused with a status saying so, and split.
//
// Writes 12_engine_frame_N.png (what the camera sees, frames 0-3), 12_engine_cache.png (every page
// of the cache) and 12_engine_chunk.obj (one geometric chunk, from the engine's buffers).
// Usage: example_12_engine [OUTPUT_DIR]
#include <tessera/core/executor.hpp>
#include <tessera/core/image.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_rows.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/core/mesh.hpp>
#include <tessera/core/mesh_sink.hpp>
#include <tessera/core/progress.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/io/png.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

// ------------------------------------------------------------------------------------------------
// The engine's code: no tessera in it.
namespace engine {
class Texture {  // RGBA8 packed in a uint32, R in the low byte
 public:
  Texture() = default;
  Texture(int w, int h) : w_(w), h_(h), texels_(std::size_t(w) * std::size_t(h), 0xff000000u) {}
  int Width() const { return w_; }
  int Height() const { return h_; }
  std::uint32_t Get(int x, int y) const { return texels_[std::size_t(y) * std::size_t(w_) + std::size_t(x)]; }
  void Set(int x, int y, std::uint32_t v) { texels_[std::size_t(y) * std::size_t(w_) + std::size_t(x)] = v; }
  std::uint32_t* Texels() { return texels_.data(); }

 private:
  int w_ = 0, h_ = 0;
  std::vector<std::uint32_t> texels_;
};

struct Vertex {  // 16-byte interleaved record
  float x, y, z;
  std::uint32_t color;
};
struct StaticMesh {
  std::vector<Vertex> vertices;
  std::vector<std::uint16_t> indices;
};

// The engine's job system: a fixed pool of workers sharing one loop at a time.
class JobPool {
 public:
  explicit JobPool(int workers) {
    for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { Work(); });
  }
  JobPool(const JobPool&) = delete;
  JobPool& operator=(const JobPool&) = delete;
  ~JobPool() {
    {
      std::lock_guard<std::mutex> lock(m_);
      quit_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
  }
  // Runs fn(i) for i in [begin, end) on the workers and the caller; returns when all are done.
  void ParallelFor(std::int64_t begin, std::int64_t end, const std::function<void(std::int64_t)>& fn) {
    if (end <= begin) return;
    std::unique_lock<std::mutex> lock(m_);
    fn_ = &fn;
    next_ = begin;
    end_ = end;
    busy_ = static_cast<int>(threads_.size());
    ++generation_;
    lock.unlock();
    wake_.notify_all();
    Drain();
    lock.lock();
    done_.wait(lock, [&] { return busy_ == 0; });
    fn_ = nullptr;
  }

 private:
  void Drain() {
    for (std::int64_t i; (i = next_.fetch_add(1)) < end_;) (*fn_)(i);
  }
  void Work() {
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(m_);
    for (;;) {
      wake_.wait(lock, [&] { return quit_ || generation_ != seen; });
      if (quit_) return;
      seen = generation_;
      lock.unlock();
      Drain();
      lock.lock();
      if (--busy_ == 0) done_.notify_one();
    }
  }
  std::vector<std::thread> threads_;
  std::mutex m_;
  std::condition_variable wake_, done_;
  const std::function<void(std::int64_t)>* fn_ = nullptr;
  std::atomic<std::int64_t> next_{0};
  std::int64_t end_ = 0;
  int busy_ = 0;
  std::uint64_t generation_ = 0;
  bool quit_ = false;
};
}  // namespace engine

// ------------------------------------------------------------------------------------------------
// The adapters: what the engine team writes once.

// [snippet:engine-contiguous-texture]
template <>
struct tessera::image_traits<engine::Texture> {
  using rgba8 = tessera::pixel<std::uint8_t, 4>;
  static index_t width(const engine::Texture& t) { return t.Width(); }
  static index_t height(const engine::Texture& t) { return t.Height(); }
  static rgba8 read(const engine::Texture& t, index_t x, index_t y) {
    const std::uint32_t v = t.Get(int(x), int(y));
    return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
  }
  static void write(engine::Texture& t, index_t x, index_t y, const rgba8& p) {
    t.Set(int(x), int(y),
          std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24);
  }
  // The fast path: the texels are rows of memory holding R, G, B, A bytes (R in the low byte of a
  // little-endian uint32), exactly what read() and write() show. tessera writes rows through it.
  static_assert(std::endian::native == std::endian::little, "RGBA8-in-uint32 is R, G, B, A in memory");
  static tessera::image_view<std::uint8_t, 4> view(engine::Texture& t) {
    return {reinterpret_cast<std::uint8_t*>(t.Texels()), t.Width(), t.Height()};
  }
};
static_assert(tessera::ContiguousImage<engine::Texture>);
// [/snippet]

// The engine's job system as a tessera Executor: one member, parallel_for.
struct job_pool_executor {
  engine::JobPool* pool;
  template <class F>
  void parallel_for(tessera::index_t begin, tessera::index_t end, F&& fn) const {
    const std::function<void(std::int64_t)> job = [&fn](std::int64_t i) { fn(tessera::index_t(i)); };
    pool->ParallelFor(begin, end, job);
  }
};
static_assert(tessera::Executor<job_pool_executor>);

// The engine mesh as a tessera Mesh (read back for the OBJ).
template <>
struct tessera::mesh_traits<engine::StaticMesh> {
  static index_t num_vertices(const engine::StaticMesh& m) { return index_t(m.vertices.size()); }
  static index_t num_faces(const engine::StaticMesh& m) { return index_t(m.indices.size() / 3); }
  static index_t face_vertex(const engine::StaticMesh& m, index_t f, int k) {
    return m.indices[std::size_t(3 * f + k)];
  }
  static std::array<float, 3> position(const engine::StaticMesh& m, index_t v) {
    const engine::Vertex& p = m.vertices[std::size_t(v)];
    return {p.x, p.y, p.z};
  }
};
static_assert(tessera::Mesh<engine::StaticMesh>);

// [snippet:engine-mesh-sink]
// A sink that grows the engine's own vectors: positions at byte 0 of each 16-byte Vertex.
tessera::result<tessera::mesh_sink<float, std::uint16_t>> sink_into(engine::StaticMesh& mesh) {
  return tessera::make_growing_mesh_sink<float, std::uint16_t>(
      [&mesh](std::size_t vertex_bytes, std::size_t index_count, tessera::mesh_buffers<std::uint16_t>& b) {
        mesh.vertices.resize((vertex_bytes + sizeof(engine::Vertex) - 1) / sizeof(engine::Vertex),
                             engine::Vertex{0, 0, 0, 0xff808080u});
        mesh.indices.resize(index_count);
        b = {mesh.vertices.data(), mesh.vertices.size() * sizeof(engine::Vertex), mesh.indices.data(),
             mesh.indices.size()};
        return tessera::status{};
      },
      {.offset = offsetof(engine::Vertex, x), .stride = sizeof(engine::Vertex)});
}
// [/snippet]

namespace {
using tessera::index_t;
int fail(const tessera::status& s) {
  std::fprintf(stderr, "12_engine: %s\n", s.to_string().c_str());
  return 1;
}
constexpr int page = 128;  // texture cache page size, pixels
}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  engine::JobPool jobs(std::max(1u, std::thread::hardware_concurrency()) - 1);
  const job_pool_executor exec{&jobs};

  // ---- content, prepared once (at load time in a real engine)
  auto cells = tessera::make_exemplar<std::uint8_t, 4>(tessera::exemplar_kind::cells, {.width = 96, .height = 96});
  auto rock = tessera::make_exemplar<std::uint8_t, 4>(tessera::exemplar_kind::rock, {.width = 128, .height = 128});
  if (!cells || !rock) return fail(!cells ? cells.error() : rock.error());
  auto wang = tessera::build_wang_tiles(*cells, {.tile_size = 64, .seed = 3}, exec);
  if (!wang) return fail(wang.error());
  auto plane_colors = tessera::hash_coloring::create(2, 2, 17);  // the infinite colouring
  if (!plane_colors) return fail(plane_colors.error());
  auto model = tessera::build_patch_model(*rock, {}, exec);
  if (!model) return fail(model.error());

  // ---- the streaming texture cache: pages keyed by (page x, page y)
  std::map<std::pair<int, int>, engine::Texture> cache;
  int rendered = 0, reports = 0;
  tessera::cancellation_token stale;  // raised when the camera no longer needs a request
  auto render_page = [&](int px, int py, engine::Texture& tex) -> tessera::status {
    const tessera::progress progress{.callback =
                                         [&](double, std::string_view) {
                                           ++reports;
                                           return true;
                                         },
                                     .token = &stale};
    if (px < 0) {  // west: Wang tiles; compose_tiles takes the infinite hash colouring directly
      return tessera::compose_tiles(*wang, *plane_colors, tex, {.x = px * page, .y = py * page, .seed = 5}, exec);
    }
    auto stats = tessera::synthesize(*model, tex, {.origin = {px * page, py * page}, .seed = 9, .progress = progress},
                                     exec);  // east: patch synthesis
    return stats ? tessera::status{} : stats.error();
  };

  // A request that becomes stale: the camera teleports before it is rendered; the token cancels it.
  {
    engine::Texture tex(page, page);
    stale.cancel();
    const tessera::status s = render_page(40, 40, tex);
    std::printf("stale request for page (40, 40): %s\n", s.to_string().c_str());
    if (s.code() != tessera::status_code::cancelled) return 1;
    stale.reset();
  }

  // The camera: a 320 x 192 viewport moving east across x = 0, four frames.
  const int view_w = 320, view_h = 192;
  for (int frame = 0; frame < 4; ++frame) {
    const int cam_x = -400 + frame * 180, cam_y = -60 + frame * 20;  // top-left of the viewport, world pixels
    const int p0x = int(tessera::floor_div(cam_x, page)), p1x = int(tessera::floor_div(cam_x + view_w - 1, page));
    const int p0y = int(tessera::floor_div(cam_y, page)), p1y = int(tessera::floor_div(cam_y + view_h - 1, page));
    for (int py = p0y; py <= p1y; ++py)
      for (int px = p0x; px <= p1x; ++px) {
        if (cache.count({px, py})) continue;
        engine::Texture tex(page, page);
        if (auto s = render_page(px, py, tex); !s) return fail(s);
        cache.emplace(std::make_pair(px, py), std::move(tex));
        ++rendered;
      }
    // the frame: the visible part of every page, copied by the engine
    engine::Texture screen(view_w, view_h);
    for (int y = 0; y < view_h; ++y)
      for (int x = 0; x < view_w; ++x) {
        const int wx = cam_x + x, wy = cam_y + y;
        const int px = int(tessera::floor_div(wx, page)), py = int(tessera::floor_div(wy, page));
        screen.Set(x, y, cache.at({px, py}).Get(wx - px * page, wy - py * page));
      }
    const std::string path = dir + "/12_engine_frame_" + std::to_string(frame) + ".png";
    if (auto s = tessera::write_png(path, screen); !s) return fail(s);  // any Image, the engine's too
    // evict pages more than one page away from the viewport
    for (auto it = cache.begin(); it != cache.end();)
      it = (it->first.first < p0x - 1 || it->first.first > p1x + 1 || it->first.second < p0y - 1 ||
            it->first.second > p1y + 1)
               ? cache.erase(it)
               : std::next(it);
    std::printf("frame %d: camera (%d, %d), %zu pages cached, %d rendered so far\n", frame, cam_x, cam_y, cache.size(),
                rendered);
  }
  std::printf("%d progress reports from patch synthesis\n", reports);

  // Streaming is consistent: a page rendered alone equals the same region of one large render.
  {
    engine::Texture big(3 * page, page), alone(page, page);
    if (auto s = tessera::compose_tiles(*wang, *plane_colors, big, {.x = -3 * page, .y = 0, .seed = 5}, exec); !s)
      return fail(s);
    if (auto s = render_page(-2, 0, alone); !s) return fail(s);
    bool same = true;
    for (int y = 0; y < page; ++y)
      for (int x = 0; x < page; ++x) same = same && big.Get(page + x, y) == alone.Get(x, y);
    std::printf("page (-2, 0) rendered alone %s the same region of a 3-page render\n",
                same ? "equals" : "DIFFERS from");
    if (!same) return 1;
  }

  // A picture of the cache's last contents, side by side.
  {
    engine::Texture sheet(int(cache.size()) * (page + 4), page);
    int i = 0;
    for (auto& [key, tex] : cache) {
      auto dst = tessera::contiguous_view(sheet).subview(i++ * (page + 4), 0, page, page);
      if (auto s = tessera::copy_image(tex, dst); !s) return fail(s);
    }
    if (auto s = tessera::write_png(dir + "/12_engine_cache.png", sheet); !s) return fail(s);
  }

  // ---- geometric tiles into the engine's vertex and index buffers
  auto rings = tessera::make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 10, .tube_segments = 5});
  if (!rings) return fail(rings.error());
  auto prepared = tessera::prepare_quilt_exemplar(*rings);
  if (!prepared) return fail(prepared.error());
  tessera::geometric_wang_options go;
  go.tile_size = 4.0;
  go.quilt.seed = 11;
  auto tiles = tessera::build_geometric_wang_tiles(*prepared, go);
  if (!tiles) return fail(tiles.error());
  auto hash = tessera::hash_coloring::create(tiles->horizontal_colors, tiles->vertical_colors, 23);
  if (!hash) return fail(hash.error());
  // One 48 x 48-tile chunk does not fit 16-bit indices: the sink says so before writing anything ...
  {
    engine::StaticMesh too_big;
    auto sink = sink_into(too_big);
    auto window = hash->window(0, 0, 48, 48);
    if (!sink || !window) return 1;
    const tessera::status s = tessera::tile_geometric_plane(*tiles, *window, 48, 48, *sink, exec);
    std::printf("48 x 48 tiles into uint16 indices: %s\n", s.to_string().c_str());
    if (s.code() != tessera::status_code::size_overflow || !too_big.vertices.empty()) return 1;
  }
  // ... so the engine streams 4 x 4-tile chunks, each in its own uint16 buffers.
  std::vector<engine::StaticMesh> chunks(4);
  for (int c = 0; c < 4; ++c) {
    auto sink = sink_into(chunks[std::size_t(c)]);
    auto window = hash->window(4 * (c % 2), 4 * (c / 2), 4, 4);  // the chunk's cells of the infinite colouring
    if (!sink) return fail(sink.error());
    if (!window) return fail(window.error());
    if (auto s = tessera::tile_geometric_plane(*tiles, *window, 4, 4, *sink, exec); !s) return fail(s);
    std::printf("chunk %d: %zu vertices, %zu triangles in the engine's buffers\n", c,
                chunks[std::size_t(c)].vertices.size(), chunks[std::size_t(c)].indices.size() / 3);
  }
  if (auto s = tessera::write_obj(dir + "/12_engine_chunk.obj", chunks[0]); !s) return fail(s);
  std::printf("wrote 12_engine_frame_0..3.png, 12_engine_cache.png and 12_engine_chunk.obj in %s\n", dir.c_str());
  return 0;
}
