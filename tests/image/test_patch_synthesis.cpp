#include <tessera/image/patch_synthesis.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/core/random.hpp>
#include <tessera/image/exemplars.hpp>
#include "../support/test_support.hpp"

using tessera_test::crop;
using tessera_test::exemplar;
using tessera_test::user_image;

using tessera::index_t;
using tessera::seam_mode;

namespace {

// A small model shared by several tests (built once).
const tessera::patch_model<std::uint8_t, 3>& bricks_model() {
  static const auto model = [] {
    const auto ex = exemplar(tessera::exemplar_kind::bricks, 48);
    return tessera::build_patch_model(ex, {.patch_width = 12, .patch_height = 12, .overlap = 4, .seams = true}).value();
  }();
  return model;
}

}  // namespace

TEST_CASE("synthesize: windows of the infinite texture are bit-identical to one large render", "[patch_synthesis]") {
  const auto& m = bricks_model();
  for (int variant = 0; variant < 3; ++variant) {  // feather over the whole overlap, over 1 pixel, cut
    const seam_mode mode = variant == 2 ? seam_mode::cut : seam_mode::feather;
    const index_t band = variant == 1 ? 1 : 0;
    const tessera::patch_synthesis_options whole{.origin = {-53, 29}, .seed = 11, .seams = mode, .feather_width = band};
    tessera::image_buffer<std::uint8_t, 3> full(101, 77);
    REQUIRE(tessera::synthesize(m, full, whole).ok());
    // uneven pieces, including ones that start inside overlaps and cells
    const index_t xs[] = {0, 7, 40, 41, 101}, ys[] = {0, 13, 14, 60, 77};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const index_t x0 = xs[a], y0 = ys[b], w = xs[a + 1] - x0, h = ys[b + 1] - y0;
        tessera::image_buffer<std::uint8_t, 3> piece(w, h);
        auto o = whole;
        o.origin = {whole.origin.x + x0, whole.origin.y + y0};
        REQUIRE(tessera::synthesize(m, piece, o).ok());
        INFO("piece at " << x0 << ", " << y0);
        CHECK(piece == crop(full, x0, y0, w, h));
      }
    // far from the origin, negative coordinates
    tessera::image_buffer<std::uint8_t, 3> far1(40, 30), far2(20, 30);
    auto o1 = whole, o2 = whole;
    o1.origin = {-(index_t{1} << 40), 123456789};
    o2.origin = {-(index_t{1} << 40) + 20, 123456789};
    REQUIRE(tessera::synthesize(m, far1, o1).ok());
    REQUIRE(tessera::synthesize(m, far2, o2).ok());
    CHECK(far2 == crop(far1, 20, 0, 20, 30));
  }
}

TEST_CASE("synthesize: bit-identical for any executor and thread count, and seeded", "[patch_synthesis]") {
  const auto& m = bricks_model();
  for (int variant = 0; variant < 3; ++variant) {  // feather over the whole overlap, over 3 pixels, cut
    const seam_mode mode = variant == 2 ? seam_mode::cut : seam_mode::feather;
    tessera::image_buffer<std::uint8_t, 3> a(150, 97), b(150, 97), c(150, 97), d(150, 97);
    const tessera::patch_synthesis_options o{
        .origin = {5, -3}, .seed = 2, .seams = mode, .feather_width = variant == 1 ? 3 : 0};
    const auto sa = tessera::synthesize(m, a, o).value();
    tessera::thread_pool_executor two(2), three(3);
    const auto sb = tessera::synthesize(m, b, o, two).value();
    REQUIRE(tessera::synthesize(m, c, o, three).ok());
    CHECK(a == b);
    CHECK(a == c);
    CHECK(sa.cells == sb.cells);
    CHECK(sa.empty_intersections == sb.empty_intersections);
    auto other = o;
    other.seed = 3;
    REQUIRE(tessera::synthesize(m, d, other).ok());
    CHECK(!(a == d));
  }
}

TEST_CASE("synthesize: checkerboard counts and intersections", "[patch_synthesis]") {
  const auto& m = bricks_model();
  tessera::image_buffer<std::uint8_t, 3> out(60, 60);
  const auto s = tessera::synthesize(m, out, {.seed = 1}).value();
  // cells -1..4 in both directions touch the window (the left/top ones through their overlap)
  CHECK(s.cells == 36);
  CHECK(s.placed == 18);
  CHECK(s.filled == 18);
  CHECK(s.phase_group >= 16);
  // when every set holds every patch, the four sets always intersect
  const auto ex = exemplar(tessera::exemplar_kind::sand, 16);
  const auto all =
      tessera::build_patch_model(ex, {.patch_width = 8, .patch_height = 8, .overlap = 2, .candidates = 64}).value();
  REQUIRE(all.candidates() == all.num_patches());
  const auto t = tessera::synthesize(all, out, {.seed = 1}).value();
  CHECK(t.empty_intersections == 0);
  // a radius of max(patch_width, patch_height) or more takes every phase, up to the largest index_t
  // (2 radius + 1 would overflow: the radius is clamped)
  tessera::image_buffer<std::uint8_t, 3> all_phases(40, 30), huge_radius(40, 30);
  const auto r12 = tessera::synthesize(m, all_phases, {.seed = 5, .phase_radius = 12}).value();
  const auto rmax =
      tessera::synthesize(m, huge_radius, {.seed = 5, .phase_radius = std::numeric_limits<index_t>::max()}).value();
  CHECK(r12.phase_group == m.num_patches());
  CHECK(rmax.phase_group == m.num_patches());
  CHECK(all_phases == huge_radius);
  for (index_t radius : {index_t{1} << 62, std::numeric_limits<index_t>::max() / 2 + 1})
    CHECK(tessera::synthesize(m, huge_radius, {.seed = 5, .phase_radius = radius}).value().phase_group ==
          m.num_patches());
}

