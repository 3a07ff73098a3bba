// tessera/terrain/detail/session_projection.hpp: the lean per-frame projection of a
// terrain_session. A session needs per frame only which faces are visible (and whether they cross
// the near plane) and the clip-space corners the renderer rasterizes; it validated its mesh once,
// and ground-anchored coordinates need no screen bounds. So, unlike project_mesh, this computes
// one outcode byte per vertex and culls faces from three byte loads; `screen` and `bounds` are
// sized but not filled. Visibility is project_mesh's rule (all corners beyond one frustum plane:
// culled; back faces when asked), except that a face crossing the near plane whose clipped
// polygon misses the viewport stays visible (it draws nothing).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "../../core/config.hpp"
#include "../../core/executor.hpp"
#include "../../core/status.hpp"
#include "../../core/vec.hpp"
#include "../prepare_terrain_mesh.hpp"
#include "../project_mesh.hpp"
#include "../terrain_camera.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Projects a mesh that passed validate_terrain_mesh for a camera that passed validate_camera into
/// `out` (see the file comment); `codes` is per-vertex scratch. Vertex indices are checked again
/// (a mesh changed in place since): out_of_range naming the face. O(V + F), parallel through `exec`.
template <class E>
status project_for_session(const terrain_mesh& mesh, const terrain_camera& camera, const project_options& opts,
                           screen_projection& out, std::vector<std::uint8_t>& codes, E& exec) {
  const index_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  const bool zo = camera.depth == clip_depth::zero_to_one;
  const glm::dmat4 m = camera.projection * camera.view;
  out.width = camera.width;
  out.height = camera.height;
  out.depth = camera.depth;
  out.eye = camera_eye(camera);
  out.clip.resize(to_size(nv));
  out.screen.resize(to_size(nv));
  out.state.resize(to_size(nf));
  out.bounds.resize(to_size(nf));
  codes.resize(to_size(nv));
  constexpr index_t block = 16384;
  exec.parallel_for(0, (nv + block - 1) / block, [&](index_t b) {
    for (index_t v = b * block; v < std::min(nv, (b + 1) * block); ++v) {
      const vec3& p = mesh.positions[to_size(v)];
      const glm::dvec4 c = m * glm::dvec4(p.x, p.y, p.z, 1.0);
      out.clip[to_size(v)] = {c.x, c.y, c.z, c.w};
      codes[to_size(v)] = clip_outcode(out.clip[to_size(v)], zo);
    }
  });
  const index_t chunks = (nf + block - 1) / block;
  std::vector<index_t> count(to_size(chunks + 1), 0), bad(to_size(chunks), -1);
  exec.parallel_for(0, chunks, [&](index_t b) {
    index_t n = 0;
    for (index_t f = b * block; f < std::min(nf, (b + 1) * block); ++f) {
      const auto& face = mesh.faces[to_size(f)];
      if (static_cast<std::uint32_t>(face[0]) >= static_cast<std::uint64_t>(nv) ||
          static_cast<std::uint32_t>(face[1]) >= static_cast<std::uint64_t>(nv) ||
          static_cast<std::uint32_t>(face[2]) >= static_cast<std::uint64_t>(nv)) {
        if (bad[to_size(b)] < 0) bad[to_size(b)] = f;
        out.state[to_size(f)] = 0;
        continue;
      }
      const std::uint8_t c0 = codes[to_size(face[0])], c1 = codes[to_size(face[1])], c2 = codes[to_size(face[2])];
      std::uint8_t st = 0;
      if ((c0 & c1 & c2) == 0) {
        st = static_cast<std::uint8_t>(((c0 | c1 | c2) & 16) ? face_visibility::near_clipped : face_visibility::inside);
        if (opts.cull_back_faces) {
          const vec3 a = mesh.position(face[0]), n3 = cross(mesh.position(face[1]) - a, mesh.position(face[2]) - a);
          if (dot(n3, a - out.eye) >= 0) st = 0;
        }
      }
      out.state[to_size(f)] = st;
      n += st != 0 ? 1 : 0;
    }
    count[to_size(b + 1)] = n;
  });
  for (const index_t f : bad)
    if (f >= 0) {
      out.visible.clear();
      return status::out_of_range(detail::cat("terrain_mesh face ", f, " names a vertex outside the mesh's ", nv,
                                              " vertices (the mesh changed since the session was made)"));
    }
  gather_visible_faces(out, count, block, exec);
  return {};
}

}  // namespace detail
TESSERA_NAMESPACE_END
