// tessera/terrain/terrain_camera.hpp: the camera of terrain synthesis (§2.1 of paper 003: "set the
// view point, view direction and projection plane, which fixes the projection matrix"): GLM view
// and projection matrices plus a viewport in pixels. make_camera() builds one from a look-at
// description and rejects degenerate cameras; make_camera_preset() gives the views the docs, tests
// and benchmarks use, including the paper's low grazing view over a wide plane.
#pragma once

#include <algorithm>
#include <cmath>
#include <string_view>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "../render/triangle_rasterizer.hpp"

TESSERA_NAMESPACE_BEGIN

/// The clip-space depth convention GLM's projection functions produce in the translation unit that
/// reads it (GLM_FORCE_DEPTH_ZERO_TO_ONE or not): set `terrain_camera::depth = glm_clip_depth` in
/// code built with that macro. Deliberately not `inline`: it has internal linkage, one value per
/// translation unit, and tessera's own definitions never use it, so translation units built with
/// and without the macro do not see two different definitions of one entity (an ODR violation).
#ifdef GLM_FORCE_DEPTH_ZERO_TO_ONE
constexpr clip_depth glm_clip_depth = clip_depth::zero_to_one;
#else
constexpr clip_depth glm_clip_depth = clip_depth::negative_one_to_one;
#endif

/// Largest viewport side accepted by the terrain pipeline.
inline constexpr index_t max_viewport_side = 16384;

namespace detail {
/// validate_camera: a view or projection matrix whose |determinant| is at or below this is singular.
inline constexpr double camera_singular_determinant = 1e-300;
/// validate_camera: bottom-row entries of the view matrix within this fraction of its largest entry
/// count as 0 (the matrix is affine).
inline constexpr double camera_affine_tolerance = 1e-9;
/// make_camera: positive floor of the eye / target magnitude the coincidence test is relative to.
inline constexpr double camera_position_scale_floor = 1e-300;
/// make_camera: an eye closer to its target than this fraction of their magnitudes equals it.
inline constexpr double camera_coincident_fraction = 1e-12;
/// make_camera: |view direction x up| (both unit) at or below this means up is parallel to the view.
inline constexpr double camera_parallel_up_sine = 1e-9;
/// camera_preset_look_at: positive floor of the scene's size, diagonal and near distance, so flat or
/// point-like bounds still give a valid camera.
inline constexpr double camera_preset_min_extent = 1e-9;
}  // namespace detail

/// A camera: world -> view -> clip matrices (GLM, column-major, right-handed as glm::lookAt and
/// glm::perspective build them) and a viewport of width x height pixels (row 0 at the top).
struct terrain_camera {
  /// World -> view (eye) space, as glm::lookAt builds it; must be affine and invertible.
  glm::dmat4 view{1.0};
  /// View -> clip space, as glm::perspective builds it; must be invertible.
  glm::dmat4 projection{1.0};
  /// Viewport width in pixels, 1 to max_viewport_side.
  index_t width = 0;
  /// Viewport height in pixels (row 0 at the top), 1 to max_viewport_side.
  index_t height = 0;
  /// How `projection` maps depth: GLM's default, [-1, 1]; set glm_clip_depth (or
  /// clip_depth::zero_to_one) when GLM_FORCE_DEPTH_ZERO_TO_ONE is defined.
  clip_depth depth = clip_depth::negative_one_to_one;
};

