#include <tessera/fabric/tone_proportions.hpp>

#include <catch2/catch.hpp>

#include <limits>

#include <tessera/core/image_buffer.hpp>
#include <tessera/fabric/cat_map.hpp>
#include <tessera/image/exemplars.hpp>

using namespace tessera;

TEST_CASE("tone_proportions assigns each pixel to its nearest palette tone", "[tone_proportions]") {
  const palette three = {{{0.8f, 0.1f, 0.1f}, 5}, {{0.1f, 0.7f, 0.2f}, 3}, {{0.1f, 0.1f, 0.9f}, 2}};
  image_buffer<std::uint8_t, 3> img(80, 80);
  REQUIRE(make_source_image(img, three, {.layout = source_layout::blocks, .feature_size = 8}).ok());
  auto p = tone_proportions(img, three);
  REQUIRE(p.ok());
  CHECK((*p)[0] == Approx(0.5));
  CHECK((*p)[1] == Approx(0.3));
  CHECK((*p)[2] == Approx(0.2));
  // invariant under the cat map (a permutation)
  CHECK(*tone_proportions(*cat_map(img, 60), three) == *p);
  // nearby colours go to the nearest tone; a tie goes to the first tone
  image_buffer<float, 3> two(2, 1);
  two.write(0, 0, {0.6f, 0.2f, 0.2f});
  two.write(1, 0, {0.5f, 0.5f, 0.5f});
  auto q = tone_proportions(two, {{{0, 0, 0}, 1}, {{1, 1, 1}, 1}});
  CHECK((*q)[0] == Approx(1.0));
}

TEST_CASE("dominant_tones recovers the tones of an image by k-means", "[tone_proportions]") {
  const palette three = {{{0.8f, 0.1f, 0.1f}, 5}, {{0.1f, 0.7f, 0.2f}, 3}, {{0.1f, 0.1f, 0.9f}, 2}};
  image_buffer<float, 3> img(60, 60);
  REQUIRE(make_source_image(img, three, {.layout = source_layout::cells, .feature_size = 10}).ok());
  const auto truth = *tone_proportions(img, three);
  auto d = dominant_tones(img, 3);
  REQUIRE(d.ok());
  REQUIRE(d->size() == 3);
  // sorted by share; each found tone is one of the palette colours with its share
  CHECK((*d)[0].proportion >= (*d)[1].proportion);
  CHECK((*d)[1].proportion >= (*d)[2].proportion);
  for (const tone& t : *d) {
    bool matched = false;
    for (std::size_t i = 0; i < three.size(); ++i)
      if (std::abs(t.color[0] - three[i].color[0]) < 1e-4 && std::abs(t.color[1] - three[i].color[1]) < 1e-4 &&
          std::abs(t.color[2] - three[i].color[2]) < 1e-4) {
        matched = true;
        CHECK(t.proportion == Approx(truth[i]));
      }
    CHECK(matched);
  }
  // more clusters than colours: only the colours present
  CHECK(dominant_tones(img, 8)->size() == 3);
  // a photo-like exemplar: k tones, shares summing to 1, deterministic
  const auto sand = *make_exemplar<std::uint8_t, 3>(exemplar_kind::rock, {.width = 64, .height = 64});
  auto a = *dominant_tones(sand, 4), b = *dominant_tones(sand, 4);
  REQUIRE(a.size() == 4);
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sum += a[i].proportion;
    CHECK(a[i].color == b[i].color);
  }
  CHECK(sum == Approx(1.0));
}

TEST_CASE("tone measurements reject bad input", "[tone_proportions]") {
  image_buffer<std::uint8_t, 3> img(4, 4);
  image_view<const std::uint8_t, 3> empty;
  CHECK(tone_proportions(img, {}).error().code() == status_code::invalid_argument);
  CHECK(tone_proportions(empty, {{{0, 0, 0}, 1}}).error().code() == status_code::invalid_argument);
  CHECK(dominant_tones(img, 0).error().message().find("k must be >= 1, got 0") != std::string::npos);
  CHECK_FALSE(dominant_tones(empty, 2).ok());
  CHECK_FALSE(dominant_tones(img, 2, {.max_iterations = -1}).ok());
  // a NaN or infinite channel is rejected, naming the pixel (never binned out of bounds or
  // counted as the first tone)
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()}) {
    image_buffer<float, 3> hdr(5, 4, {0.2f, 0.3f, 0.4f});
    hdr.write(3, 2, {0.5f, bad, 0.5f});
    auto p = tone_proportions(hdr, {{{0, 0, 0}, 1}, {{1, 1, 1}, 1}});
    REQUIRE_FALSE(p.ok());
    CHECK(p.error().code() == status_code::invalid_argument);
    CHECK(p.error().message().find("(3, 2)") != std::string::npos);
    auto d = dominant_tones(hdr, 2);
    REQUIRE_FALSE(d.ok());
    CHECK(d.error().message().find("(3, 2)") != std::string::npos);
  }
  // finite HDR values are fine: measured as they are, binned clamped
  image_buffer<float, 3> bright(4, 4, {4.0f, 4.0f, 4.0f});
  CHECK((*tone_proportions(bright, {{{0, 0, 0}, 1}, {{1, 1, 1}, 1}}))[1] == 1.0);
  const auto d = *dominant_tones(bright, 2);
  REQUIRE(d.size() == 1);
  CHECK(d[0].color == pixel<float, 3>{1.0f, 1.0f, 1.0f});
}
