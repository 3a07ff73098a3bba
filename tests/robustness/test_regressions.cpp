// Regression tests of issue 21 ("never crash on what users feed it"): each case below crashed,
// aborted or allocated gigabytes before the fix; now each gives a valid output or a clear status.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/geometry/constrained_mesh_quilt.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_size.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/image/quilt.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/tiling/complete_tile_set.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include "../support/test_support.hpp"

using tessera_test::mentions;

using tessera::index_t;

namespace {

template <class T, int C>
tessera::image_buffer<T, C> flat(index_t w, index_t h, tessera::pixel<T, C> p) {
  return tessera::image_buffer<T, C>(w, h, p);
}

// Builds a patch model of a flat exemplar and checks that synthesis reproduces the flat colour.
template <class T, int C>
void check_flat_synthesis(tessera::pixel<T, C> colour, tessera::seam_mode seams) {
  const auto ex = flat<T, C>(48, 48, colour);
  tessera::patch_model_options mo;
  mo.seams = seams == tessera::seam_mode::cut;
  auto model = tessera::build_patch_model(ex, mo);
  REQUIRE(model);
  tessera::image_buffer<T, C> out(40, 30);
  auto st = tessera::synthesize(*model, out, {.seed = 3, .seams = seams});
  REQUIRE(st);
  for (index_t y = 0; y < out.height(); ++y)
    for (index_t x = 0; x < out.width(); ++x) REQUIRE(out.read(x, y) == colour);
}

}  // namespace

TEST_CASE("issue 21: a flat exemplar builds a patch model and synthesizes its colour") {
  check_flat_synthesis<std::uint8_t, 3>({100, 50, 20}, tessera::seam_mode::feather);
  check_flat_synthesis<std::uint8_t, 3>({100, 50, 20}, tessera::seam_mode::cut);
  check_flat_synthesis<std::uint8_t, 3>({0, 0, 0}, tessera::seam_mode::feather);
  check_flat_synthesis<std::uint8_t, 4>({0, 0, 0, 0}, tessera::seam_mode::cut);
  check_flat_synthesis<float, 1>({0.25f}, tessera::seam_mode::feather);
  check_flat_synthesis<std::uint16_t, 2>({65535, 0}, tessera::seam_mode::cut);
}

TEST_CASE("issue 21: exact sets and a two-valued exemplar work too") {
  auto ex = flat<std::uint8_t, 1>(40, 40, {0});
  for (index_t x = 0; x < 40; ++x) ex.write(x, 20, {255});  // one bright row: rank-1 strips
  tessera::patch_model_options mo;
  mo.exact_sets = true;
  auto model = tessera::build_patch_model(ex, mo);
  REQUIRE(model);
  mo.exact_sets = false;
  REQUIRE(tessera::build_patch_model(ex, mo));
}

TEST_CASE("issue 21: one NaN or infinity in a float exemplar is refused by name") {
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity()}) {
    auto ex = tessera::make_exemplar<float, 3>(tessera::exemplar_kind::rock, {.width = 48, .height = 48}).value();
    auto p = ex.read(7, 5);
    p[1] = bad;
    ex.write(7, 5, p);
    auto model = tessera::build_patch_model(ex);
    REQUIRE_FALSE(model);
    CHECK(model.error().code() == tessera::status_code::invalid_argument);
    CHECK(mentions(model.error(), "exemplar: pixel (7, 5) channel 1"));
    auto analysis = tessera::analyze_patch_size(ex);
    REQUIRE_FALSE(analysis);
    CHECK(mentions(analysis.error(), "pixel (7, 5)"));
    REQUIRE_FALSE(tessera::analyze_overlap(ex, 8, 8));
    auto pyramid = tessera::build_exemplar_pyramid(ex);
    REQUIRE_FALSE(pyramid);
    CHECK(mentions(pyramid.error(), "pixel (7, 5)"));
    tessera::image_buffer<float, 3> out(32, 32);
    CHECK_FALSE(tessera::quilt(ex, out));
  }
}

TEST_CASE("issue 21: mesh quilting refuses an exemplar with a coordinate at 1e300") {
  auto ex = tessera::make_stone_exemplar({}).value();
  ex.positions[0].x = 1e300;
  auto q = tessera::mesh_quilt(ex, 10.0, 10.0);
  REQUIRE_FALSE(q);
  CHECK(q.error().code() == tessera::status_code::size_overflow);
  CHECK(mentions(q.error(), "max_quilt_exemplar_cells"));
  CHECK_FALSE(tessera::prepare_quilt_exemplar(ex));
  tessera::geometric_wang_options wo;
  CHECK_FALSE(tessera::build_geometric_wang_tiles(ex, wo));
}

TEST_CASE("issue 21: image_view with null data or a short stride is refused, not read") {
  auto ex = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::sand, {.width = 48, .height = 48});
  REQUIRE(ex);
  auto model = tessera::build_patch_model(*ex);
  REQUIRE(model);
  const tessera::image_view<std::uint8_t, 3> null_view(nullptr, 64, 64);
  auto st = tessera::synthesize(*model, null_view);
  REQUIRE_FALSE(st);
  CHECK(mentions(st.error(), "output: image_view data is null"));
  std::vector<std::uint8_t> small(64 * 3);
  const tessera::image_view<std::uint8_t, 3> short_stride(small.data(), 64, 2, 5);
  auto st2 = tessera::synthesize(*model, short_stride);
  REQUIRE_FALSE(st2);
  CHECK(mentions(st2.error(), "stride 5"));
  const tessera::image_view<const std::uint8_t, 3> null_in(nullptr, 48, 48);
  CHECK_FALSE(tessera::build_patch_model(null_in));
  tessera::image_buffer<std::uint8_t, 3> out(16, 16);
  CHECK_FALSE(tessera::quilt(null_in, out));
}