TEST_CASE("synthesize: quality invariants", "[patch_synthesis]") {
  for (auto kind : {tessera::exemplar_kind::sand, tessera::exemplar_kind::bricks, tessera::exemplar_kind::weave}) {
    const auto ex = exemplar(kind, 64);
    const auto m = tessera::build_patch_model(ex, {.patch_width = 20, .patch_height = 20, .overlap = 5}).value();
    tessera::image_buffer<std::uint8_t, 3> out(128, 128), noise(48, 48);
    REQUIRE(tessera::synthesize(m, out, {.seed = 4}).ok());
    const tessera::counter_rng rng(9);
    for (index_t i = 0; i < 48 * 48 * 3; ++i) noise.data()[i] = static_cast<std::uint8_t>(rng.below(256, i));
    const tessera::neighborhood_energy_options eo{.window = 5, .sample_step = 4};
    const double e_out = tessera::neighborhood_energy(out, ex, eo).value();
    const double e_noise = tessera::neighborhood_energy(noise, ex, eo).value();
    INFO(tessera::to_string(kind) << ": energy " << e_out << " vs noise " << e_noise);
    CHECK(e_out < 0.1 * e_noise);
    CHECK(tessera::histogram_distance(out, ex).value() < 0.35);
    const auto seams = tessera::patch_seam_lines(m, 128, 128);
    const double ratio = tessera::seam_gradient_ratio(out, seams, ex).value();
    INFO("seam gradient ratio " << ratio);
    CHECK(ratio < 1.5);
  }
  // stochastic textures do not repeat visibly
  const auto sand = exemplar(tessera::exemplar_kind::sand, 64);
  const auto m = tessera::build_patch_model(sand).value();  // automatic size and overlap
  CHECK(m.analysis().has_value());
  tessera::image_buffer<std::uint8_t, 3> out(128, 128);
  REQUIRE(tessera::synthesize(m, out, {.seed = 4}).ok());
  CHECK(tessera::repetition_score(out, 16).value() < 0.6);
}

TEST_CASE("synthesize: pixels come from the exemplar (source map)", "[patch_synthesis]") {
  const auto& m = bricks_model();
  const auto& ex = m.exemplar();
  const tessera::patch_synthesis_options cut{.origin = {-9, 4}, .seed = 8, .seams = seam_mode::cut};
  tessera::image_buffer<std::uint8_t, 3> out(70, 50);
  tessera::image_buffer<std::uint16_t, 2> src(70, 50);
  tessera::image_buffer<float, 3> srcf(70, 50);
  REQUIRE(tessera::synthesize(m, out, cut).ok());
  REQUIRE(tessera::synthesize_source_map(m, src, cut).ok());
  REQUIRE(tessera::synthesize_source_map(m, srcf, cut).ok());
  for (index_t y = 0; y < 50; ++y)
    for (index_t x = 0; x < 70; ++x) {
      const auto s = src.read(x, y);
      REQUIRE(s[0] < ex.width());
      REQUIRE(s[1] < ex.height());
      CHECK(out.read(x, y) == ex.read(s[0], s[1]));  // a seam cut copies every pixel
      CHECK(srcf.read(x, y)[0] == float(s[0]));
      CHECK(srcf.read(x, y)[2] == 0.0f);
    }
  // feathering: outside the overlaps pixels are copies too; inside they lie between their sources
  tessera::patch_synthesis_options feather = cut;
  feather.seams = seam_mode::feather;
  REQUIRE(tessera::synthesize(m, out, feather).ok());
  REQUIRE(tessera::synthesize_source_map(m, src, feather).ok());
  for (index_t y = 0; y < 50; ++y)
    for (index_t x = 0; x < 70; ++x) {
      const index_t X = x - 9, Y = y + 4;
      const bool in_overlap = ((X % 12) + 12) % 12 < 4 || ((Y % 12) + 12) % 12 < 4;
      if (!in_overlap) CHECK(out.read(x, y) == ex.read(src.read(x, y)[0], src.read(x, y)[1]));
    }
  // a feather band of one pixel (position (v - 1) / 2 = 1 of the overlap, weight 1/2) is a straight cut
  // through the overlap elsewhere: every pixel off the band a copy of the source the map names (weights
  // 0 and 1 are exact in fixed point)
  feather.feather_width = 1;
  REQUIRE(tessera::synthesize(m, out, feather).ok());
  REQUIRE(tessera::synthesize_source_map(m, src, feather).ok());
  index_t copies = 0;
  for (index_t y = 0; y < 50; ++y)
    for (index_t x = 0; x < 70; ++x) {
      const index_t X = x - 9, Y = y + 4;
      if (((X % 12) + 12) % 12 == 1 || ((Y % 12) + 12) % 12 == 1) continue;
      CHECK(out.read(x, y) == ex.read(src.read(x, y)[0], src.read(x, y)[1]));
      ++copies;
    }
  CHECK(copies == 70 * 50 - (5 * 50 + 4 * 70 - 5 * 4));  // band columns X = 1 mod 12 (5), rows (4)
}

