// tessera/terrain/export_corner_uvs.hpp: what an engine needs from a synthesized terrain frame
// (paper 003, §2.3): per face the texture offset, corner coordinates, level and scale
// (export_corner_uvs), and the same as a small binary file an engine or a script can read
// (`tessera terrain --uv-out`; write_terrain_uv_file / read_terrain_uv_file). The file's layout,
// all numbers little-endian, no padding:
//
//   offset  size  header
//        0     4  magic "TSUV"
//        4     4  u32 version = 3
//        8     4  u32 F: faces (the mesh's, culled ones included)
//       12     8  u32 viewport width, u32 viewport height (pixels)
//       20     8  u32 exemplar width, u32 exemplar height (level 0 of the pyramid)
//       28     4  u32 levels of the scale field
//       32     4  f32 min_scale of the scale field
//       36     4  u32 mapping: 0 screen (paper 003: interpolate corner uv linearly in screen space,
//                 or use the offset form), 1 ground-anchored (terrain_session: interpolate corner uv
//                 PERSPECTIVE-correctly; offset NaN)
//
//   then F records of 44 bytes, face f at 40 + 44 f:
//        0    24  f32 u0 v0 u1 v1 u2 v2: corner uv (NaN where a corner is behind the eye, or culled)
//       24     8  f32 offset x, y: uv = pixel position (y down, centres at +0.5) + offset
//       32     4  i32 level (-1: culled)
//       36     4  f32 scale (0: culled)
//       40     4  u32 state: 0 culled, 1 visible, 2 visible and crossing the near plane
//
// uv is in pixels of the exemplar shrunk by `scale`, from its centre: sample it at normalized
// coordinates 0.5 + uv / (exemplar width * scale, exemplar height * scale). Version 2 had no
// mapping field (a 36-byte header, always screen mapping; still read). Version 1 had 32-byte
// records without offset and state and a 12-byte header.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "assign_scale_field.hpp"
#include "prepare_terrain_mesh.hpp"
#include "project_mesh.hpp"
#include "synthesize_triangles.hpp"

TESSERA_NAMESPACE_BEGIN

/// What a shader needs to texture every visible face. Per face (indexed like the mesh):
///   - `offset`: uv = pixel position (x right, y DOWN, pixel centres at +0.5) + offset, in pixels of
///     the face's level image measured from that image's centre. This form works for every visible
///     face, including faces crossing the near plane: compute it per fragment from gl_FragCoord
///     (flip y: y_down = height - y_up).
///   - `corner_uv`: the same at the three corners (u0 v0 u1 v1 u2 v2), to interpolate linearly in
///     SCREEN space (GLSL `noperspective`). NaN at corners behind the eye (state near_clipped):
///     such a corner has no screen position; use the offset form for those faces.
///   - `level`, `scale`: the pyramid level and the scale; the exemplar shrunk by `scale` is sampled
///     at normalized coordinates 0.5 + uv / (exemplar_width * scale, exemplar_height * scale).
///   - `state`: a face_visibility (0 culled: level -1, scale 0, NaN coordinates).
struct terrain_uv_buffer {
  /// The viewport size in pixels.
  index_t viewport_width = 0, viewport_height = 0;
  /// The exemplar size in pixels (level 0).
  index_t exemplar_width = 0, exemplar_height = 0;
  index_t levels = 0;                           ///< of the scale field
  double min_scale = 1;                         ///< of the scale field
  std::vector<std::array<float, 6>> corner_uv;  ///< u0 v0 u1 v1 u2 v2
  /// Per face: the offset form (see above).
  std::vector<std::array<float, 2>> offset;
  /// Per face: the pyramid level (-1 when culled).
  std::vector<std::int32_t> level;
  /// Per face: the scale (0 when culled).
  std::vector<float> scale;
  /// Per face: a face_visibility.
  std::vector<std::uint8_t> state;
  std::uint32_t mapping = 0;  ///< 0: screen-space (paper 003), 1: ground-anchored (perspective-correct uv)

  /// Sizes the per-face arrays for `nf` faces, every face culled: NaN coordinates and offset,
  /// level -1, scale 0, state 0.
  void reset_faces(std::size_t nf) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    corner_uv.assign(nf, {nan, nan, nan, nan, nan, nan});
    offset.assign(nf, {nan, nan});
    level.assign(nf, -1);
    scale.assign(nf, 0.0f);
    state.assign(nf, 0);
  }
};

