// The code blocks of docs/core.md, compiled and run (tests/structural/snippets.cmake keeps the page
// identical to the regions between the snippet markers).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <string_view>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/format.hpp>
#include <tessera/core/image.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/core/progress.hpp>
#include <tessera/core/random.hpp>
#include <tessera/core/tri_mesh.hpp>

namespace {

// Stand-in for a user's kernel, called by the dispatch_format snippet.
template <class T, int C>
tessera::status process(const tessera::image_view<T, C>& view) {
  return view.empty() ? tessera::status::invalid_argument("empty") : tessera::status{};
}

}  // namespace

TEST_CASE("docs: core.md make_image_view refuses a short stride") {
  std::vector<std::uint8_t> buffer(4 * 2 * 3);
  std::uint8_t* pixels = buffer.data();
  const tessera::index_t width = 4, height = 2, stride = 8;
  bool refused = true;
  [&] {
    // [snippet:core_make_image_view]
    auto view = tessera::make_image_view<3>(pixels, width, height, stride);
    if (!view) {
      std::fprintf(stderr, "%s\n", view.error().to_string().c_str());
      // invalid_argument: image_view: stride 8 is smaller than width * channels = 12 (stride counts channel values, not bytes)
      return;
    }
    tessera::image_view<std::uint8_t, 3> v = *view;
    // [/snippet]
    refused = v.empty();
  }();
  CHECK(refused);
}

TEST_CASE("docs: core.md convert_pixel") {
  // [snippet:core_convert_pixel]
  using tessera::pixel;
  auto rgba = tessera::convert_pixel<pixel<std::uint16_t, 4>>(pixel<std::uint8_t, 3>{200, 100, 50});
  // {51400, 25700, 12850, 65535}
  float grey = tessera::convert_pixel<float>(pixel<float, 3>{1, 0, 0});  // 0.299
  // [/snippet]
  CHECK(rgba == pixel<std::uint16_t, 4>{51400, 25700, 12850, 65535});
  CHECK(grey == Approx(0.299f));
}

TEST_CASE("docs: core.md views over an atlas") {
  // [snippet:core_atlas_views]
  std::vector<std::uint8_t> atlas(512 * 256 * 4);
  auto whole = tessera::make_image_view<4>(atlas.data(), 512, 256);          // packed RGBA
  auto tile = whole->subview(128, 0, 128, 128);                              // same memory, stride 2048
  auto rows = tessera::make_image_view<4>(atlas.data(), 100, 256, 512 * 4);  // explicit stride
  // [/snippet]
  CHECK(tile.stride() == 2048);
  CHECK(rows->stride() == 2048);
}

TEST_CASE("docs: core.md dispatch_format") {
  std::vector<std::uint16_t> pixels(8 * 4 * 3);
  void* data = pixels.data();
  const tessera::index_t w = 8, h = 4;
  const int channels_from_file = 3;
  // [snippet:core_dispatch_format]
  tessera::pixel_format fmt{tessera::channel_type::uint16, channels_from_file};
  tessera::status s = tessera::dispatch_format(fmt, [&]<class T, int C>(tessera::format_tag<T, C>) {
    auto view = tessera::make_image_view<C>(static_cast<T*>(data), w, h);
    if (!view) return view.error();
    return process(*view);  // instantiated once per (T, C): 12 combinations at most
  });
  // [/snippet]
  CHECK(s.ok());
}

TEST_CASE("docs: core.md a mesh over raw buffers") {
  const tessera::status result = [] {
    // [snippet:core_mesh_view]
    const std::vector<float> vb = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    const std::vector<std::uint32_t> ib = {0, 1, 2, 2, 1, 3};
    auto view = tessera::make_mesh_view(vb.data(), 4, ib.data(), 2);
    if (auto s = tessera::validate_mesh(*view, "quad"); !s) return s;
    auto adjacency = tessera::face_adjacency(*view);    // neighbor[0][1] == 1, boundary_edges == 4
    auto parts = tessera::connected_components(*view);  // parts.count == 1
    // [/snippet]
    CHECK(adjacency.neighbor[0][1] == 1);
    CHECK(adjacency.boundary_edges == 4);
    CHECK(parts.count == 1);
    return tessera::status{};
  }();
  CHECK(result.ok());
}

TEST_CASE("docs: core.md executors") {
  // [snippet:core_executor]
  tessera::thread_pool_executor pool(8);
  std::vector<double> roots(1000);
  pool.parallel_for(0, 1000, [&](tessera::index_t i) { roots[std::size_t(i)] = std::sqrt(double(i)); });
  // each index writes its own slot: the same bytes as with tessera::serial_executor{}
  // [/snippet]
  CHECK(roots[81] == 9.0);
}

TEST_CASE("docs: core.md counter_rng") {
  const std::uint64_t seed = 7, num_patches = 40;
  const std::int64_t cell_x = 3, cell_y = -2, tile = 5;
  std::vector<int> order(10);
  std::iota(order.begin(), order.end(), 0);
  // [snippet:core_counter_rng]
  const tessera::counter_rng rng(seed, tessera::stream_id("patch.placement"));
  std::uint64_t patch = rng.below(num_patches, cell_x, cell_y);  // uniform in [0, num_patches)
  double jitter = rng.uniform(cell_x, cell_y, 1);                // uniform in [0, 1)
  auto seq = rng.sequence(tile);                                 // several draws for one decision
  std::shuffle(order.begin(), order.end(), seq);                 // a UniformRandomBitGenerator
  // [/snippet]
  CHECK(patch < num_patches);
  CHECK(jitter >= 0.0);
  CHECK(jitter < 1.0);
}

TEST_CASE("docs: core.md progress and cancellation") {
  struct {
    tessera::progress progress;
  } options;
  // [snippet:core_progress]
  tessera::cancellation_token stop;  // e.g. raised by a UI thread: stop.cancel()
  options.progress = {.callback =
                          [](double f, std::string_view stage) {
                            std::printf("%.*s %3.0f%%\n", int(stage.size()), stage.data(), 100 * f);
                            return true;
                          },
                      .token = &stop};
  // [/snippet]
  CHECK(options.progress.report(0.5, "docs"));
  stop.cancel();
  CHECK_FALSE(options.progress.report(0.6, "docs"));
}
