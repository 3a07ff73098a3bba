#include <tessera/core/image.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

using tessera::index_t;

namespace {
// A member-style user image: grey float pixels in a vector.
struct grey_image {
  index_t w = 0, h = 0;
  std::vector<float> v;
  index_t width() const { return w; }
  index_t height() const { return h; }
  float read(index_t x, index_t y) const { return v[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, float p) { v[static_cast<std::size_t>(y * w + x)] = p; }
};
// A read-only member-style image returning std::array by value.
struct checker {
  int width() const { return 4; }  // int converts to index_t
  int height() const { return 2; }
  std::array<std::uint8_t, 3> read(index_t x, index_t y) const {
    const std::uint8_t c = (x + y) % 2 ? 255 : 0;
    return {c, c, c};
  }
};
// A foreign type reached through an image_traits specialization.
struct engine_texture {
  int size_x = 2, size_y = 3;
  std::vector<std::uint16_t> texels = std::vector<std::uint16_t>(12, 0);  // 2 channels
};
}  // namespace

template <>
struct tessera::image_traits<engine_texture> {
  static index_t width(const engine_texture& t) { return t.size_x; }
  static index_t height(const engine_texture& t) { return t.size_y; }
  static std::array<std::uint16_t, 2> read(const engine_texture& t, index_t x, index_t y) {
    const auto i = static_cast<std::size_t>(2 * (y * t.size_x + x));
    return {t.texels[i], t.texels[i + 1]};
  }
  static void write(engine_texture& t, index_t x, index_t y, const std::array<std::uint16_t, 2>& p) {
    const auto i = static_cast<std::size_t>(2 * (y * t.size_x + x));
    t.texels[i] = p[0];
    t.texels[i + 1] = p[1];
  }
};

static_assert(tessera::Channel<std::uint8_t> && tessera::Channel<std::uint16_t> && tessera::Channel<float>);
static_assert(!tessera::Channel<double> && !tessera::Channel<int> && !tessera::Channel<std::int8_t>);
static_assert(tessera::Pixel<float> && tessera::Pixel<std::uint8_t> && tessera::Pixel<std::array<float, 4>>);
static_assert(!tessera::Pixel<double>);                 // channel type not supported
static_assert(!tessera::Pixel<std::array<float, 5>>);   // too many channels
static_assert(!tessera::Pixel<std::array<float, 0>>);   // too few
static_assert(!tessera::Pixel<std::array<double, 3>>);  // channel type
static_assert(!tessera::Pixel<std::vector<float>>);     // unknown to pixel_traits
static_assert(tessera::Image<grey_image> && tessera::WritableImage<grey_image>);
static_assert(tessera::Image<checker> && !tessera::WritableImage<checker>);
static_assert(tessera::Image<engine_texture> && tessera::WritableImage<engine_texture>);
static_assert(!tessera::Image<int> && !tessera::Image<std::vector<float>>);
static_assert(std::is_same_v<tessera::pixel_t<checker>, std::array<std::uint8_t, 3>>);
static_assert(std::is_same_v<tessera::channel_t<engine_texture>, std::uint16_t>);
static_assert(tessera::channels_v<engine_texture> == 2 && tessera::channels_v<grey_image> == 1);
static_assert(std::is_same_v<tessera::pixel<float, 3>, std::array<float, 3>>);

TEST_CASE("image: channel <-> unit conversions", "[image]") {
  using tessera::channel_to_unit;
  using tessera::unit_to_channel;
  REQUIRE(channel_to_unit(std::uint8_t{0}) == 0.0f);
  REQUIRE(channel_to_unit(std::uint8_t{255}) == 1.0f);
  REQUIRE(channel_to_unit(std::uint16_t{65535}) == 1.0f);
  REQUIRE(channel_to_unit(0.25f) == 0.25f);
  REQUIRE(unit_to_channel<std::uint8_t>(-0.5f) == 0);
  REQUIRE(unit_to_channel<std::uint8_t>(1.5f) == 255);
  REQUIRE(unit_to_channel<std::uint8_t>(std::numeric_limits<float>::quiet_NaN()) == 0);
  REQUIRE(unit_to_channel<std::uint16_t>(std::numeric_limits<float>::infinity()) == 65535);
  REQUIRE(unit_to_channel<std::uint8_t>(0.5f / 255.0f + 1e-6f) == 1);  // rounds to nearest
  REQUIRE(unit_to_channel<std::uint8_t>(0.5f / 255.0f - 1e-6f) == 0);
  REQUIRE(unit_to_channel<float>(1.5f) == 1.5f);  // float keeps its range
}

TEST_CASE("image: integer channel round trips are exact", "[image]") {
  using tessera::convert_channel;
  int bad = 0;  // counted rather than asserted one by one, to keep the test fast
  for (int v = 0; v <= 255; ++v) {
    const auto c = static_cast<std::uint8_t>(v);
    bad += convert_channel<std::uint8_t>(convert_channel<float>(c)) != c;
    bad += convert_channel<std::uint16_t>(c) != v * 257;
    bad += convert_channel<std::uint8_t>(convert_channel<std::uint16_t>(c)) != c;
  }
  REQUIRE(bad == 0);
  for (int v = 0; v <= 65535; ++v) {
    const auto c = static_cast<std::uint16_t>(v);
    bad += convert_channel<std::uint16_t>(convert_channel<float>(c)) != c;
    const auto down = convert_channel<std::uint8_t>(c);
    bad += std::abs(down * 257 - v) > 128;  // nearest uint8 level
    // the integer path agrees with the float path up to ties
    bad += std::abs(int(down) - int(tessera::unit_to_channel<std::uint8_t>(tessera::channel_to_unit(c)))) > 1;
  }
  REQUIRE(bad == 0);
}

TEST_CASE("image: convert_pixel between channel counts", "[image]") {
  using tessera::convert_pixel;
  using tessera::pixel;
  // grey -> rgb -> grey
  const auto rgb = convert_pixel<pixel<std::uint8_t, 3>>(std::uint8_t{77});
  REQUIRE(rgb == pixel<std::uint8_t, 3>{77, 77, 77});
  REQUIRE(convert_pixel<std::uint8_t>(rgb) == 77);
  // colour -> Rec. 601 luma
  REQUIRE(convert_pixel<float>(pixel<float, 3>{1, 0, 0}) == Approx(0.299f));
  REQUIRE(convert_pixel<float>(pixel<float, 3>{0, 1, 0}) == Approx(0.587f));
  REQUIRE(convert_pixel<std::uint8_t>(pixel<std::uint8_t, 3>{0, 0, 255}) == 29);  // 0.114 * 255 = 29.07
  // alpha: added opaque, dropped, kept through grey + alpha
  REQUIRE(convert_pixel<pixel<std::uint16_t, 4>>(pixel<std::uint8_t, 3>{1, 2, 3}) ==
          pixel<std::uint16_t, 4>{257, 514, 771, 65535});
  REQUIRE(convert_pixel<pixel<float, 3>>(pixel<float, 4>{0.1f, 0.2f, 0.3f, 0.0f}) == pixel<float, 3>{0.1f, 0.2f, 0.3f});
  const auto ga = convert_pixel<pixel<float, 2>>(pixel<float, 4>{0.5f, 0.5f, 0.5f, 0.25f});
  REQUIRE(ga[0] == Approx(0.5f));
  REQUIRE(ga[1] == 0.25f);
  REQUIRE(convert_pixel<pixel<std::uint8_t, 4>>(pixel<std::uint8_t, 2>{10, 20}) ==
          pixel<std::uint8_t, 4>{10, 10, 10, 20});
  // same channel count: per channel
  REQUIRE(convert_pixel<pixel<std::uint8_t, 2>>(pixel<std::uint16_t, 2>{65535, 0}) == pixel<std::uint8_t, 2>{255, 0});
}

TEST_CASE("image: traits reach member-style and specialized types", "[image]") {
  grey_image g{3, 2, std::vector<float>(6, 0.0f)};
  tessera::image_traits<grey_image>::write(g, 2, 1, 0.75f);
  REQUIRE(tessera::image_traits<grey_image>::read(g, 2, 1) == 0.75f);
  REQUIRE(tessera::width_of(g) == 3);
  REQUIRE(tessera::height_of(g) == 2);

  const checker c;
  REQUIRE(tessera::width_of(c) == 4);
  REQUIRE(tessera::image_traits<checker>::read(c, 1, 0)[0] == 255);

  engine_texture t;
  tessera::image_traits<engine_texture>::write(t, 1, 2, {7, 9});
  REQUIRE(t.texels[10] == 7);
  REQUIRE(t.texels[11] == 9);
  REQUIRE(tessera::height_of(t) == 3);
}
