// tessera/core/vec.hpp: small value types for positions and texture coordinates (double precision),
// with the handful of operations mesh code needs. Heavy linear algebra uses Eigen; these keep the
// core free of it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "config.hpp"

TESSERA_NAMESPACE_BEGIN

/// A 2D point or vector (texture coordinates, XY positions): plain doubles, constexpr arithmetic.
struct vec2 {
  /// The coordinates.
  double x = 0, y = 0;
  /// Coordinate i: 0 is x, 1 is y.
  constexpr double& operator[](int i) noexcept { return i == 0 ? x : y; }
  constexpr double operator[](int i) const noexcept { return i == 0 ? x : y; }
  /// Component-wise sum.
  friend constexpr vec2 operator+(vec2 a, vec2 b) noexcept { return {a.x + b.x, a.y + b.y}; }
  /// Component-wise difference.
  friend constexpr vec2 operator-(vec2 a, vec2 b) noexcept { return {a.x - b.x, a.y - b.y}; }
  /// Negation.
  friend constexpr vec2 operator-(vec2 a) noexcept { return {-a.x, -a.y}; }
  /// Scaling.
  friend constexpr vec2 operator*(vec2 a, double s) noexcept { return {a.x * s, a.y * s}; }
  /// Scaling.
  friend constexpr vec2 operator*(double s, vec2 a) noexcept { return {a.x * s, a.y * s}; }
  /// Division by a scalar.
  friend constexpr vec2 operator/(vec2 a, double s) noexcept { return {a.x / s, a.y / s}; }
  constexpr vec2& operator+=(vec2 b) noexcept {
    x += b.x;
    y += b.y;
    return *this;
  }
  constexpr vec2& operator-=(vec2 b) noexcept {
    x -= b.x;
    y -= b.y;
    return *this;
  }
  constexpr vec2& operator*=(double s) noexcept {
    x *= s;
    y *= s;
    return *this;
  }
  friend constexpr bool operator==(vec2, vec2) = default;
};

/// A 3D point or vector (positions, normals): plain doubles, constexpr arithmetic.
struct vec3 {
  /// The coordinates.
  double x = 0, y = 0, z = 0;
  /// Coordinate i: 0 is x, 1 is y, 2 is z.
  constexpr double& operator[](int i) noexcept { return i == 0 ? x : i == 1 ? y : z; }
  constexpr double operator[](int i) const noexcept { return i == 0 ? x : i == 1 ? y : z; }
  /// Component-wise sum.
  friend constexpr vec3 operator+(vec3 a, vec3 b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  /// Component-wise difference.
  friend constexpr vec3 operator-(vec3 a, vec3 b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  /// Negation.
  friend constexpr vec3 operator-(vec3 a) noexcept { return {-a.x, -a.y, -a.z}; }
  /// Scaling.
  friend constexpr vec3 operator*(vec3 a, double s) noexcept { return {a.x * s, a.y * s, a.z * s}; }
  /// Scaling.
  friend constexpr vec3 operator*(double s, vec3 a) noexcept { return {a.x * s, a.y * s, a.z * s}; }
  /// Division by a scalar.
  friend constexpr vec3 operator/(vec3 a, double s) noexcept { return {a.x / s, a.y / s, a.z / s}; }
  constexpr vec3& operator+=(vec3 b) noexcept {
    x += b.x;
    y += b.y;
    z += b.z;
    return *this;
  }
  constexpr vec3& operator-=(vec3 b) noexcept {
    x -= b.x;
    y -= b.y;
    z -= b.z;
    return *this;
  }
  constexpr vec3& operator*=(double s) noexcept {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  friend constexpr bool operator==(vec3, vec3) = default;
};

/// Dot product.
constexpr double dot(vec2 a, vec2 b) noexcept { return a.x * b.x + a.y * b.y; }
constexpr double dot(vec3 a, vec3 b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// z of the 3D cross product: twice the signed area of the triangle (0, a, b).
constexpr double cross(vec2 a, vec2 b) noexcept { return a.x * b.y - a.y * b.x; }
/// Cross product a x b.
constexpr vec3 cross(vec3 a, vec3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Euclidean length, squared length and distance.
inline double norm(vec2 a) noexcept { return std::sqrt(dot(a, a)); }
/// Euclidean length.
inline double norm(vec3 a) noexcept { return std::sqrt(dot(a, a)); }
constexpr double squared_norm(vec2 a) noexcept { return dot(a, a); }
constexpr double squared_norm(vec3 a) noexcept { return dot(a, a); }
/// Euclidean distance.
inline double distance(vec2 a, vec2 b) noexcept { return norm(a - b); }
/// Euclidean distance.
inline double distance(vec3 a, vec3 b) noexcept { return norm(a - b); }
/// a / |a|, or the zero vector when |a| is 0 (or not finite).
inline vec2 normalized(vec2 a) noexcept {
  const double n = norm(a);
  return n > 0 && std::isfinite(n) ? a / n : vec2{};
}
/// a / |a|, or zero when the length is 0 or not finite.
inline vec3 normalized(vec3 a) noexcept {
  const double n = norm(a);
  return n > 0 && std::isfinite(n) ? a / n : vec3{};
}
/// True when no coordinate is NaN or infinite.
inline bool is_finite(vec3 a) noexcept { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
/// True when both coordinates are finite.
inline bool is_finite(vec2 a) noexcept { return std::isfinite(a.x) && std::isfinite(a.y); }
/// Component-wise minimum and maximum.
constexpr vec3 min(vec3 a, vec3 b) noexcept { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
constexpr vec3 max(vec3 a, vec3 b) noexcept { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }

/// Axis-aligned bounding box. Default-constructed it is empty (min > max), and extending it by a
/// point makes it that point. Extending by a point with NaN coordinates leaves those axes unchanged.
struct aabb {
  /// Smallest corner; +infinity when empty.
  vec3 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  /// Largest corner; -infinity when empty.
  vec3 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};

  /// True when nothing was added.
  [[nodiscard]] constexpr bool empty() const noexcept { return min.x > max.x || min.y > max.y || min.z > max.z; }
  constexpr void extend(vec3 p) noexcept {
    min = tessera::min(min, p);
    max = tessera::max(max, p);
  }
  constexpr void extend(const aabb& b) noexcept {
    min = tessera::min(min, b.min);
    max = tessera::max(max, b.max);
  }
  /// max - min, or zero when empty.
  [[nodiscard]] constexpr vec3 extent() const noexcept { return empty() ? vec3{} : max - min; }
  /// Centre of the box; the origin for an empty box.
  [[nodiscard]] constexpr vec3 center() const noexcept { return empty() ? vec3{} : (min + max) * 0.5; }
  /// True when p is inside or on the box.
  [[nodiscard]] constexpr bool contains(vec3 p) const noexcept {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
  }
};

TESSERA_NAMESPACE_END