TEST_CASE("synthesize_aligned: several maps from one model", "[patch_synthesis]") {
  const auto& m = bricks_model();
  const auto& albedo = m.exemplar();
  // the same content as float RGB and as 16-bit grey height
  tessera::image_buffer<float, 3> albedo_f(albedo.width(), albedo.height());
  tessera::image_buffer<std::uint16_t, 1> height(albedo.width(), albedo.height());
  REQUIRE(tessera::copy_image(albedo, albedo_f).ok());
  REQUIRE(tessera::copy_image(albedo, height).ok());
  for (seam_mode mode : {seam_mode::feather, seam_mode::cut}) {
    const tessera::patch_synthesis_options o{.origin = {17, 5}, .seed = 21, .seams = mode};
    tessera::image_buffer<std::uint8_t, 3> out(64, 48);
    tessera::image_buffer<float, 3> out_f(64, 48);
    tessera::image_buffer<std::uint16_t, 1> out_h(64, 48);
    REQUIRE(tessera::synthesize(m, out, o).ok());
    REQUIRE(tessera::synthesize_aligned(m, albedo_f, out_f, o).ok());
    REQUIRE(tessera::synthesize_aligned(m, height, out_h, o).ok());
    for (index_t y = 0; y < 48; ++y)
      for (index_t x = 0; x < 64; ++x)
        for (int c = 0; c < 3; ++c) {
          const float a = tessera::channel_to_unit(out.read(x, y)[c]), b = out_f.read(x, y)[c];
          if (mode == seam_mode::cut)
            CHECK(a == Approx(b).margin(1e-6));  // same pixels exactly
          else
            CHECK(a == Approx(b).margin(1.0 / 255.0 + 1e-6));  // same weights, other rounding (one level)
        }
    // the aligned grey map follows the same patches
    tessera::image_buffer<std::uint16_t, 1> grey(64, 48);
    REQUIRE(tessera::copy_image(out_f, grey).ok());
    for (index_t y = 0; y < 48; ++y)
      for (index_t x = 0; x < 64; ++x) CHECK(std::abs(int(grey.read(x, y)[0]) - int(out_h.read(x, y)[0])) <= 520);
  }
  // an aligned map of another size is refused
  tessera::image_buffer<float, 1> wrong(47, 48);
  tessera::image_buffer<float, 1> out(8, 8);
  auto r = tessera::synthesize_aligned(m, wrong, out);
  REQUIRE(!r);
  CHECK(r.error().message().find("aligned_exemplar") != std::string::npos);
}

TEST_CASE("synthesize: generic outputs through image_traits", "[patch_synthesis]") {
  const auto& m = bricks_model();
  const tessera::patch_synthesis_options o{.origin = {3, 3}, .seed = 6};
  tessera::image_buffer<std::uint8_t, 3> direct(33, 29);
  REQUIRE(tessera::synthesize(m, direct, o).ok());
  user_image user{33, 29, std::vector<std::array<std::uint16_t, 3>>(33 * 29)};
  tessera::thread_pool_executor pool(2);
  REQUIRE(tessera::synthesize(m, user, o, pool).ok());
  std::vector<std::uint8_t> raw(33 * 29 * 4, 7);
  auto view = tessera::make_image_view<4>(raw.data(), 33, 29).value();  // RGBA view of an RGB model
  REQUIRE(tessera::synthesize(m, view, o).ok());
  for (index_t y = 0; y < 29; ++y)
    for (index_t x = 0; x < 33; ++x) {
      CHECK(user.read(x, y) == tessera::convert_pixel<std::array<std::uint16_t, 3>>(direct.read(x, y)));
      const auto p = view.read(x, y);
      CHECK(p[0] == direct.read(x, y)[0]);
      CHECK(p[3] == 255);
    }
  // a strided view of the model's own pixel type writes in place and leaves the padding alone
  std::vector<std::uint8_t> padded(40 * 29 * 3, 99);
  auto strided = tessera::make_image_view<3>(padded.data(), 33, 29, 40 * 3).value();
  REQUIRE(tessera::synthesize(m, strided, o).ok());
  for (index_t y = 0; y < 29; ++y) {
    for (index_t x = 0; x < 33; ++x) CHECK(strided.read(x, y) == direct.read(x, y));
    for (index_t i = 33 * 3; i < 40 * 3; ++i) CHECK(padded[static_cast<std::size_t>(y * 120 + i)] == 99);
  }
}

TEST_CASE("synthesize: bad input and cancellation", "[patch_synthesis]") {
  const auto& m = bricks_model();
  tessera::image_view<std::uint8_t, 3> empty;
  CHECK(tessera::synthesize(m, empty).error().code() == tessera::status_code::invalid_argument);
  tessera::image_buffer<std::uint8_t, 3> out(16, 16);
  const tessera::patch_model<std::uint8_t, 3> none;
  CHECK(tessera::synthesize(none, out).error().message().find("empty") != std::string::npos);
  auto far = tessera::synthesize(m, out, {.origin = {index_t{1} << 60, 0}});
  REQUIRE(!far);
  CHECK(far.error().code() == tessera::status_code::out_of_range);
  CHECK(far.error().message().find("origin") != std::string::npos);
  CHECK(!tessera::synthesize(m, out, {.origin = {0, -(index_t{1} << 53)}}));
  CHECK(tessera::synthesize(m, out, {.phase_radius = -2}).error().message().find("phase_radius") != std::string::npos);
  CHECK(tessera::synthesize(m, out, {.min_phase_group = 0}).error().message().find("min_phase_group") !=
        std::string::npos);
  CHECK(tessera::synthesize(m, out, {.feather_width = -1}).error().message().find("feather_width") !=
        std::string::npos);
  CHECK(tessera::synthesize(m, out, {.feather_width = 1000}).ok());  // clamped to the overlap
  tessera::image_buffer<std::uint16_t, 1> one(4, 4);
  CHECK(tessera::synthesize_source_map(m, one).error().message().find("2 channels") != std::string::npos);
  // uint8 source maps cannot address exemplars wider than 256 pixels
  const auto wide =
      tessera::make_exemplar<std::uint8_t, 1>(tessera::exemplar_kind::sand, {.width = 300, .height = 14}).value();
  const auto wm =
      tessera::build_patch_model(wide, {.patch_width = 8, .patch_height = 8, .overlap = 2, .candidates = 2}).value();
  tessera::image_buffer<std::uint8_t, 2> small(4, 4);
  CHECK(tessera::synthesize_source_map(wm, small).error().message().find("channel type") != std::string::npos);
  tessera::image_buffer<std::uint16_t, 2> ok(4, 4);
  CHECK(tessera::synthesize_source_map(wm, ok).ok());
  // cancellation: a raised token, or a callback saying stop
  tessera::cancellation_token stop;
  stop.cancel();
  tessera::patch_synthesis_options o;
  o.progress.token = &stop;
  CHECK(tessera::synthesize(m, out, o).error().code() == tessera::status_code::cancelled);
  tessera::image_buffer<std::uint8_t, 3> big(64, 256);
  tessera::patch_synthesis_options p;
  int calls = 0;
  p.progress.callback = [&](double, std::string_view) { return ++calls < 2; };
  CHECK(tessera::synthesize(m, big, p).error().code() == tessera::status_code::cancelled);
  CHECK(calls == 2);
}

