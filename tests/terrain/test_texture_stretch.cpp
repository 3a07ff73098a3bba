#include <tessera/terrain/texture_stretch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

namespace {
using tessera::vec2;
using tessera::vec3;
// the texture corners of triangle a, b, c laid into the plane by its own frame, then mapped by M and shifted
std::array<float, 6> mapped(const vec3& a, const vec3& b, const vec3& c, double tpu, std::array<double, 4> M,
                            vec2 shift) {
  const vec3 e1 = b - a, e2 = c - a;
  const vec3 u = tessera::normalized(e1), n = tessera::normalized(tessera::cross(e1, e2)), v = tessera::cross(n, u);
  std::array<float, 6> t{};
  const vec3 p[3] = {a, b, c};
  for (std::size_t k = 0; k < 3; ++k) {
    const double x = tessera::dot(p[k] - a, u) * tpu, y = tessera::dot(p[k] - a, v) * tpu;
    t[2 * k] = static_cast<float>(M[0] * x + M[1] * y + shift.x);
    t[2 * k + 1] = static_cast<float>(M[2] * x + M[3] * y + shift.y);
  }
  return t;
}
}  // namespace

TEST_CASE("triangle_stretch: 1 for congruent copies, the largest scaling of a direction otherwise",
          "[terrain][stretch]") {
  // a steep face (45 degrees), its texture in its own plane: congruent whatever the rotation and shift
  const vec3 a{0, 0, 0}, b{3, 0, 3}, c{0.5, 2, 1};
  const double tpu = 2.5;
  for (const double angle : {0.0, 0.7, 2.0, -2.9}) {
    const std::array<double, 4> R = {std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)};
    REQUIRE(tessera::triangle_stretch(a, b, c, mapped(a, b, c, tpu, R, {12.5, -40}), tpu) == Approx(1).epsilon(1e-5));
    // stretched by 10 % along x: 1.1; compressed to 90 % along y: 1 / 0.9; both: the larger
    const std::array<double, 4> S = {1.1 * R[0], 1.1 * R[1], R[2], R[3]};
    REQUIRE(tessera::triangle_stretch(a, b, c, mapped(a, b, c, tpu, S, {}), tpu) == Approx(1.1).epsilon(1e-5));
    const std::array<double, 4> C = {R[0], R[1], 0.9 * R[2], 0.9 * R[3]};
    REQUIRE(tessera::triangle_stretch(a, b, c, mapped(a, b, c, tpu, C, {}), tpu) == Approx(1 / 0.9).epsilon(1e-5));
  }
  // a uniform scaling is not congruent (the anisotropy s1 / s2 would call it 1)
  REQUIRE(tessera::triangle_stretch(a, b, c, mapped(a, b, c, tpu, {1.2, 0, 0, 1.2}, {}), tpu) ==
          Approx(1.2).epsilon(1e-5));
  REQUIRE(tessera::triangle_stretch(a, b, c, mapped(a, b, c, tpu, {0.8, 0, 0, 0.8}, {}), tpu) ==
          Approx(1.25).epsilon(1e-5));
  // the projection of the 45-degree face onto the ground plane (what a planar mapping gives): sqrt 2
  std::array<float, 6> ground{};
  const vec3 p[3] = {a, b, c};
  for (std::size_t k = 0; k < 3; ++k) {
    ground[2 * k] = static_cast<float>(p[k].x * tpu);
    ground[2 * k + 1] = static_cast<float>(p[k].y * tpu);
  }
  REQUIRE(tessera::triangle_stretch(a, b, c, ground, tpu) > 1.2);
  // mirrored, degenerate texture, degenerate face, bad density: infinite
  constexpr double inf = std::numeric_limits<double>::infinity();
  REQUIRE(tessera::triangle_stretch(a, b, c, mapped(a, b, c, tpu, {1, 0, 0, -1}, {}), tpu) == inf);
  REQUIRE(tessera::triangle_stretch(a, b, c, {1, 1, 2, 2, 3, 3}, tpu) == inf);
  REQUIRE(tessera::triangle_stretch(a, a, c, mapped(a, b, c, tpu, {1, 0, 0, 1}, {}), tpu) == inf);
  REQUIRE(tessera::triangle_stretch(a, b, c, mapped(a, b, c, tpu, {1, 0, 0, 1}, {}), 0) == inf);
}

TEST_CASE("summarize_stretch: quantiles, maximum, share above 1 %", "[terrain][stretch]") {
  std::vector<double> s;
  for (int i = 0; i < 100; ++i) s.push_back(1 + 0.001 * i);  // 1.000 .. 1.099
  const auto q = tessera::summarize_stretch(s);
  REQUIRE(q.faces == 100);
  REQUIRE(q.median == Approx(1.05).margin(0.0011));
  REQUIRE(q.p95 == Approx(1.094).margin(0.0011));
  REQUIRE(q.max == Approx(1.099));
  REQUIRE(q.over_1_percent == Approx(0.89).margin(0.011));
  std::vector<double> none;
  REQUIRE(tessera::summarize_stretch(none).faces == 0);
  REQUIRE(tessera::summarize_stretch(none).max == 1);
}
