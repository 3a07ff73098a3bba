#include <tessera/core/vec.hpp>

#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

using tessera::aabb;
using tessera::vec2;
using tessera::vec3;

static_assert(vec3{1, 2, 3} + vec3{1, 1, 1} == vec3{2, 3, 4});
static_assert(tessera::dot(vec3{1, 2, 3}, vec3{4, 5, 6}) == 32);
static_assert(tessera::cross(vec3{1, 0, 0}, vec3{0, 1, 0}) == vec3{0, 0, 1});
static_assert(tessera::cross(vec2{2, 0}, vec2{0, 3}) == 6);

TEST_CASE("vec: arithmetic and products", "[vec]") {
  vec3 a{1, 2, 3};
  a += {1, 1, 1};
  a -= {0, 1, 0};
  a *= 2;
  REQUIRE(a == vec3{4, 4, 8});
  REQUIRE(-a == vec3{-4, -4, -8});
  REQUIRE(a / 4 == vec3{1, 1, 2});
  REQUIRE(0.5 * a == a * 0.5);
  REQUIRE(a[0] == 4);
  REQUIRE(a[2] == 8);
  a[1] = 5;
  REQUIRE(a.y == 5);
  REQUIRE(tessera::norm(vec3{2, 3, 6}) == 7);
  REQUIRE(tessera::squared_norm(vec3{2, 3, 6}) == 49);
  REQUIRE(tessera::distance(vec3{1, 1, 1}, vec3{3, 4, 7}) == 7);
  REQUIRE(tessera::norm(tessera::normalized(vec3{0, 3, 4})) == Approx(1.0));
  REQUIRE(tessera::normalized(vec3{}) == vec3{});  // zero stays zero, no NaN
  REQUIRE(tessera::normalized(vec3{std::numeric_limits<double>::infinity(), 0, 0}) == vec3{});

  vec2 b{3, 4};
  b *= 2;
  b -= {1, 1};
  REQUIRE(b == vec2{5, 7});
  REQUIRE(b[1] == 7);
  REQUIRE(tessera::squared_norm(vec2{3, 4}) == 25);
  REQUIRE(tessera::norm(vec2{3, 4}) == 5);
  REQUIRE(tessera::distance(vec2{0, 0}, vec2{3, 4}) == 5);
  REQUIRE(tessera::normalized(vec2{0, 2}) == vec2{0, 1});
  REQUIRE(tessera::normalized(vec2{}) == vec2{});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_FALSE(tessera::is_finite(vec3{0, nan, 0}));
  REQUIRE_FALSE(tessera::is_finite(vec2{std::numeric_limits<double>::infinity(), 0}));
  REQUIRE(tessera::is_finite(vec3{1, 2, 3}));
}

TEST_CASE("vec: bounding boxes", "[vec]") {
  aabb box;
  REQUIRE(box.empty());
  REQUIRE(box.extent() == vec3{});
  REQUIRE(box.center() == vec3{});  // no NaN from an empty box
  REQUIRE_FALSE(box.contains({0, 0, 0}));
  box.extend(vec3{1, 2, 3});
  REQUIRE_FALSE(box.empty());
  REQUIRE(box.min == vec3{1, 2, 3});
  REQUIRE(box.max == vec3{1, 2, 3});
  REQUIRE(box.extent() == vec3{});
  box.extend(vec3{-1, 4, 3});
  REQUIRE(box.center() == vec3{0, 3, 3});
  REQUIRE(box.extent() == vec3{2, 2, 0});
  REQUIRE(box.contains({0, 3, 3}));
  REQUIRE_FALSE(box.contains({0, 5, 3}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  box.extend(vec3{nan, nan, nan});  // ignored
  REQUIRE(box.min == vec3{-1, 2, 3});
  REQUIRE(box.max == vec3{1, 4, 3});

  aabb other;
  other.extend(vec3{5, 5, 5});
  box.extend(other);
  REQUIRE(box.max == vec3{5, 5, 5});
  box.extend(aabb{});  // an empty box changes nothing
  REQUIRE(box.min == vec3{-1, 2, 3});
}