namespace {

// Seam cuts copy every pixel: the output equals the exemplar at the source map's coordinates.
template <class T, int C>
void check_copies_exemplar(tessera::exemplar_kind kind) {
  const auto ex = exemplar<T, C>(kind, 32);
  const auto m =
      tessera::build_patch_model(ex, {.patch_width = 10, .patch_height = 8, .overlap = 3, .candidates = 4}).value();
  const tessera::patch_synthesis_options o{.origin = {-5, 11}, .seed = 2, .seams = seam_mode::cut};
  tessera::image_buffer<T, C> out(37, 23);
  tessera::image_buffer<std::uint16_t, 2> src(37, 23);
  REQUIRE(tessera::synthesize(m, out, o).ok());
  REQUIRE(tessera::synthesize_source_map(m, src, o).ok());
  for (index_t y = 0; y < 23; ++y)
    for (index_t x = 0; x < 37; ++x) {
      const auto s = src.read(x, y);
      REQUIRE(out.read(x, y) == ex.read(s[0], s[1]));
    }
  // feathering stays within the range of the channel type
  tessera::image_buffer<T, C> blended(37, 23);
  REQUIRE(tessera::synthesize(m, blended, {.origin = {-5, 11}, .seed = 2}).ok());
  for (index_t y = 0; y < 23; ++y)
    for (index_t x = 0; x < 37; ++x)
      for (int c = 0; c < C; ++c) {
        const double v = tessera::channel_to_unit(blended.read(x, y)[c]);
        REQUIRE(v >= 0.0);
        REQUIRE(v <= 1.0);
      }
}

}  // namespace

TEST_CASE("synthesize: models of every channel type and 1 to 4 channels", "[patch_synthesis]") {
  check_copies_exemplar<std::uint8_t, 1>(tessera::exemplar_kind::rock);
  check_copies_exemplar<std::uint8_t, 4>(tessera::exemplar_kind::cells);
  check_copies_exemplar<std::uint16_t, 2>(tessera::exemplar_kind::grass);
  check_copies_exemplar<std::uint16_t, 3>(tessera::exemplar_kind::bricks);
  check_copies_exemplar<float, 1>(tessera::exemplar_kind::sand);
  check_copies_exemplar<float, 4>(tessera::exemplar_kind::weave);
}

namespace {

// A writable user image of any size, zero included, that stores nothing (image_buffer refuses 0 x N).
template <class T, int C>
struct sized_image {
  index_t w = 0, h = 0;
  index_t width() const { return w; }
  index_t height() const { return h; }
  std::array<T, C> read(index_t, index_t) const { return {}; }
  void write(index_t, index_t, const std::array<T, C>&) { FAIL("a zero-size output was written"); }
};

}  // namespace

TEST_CASE("synthesize: zero-size outputs and windows past the index range at every entry point", "[patch_synthesis]") {
  const auto& m = bricks_model();
  tessera::image_buffer<float, 3> aligned(m.exemplar().width(), m.exemplar().height());
  REQUIRE(tessera::copy_image(m.exemplar(), aligned).ok());
  for (auto [w, h] : {std::pair<index_t, index_t>{0, 5}, {5, 0}, {0, 0}}) {
    INFO(w << " x " << h);
    sized_image<std::uint8_t, 3> out{w, h};
    sized_image<float, 3> out_f{w, h};
    sized_image<std::uint16_t, 2> src{w, h};
    const auto a = tessera::synthesize(m, out);
    REQUIRE(!a);
    CHECK(a.error().code() == tessera::status_code::invalid_argument);
    CHECK(a.error().message().find("output") != std::string::npos);
    CHECK(tessera::synthesize_aligned(m, aligned, out_f).error().code() == tessera::status_code::invalid_argument);
    const auto s = tessera::synthesize_source_map(m, src);
    REQUIRE(!s);
    CHECK(s.error().message().find("source_map") != std::string::npos);
  }
  // windows whose cells would overflow index arithmetic: refused before any pixel is written
  const index_t huge = std::numeric_limits<index_t>::max() - 4;
  for (tessera::texture_offset origin : {tessera::texture_offset{huge, 0}, {0, huge}, {-huge, 0}, {0, -huge}}) {
    tessera::image_buffer<std::uint8_t, 3> out(8, 8, {1, 2, 3});
    tessera::image_buffer<float, 3> out_f(8, 8);
    tessera::image_buffer<std::uint16_t, 2> src(8, 8);
    const tessera::patch_synthesis_options o{.origin = origin};
    const auto a = tessera::synthesize(m, out, o);
    REQUIRE(!a);
    CHECK(a.error().code() == tessera::status_code::out_of_range);
    CHECK(a.error().message().find("origin") != std::string::npos);
    CHECK(out.read(7, 7) == tessera::pixel<std::uint8_t, 3>{1, 2, 3});
    CHECK(tessera::synthesize_aligned(m, aligned, out_f, o).error().code() == tessera::status_code::out_of_range);
    CHECK(tessera::synthesize_source_map(m, src, o).error().code() == tessera::status_code::out_of_range);
  }
  // the last window inside the supported plane still renders
  const index_t edge = index_t{1} << 52;
  tessera::image_buffer<std::uint8_t, 3> out(8, 8);
  CHECK(tessera::synthesize(m, out, {.origin = {edge - 8, -edge}}).ok());
}

