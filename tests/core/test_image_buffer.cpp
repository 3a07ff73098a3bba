#include <tessera/core/image_buffer.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

using tessera::image_buffer;
using tessera::index_t;
using tessera::pixel;
using tessera::status_code;

namespace {
// member-style user image with its own pixel struct reached through pixel_traits
struct rgb16 {
  std::uint16_t r = 0, g = 0, b = 0;
};
struct user_image {
  index_t w = 0, h = 0;
  std::vector<rgb16> px;
  index_t width() const { return w; }
  index_t height() const { return h; }
  rgb16 read(index_t x, index_t y) const { return px[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, const rgb16& p) { px[static_cast<std::size_t>(y * w + x)] = p; }
};
}  // namespace

template <>
struct tessera::pixel_traits<rgb16> {
  using channel_type = std::uint16_t;
  static constexpr int channels = 3;
  static std::uint16_t get(const rgb16& p, int c) { return c == 0 ? p.r : c == 1 ? p.g : p.b; }
  static void set(rgb16& p, int c, std::uint16_t v) { (c == 0 ? p.r : c == 1 ? p.g : p.b) = v; }
};

static_assert(tessera::WritableImage<image_buffer<float, 3>>);
static_assert(tessera::WritableImage<image_buffer<std::uint8_t, 1>>);
static_assert(tessera::WritableImage<user_image>);

TEST_CASE("image_buffer: construction, fill, read and write", "[image_buffer]") {
  image_buffer<std::uint8_t, 4> b(3, 2, {1, 2, 3, 4});
  REQUIRE(b.width() == 3);
  REQUIRE(b.height() == 2);
  REQUIRE(b.stride() == 12);
  REQUIRE(b.size_bytes() == 24);
  REQUIRE_FALSE(b.empty());
  for (index_t y = 0; y < 2; ++y)
    for (index_t x = 0; x < 3; ++x) REQUIRE(b.read(x, y) == pixel<std::uint8_t, 4>{1, 2, 3, 4});
  b.write(2, 1, {9, 8, 7, 6});
  REQUIRE(b.pixel_ptr(2, 1)[0] == 9);
  REQUIRE(b.row(1)[8 + 3] == 6);
  REQUIRE(b.view().read(2, 1) == b.read(2, 1));
  REQUIRE(b.cview().stride() == 12);

  image_buffer<std::uint8_t, 4> copy = b;
  REQUIRE(copy == b);
  copy.write(0, 0, {0, 0, 0, 0});
  REQUIRE_FALSE(copy == b);
  REQUIRE(image_buffer<float, 1>().empty());
}

TEST_CASE("image_buffer: create validates the size", "[image_buffer]") {
  REQUIRE(image_buffer<float, 3>::create(4, 4).ok());
  REQUIRE(image_buffer<float, 3>::create(0, 4).error().code() == status_code::invalid_argument);
  REQUIRE(image_buffer<float, 3>::create(4, -2).error().code() == status_code::invalid_argument);
  REQUIRE(image_buffer<float, 3>::create(std::numeric_limits<index_t>::max(), 2).error().code() ==
          status_code::size_overflow);
  const auto s = image_buffer<float, 3>::create(-1, 2).error();
  REQUIRE(s.message().find("image_buffer") != std::string::npos);
  // the plain constructor never throws or over-allocates: a bad size gives an empty image
  for (auto [w, h] : {std::pair<index_t, index_t>{-1, 2}, {0, 0}, {3, 0}, {std::numeric_limits<index_t>::max(), 2}}) {
    const image_buffer<float, 3> img(w, h);
    CHECK(img.width() == 0);
    CHECK(img.height() == 0);
  }
}

TEST_CASE("image_buffer: to_buffer converts any image", "[image_buffer]") {
  user_image u{2, 2, {{0, 0, 0}, {65535, 0, 0}, {0, 65535, 0}, {257, 514, 771}}};
  auto same = tessera::to_buffer(u);
  static_assert(std::is_same_v<decltype(same)::value_type, image_buffer<std::uint16_t, 3>>);
  REQUIRE(same.ok());
  REQUIRE(same->read(1, 1) == pixel<std::uint16_t, 3>{257, 514, 771});

  auto bytes = tessera::to_buffer<std::uint8_t, 4>(u);
  REQUIRE(bytes->read(1, 0) == pixel<std::uint8_t, 4>{255, 0, 0, 255});
  REQUIRE(bytes->read(1, 1) == pixel<std::uint8_t, 4>{1, 2, 3, 255});

  auto grey = tessera::to_buffer<float, 1>(u);
  REQUIRE(grey->read(1, 0)[0] == Approx(0.299f));

  // from a strided view: only the viewed pixels are copied
  std::vector<float> raw = {1, 2, -1, 3, 4, -1};
  tessera::image_view<const float, 1> v(raw.data(), 2, 2, 3);
  auto packed = tessera::to_buffer(v);
  REQUIRE(packed->stride() == 2);
  REQUIRE(packed->data()[2] == 3.0f);

  // an empty image is an error naming it
  user_image empty;
  auto e = tessera::to_buffer(empty, "exemplar");
  REQUIRE(e.error().code() == status_code::invalid_argument);
  REQUIRE(e.error().message().find("exemplar") == 0);
}

TEST_CASE("image_buffer: copy_image converts into any writable image", "[image_buffer]") {
  image_buffer<float, 3> src(2, 2, {1.0f, 0.5f, 0.0f});
  user_image dst{2, 2, std::vector<rgb16>(4)};
  REQUIRE(tessera::copy_image(src, dst).ok());
  REQUIRE(dst.px[3].r == 65535);
  REQUIRE(dst.px[3].g == 32768);
  REQUIRE(dst.px[3].b == 0);

  user_image wrong{3, 2, std::vector<rgb16>(6)};
  const auto s = tessera::copy_image(src, wrong);
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(s.message().find("destination is 3 x 2") != std::string::npos);
  for (const auto& p : wrong.px) REQUIRE(p.r == 0);  // nothing written on failure

  image_buffer<float, 3> empty;
  REQUIRE(tessera::copy_image(empty, dst).code() == status_code::invalid_argument);
}