/// Checks a camera: viewport 1 to 16384 pixels per side, finite matrices, invertible view and
/// projection, and an affine view (bottom row 0, 0, 0, w with w > 0), so the eye is a finite point:
/// a projective view would put the eye at infinity (w = 0) or mirror it, and every view distance
/// of §2.2 would be undefined. Errors name the field and the value.
inline status validate_camera(const terrain_camera& c) {
  if (auto s = validate_enum(c.depth, {"negative_one_to_one", "zero_to_one"}, "camera depth"); !s) return s;
  if (c.width < 1 || c.height < 1 || c.width > max_viewport_side || c.height > max_viewport_side)
    return status::invalid_argument(detail::cat("camera viewport must be 1 to ", max_viewport_side,
                                                " pixels per side, got ", c.width, " x ", c.height));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (!std::isfinite(c.view[i][j]) || !std::isfinite(c.projection[i][j]))
        return status::invalid_argument(detail::cat("camera matrices must be finite (column ", i, ", row ", j, ")"));
  const double dv = glm::determinant(c.view), dp = glm::determinant(c.projection);
  if (!(std::abs(dv) > detail::camera_singular_determinant))
    return status::invalid_argument(detail::cat("camera view matrix is singular (determinant ", dv, ")"));
  if (!(std::abs(dp) > detail::camera_singular_determinant))
    return status::invalid_argument(detail::cat("camera projection matrix is singular (determinant ", dp, ")"));
  // GLM is column-major: view[col][3] is the bottom row
  double largest = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) largest = std::max(largest, std::abs(c.view[i][j]));
  const double tol = detail::camera_affine_tolerance * std::max(largest, std::abs(c.view[3][3]));
  if (std::abs(c.view[0][3]) > tol || std::abs(c.view[1][3]) > tol || std::abs(c.view[2][3]) > tol ||
      !(c.view[3][3] > tol))
    return status::invalid_argument(
        detail::cat("camera view matrix must be affine (bottom row 0, 0, 0, w with w > 0), got ", c.view[0][3], ", ",
                    c.view[1][3], ", ", c.view[2][3], ", ", c.view[3][3]));
  const glm::dvec4 eye = glm::inverse(c.view) * glm::dvec4(0, 0, 0, 1);
  if (!(eye.w > 0) || !std::isfinite(eye.x / eye.w) || !std::isfinite(eye.y / eye.w) || !std::isfinite(eye.z / eye.w))
    return status::invalid_argument(detail::cat("camera view matrix puts the eye at (", eye.x, ", ", eye.y, ", ", eye.z,
                                                ", w = ", eye.w, "): not a finite point"));
  return {};
}

/// The eye of a camera that passed validate_camera: the world point the view maps to the origin.
inline vec3 camera_eye(const terrain_camera& c) {
  const glm::dvec4 e = glm::inverse(c.view) * glm::dvec4(0, 0, 0, 1);
  return {e.x / e.w, e.y / e.w, e.z / e.w};
}

/// A perspective camera described by where it is and where it looks (z is up in tessera's terrain
/// scenes, but any up vector not parallel to the view direction works).
struct look_at_camera {
  /// Where the camera is, in world coordinates.
  vec3 eye{0, 0, 1};
  /// The world point it looks at; must differ from `eye`.
  vec3 target{0, 1, 0};
  /// The world direction that is up on the screen; must not be parallel to target - eye.
  vec3 up{0, 0, 1};
  double fov_y_degrees = 60;  ///< vertical field of view, in (0, 180)
  double near = 0.01;         ///< distance to the near plane, > 0
  double far = 1000;          ///< distance to the far plane, > near
};

/// Builds a terrain_camera with glm::lookAt and glm::perspective (aspect = width / height).
/// Errors (invalid_argument, naming the value): non-finite vectors, eye equal to target, up
/// parallel to the view direction, fov_y_degrees outside (0, 180), near <= 0, far <= near, viewport
/// outside 1..16384 pixels. O(1); thread-safe.
inline result<terrain_camera> make_camera(const look_at_camera& c, index_t width, index_t height) {
  if (!is_finite(c.eye) || !is_finite(c.target) || !is_finite(c.up))
    return status::invalid_argument("camera eye, target and up must be finite");
  const vec3 dir = c.target - c.eye;
  const double scale = std::max({norm(c.eye), norm(c.target), detail::camera_position_scale_floor});
  if (norm(dir) <= detail::camera_coincident_fraction * scale)
    return status::invalid_argument(detail::cat("camera eye (", c.eye.x, ", ", c.eye.y, ", ", c.eye.z,
                                                ") equals its target: the view direction is undefined"));
  if (norm(cross(normalized(dir), normalized(c.up))) <= detail::camera_parallel_up_sine)
    return status::invalid_argument(
        detail::cat("camera up (", c.up.x, ", ", c.up.y, ", ", c.up.z, ") is zero or parallel to the view direction"));
  if (!(c.fov_y_degrees > 0 && c.fov_y_degrees < 180))
    return status::invalid_argument(detail::cat("camera fov_y_degrees must be in (0, 180), got ", c.fov_y_degrees));
  if (!(c.near > 0) || !std::isfinite(c.near))
    return status::invalid_argument(detail::cat("camera near must be positive and finite, got ", c.near));
  if (!(c.far > c.near) || !std::isfinite(c.far))
    return status::invalid_argument(
        detail::cat("camera far must be finite and greater than near = ", c.near, ", got ", c.far));
  terrain_camera cam;
  cam.width = width;
  cam.height = height;
  if (auto s = validate_camera(cam); !s) return s;
  cam.view = glm::lookAt(glm::dvec3(c.eye.x, c.eye.y, c.eye.z), glm::dvec3(c.target.x, c.target.y, c.target.z),
                         glm::dvec3(c.up.x, c.up.y, c.up.z));
  cam.projection = glm::perspective(glm::radians(c.fov_y_degrees),
                                    static_cast<double>(width) / static_cast<double>(height), c.near, c.far);
  if (auto s = validate_camera(cam); !s) return s;
  return cam;
}