namespace {

// The patch of every cell (i, j) in [i0, i0 + ni) x [j0, j0 + nj) of the texture, recovered from the
// source map: inside a cell, away from its overlaps, every pixel is its patch's pixel (lx, ly).
struct cell_grid {
  index_t i0 = 0, j0 = 0, ni = 0, nj = 0;
  std::vector<index_t> patch;
  index_t at(index_t i, index_t j) const { return patch[static_cast<std::size_t>((j - j0) * ni + (i - i0))]; }
};

template <class M>
cell_grid recover_cells(const M& m, const tessera::patch_synthesis_options& o, index_t i0, index_t j0, index_t ni,
                        index_t nj) {
  const index_t pw = m.patch_width(), ph = m.patch_height(), v = m.overlap();
  tessera::image_buffer<std::uint16_t, 2> src(ni * pw, nj * ph);
  auto window = o;
  window.origin = {i0 * pw, j0 * ph};
  REQUIRE(tessera::synthesize_source_map(m, src, window).ok());
  cell_grid g{i0, j0, ni, nj, {}};
  for (index_t cj = 0; cj < nj; ++cj)
    for (index_t ci = 0; ci < ni; ++ci) {
      // every interior pixel of the cell must agree on the patch origin
      const auto s = src.read(ci * pw + v, cj * ph + v);
      const index_t x = s[0] - v, y = s[1] - v;
      for (index_t ly = v; ly < ph; ly += 3)
        for (index_t lx = v; lx < pw; lx += 3) {
          const auto t = src.read(ci * pw + lx, cj * ph + ly);
          REQUIRE(index_t(t[0]) == x + lx);
          REQUIRE(index_t(t[1]) == y + ly);
        }
      REQUIRE(x >= 0);
      REQUIRE(y >= 0);
      REQUIRE(x < m.patches_x());
      REQUIRE(y < m.patches_y());
      g.patch.push_back(y * m.patches_x() + x);
    }
  return g;
}

// Brute-force filling of a vacant cell (paper 002 §2 and the documented tie-break): the members of all
// four facing sets, or the patch in the most sets, then the smallest estimated error (errors in the sets
// holding it, the set's k-th error otherwise, summed west, east, north, south), then the smallest index.
template <class M>
std::pair<std::vector<index_t>, index_t> brute_fill(const M& m, index_t west, index_t east, index_t north,
                                                    index_t south) {
  const index_t owners[4] = {west, east, north, south};
  const int facing[4] = {tessera::side_east, tessera::side_west, tessera::side_south, tessera::side_north};
  std::vector<index_t> candidates, inter;
  for (int s = 0; s < 4; ++s)
    for (std::uint32_t q : m.compatible(owners[s], facing[s])) candidates.push_back(q);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  index_t best = -1, best_count = 0;
  double best_error = 0;
  for (index_t q : candidates) {
    index_t count = 0;
    double error = 0;
    for (int s = 0; s < 4; ++s) {
      const auto set = m.compatible(owners[s], facing[s]);
      const auto errors = m.compatible_errors(owners[s], facing[s]);
      const auto it = std::find(set.begin(), set.end(), static_cast<std::uint32_t>(q));
      count += it != set.end();
      error += static_cast<double>(it != set.end() ? errors[static_cast<std::size_t>(it - set.begin())]
                                                   : m.kth_error(owners[s], facing[s]));
    }
    if (count == 4) inter.push_back(q);
    if (count > best_count || (count == best_count && error < best_error))
      best = q, best_count = count, best_error = error;
  }
  return {inter, best};
}

// The member of the union of the four facing sets of a vacant cell with the smallest total(q, owners,
// facing), ties by the smaller index, and its total.
template <class M, class Total>
std::pair<index_t, double> brute_union_fill(const M& m, index_t west, index_t east, index_t north, index_t south,
                                            Total&& total_of) {
  const index_t owners[4] = {west, east, north, south};
  const int facing[4] = {tessera::side_east, tessera::side_west, tessera::side_south, tessera::side_north};
  std::vector<index_t> candidates;
  for (int s = 0; s < 4; ++s)
    for (std::uint32_t q : m.compatible(owners[s], facing[s])) candidates.push_back(q);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  index_t best = -1;
  double best_total = std::numeric_limits<double>::infinity();
  for (index_t q : candidates) {
    const double total = total_of(q, owners, facing);
    if (total < best_total) best = q, best_total = total;  // ascending: ties keep the smaller index
  }
  return {best, best_total};
}

// Brute-force overlap_error fallback: the member of the union of the four facing sets with the smallest
// true overlap error (overlap_error against each neighbour, summed), ties by the smaller index. Returns
// the patch and its total.
template <class M>
std::pair<index_t, double> brute_overlap_fill(const M& m, index_t west, index_t east, index_t north, index_t south) {
  return brute_union_fill(m, west, east, north, south, [&](index_t q, const index_t* owners, const int* facing) {
    double total = 0;
    for (int s = 0; s < 4; ++s) total += m.overlap_error(owners[s], q, facing[s]);
    return total;
  });
}

// Brute-force estimated_error fallback: the member of the union of the four facing sets with the
// smallest total, the errors a set holds (summed west, east, north, south) plus, for each set not
// holding it, patch_model::estimated_error (in the same order); ties by the smaller index.
template <class M>
index_t brute_estimated_fill(const M& m, index_t west, index_t east, index_t north, index_t south) {
  return brute_union_fill(m, west, east, north, south,
                          [&](index_t q, const index_t* owners, const int* facing) {
                            double known = 0;
                            bool held[4] = {};
                            for (int s = 0; s < 4; ++s) {
                              const auto set = m.compatible(owners[s], facing[s]);
                              const auto errors = m.compatible_errors(owners[s], facing[s]);
                              const auto it = std::find(set.begin(), set.end(), static_cast<std::uint32_t>(q));
                              held[s] = it != set.end();
                              if (held[s])
                                known += static_cast<double>(errors[static_cast<std::size_t>(it - set.begin())]);
                            }
                            double total = known;
                            for (int s = 0; s < 4; ++s)
                              if (!held[s]) total += m.estimated_error(owners[s], q, facing[s]);
                            return total;
                          })
      .first;
}

}  // namespace

