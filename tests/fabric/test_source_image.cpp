#include <tessera/fabric/source_image.hpp>

#include <map>

#include <catch2/catch.hpp>

#include <tessera/core/image_buffer.hpp>
#include <tessera/fabric/cat_map.hpp>

using namespace tessera;

namespace {
const palette black_white = {{{0, 0, 0}, 0.75}, {{1, 1, 1}, 0.25}};

template <class Img>
std::map<std::array<std::uint8_t, 3>, double> shares(const Img& img) {
  std::map<std::array<std::uint8_t, 3>, double> m;
  for (index_t y = 0; y < img.height(); ++y)
    for (index_t x = 0; x < img.width(); ++x)
      m[img.read(x, y)] += 1.0 / static_cast<double>(img.width() * img.height());
  return m;
}
}  // namespace

TEST_CASE("parse_palette reads #rrggbb:weight lists", "[source_image]") {
  auto p = parse_palette("#000000:0.75,#ffffff:0.25");
  REQUIRE(p.ok());
  REQUIRE(p->size() == 2);
  CHECK((*p)[1].color == pixel<float, 3>{1, 1, 1});
  CHECK((*p)[0].proportion == 0.75);
  auto q = parse_palette(" #FF8000:3 , 102030:1");
  REQUIRE(q.ok());
  CHECK((*q)[0].color[1] == Approx(128.0 / 255));
  CHECK((*q)[1].color[0] == Approx(16.0 / 255));
  for (const char* bad :
       {"", "#000000", "#00000:1", "#00000g:1", "#000000:x", "#000000:-1", "#000000:0,#ffffff:0", "#000000:0.5,"}) {
    INFO(bad);
    auto e = parse_palette(bad);
    REQUIRE_FALSE(e.ok());
    CHECK(e.error().code() == status_code::parse_error);
  }
}

TEST_CASE("palettes: proportions are normalized, invalid tones rejected", "[source_image]") {
  auto n = normalized_proportions({{{0, 0, 0}, 3}, {{1, 1, 1}, 1}});
  REQUIRE(n.ok());
  CHECK((*n)[0] == Approx(0.75));
  CHECK((*n)[1] == Approx(0.25));
  CHECK(normalized_proportions({}).error().message().find("empty") != std::string::npos);
  CHECK(normalized_proportions({{{0, 0, 0}, -1}}).error().message().find("-1") != std::string::npos);
  CHECK(normalized_proportions({{{0, 0, 0}, 0}}).error().message().find("sum to 0") != std::string::npos);
  CHECK_FALSE(normalized_proportions({{{1.5f, 0, 0}, 1}}).ok());
  CHECK_FALSE(normalized_proportions({{{0, 0, 0}, std::nan("")}}).ok());
  // finite weights whose sum overflows are rejected, not normalized to 0 / inf = 0 each
  auto big = normalized_proportions({{{0, 0, 0}, 1e308}, {{1, 1, 1}, 1e308}});
  REQUIRE_FALSE(big.ok());
  CHECK(big.error().code() == status_code::invalid_argument);
  CHECK(big.error().message().find("inf") != std::string::npos);
  CHECK_FALSE(parse_palette("#000000:1e308,#ffffff:1e308").ok());
}

TEST_CASE("source images reproduce the palette proportions", "[source_image]") {
  image_buffer<std::uint8_t, 3> img(96, 96);
  // stripes: bands of 16 rows split 12 / 4
  REQUIRE(make_source_image(img, black_white, {.layout = source_layout::stripes, .feature_size = 16}).ok());
  auto s = shares(img);
  CHECK(s[{0, 0, 0}] == Approx(0.75));
  CHECK(s[{255, 255, 255}] == Approx(0.25));
  for (index_t x = 0; x < 96; ++x) CHECK(img.read(x, 13) == img.read(0, 13));  // horizontal bands
  REQUIRE(make_source_image(img, black_white, {.layout = source_layout::stripes, .feature_size = 16, .vertical = true})
              .ok());
  for (index_t y = 0; y < 96; ++y) CHECK(img.read(13, y) == img.read(13, 0));
  // blocks: 36 blocks of 16 x 16, exactly 27 black
  REQUIRE(make_source_image(img, black_white, {.layout = source_layout::blocks, .feature_size = 16, .seed = 5}).ok());
  s = shares(img);
  CHECK(s[{0, 0, 0}] == Approx(0.75));
  // cells: within one cell area of the target
  REQUIRE(make_source_image(img, black_white, {.layout = source_layout::cells, .feature_size = 12, .seed = 2}).ok());
  s = shares(img);
  CHECK(std::abs(s[{0, 0, 0}] - 0.75) < 2.0 * 144 / (96.0 * 96.0));
  CHECK(s.size() == 2);
  // three tones with unnormalized weights
  const palette three = {{{1, 0, 0}, 2}, {{0, 1, 0}, 1}, {{0, 0, 1}, 1}};
  REQUIRE(make_source_image(img, three, {.layout = source_layout::blocks, .feature_size = 8}).ok());
  s = shares(img);
  CHECK(s[{255, 0, 0}] == Approx(0.5));
  CHECK(s[{0, 255, 0}] == Approx(0.25));
}

TEST_CASE("source images are seeded and deterministic, the cat map keeps their proportions", "[source_image]") {
  for (source_layout l : {source_layout::blocks, source_layout::cells}) {
    image_buffer<std::uint8_t, 3> a(64, 64), b(64, 64), c(64, 64);
    REQUIRE(make_source_image(a, black_white, {.layout = l, .seed = 1}).ok());
    REQUIRE(make_source_image(b, black_white, {.layout = l, .seed = 1}).ok());
    REQUIRE(make_source_image(c, black_white, {.layout = l, .seed = 2}).ok());
    CHECK(a == b);
    CHECK_FALSE(a == c);
    CHECK(shares(*cat_map(a, 31)) == shares(a));
  }
  // grey and RGBA outputs get luma and opaque alpha
  image_buffer<float, 1> grey(8, 8);
  REQUIRE(make_source_image(grey, {{{1, 0, 0}, 1}}).ok());
  CHECK(grey.read(3, 3)[0] == Approx(0.299));
  image_buffer<std::uint16_t, 4> rgba(8, 8);
  REQUIRE(make_source_image(rgba, {{{1, 0, 0}, 1}}).ok());
  CHECK(rgba.read(2, 5) == pixel<std::uint16_t, 4>{65535, 0, 0, 65535});
}

TEST_CASE("make_source_image rejects bad input", "[source_image]") {
  image_buffer<std::uint8_t, 3> img(16, 16);
  CHECK(make_source_image(img, {}).code() == status_code::invalid_argument);
  CHECK(make_source_image(img, {{{0, 0, 0}, -0.5}}).code() == status_code::invalid_argument);
  auto s = make_source_image(img, black_white, {.feature_size = -3});
  CHECK(s.code() == status_code::invalid_argument);
  CHECK(s.message().find("-3") != std::string::npos);
  CHECK(make_source_image(img, black_white, {.layout = static_cast<source_layout>(9)}).code() ==
        status_code::invalid_argument);
  image_view<std::uint8_t, 3> empty;
  CHECK(make_source_image(empty, black_white).code() == status_code::invalid_argument);
}