/// Collects the engine-facing outputs of a synthesis (see terrain_uv_buffer). Errors
/// (invalid_argument): a projection, field or synthesis that does not belong to `mesh`, or a
/// visible face the field or the synthesis did not cover (made from another projection). O(F).
inline result<terrain_uv_buffer> export_corner_uvs(const terrain_mesh& mesh, const screen_projection& proj,
                                                   const scale_field& field, const triangle_synthesis& syn) {
  if (auto s = detail::check_projection(mesh, proj, "export_corner_uvs"); !s) return s;
  const auto nf = detail::to_size(mesh.num_faces());
  if (field.level.size() != nf || field.scale.size() != nf || syn.offset.size() != nf || syn.region.size() != nf)
    return status::invalid_argument(detail::cat("export_corner_uvs: the scale field (", field.level.size(),
                                                " faces) and synthesis (", syn.region.size(),
                                                " faces) must belong to the mesh (", nf, " faces)"));
  terrain_uv_buffer b;
  b.viewport_width = proj.width;
  b.viewport_height = proj.height;
  b.exemplar_width = syn.exemplar_width;
  b.exemplar_height = syn.exemplar_height;
  b.levels = field.levels;
  b.min_scale = field.min_scale;
  b.reset_faces(nf);
  for (std::size_t i = 0; i < proj.visible.size(); ++i) {
    const std::int32_t f = proj.visible[i];
    if (!detail::is_visible_face(proj, f))
      return detail::bad_visible_entry("export_corner_uvs", static_cast<index_t>(i), f);
    const auto fi = detail::to_size(f);
    if (field.level[fi] < 0 || syn.region[fi] < 0)
      return status::invalid_argument(detail::cat("export_corner_uvs: visible face ", f, " has level ", field.level[fi],
                                                  " and region ", syn.region[fi],
                                                  ": the field and synthesis must come from this projection"));
    const vec2 o = syn.offset[fi];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t v = mesh.faces[fi][k];
      if (v < 0 || detail::to_size(v) >= proj.screen.size())
        return status::out_of_range(detail::cat("export_corner_uvs: face ", f, " corner ", k, " names vertex ", v));
      const vec2 p = proj.screen[detail::to_size(v)] + o;
      b.corner_uv[fi][2 * k] = static_cast<float>(p.x);
      b.corner_uv[fi][2 * k + 1] = static_cast<float>(p.y);
    }
    b.offset[fi] = {static_cast<float>(o.x), static_cast<float>(o.y)};
    b.level[fi] = field.level[fi];
    b.scale[fi] = field.scale[fi];
    b.state[fi] = proj.state[fi];
  }
  return b;
}

/// Version number written in TSUV files (io/terrain_uv_file.hpp).
inline constexpr std::uint32_t terrain_uv_file_version = 3;
/// Sizes of a TSUV file's header and of one face record, in bytes.
inline constexpr std::size_t terrain_uv_header_bytes = 40, terrain_uv_record_bytes = 44;

namespace detail {
inline void put_u32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}
inline void put_f32(std::vector<unsigned char>& out, float f) {
  std::uint32_t v;
  std::memcpy(&v, &f, 4);
  put_u32(out, v);
}
inline std::uint32_t get_u32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
inline float get_f32(const unsigned char* p) {
  const std::uint32_t v = get_u32(p);
  float f;
  std::memcpy(&f, &v, 4);
  return f;
}
}  // namespace detail