TEST_CASE("synthesize: a vacant cell's patch is in its neighbours' set intersection, else the chosen fallback",
          "[patch_synthesis]") {
  // k = 8 on bricks mostly intersects; k = 2 on sand mostly does not: both branches are checked.
  // Exact sets: each set's k-th error bounds every patch outside it, so the overlap_error fallback with
  // a budget covering the union is the exact minimum over the union.
  const auto sand = exemplar(tessera::exemplar_kind::sand, 40);
  const auto small_k =
      tessera::build_patch_model(sand, {.patch_width = 10, .patch_height = 10, .overlap = 3, .candidates = 2}).value();
  const auto small_k_exact =
      tessera::build_patch_model(
          sand, {.patch_width = 10, .patch_height = 10, .overlap = 3, .candidates = 3, .exact_sets = true})
          .value();
  auto check = [](const auto& m, std::uint64_t seed, tessera::fill_fallback rule) {
    const tessera::patch_synthesis_options o{.seed = seed, .fallback = rule, .fallback_budget = 256};
    const index_t ci0 = -3, cj0 = 5, nci = 6, ncj = 5;
    const auto g = recover_cells(m, o, ci0 - 2, cj0 - 2, nci + 3, ncj + 3);
    tessera::image_buffer<std::uint8_t, 3> out(nci * m.patch_width(), ncj * m.patch_height());
    auto window = o;
    window.origin = {ci0 * m.patch_width(), cj0 * m.patch_height()};
    const auto stats = tessera::synthesize(m, out, window).value();
    // the plan's cells: [ci0 - 1, ci0 + nci) x [cj0 - 1, cj0 + ncj) (the left and top ones overlap the window)
    index_t empty = 0, intersected = 0;
    for (index_t j = cj0 - 1; j < cj0 + ncj; ++j)
      for (index_t i = ci0 - 1; i < ci0 + nci; ++i) {
        if (((i + j) & 1) == 0) continue;  // distributed cell
        const index_t w = g.at(i - 1, j), e = g.at(i + 1, j), n = g.at(i, j - 1), s = g.at(i, j + 1);
        const auto [inter, fallback] = brute_fill(m, w, e, n, s);
        INFO("cell " << i << ", " << j << ": " << inter.size() << " common patches");
        if (inter.empty()) {
          ++empty;
          if (rule == tessera::fill_fallback::most_sets) {
            CHECK(g.at(i, j) == fallback);
          } else if (rule == tessera::fill_fallback::estimated_error) {
            CHECK(g.at(i, j) == brute_estimated_fill(m, w, e, n, s));
          } else {
            const auto [best, total] = brute_overlap_fill(m, w, e, n, s);
            INFO("chosen " << g.at(i, j) << ", brute force " << best << " (total " << total << ")");
            CHECK(g.at(i, j) == best);
          }
        } else {
          ++intersected;
          CHECK(std::find(inter.begin(), inter.end(), g.at(i, j)) != inter.end());
        }
      }
    CHECK(stats.empty_intersections == empty);
    CHECK(stats.filled == empty + intersected);
    if (rule != tessera::fill_fallback::overlap_error) CHECK(stats.evaluated_errors == 0);
    if (rule == tessera::fill_fallback::overlap_error && empty > 0) CHECK(stats.evaluated_errors > 0);
    return std::pair{empty, intersected};
  };
  for (auto rule : {tessera::fill_fallback::most_sets, tessera::fill_fallback::overlap_error,
                    tessera::fill_fallback::estimated_error}) {
    CHECK(check(bricks_model(), 3, rule).second > 0);  // intersections were checked
    CHECK(check(small_k, 4, rule).first > 0);          // and fallbacks
  }
  CHECK(check(small_k_exact, 5, tessera::fill_fallback::overlap_error).first > 0);
  CHECK(check(small_k_exact, 6, tessera::fill_fallback::overlap_error).first > 0);
}