namespace {
// An adapter that knows how many pixels it holds and says so through the validate hook.
struct short_adapter {
  index_t w = 0, h = 0;
  std::vector<std::array<std::uint8_t, 3>> px;
  index_t width() const { return w; }
  index_t height() const { return h; }
  std::array<std::uint8_t, 3> read(index_t x, index_t y) const { return px[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, const std::array<std::uint8_t, 3>& p) {
    px[static_cast<std::size_t>(y * w + x)] = p;
  }
  tessera::status validate(std::string_view what) const {
    if (px.size() < static_cast<std::size_t>(w * h))
      return tessera::status::invalid_argument(
          tessera::detail::cat(what, ": holds ", px.size(), " pixels, claims ", w, " x ", h));
    return {};
  }
};
}  // namespace

TEST_CASE("issue 21: an adapter's validate hook is run on inputs and outputs") {
  short_adapter bad{32, 32, std::vector<std::array<std::uint8_t, 3>>(10)};
  auto model = tessera::build_patch_model(bad);
  REQUIRE_FALSE(model);
  CHECK(mentions(model.error(), "exemplar: holds 10 pixels"));
  auto ex = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::sand, {.width = 48, .height = 48});
  auto good_model = tessera::build_patch_model(*ex);
  REQUIRE(good_model);
  auto st = tessera::synthesize(*good_model, bad);
  REQUIRE_FALSE(st);
  CHECK(mentions(st.error(), "output: holds 10 pixels"));
  CHECK_FALSE(tessera::quilt(*ex, bad));
}

TEST_CASE("issue 21: out-of-range enum options are refused") {
  auto ex = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::sand, {.width = 48, .height = 48});
  auto model = tessera::build_patch_model(*ex);
  REQUIRE(model);
  tessera::image_buffer<std::uint8_t, 3> out(16, 16);
  auto st = tessera::synthesize(*model, out, {.seams = static_cast<tessera::seam_mode>(42)});
  REQUIRE_FALSE(st);
  CHECK(mentions(st.error(), "options.seams has the unknown value 42"));
  CHECK(mentions(st.error(), "feather, cut"));
  auto bad_kind = tessera::make_exemplar(static_cast<tessera::exemplar_kind>(-1));
  REQUIRE_FALSE(bad_kind);
  CHECK(mentions(bad_kind.error(), "kind has the unknown value -1"));
  auto stones = tessera::make_stone_exemplar({}).value();
  tessera::mesh_quilt_options mo;
  mo.rules = static_cast<tessera::merge_rules>(7);
  auto q = tessera::mesh_quilt(stones, 4.0, 4.0, mo);
  REQUIRE_FALSE(q);
  CHECK(mentions(q.error(), "options.rules"));
}

TEST_CASE("issue 21: make_exemplar with a huge size returns a status before allocating") {
  auto big = tessera::make_exemplar(tessera::exemplar_kind::grass, {.width = 600000, .height = 600000});
  REQUIRE_FALSE(big);
  CHECK(big.error().code() == tessera::status_code::size_overflow);
  CHECK(mentions(big.error(), "max_exemplar_pixels"));
  auto wide = tessera::make_exemplar<float, 4>(tessera::exemplar_kind::dots, {.width = 600000, .height = 128});
  CHECK_FALSE(wide);
  tessera::weave_exemplar_options wo;
  wo.size = 1e6;
  auto weave = tessera::make_weave_exemplar(wo);
  REQUIRE_FALSE(weave);
  CHECK(mentions(weave.error(), "max_exemplar_mesh_vertices"));
  tessera::ring_exemplar_options ro;
  ro.size = 1e7;
  CHECK_FALSE(tessera::make_ring_exemplar(ro));
  ro.chain_mail = true;
  CHECK_FALSE(tessera::make_ring_exemplar(ro));
  tessera::stone_exemplar_options so;
  so.size = 1e5;
  so.subdivisions = 5;
  CHECK_FALSE(tessera::make_stone_exemplar(so));
}

TEST_CASE("issue 21: tile_geometric_plane refuses a huge grid before allocating cells") {
  tessera::geometric_tile_set set;
  set.tile_size = 1;
  set.horizontal_colors = set.vertical_colors = 2;
  for (index_t t = 0; t < tessera::complete_tile_count(2, 2); ++t) {
    set.edges.push_back(tessera::complete_tile_edges(t, 2, 2));
    tessera::tri_mesh m;
    for (int i = 0; i < 16; ++i) {
      const double x = 0.2 + 0.03 * i;
      m.add_face(m.add_vertex({x, 0.2, 0}), m.add_vertex({x + 0.02, 0.2, 0}), m.add_vertex({x, 0.3, 0}));
    }
    set.tiles.push_back(m);
  }
  auto plane = tessera::hash_coloring::create(2, 2, 1).value();
  auto window = plane.window(0, 0, 65536, 4096);
  REQUIRE(window);
  auto out = tessera::tile_geometric_plane(set, *window, 65536, 4096);
  REQUIRE_FALSE(out);
  CHECK(out.error().code() == tessera::status_code::size_overflow);
  CHECK_FALSE(tessera::validate_geometric_plane_size(set, 65536, 4096));
  CHECK(tessera::validate_geometric_plane_size(set, 64, 64));
}