/// Encodes a terrain_uv_buffer in the layout above. Errors (invalid_argument): arrays of different
/// lengths, more than 2^32 - 1 faces or sizes that do not fit a u32. O(F).
inline result<std::vector<unsigned char>> encode_terrain_uvs(const terrain_uv_buffer& uv) {
  const std::size_t n = uv.level.size();
  if (uv.corner_uv.size() != n || uv.offset.size() != n || uv.scale.size() != n || uv.state.size() != n)
    return status::invalid_argument(detail::cat("terrain uv buffer: arrays of different lengths (", uv.corner_uv.size(),
                                                ", ", uv.offset.size(), ", ", n, ", ", uv.scale.size(), ", ",
                                                uv.state.size(), ")"));
  constexpr index_t u32max = 0xffffffff;
  for (const index_t v : {static_cast<index_t>(n), uv.viewport_width, uv.viewport_height, uv.exemplar_width,
                          uv.exemplar_height, uv.levels})
    if (v < 0 || v > u32max)
      return status::invalid_argument(detail::cat("terrain uv buffer: ", v, " does not fit the file's u32 fields"));
  std::vector<unsigned char> out;
  out.reserve(terrain_uv_header_bytes + terrain_uv_record_bytes * n);
  for (const char c : {'T', 'S', 'U', 'V'}) out.push_back(static_cast<unsigned char>(c));
  detail::put_u32(out, terrain_uv_file_version);
  for (const index_t v : {static_cast<index_t>(n), uv.viewport_width, uv.viewport_height, uv.exemplar_width,
                          uv.exemplar_height, uv.levels})
    detail::put_u32(out, static_cast<std::uint32_t>(v));
  detail::put_f32(out, static_cast<float>(uv.min_scale));
  detail::put_u32(out, uv.mapping);
  for (std::size_t f = 0; f < n; ++f) {
    for (const float c : uv.corner_uv[f]) detail::put_f32(out, c);
    for (const float c : uv.offset[f]) detail::put_f32(out, c);
    detail::put_u32(out, static_cast<std::uint32_t>(uv.level[f]));
    detail::put_f32(out, uv.scale[f]);
    detail::put_u32(out, uv.state[f]);
  }
  return out;
}

/// Decodes the layout above (version 3, or version 2: no mapping field, screen mapping). Errors
/// (invalid_argument): wrong magic or version, an unknown mapping, a size that does not match the
/// face count. O(F).
inline result<terrain_uv_buffer> decode_terrain_uvs(const unsigned char* data, std::size_t size) {
  if (size < 36 || std::memcmp(data, "TSUV", 4) != 0)
    return status::invalid_argument(detail::cat("terrain uv file: no 'TSUV' header (", size, " bytes)"));
  const std::uint32_t version = detail::get_u32(data + 4);
  if (version != terrain_uv_file_version && version != 2)
    return status::invalid_argument(
        detail::cat("terrain uv file: version ", version, ", expected 2 or ", terrain_uv_file_version));
  const std::size_t header = version == 2 ? 36 : terrain_uv_header_bytes;
  if (size < header)
    return status::invalid_argument(detail::cat("terrain uv file: ", size, " bytes are shorter than the header"));
  const std::uint32_t mapping = version == 2 ? 0 : detail::get_u32(data + 36);
  if (mapping > 1)
    return status::invalid_argument(detail::cat("terrain uv file: mapping ", mapping, " (expected 0 or 1)"));
  const std::size_t n = detail::get_u32(data + 8);
  if ((size - header) / terrain_uv_record_bytes != n || (size - header) % terrain_uv_record_bytes != 0)
    return status::invalid_argument(detail::cat("terrain uv file: ", size, " bytes do not hold ", n, " faces"));
  terrain_uv_buffer uv;
  uv.viewport_width = detail::get_u32(data + 12);
  uv.viewport_height = detail::get_u32(data + 16);
  uv.exemplar_width = detail::get_u32(data + 20);
  uv.exemplar_height = detail::get_u32(data + 24);
  uv.levels = detail::get_u32(data + 28);
  uv.min_scale = detail::get_f32(data + 32);
  uv.mapping = mapping;
  uv.corner_uv.resize(n);
  uv.offset.resize(n);
  uv.level.resize(n);
  uv.scale.resize(n);
  uv.state.resize(n);
  for (std::size_t f = 0; f < n; ++f) {
    const unsigned char* r = data + header + terrain_uv_record_bytes * f;
    for (std::size_t k = 0; k < 6; ++k) uv.corner_uv[f][k] = detail::get_f32(r + 4 * k);
    uv.offset[f] = {detail::get_f32(r + 24), detail::get_f32(r + 28)};
    uv.level[f] = static_cast<std::int32_t>(detail::get_u32(r + 32));
    uv.scale[f] = detail::get_f32(r + 36);
    uv.state[f] = static_cast<std::uint8_t>(detail::get_u32(r + 40));
  }
  return uv;
}

TESSERA_NAMESPACE_END
