// Degenerate-content matrix of the image family: every entry point on flat, two-valued, 1 x 1, one
// row, one column, smaller-than-a-patch, zero-alpha and non-finite images. Each call must give a
// valid output or a status with a message; inputs with NaN or infinity must be refused by every entry
// point that does maths on pixel values.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/constrained_quilt.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/image/metrics.hpp>
#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_size.hpp>
#include <tessera/image/patch_synthesis.hpp>
#include <tessera/image/quilt.hpp>
#include <tessera/image/wang_atlas.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include "robustness_support.hpp"

using robust::index_t;

namespace {

template <class T, int C>
void run_image_matrix() {
  for (const auto& [name, img] : robust::degenerate_images<T, C>()) {
    INFO("input: " << name << " (" << img.width() << " x " << img.height() << ")");
    const auto copy = img;
    const bool bad = robust::non_finite_case(name);

    auto analysis = tessera::analyze_patch_size(img);
    if (robust::ok_or_refused_result(analysis)) CHECK_FALSE(bad);

    tessera::patch_model_options mo;
    mo.candidates = 4;
    mo.pca_samples = 64;
    for (bool seams : {false, true}) {
      mo.seams = seams;
      auto model = tessera::build_patch_model(img, mo);
      if (!robust::ok_or_refused_result(model)) continue;
      CHECK_FALSE(bad);
      tessera::image_buffer<T, C> out(23, 17);
      const auto mode = seams ? tessera::seam_mode::cut : tessera::seam_mode::feather;
      if (robust::ok_or_refused_result(tessera::synthesize(*model, out, {.seed = 2, .seams = mode})))
        CHECK(robust::all_finite(out));
    }

    tessera::image_buffer<T, C> quilted(20, 20);
    if (robust::ok_or_refused(tessera::quilt(img, quilted, {.patch_size = 0, .seed = 3}))) {
      CHECK_FALSE(bad);
      CHECK(robust::all_finite(quilted));
    }
    tessera::image_buffer<T, C> seamless(20, 20);
    robust::ok_or_refused(tessera::quilt(img, seamless, {.seamless = true}));

    tessera::image_buffer<std::uint8_t, 1> mask(img.width(), img.height(), {0});
    mask.write(img.width() / 2, img.height() / 2, {255});
    tessera::image_buffer<T, C> filled(img.width(), img.height());
    if (robust::ok_or_refused(tessera::constrained_quilt(img, mask, filled))) CHECK_FALSE(bad);
    tessera::image_buffer<T, C> filled2(img.width(), img.height());
    if (robust::ok_or_refused(tessera::constrained_quilt(img, img, mask, filled2))) CHECK_FALSE(bad);

    tessera::wang_tile_options wo;
    wo.tile_size = 12;
    wo.mip_levels = 1;
    auto set = tessera::build_wang_tiles(img, wo);
    if (robust::ok_or_refused_result(set)) {
      CHECK_FALSE(bad);
      auto coloring = tessera::hash_coloring::create(2, 2, 1).value().window(0, 0, 3, 2).value();
      tessera::image_buffer<T, C> plane(30, 20);
      CHECK(tessera::compose_tiles(*set, coloring, plane));
      auto atlas = tessera::build_wang_atlas(*set);
      robust::ok_or_refused_result(atlas);
    }

    if (robust::ok_or_refused_result(tessera::neighborhood_energy(img, img))) CHECK_FALSE(bad);
    auto hist = tessera::histogram_distance(img, img);
    if (robust::ok_or_refused_result(hist)) {  // bins clamp values and count NaN as 0: any input is valid
      CHECK(*hist >= 0);
      CHECK(*hist <= 2);
    }
    if (robust::ok_or_refused_result(tessera::repetition_score(img, 1))) CHECK_FALSE(bad);
    const std::array<tessera::seam_segment, 1> seams{tessera::seam_segment{true, 0, 0, img.height()}};
    robust::ok_or_refused_result(tessera::seam_gradient_ratio(img, std::span<const tessera::seam_segment>(seams), img));

    // inputs are never modified
    REQUIRE(img.width() == copy.width());
    CHECK(std::equal(img.data(), img.data() + img.width() * img.height() * C, copy.data(),
                     [](T a, T b) { return a == b || (a != a && b != b); }));
  }
}

}  // namespace

TEST_CASE("robustness: image entry points on degenerate uint8 RGB images") { run_image_matrix<std::uint8_t, 3>(); }
TEST_CASE("robustness: image entry points on degenerate uint8 RGBA images") { run_image_matrix<std::uint8_t, 4>(); }
TEST_CASE("robustness: image entry points on degenerate float grey images") { run_image_matrix<float, 1>(); }
TEST_CASE("robustness: image entry points on degenerate float RGB images") { run_image_matrix<float, 3>(); }

TEST_CASE("robustness: image entry points refuse absurd sizes and options before allocating") {
  const auto ex = robust::noise<std::uint8_t, 3>(32, 32, 1);
  tessera::image_buffer<std::uint8_t, 3> out(16, 16);
  robust::check_refusal(tessera::quilt(ex, out, {.patch_size = index_t{1} << 40}));
  robust::check_refusal(tessera::quilt(ex, out, {.patch_size = 8, .overlap = -3}));
  robust::check_refusal(tessera::quilt(ex, out, {.tolerance = std::numeric_limits<double>::quiet_NaN()}));
  tessera::wang_tile_options wo;
  wo.tile_size = index_t{1} << 30;
  robust::check_refusal(tessera::build_wang_tiles(ex, wo).error());
  wo.tile_size = 16;
  wo.horizontal_colors = 1 << 20;
  robust::check_refusal(tessera::build_wang_tiles(ex, wo).error());
  tessera::patch_model_options mo;
  mo.patch_width = index_t{1} << 40;
  mo.patch_height = 4;
  robust::check_refusal(tessera::build_patch_model(ex, mo).error());
  mo = {};
  mo.candidates = 1 << 30;
  robust::check_refusal(tessera::build_patch_model(ex, mo).error());
  auto model = tessera::build_patch_model(ex).value();
  tessera::patch_synthesis_options so;
  so.origin = {index_t{1} << 60, 0};
  robust::check_refusal(tessera::synthesize(model, out, so).error());
  robust::check_refusal(tessera::histogram_distance(ex, ex, 1 << 30).error());
  robust::check_refusal(tessera::repetition_score(ex, index_t{1} << 40).error());
  auto big = tessera::make_exemplar(tessera::exemplar_kind::weave, {.width = index_t{1} << 30, .height = 1 << 30});
  REQUIRE_FALSE(big);
  robust::check_refusal(big.error());
}
