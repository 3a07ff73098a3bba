// tessera/terrain/project_mesh.hpp: screen projection of a prepared terrain mesh (§2.1 of paper
// 003): every vertex through projection * view to clip space and through the viewport to pixels;
// triangles entirely outside the view frustum (all three corners beyond one frustum plane, behind
// the near plane or past the far plane) are culled, the paper's "triangles outside the screen are
// removed".
//
// Partially visible triangles are KEPT WHOLE, not clipped: their corners keep their true screen
// positions (which may lie outside the viewport), so texture coordinates stay continuous across
// the viewport border. Only their screen bounds are clipped to the viewport (that is what the
// synthesis must fit into an exemplar). A triangle crossing the near plane has no screen position
// for its corners behind the eye: it is marked `near_clipped`, its bounds come from the triangle
// clipped against the near plane, and those corners' screen positions are NaN.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "../render/triangle_rasterizer.hpp"
#include "prepare_terrain_mesh.hpp"
#include "terrain_camera.hpp"

TESSERA_NAMESPACE_BEGIN

/// What projection decided for a face.
enum class face_visibility : std::uint8_t {
  culled = 0,        ///< entirely outside the view frustum (or back-facing when asked)
  inside = 1,        ///< visible or partly visible, all corners in front of the near plane
  near_clipped = 2,  ///< partly visible, some corner behind the near plane
};

/// The mesh as the camera sees it. Per-vertex and per-face arrays are indexed like the mesh.
struct screen_projection {
  index_t width = 0, height = 0;                       ///< viewport in pixels
  clip_depth depth = clip_depth::negative_one_to_one;  ///< the camera's
  vec3 eye;                                            ///< eye position in world space
  std::vector<std::array<double, 4>> clip;             ///< per vertex: projection * view * position
  std::vector<vec2> screen;                  ///< per vertex: pixel position (y down); NaN behind the near plane
  std::vector<std::uint8_t> state;           ///< per face: a face_visibility
  std::vector<std::array<float, 4>> bounds;  ///< per face: visible screen box x0, y0, x1, y1 (clipped to the viewport)
  std::vector<std::int32_t> visible;         ///< faces not culled, ascending
  index_t near_clipped = 0;                  ///< how many visible faces cross the near plane

  /// True when face f is not culled.
  [[nodiscard]] bool is_visible(index_t f) const noexcept { return state[detail::to_size(f)] != 0; }
  /// Number of faces not culled.
  [[nodiscard]] index_t num_visible() const noexcept { return static_cast<index_t>(visible.size()); }
  /// The clip-space corners of face f of `mesh` (for rasterize_clip_triangles).
  [[nodiscard]] clip_triangle clip_face(const terrain_mesh& mesh, index_t f) const noexcept {
    clip_triangle t;
    for (int k = 0; k < 3; ++k) {
      const auto& c = clip[detail::to_size(mesh.face_vertex(f, k))];
      t[detail::to_size(k)] = {c[0], c[1], c[2], c[3]};
    }
    return t;
  }
};

namespace detail {
/// The last pass of a projection: `out.visible` (ascending) and `out.near_clipped` from `out.state`,
/// given `count[b + 1]`, the number of visible faces in block b of `block` faces (count[0] = 0).
/// Parallel over blocks through `exec`; the result does not depend on the executor.
template <class E>
void gather_visible_faces(screen_projection& out, std::vector<index_t>& count, index_t block, E& exec) {
  const auto nf = static_cast<index_t>(out.state.size());
  const auto chunks = static_cast<index_t>(count.size()) - 1;
  for (index_t b = 0; b < chunks; ++b) count[to_size(b + 1)] += count[to_size(b)];
  out.visible.resize(to_size(count[to_size(chunks)]));
  std::vector<index_t> near_count(to_size(chunks), 0);
  exec.parallel_for(0, chunks, [&](index_t b) {
    index_t at = count[to_size(b)];
    for (index_t f = b * block; f < std::min(nf, (b + 1) * block); ++f) {
      const auto st = out.state[to_size(f)];
      if (st == 0) continue;
      out.visible[to_size(at++)] = static_cast<std::int32_t>(f);
      if (st == static_cast<std::uint8_t>(face_visibility::near_clipped)) ++near_count[to_size(b)];
    }
  });
  out.near_clipped = 0;
  for (const index_t n : near_count) out.near_clipped += n;
}
}  // namespace detail

/// Options of project_mesh.
struct project_options {
  /// Also cull faces whose front side (counter-clockwise corners) faces away from the eye. Off by
  /// default: meshes from elsewhere may be wound either way, and hidden faces are harmless.
  bool cull_back_faces = false;
};

