// tessera/terrain/export_session_uvs.hpp: what an engine needs from a ground-anchored frame of a
// terrain_session (terrain_session.hpp), in the terrain_uv_buffer of export_corner_uvs.hpp (and so
// in the TSUV file, version 3, mapping 1): per face the corner coordinates in texels of its level
// image from that image's centre (interpolate them PERSPECTIVE-correctly), the level and scale,
// the visibility state; the offset is NaN (there is no screen-space offset form in this mode).
#pragma once

#include <limits>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "export_corner_uvs.hpp"
#include "terrain_session.hpp"

TESSERA_NAMESPACE_BEGIN

/// The current frame of `session` as a terrain_uv_buffer (mapping 1; culled faces: NaN coordinates,
/// level -1, scale 0, state 0). Faces visible in two consecutive frames at the same level have
/// bit-identical records. Errors: a session that has no frame yet (invalid_argument). O(F).
inline result<terrain_uv_buffer> export_session_uvs(const terrain_session& session) {
  if (session.frame() < 0)
    return status::invalid_argument("export_session_uvs: the session has no frame yet (call update first)");
  const screen_projection& proj = session.projection();
  const auto nf = session.level().size();
  if (proj.state.size() != nf)
    return status::invalid_argument("export_session_uvs: the session's last update failed (no projection)");
  terrain_uv_buffer b;
  b.viewport_width = proj.width;
  b.viewport_height = proj.height;
  b.exemplar_width = session.exemplar_width();
  b.exemplar_height = session.exemplar_height();
  b.levels = session.levels();
  b.min_scale = session.options().min_scale;
  b.mapping = 1;
  b.reset_faces(nf);
  for (const std::int32_t f : proj.visible) {
    const auto fi = detail::to_size(f);
    b.corner_uv[fi] = session.corner_uv()[fi];
    b.level[fi] = session.level()[fi];
    b.scale[fi] = static_cast<float>(session.level_scale(b.level[fi]));
    b.state[fi] = proj.state[fi];
  }
  return b;
}

TESSERA_NAMESPACE_END
