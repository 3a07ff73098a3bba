#include <tessera/core/image_view.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

using tessera::image_view;
using tessera::index_t;
using tessera::status_code;

static_assert(tessera::WritableImage<image_view<std::uint8_t, 4>>);
static_assert(tessera::WritableImage<image_view<float, 1>>);
static_assert(tessera::Image<image_view<const std::uint16_t, 3>>);
static_assert(!tessera::WritableImage<image_view<const std::uint16_t, 3>>);
static_assert(std::is_convertible_v<image_view<float, 2>, image_view<const float, 2>>);
static_assert(!std::is_convertible_v<image_view<const float, 2>, image_view<float, 2>>);
static_assert(std::is_trivially_copyable_v<image_view<float, 3>>);

TEST_CASE("image_view: packed and strided buffers", "[image_view]") {
  // 3 x 2 RGB with a row stride of 11 channel values (2 padding values per row)
  std::vector<std::uint8_t> buf(22, 99);
  auto v = tessera::make_image_view<3>(buf.data(), 3, 2, 11);
  REQUIRE(v.ok());
  REQUIRE(v->width() == 3);
  REQUIRE(v->height() == 2);
  REQUIRE(v->stride() == 11);
  REQUIRE_FALSE(v->empty());
  for (index_t y = 0; y < 2; ++y)
    for (index_t x = 0; x < 3; ++x) v->write(x, y, {std::uint8_t(10 * x + y), std::uint8_t(x), std::uint8_t(y)});
  REQUIRE(v->read(2, 1) == std::array<std::uint8_t, 3>{21, 2, 1});
  REQUIRE(buf[11 + 6] == 21);  // row 1 starts at the stride
  REQUIRE(buf[9] == 99);       // padding untouched
  REQUIRE(buf[10] == 99);
  REQUIRE(buf[20] == 99);
  REQUIRE(buf[21] == 99);

  // stride 0 means packed
  auto p = tessera::make_image_view<3>(buf.data(), 3, 2);
  REQUIRE(p->stride() == 9);
  REQUIRE(p->row(1) == buf.data() + 9);
  REQUIRE(p->pixel_ptr(1, 1) == buf.data() + 12);

  // const view from a mutable one reads the same pixels
  image_view<const std::uint8_t, 3> c = *v;
  REQUIRE(c.read(2, 1) == v->read(2, 1));
  const std::vector<std::uint8_t>& cbuf = buf;
  auto cv = tessera::make_image_view<3>(cbuf.data(), 3, 2, 11);
  static_assert(std::is_same_v<decltype(cv)::value_type, image_view<const std::uint8_t, 3>>);
  REQUIRE(cv->read(0, 1) == v->read(0, 1));
}

TEST_CASE("image_view: subview addresses the same pixels", "[image_view]") {
  std::vector<float> buf(5 * 4);
  for (std::size_t i = 0; i < buf.size(); ++i) buf[i] = static_cast<float>(i);
  image_view<float, 1> v(buf.data(), 5, 4);
  auto s = v.subview(1, 2, 3, 2);
  REQUIRE(s.width() == 3);
  REQUIRE(s.height() == 2);
  REQUIRE(s.stride() == 5);
  REQUIRE(s.read(0, 0)[0] == 11.0f);
  REQUIRE(s.read(2, 1)[0] == 18.0f);
  s.write(2, 1, {-1.0f});
  REQUIRE(buf[18] == -1.0f);
  REQUIRE(v.subview(0, 0, 0, 0).empty());
}

TEST_CASE("image_view: bad buffers are rejected with a status", "[image_view]") {
  std::vector<std::uint16_t> buf(64);
  auto code = [](const auto& r) { return r.error().code(); };
  auto msg = [](const auto& r) { return r.error().message(); };

  // zero and negative sizes
  REQUIRE(code(tessera::make_image_view<2>(buf.data(), 0, 4)) == status_code::invalid_argument);
  REQUIRE(code(tessera::make_image_view<2>(buf.data(), 4, 0)) == status_code::invalid_argument);
  REQUIRE(code(tessera::make_image_view<2>(buf.data(), -4, 4)) == status_code::invalid_argument);
  REQUIRE(code(tessera::make_image_view<2>(buf.data(), 4, -1)) == status_code::invalid_argument);

  // stride smaller than width * channels (and negative strides)
  auto small = tessera::make_image_view<2>(buf.data(), 4, 4, 7);
  REQUIRE(code(small) == status_code::invalid_argument);
  REQUIRE(msg(small).find("stride 7") != std::string::npos);
  REQUIRE(msg(small).find("8") != std::string::npos);
  REQUIRE(code(tessera::make_image_view<2>(buf.data(), 4, 4, -8)) == status_code::invalid_argument);
  REQUIRE(tessera::make_image_view<2>(buf.data(), 4, 4, 8).ok());

  // null data with a non-zero size
  std::uint16_t* null = nullptr;
  auto n = tessera::make_image_view<2>(null, 4, 4);
  REQUIRE(code(n) == status_code::invalid_argument);
  REQUIRE(msg(n).find("null") != std::string::npos);

  // sizes whose element count or stride x height overflows
  const index_t big = std::numeric_limits<index_t>::max();
  REQUIRE(code(tessera::make_image_view<2>(buf.data(), big / 2, 4)) == status_code::size_overflow);
  REQUIRE(code(tessera::make_image_view<2>(buf.data(), 4, 4, big / 2)) == status_code::size_overflow);
  REQUIRE(code(tessera::make_image_view<4>(buf.data(), index_t{1} << 30, index_t{1} << 30)) ==
          status_code::size_overflow);

  // the caller's buffer is never touched by validation
  for (auto v : buf) REQUIRE(v == 0);
}