/// Views of a z-up scene used by docs, tests and benchmarks.
enum class camera_preset {
  grazing,   ///< low over the ground near one edge, looking across to the far edge (the paper's figures)
  oblique,   ///< from above a corner at about 35 degrees, the whole scene in view
  overview,  ///< from high above, slightly tilted, every triangle of a heightfield in view
};

/// Parses "grazing", "oblique" or "overview".
inline result<camera_preset> parse_camera_preset(std::string_view s) {
  if (s == "grazing") return camera_preset::grazing;
  if (s == "oblique") return camera_preset::oblique;
  if (s == "overview") return camera_preset::overview;
  return status::invalid_argument(
      detail::cat("unknown camera preset '", s, "' (expected grazing, oblique or overview)"));
}

/// The look-at description of a preset for a scene with these bounds (near and far planes fitted
/// to the scene). Errors: empty or non-finite bounds.
inline result<look_at_camera> camera_preset_look_at(camera_preset p, const aabb& bounds) {
  if (auto s = validate_enum(p, {"grazing", "oblique", "overview"}, "camera preset"); !s) return s;
  if (bounds.empty() || !is_finite(bounds.min) || !is_finite(bounds.max))
    return status::invalid_argument("camera preset: the scene bounds are empty or not finite");
  const vec3 c = bounds.center(), e = bounds.extent();
  const double size = std::max({e.x, e.y, detail::camera_preset_min_extent});
  const double diag = std::max(norm(e), detail::camera_preset_min_extent);
  look_at_camera l;
  switch (p) {
    case camera_preset::grazing:
      l.eye = {c.x, bounds.min.y + 0.04 * e.y, bounds.max.z + 0.025 * size};
      l.target = {c.x, bounds.max.y, c.z};
      l.fov_y_degrees = 55;
      break;
    case camera_preset::oblique:
      l.eye = {bounds.min.x - 0.35 * e.x, bounds.min.y - 0.35 * e.y, bounds.max.z + 0.75 * size};
      l.target = {c.x, c.y, c.z};
      l.fov_y_degrees = 50;
      break;
    case camera_preset::overview: {
      l.fov_y_degrees = 45;
      const double r = 0.5 * diag;
      const double d = 1.05 * r / std::sin(0.5 * l.fov_y_degrees * 3.14159265358979323846 / 180.0);
      l.eye = {c.x, c.y - 0.45 * d, c.z + 0.9 * d};
      l.target = c;
      break;
    }
  }
  const double reach = norm(l.eye - c) + diag;
  l.near = std::max(1e-4 * diag, detail::camera_preset_min_extent);
  l.far = 2 * reach;
  return l;
}

/// A preset camera for a scene with these bounds and a width x height viewport. Errors: as
/// camera_preset_look_at and make_camera.
inline result<terrain_camera> make_camera_preset(camera_preset p, const aabb& bounds, index_t width, index_t height) {
  auto l = camera_preset_look_at(p, bounds);
  if (!l) return l.error();
  return make_camera(*l, width, height);
}

TESSERA_NAMESPACE_END