TEST_CASE("synthesize: the overlap_error fallback fits filled cells better than the paper's rule",
          "[patch_synthesis]") {
  // the summed true overlap error of the filled cells (fill_overlap_rms, every fill known) is lower
  // than with the paper's most-sets rule, on a stochastic exemplar where sets rarely intersect
  const auto ex = exemplar(tessera::exemplar_kind::rock, 64);
  const auto m = tessera::build_patch_model(ex, {.patch_width = 16, .patch_height = 16, .overlap = 4}).value();
  tessera::image_buffer<std::uint8_t, 3> a(256, 256), b(256, 256);
  const tessera::patch_synthesis_options exact_opts{.seed = 9, .fallback = tessera::fill_fallback::overlap_error};
  const auto exact = tessera::synthesize(m, a, exact_opts).value();
  const auto paper = tessera::synthesize(m, b, {.seed = 9, .fallback = tessera::fill_fallback::most_sets}).value();
  REQUIRE(exact.empty_intersections > exact.filled / 2);
  CHECK(exact.fill_overlap_rms > 0);
  CHECK(exact.fill_overlap_rms < 0.5);
  CHECK(exact.evaluated_errors > 0);
  // the paper's rule knows all four errors only for the intersected cells; compare through brute force
  const auto g_exact = recover_cells(m, exact_opts, 0, 0, 16, 16);
  const auto g_paper = recover_cells(m, {.seed = 9, .fallback = tessera::fill_fallback::most_sets}, 0, 0, 16, 16);
  const auto g_estimated =
      recover_cells(m, {.seed = 9, .fallback = tessera::fill_fallback::estimated_error}, 0, 0, 16, 16);
  double sum_exact = 0, sum_paper = 0, sum_estimated = 0;
  for (index_t j = 1; j < 15; ++j)
    for (index_t i = 1; i < 15; ++i) {
      if (((i + j) & 1) == 0) continue;
      const int facing[4] = {tessera::side_east, tessera::side_west, tessera::side_south, tessera::side_north};
      for (const auto* g : {&g_exact, &g_paper, &g_estimated}) {
        const index_t owners[4] = {g->at(i - 1, j), g->at(i + 1, j), g->at(i, j - 1), g->at(i, j + 1)};
        double total = 0;
        for (int s = 0; s < 4; ++s) total += m.overlap_error(owners[s], g->at(i, j), facing[s]);
        (g == &g_exact ? sum_exact : g == &g_paper ? sum_paper : sum_estimated) += total;
      }
    }
  CHECK(sum_exact < sum_paper);
  // the estimated fallback (the default) fits better than the paper's rule too (the exact one, limited to
  // fallback_budget candidates, is not a bound on it)
  CHECK(sum_estimated < sum_paper);
  CHECK(paper.evaluated_errors == 0);
  // bit-identical for any thread count and window
  tessera::thread_pool_executor pool(2);
  tessera::image_buffer<std::uint8_t, 3> threaded(256, 256), part(100, 90);
  REQUIRE(tessera::synthesize(m, threaded, exact_opts, pool).ok());
  CHECK(threaded == a);
  auto window = exact_opts;
  window.origin = {37, 61};
  REQUIRE(tessera::synthesize(m, part, window).ok());
  index_t mismatches = 0;
  for (index_t y = 0; y < 90; ++y)
    for (index_t x = 0; x < 100; ++x) mismatches += part.read(x, y) != a.read(37 + x, 61 + y) ? 1 : 0;
  CHECK(mismatches == 0);
  // bad options name themselves
  auto bad = tessera::synthesize(m, a, {.fallback_budget = 0});
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().message().find("fallback_budget") != std::string::npos);
  auto bad_rule = tessera::synthesize(m, a, {.fallback = static_cast<tessera::fill_fallback>(7)});
  REQUIRE_FALSE(bad_rule.ok());
  CHECK(bad_rule.error().message().find("fallback") != std::string::npos);
}

TEST_CASE("synthesize: distributed cells draw from their phase group", "[patch_synthesis]") {
  const auto& m = bricks_model();
  const index_t pw = m.patch_width(), ph = m.patch_height();
  auto phase = [&](index_t p) { return std::pair{m.origin(p).x % pw, m.origin(p).y % ph}; };
  // the documented groups: phases within Chebyshev distance r (modulo the pitch) of a centre phase, or
  // (r = -1) phases in phase_similarity() order, those at least 0.9 similar, then more up to min_group
  auto group_of = [&](index_t cx, index_t cy, index_t r, index_t min_group) {
    std::vector<std::pair<index_t, index_t>> phases;
    auto add = [&](index_t dx, index_t dy) {
      phases.push_back({((cx + dx) % pw + pw) % pw, ((cy + dy) % ph + ph) % ph});
    };
    index_t size = 0;
    if (r >= 0) {
      for (index_t dy = -r; dy <= r; ++dy)
        for (index_t dx = -r; dx <= r; ++dx) add(dx, dy);
    } else {
      for (const auto& o : m.phase_similarity()) {
        if (o.similarity < 0.9 && size >= min_group) break;
        add(o.dx, o.dy);
        size += static_cast<index_t>(m.phase_patches(phases.back().second * pw + phases.back().first).size());
      }
    }
    std::sort(phases.begin(), phases.end());
    phases.erase(std::unique(phases.begin(), phases.end()), phases.end());
    index_t patches = 0;
    for (const auto& [x, y] : phases) patches += static_cast<index_t>(m.phase_patches(y * pw + x).size());
    return std::pair{phases, patches};
  };
  for (const auto& [radius, min_group] : {std::pair<index_t, index_t>{0, 16}, {1, 16}, {-1, 16}, {-1, 200}})
    for (std::uint64_t seed : {1u, 2u}) {
      const tessera::patch_synthesis_options o{.seed = seed, .phase_radius = radius, .min_phase_group = min_group};
      const auto g = recover_cells(m, o, -4, 7, 8, 8);
      std::vector<std::pair<index_t, index_t>> placed;
      std::vector<index_t> distinct;
      for (index_t j = 7; j < 15; ++j)
        for (index_t i = -4; i < 4; ++i)
          if (((i + j) & 1) == 0) placed.push_back(phase(g.at(i, j))), distinct.push_back(g.at(i, j));
      std::sort(distinct.begin(), distinct.end());
      distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
      CHECK(distinct.size() > 1);  // random draws, not one patch
      tessera::image_buffer<std::uint8_t, 3> out(8, 8);
      const index_t reported = tessera::synthesize(m, out, o).value().phase_group;
      // some centre phase explains every placed patch and the reported group size
      bool explained = false;
      for (index_t cy = 0; cy < ph && !explained; ++cy)
        for (index_t cx = 0; cx < pw && !explained; ++cx) {
          if (m.phase_patches(cy * pw + cx).empty()) continue;
          const auto [phases, patches] = group_of(cx, cy, radius, min_group);
          bool all = patches == reported;
          for (const auto& p : placed) all = all && std::binary_search(phases.begin(), phases.end(), p);
          explained = all;
        }
      INFO("radius " << radius << ", min group " << min_group << ", seed " << seed << ", group of " << reported);
      CHECK(explained);
      if (radius == 0) CHECK(std::all_of(placed.begin(), placed.end(), [&](const auto& p) { return p == placed[0]; }));
    }
}

