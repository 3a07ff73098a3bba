#include <tessera/core/image_checks.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include <catch2/catch.hpp>
#include "../support/test_support.hpp"

using tessera_test::mentions;

using tessera::index_t;
using tessera::status_code;
using tessera::validate_image_extent;

namespace {
struct sized {
  index_t w, h;
  index_t width() const { return w; }
  index_t height() const { return h; }
  std::array<float, 3> read(index_t, index_t) const { return {}; }
};
}  // namespace

TEST_CASE("image_checks: valid extents pass", "[image_checks]") {
  REQUIRE(validate_image_extent(1, 1, 1, "img").ok());
  REQUIRE(validate_image_extent(4096, 4096, 4, "img").ok());
  // exactly at the limit
  REQUIRE(validate_image_extent(index_t{1} << 20, index_t{1} << 20, 1, "img").ok());
  REQUIRE(validate_image_extent(index_t{1} << 19, index_t{1} << 19, 4, "img").ok());
}

TEST_CASE("image_checks: zero and negative sizes", "[image_checks]") {
  for (auto [w, h] : {std::pair<index_t, index_t>{0, 5},
                      {5, 0},
                      {0, 0},
                      {-1, 5},
                      {5, -7},
                      {-3, -3},
                      {std::numeric_limits<index_t>::min(), 1}}) {
    const auto s = validate_image_extent(w, h, 3, "exemplar");
    REQUIRE(s.code() == status_code::invalid_argument);
    REQUIRE(mentions(s, "exemplar"));
    REQUIRE(mentions(s, std::to_string(w) + " x " + std::to_string(h)));
  }
}

TEST_CASE("image_checks: channel counts outside 1..4", "[image_checks]") {
  for (int c : {0, -1, 5, 100}) {
    const auto s = validate_image_extent(8, 8, c, "output");
    REQUIRE(s.code() == status_code::invalid_argument);
    REQUIRE(mentions(s, "got " + std::to_string(c)));
  }
}

TEST_CASE("image_checks: sizes whose element or byte count overflows", "[image_checks]") {
  const index_t big = std::numeric_limits<index_t>::max();
  for (auto [w, h, c] : {std::tuple<index_t, index_t, int>{(index_t{1} << 20) + 1, index_t{1} << 20, 1},
                         {index_t{1} << 20, index_t{1} << 20, 2},
                         {big, 1, 1},
                         {1, big, 1},
                         {big, big, 4},
                         {index_t{1} << 32, index_t{1} << 32, 1},  // product wraps to 0 in 64 bits
                         {3037000500, 3037000500, 1}}) {           // product overflows index_t
    const auto s = validate_image_extent(w, h, c, "mask");
    REQUIRE(s.code() == status_code::size_overflow);
    REQUIRE(mentions(s, "mask"));
  }
}

TEST_CASE("image_checks: validate_image and validate_same_size", "[image_checks]") {
  REQUIRE(tessera::validate_image(sized{3, 2}, "a").ok());
  REQUIRE(tessera::validate_image(sized{0, 2}, "a").code() == status_code::invalid_argument);
  REQUIRE(tessera::validate_image(sized{-2, 2}, "a").code() == status_code::invalid_argument);
  REQUIRE(tessera::validate_same_size(sized{3, 2}, "a", sized{3, 2}, "b").ok());
  const auto s = tessera::validate_same_size(sized{3, 2}, "exemplar", sized{3, 4}, "mask");
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(s.message() == "mask is 3 x 4 but exemplar is 3 x 2; they must match");
}