namespace detail {
inline std::uint8_t clip_outcode(const std::array<double, 4>& c, bool zero_to_one) noexcept {
  const double x = c[0], y = c[1], z = c[2], w = c[3];
  return static_cast<std::uint8_t>((x < -w ? 1 : 0) | (x > w ? 2 : 0) | (y < -w ? 4 : 0) | (y > w ? 8 : 0) |
                                   ((zero_to_one ? z < 0 : z < -w) ? 16 : 0) | (z > w ? 32 : 0));
}
}  // namespace detail

namespace detail {
/// O(1) check that `proj` was made from `mesh` (array sizes agree, finite eye); the stages after
/// projection also check each visible face id as they read it.
inline status check_projection(const terrain_mesh& mesh, const screen_projection& proj, const char* stage) {
  if (auto s = check_terrain_mesh_sizes(mesh); !s) return s;
  if (auto s = validate_enum(proj.depth, {"negative_one_to_one", "zero_to_one"}, cat(stage, ": projection depth")); !s)
    return s;
  const auto nf = to_size(mesh.num_faces()), nv = to_size(mesh.num_vertices());
  if (proj.state.size() != nf || proj.bounds.size() != nf || proj.clip.size() != nv || proj.screen.size() != nv ||
      proj.visible.size() > nf)
    return status::invalid_argument(detail::cat(stage, ": the projection (", proj.state.size(), " faces, ",
                                                proj.clip.size(), " vertices) does not belong to the mesh (", nf,
                                                " faces, ", nv, " vertices): project this mesh first"));
  if (!is_finite(proj.eye)) return status::invalid_argument(detail::cat(stage, ": the projection's eye is not finite"));
  return {};
}
/// Whether visible entry f names a face the projection marks visible.
inline bool is_visible_face(const screen_projection& proj, std::int32_t f) noexcept {
  return f >= 0 && to_size(f) < proj.state.size() && proj.state[to_size(f)] != 0;
}
inline status bad_visible_entry(const char* stage, index_t i, std::int32_t f) {
  return status::invalid_argument(
      detail::cat(stage, ": projection.visible[", i, "] = ", f, " is not a visible face of the mesh"));
}
}  // namespace detail

