// tessera/terrain/detail/visibility.hpp: the first pass of the terrain frame renderers: the
// visible faces rasterized (render/triangle_rasterizer.hpp, clip-space input so faces crossing the
// near plane are clipped) into a per-pixel face id, depth-tested on view depth, optionally with the
// interpolated world position.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../render/triangle_rasterizer.hpp"
#include "../prepare_terrain_mesh.hpp"
#include "../project_mesh.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {

struct visibility_buffer {
  index_t width = 0, height = 0;
  std::vector<std::int32_t> face;           ///< -1 where no face covers the pixel
  std::vector<float> depth;                 ///< view depth (clip w) of the visible fragment
  std::vector<std::array<float, 3>> world;  ///< world position (only when requested)
};

/// Checks, before a frame is drawn, that `proj` belongs to `mesh` (check_projection) and that every
/// visible entry names a visible face whose corners are vertices of the mesh. O(visible faces), in
/// parallel chunks; the first failure in visible order is reported.
template <class E>
status check_visible_entries(const terrain_mesh& mesh, const screen_projection& proj, const char* stage, E& exec);
template <class E>
status check_visible_geometry(const terrain_mesh& mesh, const screen_projection& proj, const char* stage, E& exec) {
  if (auto s = check_projection(mesh, proj, stage); !s) return s;
  return check_visible_entries(mesh, proj, stage, exec);
}
/// The per-entry part of check_visible_geometry (for a projection without clip coordinates: a
/// terrain_session's).
template <class E>
status check_visible_entries(const terrain_mesh& mesh, const screen_projection& proj, const char* stage, E& exec) {
  if (proj.visible.size() > proj.state.size())
    return status::invalid_argument(detail::cat(stage, ": the projection lists more visible faces than it has"));
  const index_t nvis = proj.num_visible(), nv = mesh.num_vertices();
  constexpr index_t block = 16384;
  const index_t chunks = (nvis + block - 1) / block;
  std::vector<index_t> bad(to_size(chunks), -1);
  exec.parallel_for(0, chunks, [&](index_t c) {
    for (index_t i = c * block; i < std::min(nvis, (c + 1) * block); ++i) {
      const std::int32_t f = proj.visible[to_size(i)];
      bool ok = is_visible_face(proj, f);
      if (ok)
        for (const std::int32_t v : mesh.faces[to_size(f)]) ok = ok && v >= 0 && v < nv;
      if (!ok) {
        bad[to_size(c)] = i;
        return;
      }
    }
  });
  for (const index_t i : bad) {
    if (i < 0) continue;
    const std::int32_t f = proj.visible[to_size(i)];
    if (!is_visible_face(proj, f)) return bad_visible_entry(stage, i, f);
    return status::out_of_range(
        detail::cat(stage, ": face ", f, " names a vertex outside the mesh's ", nv, " vertices"));
  }
  return {};
}

template <class E>
status render_visibility(const terrain_mesh& mesh, const screen_projection& proj, visibility_buffer& vb,
                         bool want_world, index_t tile_size, E& exec) {
  vb.width = proj.width;
  vb.height = proj.height;
  const auto n = to_size(proj.width * proj.height);
  vb.face.assign(n, -1);
  vb.depth.assign(n, std::numeric_limits<float>::infinity());
  if (want_world) vb.world.assign(n, {0, 0, 0});
  const raster_viewport vp{0, 0, static_cast<double>(proj.width), static_cast<double>(proj.height), proj.depth};
  return rasterize_clip_triangles(
      proj.num_visible(), vp, pixel_rect{0, 0, proj.width, proj.height},
      [&](index_t i, clip_triangle& t) {
        t = proj.clip_face(mesh, proj.visible[to_size(i)]);
        return true;
      },
      [&](index_t i, const fragment& f) {
        const auto p = to_size(f.y * vb.width + f.x);
        const auto w = static_cast<float>(f.w);
        if (!(w < vb.depth[p])) return;
        vb.depth[p] = w;
        const std::int32_t face = proj.visible[to_size(i)];
        vb.face[p] = face;
        if (want_world) {
          const auto& fv = mesh.faces[to_size(face)];
          const vec3 q =
              mesh.position(fv[0]) * f.bary[0] + mesh.position(fv[1]) * f.bary[1] + mesh.position(fv[2]) * f.bary[2];
          vb.world[p] = {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)};
        }
      },
      rasterize_options{.tile_size = tile_size}, exec);
}

/// Per-face light factor ambient + (1 - ambient) max(0, n . sun) for flat Lambert shading, n the
/// face normal turned towards the eye (so either winding works); empty when `sun` is zero.
template <class E>
std::vector<float> face_light(const terrain_mesh& mesh, const screen_projection& proj, const std::array<double, 3>& sun,
                              double ambient, E& exec) {
  std::vector<float> light;
  const vec3 l = normalized(vec3{sun[0], sun[1], sun[2]});
  if (norm(l) == 0) return light;
  light.assign(to_size(mesh.num_faces()), 1.0f);
  exec.parallel_for(0, proj.num_visible(), [&](index_t i) {
    const std::int32_t f = proj.visible[to_size(i)];
    const auto& fv = mesh.faces[to_size(f)];
    const vec3 a = mesh.position(fv[0]);
    vec3 n = normalized(cross(mesh.position(fv[1]) - a, mesh.position(fv[2]) - a));
    if (dot(n, proj.eye - a) < 0) n = -n;
    light[to_size(f)] = static_cast<float>(ambient + (1 - ambient) * std::max(0.0, dot(n, l)));
  });
  return light;
}

/// Scales the colour channels (not alpha) of a unit pixel by a light factor.
template <std::size_t C>
void apply_light(std::array<float, C>& c, float light) noexcept {
  constexpr std::size_t colour = C == 2 ? 1 : C == 4 ? 3 : C;
  for (std::size_t k = 0; k < colour; ++k) c[k] *= light;
}

}  // namespace detail

TESSERA_NAMESPACE_END