TEST_CASE("synthesize: feathered overlaps are the paper's linear blend of the two sources", "[patch_synthesis]") {
  // C = (1 - w) C_A + w C_B with w = (t + 1/2) / v at overlap position t (the distance to the overlap's
  // border); where a horizontal and a vertical overlap cross, the two rows blended that way, blended again.
  // A feather band b < v: w = 0 before the band's first position s = (v - b) / 2, (t - s + 1/2) / b in
  // it, 1 after it.
  auto check = [](const auto& m, index_t band, double edge_tolerance, double corner_tolerance) {
    const index_t pw = m.patch_width(), ph = m.patch_height(), v = m.overlap();
    const index_t b = band == 0 ? v : std::min(band, v), s = (v - b) / 2;
    const tessera::patch_synthesis_options o{.origin = {-2 * pw, 3 * ph}, .seed = 12, .feather_width = band};
    const auto weight = [&](index_t t) { return t < s ? 0.0 : t >= s + b ? 1.0 : (t - s + 0.5) / double(b); };
    const auto g = recover_cells(m, o, -3, 2, 6, 5);
    tessera::image_buffer<typename std::remove_cvref_t<decltype(m)>::channel_type, 3> out(4 * pw, 3 * ph);
    REQUIRE(tessera::synthesize(m, out, o).ok());
    const auto& ex = m.exemplar();
    auto source = [&](index_t i, index_t j, index_t lx, index_t ly, int c) {
      const auto origin = m.origin(g.at(i, j));
      return static_cast<double>(ex.read(origin.x + lx, origin.y + ly)[c]);
    };
    double worst_edge = 0, worst_corner = 0;
    for (index_t y = 0; y < out.height(); ++y)
      for (index_t x = 0; x < out.width(); ++x) {
        const index_t X = o.origin.x + x, Y = o.origin.y + y;
        const index_t i = tessera::detail::floor_div(X, pw), j = tessera::detail::floor_div(Y, ph), lx = X - i * pw,
                      ly = Y - j * ph;
        const double wx = weight(lx), wy = weight(ly);
        for (int c = 0; c < 3; ++c) {
          auto row = [&](index_t jj, index_t ry) {  // the horizontally blended row of cell row jj at patch row ry
            return lx >= v ? source(i, jj, lx, ry, c)
                           : (1 - wx) * source(i - 1, jj, lx + pw, ry, c) + wx * source(i, jj, lx, ry, c);
          };
          const double expected = ly >= v ? row(j, ly) : (1 - wy) * row(j - 1, ly + ph) + wy * row(j, ly);
          double& worst = lx < v && ly < v ? worst_corner : worst_edge;
          worst = std::max(worst, std::abs(static_cast<double>(out.read(x, y)[c]) - expected));
        }
      }
    CHECK(worst_edge <= edge_tolerance);
    CHECK(worst_corner <= corner_tolerance);
  };
  for (index_t band : {0, 1, 2, 3, 4, 9}) {
    INFO("feather band " << band);
    check(bricks_model(), band, 1.0, 2.0);  // 8-bit fixed point: weight and result rounding
  }
  const auto exf = exemplar<float, 3>(tessera::exemplar_kind::grass, 40);
  const auto mf =
      tessera::build_patch_model(exf, {.patch_width = 11, .patch_height = 9, .overlap = 4, .candidates = 4}).value();
  for (index_t band : {0, 1, 3}) check(mf, band, 1e-5, 1e-5);
}

TEST_CASE("synthesize: a narrow feather band keeps outputs closer to their exemplar than the paper's",
          "[patch_synthesis]") {
  // the default band (5 pixels in an overlap of 12) blends less of two unrelated patches than the
  // paper's weights over the whole overlap: the ghosted band occurs nowhere in the exemplar
  for (auto kind : {tessera::exemplar_kind::sand, tessera::exemplar_kind::bricks}) {
    const auto ex = exemplar(kind, 64);
    const auto m = tessera::build_patch_model(ex, {.patch_width = 24, .patch_height = 24, .overlap = 12}).value();
    const tessera::neighborhood_energy_options eo{.window = 5, .sample_step = 2};
    double paper = 0, narrow = 0;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      tessera::image_buffer<std::uint8_t, 3> a(120, 120), b(120, 120);
      REQUIRE(tessera::synthesize(m, a, {.seed = seed, .feather_width = 0}).ok());
      REQUIRE(tessera::synthesize(m, b, {.seed = seed}).ok());
      paper += tessera::neighborhood_energy(a, ex, eo).value();
      narrow += tessera::neighborhood_energy(b, ex, eo).value();
    }
    INFO(tessera::to_string(kind) << ": energy, paper's feathering " << paper / 3 << ", default band " << narrow / 3);
    CHECK(narrow < paper);
  }
}

TEST_CASE("synthesize: seam cuts keep a structured texture closer to its exemplar than feathering",
          "[patch_synthesis]") {
  // bricks of 12 x 6 pixels (48-pixel exemplar) and patches of one and a half bricks: feathering ghosts
  // mortar lines across the overlaps, the cuts keep bricks whole (docs/patch_synthesis.md, picture)
  const auto ex = exemplar(tessera::exemplar_kind::bricks, 48);
  const auto m =
      tessera::build_patch_model(ex, {.patch_width = 18, .patch_height = 18, .overlap = 8, .seams = true}).value();
  for (std::uint64_t seed : {5u, 6u}) {
    tessera::image_buffer<std::uint8_t, 3> feather(96, 96), cut(96, 96);
    REQUIRE(tessera::synthesize(m, feather, {.seed = seed, .feather_width = 0}).ok());  // the paper's feathering
    REQUIRE(tessera::synthesize(m, cut, {.seed = seed, .seams = seam_mode::cut}).ok());
    const tessera::neighborhood_energy_options eo{.window = 5, .sample_step = 3};
    const double e_feather = tessera::neighborhood_energy(feather, ex, eo).value(),
                 e_cut = tessera::neighborhood_energy(cut, ex, eo).value();
    INFO("seed " << seed << ", neighbourhood energy: feather " << e_feather << ", cut " << e_cut);
    CHECK(e_cut < 0.7 * e_feather);
  }
}