/// Projects `mesh` for `camera` into `out` (its arrays are reused, so a caller that keeps `out`
/// across frames does not reallocate). Errors: an invalid camera (see validate_camera), a mesh
/// failing validate_terrain_mesh (checked in the same passes; `out` is then not usable). An empty
/// or fully culled mesh is not an error: `out.visible` is then empty. O(V + F), parallel over
/// vertices and faces through `exec`; the result does not depend on the executor.
template <Executor E = serial_executor>
status project_mesh(const terrain_mesh& mesh, const terrain_camera& camera, screen_projection& out,
                    const project_options& opts = {}, E&& exec = {}) {
  if (auto s = validate_camera(camera); !s) return s;
  if (auto s = detail::check_terrain_mesh_sizes(mesh); !s) return s;
  const index_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  const bool zo = camera.depth == clip_depth::zero_to_one;
  const glm::dmat4 m = camera.projection * camera.view;
  out.width = camera.width;
  out.height = camera.height;
  out.depth = camera.depth;
  out.eye = camera_eye(camera);
  out.clip.resize(detail::to_size(nv));
  out.screen.resize(detail::to_size(nv));
  out.state.resize(detail::to_size(nf));
  out.bounds.resize(detail::to_size(nf));
  const double W = static_cast<double>(camera.width), H = static_cast<double>(camera.height);
  constexpr index_t block = 16384;
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  // the structure of the mesh is checked in the same passes (validate_terrain_mesh's checks): the
  // smallest bad vertex / face of each block, reported in block order
  const index_t vblocks = (nv + block - 1) / block;
  std::vector<index_t> bad_vertex(detail::to_size(vblocks), -1);
  exec.parallel_for(0, vblocks, [&](index_t b) {
    for (index_t v = b * block; v < std::min(nv, (b + 1) * block); ++v) {
      const vec3& p = mesh.positions[detail::to_size(v)];
      if (!is_finite(p) && bad_vertex[detail::to_size(b)] < 0) bad_vertex[detail::to_size(b)] = v;
      const glm::dvec4 c = m * glm::dvec4(p.x, p.y, p.z, 1.0);
      out.clip[detail::to_size(v)] = {c.x, c.y, c.z, c.w};
      const bool front = (zo ? c.z >= 0 : c.z >= -c.w) && c.w > 0;
      out.screen[detail::to_size(v)] =
          front ? vec2{(c.x / c.w + 1) * 0.5 * W, (1 - c.y / c.w) * 0.5 * H} : vec2{nan, nan};
    }
  });
  const index_t chunks = (nf + block - 1) / block;
  std::vector<index_t> count(detail::to_size(chunks + 1), 0), bad_face(detail::to_size(chunks), -1);
  exec.parallel_for(0, chunks, [&](index_t b) {
    index_t n = 0;
    for (index_t f = b * block; f < std::min(nf, (b + 1) * block); ++f) {
      const auto& face = mesh.faces[detail::to_size(f)];
      auto& st = out.state[detail::to_size(f)];
      st = static_cast<std::uint8_t>(face_visibility::culled);
      const auto& nb = mesh.neighbors[detail::to_size(f)];
      bool ok = is_finite(mesh.centroids[detail::to_size(f)]);
      for (std::size_t k = 0; k < 3; ++k) ok = ok && face[k] >= 0 && face[k] < nv && nb[k] >= -1 && nb[k] < nf;
      if (!ok) {
        if (bad_face[detail::to_size(b)] < 0) bad_face[detail::to_size(b)] = f;
        continue;
      }
      std::uint8_t oc[3];
      for (int k = 0; k < 3; ++k) oc[k] = detail::clip_outcode(out.clip[detail::to_size(face[detail::to_size(k)])], zo);
      if ((oc[0] & oc[1] & oc[2]) != 0) continue;
      if (opts.cull_back_faces) {
        const vec3 a = mesh.position(face[0]), n3 = cross(mesh.position(face[1]) - a, mesh.position(face[2]) - a);
        if (dot(n3, a - out.eye) >= 0) continue;
      }
      double x0, y0, x1, y1;
      const bool near = ((oc[0] | oc[1] | oc[2]) & 16) != 0;
      if (!near) {
        const vec2 s0 = out.screen[detail::to_size(face[0])], s1 = out.screen[detail::to_size(face[1])],
                   s2 = out.screen[detail::to_size(face[2])];
        x0 = std::min({s0.x, s1.x, s2.x});
        x1 = std::max({s0.x, s1.x, s2.x});
        y0 = std::min({s0.y, s1.y, s2.y});
        y1 = std::max({s0.y, s1.y, s2.y});
      } else {
        detail::raster::polygon poly{};  // rare path: zero-filled keeps the compiler sure of initialization
        std::array<std::array<double, 4>, 3> t;
        for (int k = 0; k < 3; ++k) t[detail::to_size(k)] = out.clip[detail::to_size(face[detail::to_size(k)])];
        detail::raster::clip_polygon_to_screen(t, {0, 0, W, H}, zo, poly);
        if (poly.n < 3) continue;
        x0 = x1 = poly.v[0].x;
        y0 = y1 = poly.v[0].y;
        for (int i = 1; i < poly.n; ++i) {
          const auto& q = poly.v[detail::to_size(i)];
          x0 = std::min(x0, q.x);
          x1 = std::max(x1, q.x);
          y0 = std::min(y0, q.y);
          y1 = std::max(y1, q.y);
        }
      }
      x0 = std::max(x0, 0.0);
      y0 = std::max(y0, 0.0);
      x1 = std::min(x1, W);
      y1 = std::min(y1, H);
      if (!(x0 <= x1 && y0 <= y1)) continue;  // also rejects NaN
      out.bounds[detail::to_size(f)] = {static_cast<float>(x0), static_cast<float>(y0), static_cast<float>(x1),
                                        static_cast<float>(y1)};
      st = static_cast<std::uint8_t>(near ? face_visibility::near_clipped : face_visibility::inside);
      ++n;
    }
    count[detail::to_size(b + 1)] = n;
  });
  for (const index_t v : bad_vertex)
    if (v >= 0) {
      out.visible.clear();
      return status::invalid_argument(detail::cat("terrain_mesh vertex ", v, " is not finite"));
    }
  for (const index_t f : bad_face)
    if (f >= 0) {
      out.visible.clear();
      return detail::terrain_face_problem(mesh, f);
    }
  detail::gather_visible_faces(out, count, block, exec);
  return {};
}

/// As above, returning a new screen_projection.
template <Executor E = serial_executor>
result<screen_projection> project_mesh(const terrain_mesh& mesh, const terrain_camera& camera,
                                       const project_options& opts = {}, E&& exec = {}) {
  screen_projection out;
  if (auto s = project_mesh(mesh, camera, out, opts, exec); !s) return s;
  return out;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_project_mesh.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
