// tessera/terrain/terrain_session.hpp: ground-anchored, incremental terrain synthesis for a moving
// camera (paper 003 made frame-coherent; see docs/terrain.md, "Ground-anchored mode").
//
// A terrain_session keeps the state between frames; update() takes the next camera and
//   1. projects the mesh (§2.1; detail/session_projection.hpp, a lean project_mesh: the session's
//      projection() has clip coordinates, states and the visible list, not screen positions or
//      bounds, which ground-anchored coordinates do not need): which faces are visible;
//   2. gives each visible face a LEVEL from its view distance D on a fixed, camera-independent
//      scale (§2.2 made view-independent): g(D) = ln(max(D, D0) / D0) / ln(ratio), raw level
//      floor(g) clamped to [0, levels - 1]; level l has scale max(min_scale, ratio^-l), a mipmap-
//      like chain (the texture's size on screen follows perspective in this mode; the level is the
//      pre-filter). D0 (near_distance) is at least max centroid distance of adjacent faces /
//      ((1 - 2 hysteresis) ln ratio), so that g differs by less than 1 - 2 hysteresis between
//      neighbours and levels never differ by more than one, HYSTERESIS included: a face visible in
//      the previous frame keeps its level l while g stays in [l - hysteresis, l + 1 + hysteresis];
//   3. re-synthesizes only faces that became visible or changed level: their regions are grown
//      if they were not yet (synthesize_anchored_region.hpp, in parallel over regions), and their
//      corner coordinates in texels of their level image (anchored uv * scale of the level) are
//      written; every other face keeps its coordinates untouched, bit for bit;
//   4. optionally blends level changes over `blend_frames` frames (blend_weight(f) rises from
//      1 / (blend_frames + 1) to 1; the renderer mixes in the previous level by 1 - weight).
//
// Every face's coordinates are a pure function of (mesh, exemplar size, options, face, level):
// independent of the camera, the frame order, what else is visible and the executor.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/vec.hpp"
#include "plan_anchored_regions.hpp"
#include "prepare_terrain_mesh.hpp"
#include "project_mesh.hpp"
#include "synthesize_anchored_region.hpp"
#include "terrain_camera.hpp"
#include "detail/session_projection.hpp"
#include "detail/tolerances.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of make_terrain_session (ground-anchored frames).
struct terrain_session_options {
  /// Regions and growth (plan_anchored_regions.hpp).
  anchored_synthesis_options synthesis = {};
  double min_scale = 0.5;    ///< scale of the farthest level, in (0, 1] (at least the exemplar pyramid's)
  index_t max_levels = 64;   ///< at most this many levels, 1 to 65536
  double level_ratio = 1.5;  ///< distance ratio from one level to the next (and scale ratio), in (1, 16]
  double near_distance = 0;  ///< D0: level l >= 1 starts at D0 level_ratio^l; 0: the smallest allowed (see above)
  double hysteresis = 0.15;  ///< fraction of a level a face may stray before it changes level, [0, 0.45]
  int blend_frames = 0;      ///< frames over which a level change is blended, 0 to 255
  /// Options of the per-frame projection.
  project_options projection = {};
  bool measure_continuity = true;  ///< count continuous shared edges and the level jump every frame
};

/// What one update() did and found.
struct terrain_frame_stats {
  /// Frame number, from 0 (-1 before the first update).
  index_t frame = -1;
  /// Faces in view.
  index_t visible = 0;
  index_t resynthesized = 0;  ///< visible faces whose coordinates were (re)written: new in view or new level
  /// Regions grown this frame, their faces, and restarts while growing them.
  index_t regions_grown = 0, faces_grown = 0, restarts = 0;
  index_t common = 0;        ///< faces visible in this frame and the previous one
  index_t stable_faces = 0;  ///< of those, faces at the same level (coordinates bit-identical)
  /// stable_faces / common (1 when common is 0).
  double stable_fraction = 1;
  /// Faces that changed level this frame, and faces still blending a level change.
  index_t level_changes = 0, blending = 0;
  index_t shared_edges = 0, continuous_edges = 0;  ///< between visible faces (measure_continuity)
  /// continuous_edges / shared_edges (1 when there are none).
  double continuous_fraction = 1;
  int max_level_jump = 0;  ///< over adjacent visible faces (measure_continuity); <= 1
  status warning;          ///< ok, or out_of_range when nothing is in view
};

class terrain_session;
/// Declared here for terrain_session::update; defined below.
template <Executor E>
status update_terrain_session(terrain_session& s, const terrain_mesh& mesh, const terrain_camera& camera, E&& exec);

/// State of ground-anchored synthesis between frames (see the file comment). Make one with
/// make_terrain_session; feed it cameras with update(). Movable, not thread-safe per object.
class terrain_session {
 public:
  /// Takes the next camera (see update_terrain_session).
  template <Executor E = serial_executor>
  status update(const terrain_mesh& mesh, const terrain_camera& camera, E&& exec = {}) {
    return update_terrain_session(*this, mesh, camera, exec);
  }
  /// The projection of the current frame.
  [[nodiscard]] const screen_projection& projection() const noexcept { return proj_; }
  /// What the last update did.
  [[nodiscard]] const terrain_frame_stats& stats() const noexcept { return stats_; }
  /// The mesh's regions.
  [[nodiscard]] const anchored_regions& regions() const noexcept { return plan_; }
  /// The coordinates of the regions grown so far.
  [[nodiscard]] const anchored_atlas& atlas() const noexcept { return atlas_; }
  /// The options it was made with.
  [[nodiscard]] const terrain_session_options& options() const noexcept { return opts_; }
  /// Width of the exemplar it synthesizes for.
  [[nodiscard]] index_t exemplar_width() const noexcept { return ew_; }
  /// Height of the exemplar it synthesizes for.
  [[nodiscard]] index_t exemplar_height() const noexcept { return eh_; }
  /// Levels in use: min(max_levels, 1 + ceil(ln(1 / min_scale) / ln(level_ratio))).
  [[nodiscard]] index_t levels() const noexcept { return levels_; }
  /// D0: level l >= 1 starts at view distance D0 level_ratio^l.
  [[nodiscard]] double near_distance() const noexcept { return d0_; }
  /// Frame number of the last update (-1 before the first).
  [[nodiscard]] index_t frame() const noexcept { return frame_; }
  /// Scale of level l: max(min_scale, level_ratio^-l).
  [[nodiscard]] double level_scale(index_t l) const noexcept {
    return std::max(opts_.min_scale, std::pow(opts_.level_ratio, -static_cast<double>(l)));
  }
  /// Whether face f is visible in the current frame.
  [[nodiscard]] bool visible(index_t f) const noexcept { return seen_[detail::to_size(f)] == frame_ && frame_ >= 0; }
  /// Per face: corners u0 v0 u1 v1 u2 v2 in texels of the face's level image from its centre
  /// (sample the exemplar shrunk by scale(level) at 0.5 + uv / (width * scale, height * scale));
  /// interpolate PERSPECTIVE-correctly. Meaningful for visible faces.
  [[nodiscard]] const std::vector<std::array<float, 6>>& corner_uv() const noexcept { return uv_; }
  /// Per face: the level of the last frame it was visible in (-1: never visible).
  [[nodiscard]] const std::vector<std::int32_t>& level() const noexcept { return level_; }
  /// Weight of the current level in a blend (1: none); blend_from(f) is the level blended out.
  [[nodiscard]] float blend_weight(index_t f) const noexcept {
    const auto left = blend_left_[detail::to_size(f)];
    return left == 0 ? 1.0f : 1.0f - static_cast<float>(left) / static_cast<float>(opts_.blend_frames + 1);
  }
  /// The level blended out of face f (meaningful while blend_weight(f) < 1).
  [[nodiscard]] std::int32_t blend_from(index_t f) const noexcept { return blend_from_[detail::to_size(f)]; }
  /// Bytes held by the session (per-face state, regions, atlas and the projection).
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return plan_.memory_bytes() + atlas_.memory_bytes() + bytes(uv_) + bytes(level_) + bytes(seen_) +
           bytes(blend_from_) + bytes(blend_left_) + bytes(dirty_) + bytes(codes_) + bytes(proj_.clip) +
           bytes(proj_.screen) + bytes(proj_.state) + bytes(proj_.bounds) + bytes(proj_.visible);
  }

 private:
  friend result<terrain_session> make_terrain_session(const terrain_mesh&, index_t, index_t,
                                                      const terrain_session_options&);
  template <Executor E>
  friend status update_terrain_session(terrain_session&, const terrain_mesh&, const terrain_camera&, E&&);

  terrain_session_options opts_;
  index_t ew_ = 0, eh_ = 0, nf_ = 0, nv_ = 0;
  std::uint64_t fingerprint_ = 0;
  double d0_ = 1;
  index_t levels_ = 1;
  index_t frame_ = -1;
  anchored_regions plan_;
  anchored_atlas atlas_;
  screen_projection proj_;
  std::vector<std::array<float, 6>> uv_;
  std::vector<std::int32_t> level_, seen_, blend_from_;
  std::vector<std::uint8_t> blend_left_, dirty_, codes_;
  std::vector<float> scales_;  ///< per level
  terrain_frame_stats stats_;
};

namespace detail {
/// A cheap fingerprint of a mesh: sizes and up to 64 sampled faces and vertices (bit patterns).
inline std::uint64_t terrain_mesh_fingerprint(const terrain_mesh& m) {
  std::uint64_t h = hash_keys(static_cast<std::uint64_t>(m.num_faces()), static_cast<std::uint64_t>(m.num_vertices()));
  const index_t nf = m.num_faces(), nv = m.num_vertices();
  for (index_t i = 0; i < 64 && nf > 0; ++i) {
    const auto f = to_size(i * nf / 64);
    for (const std::int32_t v : m.faces[f]) h = hash_keys(h, static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)));
  }
  for (index_t i = 0; i < 64 && nv > 0; ++i) {
    const vec3& p = m.positions[to_size(i * nv / 64)];
    std::uint64_t b[3];
    std::memcpy(&b[0], &p.x, 8);
    std::memcpy(&b[1], &p.y, 8);
    std::memcpy(&b[2], &p.z, 8);
    h = hash_keys(h, b[0], b[1], b[2]);
  }
  return h;
}
}  // namespace detail

/// Makes a session for `mesh` and an exemplar of `exemplar_width` x `exemplar_height` pixels:
/// plans the regions (plan_anchored_regions) and the level width. Errors (invalid_argument naming
/// the value): as plan_anchored_regions; min_scale outside (0, 1], max_levels outside 1..65536,
/// level_ratio outside (1, 16], hysteresis outside [0, 0.45], blend_frames outside 0..255,
/// near_distance negative, not finite, or below the minimum that keeps adjacent faces within one
/// level (the message gives it). O(F).
inline result<terrain_session> make_terrain_session(const terrain_mesh& mesh, index_t exemplar_width,
                                                    index_t exemplar_height, const terrain_session_options& opts = {}) {
  if (!(opts.min_scale > 0 && opts.min_scale <= 1))
    return status::invalid_argument(detail::cat("min_scale must be in (0, 1], got ", opts.min_scale));
  if (opts.max_levels < 1 || opts.max_levels > 65536)
    return status::invalid_argument(detail::cat("max_levels must be 1 to 65536, got ", opts.max_levels));
  if (!(opts.hysteresis >= 0 && opts.hysteresis <= 0.45))
    return status::invalid_argument(detail::cat("hysteresis must be in [0, 0.45], got ", opts.hysteresis));
  if (opts.blend_frames < 0 || opts.blend_frames > 255)
    return status::invalid_argument(detail::cat("blend_frames must be 0 to 255, got ", opts.blend_frames));
  if (!(opts.level_ratio > 1 && opts.level_ratio <= 16))
    return status::invalid_argument(detail::cat("level_ratio must be in (1, 16], got ", opts.level_ratio));
  if (!(opts.near_distance >= 0) || !std::isfinite(opts.near_distance))
    return status::invalid_argument(detail::cat("near_distance must be >= 0 (0: automatic), got ", opts.near_distance));
  auto plan = plan_anchored_regions(mesh, exemplar_width, exemplar_height, opts.synthesis);
  if (!plan) return plan.error();
  terrain_session s;
  s.opts_ = opts;
  s.ew_ = exemplar_width;
  s.eh_ = exemplar_height;
  s.nf_ = mesh.num_faces();
  s.nv_ = mesh.num_vertices();
  s.fingerprint_ = detail::terrain_mesh_fingerprint(mesh);
  const double d_min = plan->max_neighbor_distance / ((1 - 2 * opts.hysteresis) * std::log(opts.level_ratio)) *
                       (1 + detail::scale_match_slack);
  if (opts.near_distance > 0 && opts.near_distance < d_min)
    return status::invalid_argument(detail::cat("near_distance ", opts.near_distance, " is below ", d_min,
                                                ", the smallest that keeps adjacent faces within one level (largest "
                                                "distance between adjacent centroids / ((1 - 2 hysteresis) ln "
                                                "level_ratio))"));
  s.d0_ = opts.near_distance > 0 ? opts.near_distance : (d_min > 0 ? d_min : 1.0);
  const double need =
      std::ceil(std::log(1 / opts.min_scale) / std::log(opts.level_ratio) - detail::level_count_rounding);
  s.levels_ = std::clamp<index_t>(1 + static_cast<index_t>(std::max(0.0, need)), 1, opts.max_levels);
  for (index_t l = 0; l < s.levels_; ++l) s.scales_.push_back(static_cast<float>(s.level_scale(l)));
  s.plan_ = std::move(*plan);
  reset_anchored_atlas(s.plan_, s.nf_, s.atlas_);
  const auto nf = detail::to_size(s.nf_);
  s.uv_.assign(nf, {});
  s.level_.assign(nf, -1);
  s.seen_.assign(nf, -2);
  s.blend_from_.assign(nf, -1);
  s.blend_left_.assign(nf, 0);
  s.dirty_.assign(nf, 0);
  return s;
}

/// The next frame of `s` for `camera` (see the file comment); stats() describes it. Errors: a mesh
/// other than the session's (sizes or sampled contents differ: invalid_argument), an invalid camera
/// (validate_camera), as project_mesh. On an error the projection is emptied and the per-face state
/// kept (the next frame continues from the last good one). Nothing in
/// view is not an error: stats().warning says so and the frame is empty. O(V + visible faces +
/// faces of newly grown regions), parallel through `exec`; bit-identical for any executor.
template <Executor E>
status update_terrain_session(terrain_session& s, const terrain_mesh& mesh, const terrain_camera& camera, E&& exec) {
  if (mesh.num_faces() != s.nf_ || mesh.num_vertices() != s.nv_ ||
      detail::terrain_mesh_fingerprint(mesh) != s.fingerprint_)
    return status::invalid_argument(detail::cat("terrain_session: this mesh (", mesh.num_faces(), " faces, ",
                                                mesh.num_vertices(), " vertices) is not the session's (", s.nf_,
                                                " faces, ", s.nv_, " vertices): make a session per mesh"));
  if (auto st = validate_camera(camera); !st) return st;
  if (auto st = detail::project_for_session(mesh, camera, s.opts_.projection, s.proj_, s.codes_, exec); !st) {
    s.proj_.visible.clear();
    std::fill(s.proj_.state.begin(), s.proj_.state.end(), std::uint8_t{0});
    return st;
  }
  const std::int32_t fr = static_cast<std::int32_t>(++s.frame_);
  terrain_frame_stats& out = s.stats_;
  out = terrain_frame_stats{};
  out.frame = s.frame_;
  const index_t nvis = s.proj_.num_visible();
  out.visible = nvis;
  if (nvis == 0) {
    out.warning = status::out_of_range(detail::cat("terrain_session frame ", s.frame_, ": no face is in view"));
    return {};
  }
  const std::int32_t* vis = s.proj_.visible.data();
  constexpr index_t block = 16384;
  const index_t chunks = (nvis + block - 1) / block;
  struct partial {
    index_t common = 0, stable = 0, changes = 0, resyn = 0, blending = 0, shared = 0, same = 0;
    int jump = 0;
    std::vector<std::int32_t> regions;
  };
  std::vector<partial> part(detail::to_size(chunks));
  // squared distance thresholds instead of a logarithm per face: level l >= 1 starts at D0 ratio^l;
  // a face keeps level l while D0 ratio^(l - hysteresis) <= D <= D0 ratio^(l + 1 + hysteresis)
  const double beta = s.opts_.hysteresis, rho = s.opts_.level_ratio;
  const index_t top = s.levels_ - 1;
  std::vector<double> start2(detail::to_size(top + 1)), lo2(start2.size()), hi2(start2.size());
  for (index_t l = 0; l <= top; ++l) {
    const auto i = detail::to_size(l);
    const double dl = static_cast<double>(l);
    start2[i] = std::pow(s.d0_ * std::pow(rho, dl), 2);
    lo2[i] = l == 0 ? -1.0 : std::pow(s.d0_ * std::pow(rho, dl - beta), 2);
    hi2[i] = l == top ? std::numeric_limits<double>::infinity() : std::pow(s.d0_ * std::pow(rho, dl + 1 + beta), 2);
  }
  const vec3 eye = s.proj_.eye;
  const auto blend = static_cast<std::uint8_t>(s.opts_.blend_frames);
  // pass 1: levels (with hysteresis), what to re-synthesize, which regions to grow
  exec.parallel_for(0, chunks, [&](index_t c) {
    partial& p = part[detail::to_size(c)];
    for (index_t i = c * block; i < std::min(nvis, (c + 1) * block); ++i) {
      const auto f = detail::to_size(vis[i]);
      const vec3 d = mesh.centroids[f] - eye;
      const double d2 = dot(d, d);
      std::int32_t raw = 0;
      while (raw < top && d2 >= start2[detail::to_size(raw + 1)]) ++raw;
      const bool was = s.seen_[f] == fr - 1;
      const std::int32_t old = s.level_[f];
      std::int32_t l = raw;
      if (was && d2 >= lo2[detail::to_size(old)] && d2 <= hi2[detail::to_size(old)]) l = old;
      if (was) {
        ++p.common;
        if (l == old) {
          ++p.stable;
          if (s.blend_left_[f] > 0) --s.blend_left_[f];
        } else {
          ++p.changes;
          s.blend_from_[f] = old;
          s.blend_left_[f] = blend;
        }
      } else {
        s.blend_left_[f] = 0;
      }
      p.blending += s.blend_left_[f] > 0 ? 1 : 0;
      s.seen_[f] = fr;
      if (!was || l != old) {
        s.level_[f] = l;
        s.dirty_[f] = 1;
        ++p.resyn;
        const std::int32_t r = s.plan_.region[f];
        if (!s.atlas_.region_done[detail::to_size(r)] && (p.regions.empty() || p.regions.back() != r))
          p.regions.push_back(r);
      }
    }
  });
  std::vector<std::int32_t> grow;
  for (partial& p : part) grow.insert(grow.end(), p.regions.begin(), p.regions.end());
  std::sort(grow.begin(), grow.end());
  grow.erase(std::unique(grow.begin(), grow.end()), grow.end());
  // pass 2: grow the new regions (independent of each other)
  std::vector<anchored_region_stats> grown(grow.size());
  exec.parallel_for(0, static_cast<index_t>(grow.size()), [&](index_t i) {
    (void)synthesize_anchored_region(mesh, s.plan_, grow[detail::to_size(i)], s.ew_, s.eh_, s.opts_.synthesis, s.atlas_,
                                     &grown[detail::to_size(i)]);
  });
  out.regions_grown = static_cast<index_t>(grow.size());
  for (const auto& g : grown) {
    out.faces_grown += g.faces;
    out.restarts += g.restarts;
  }
  // pass 3: write the coordinates of the re-synthesized faces; continuity and level jumps
  const bool measure = s.opts_.measure_continuity;
  exec.parallel_for(0, chunks, [&](index_t c) {
    partial& p = part[detail::to_size(c)];
    for (index_t i = c * block; i < std::min(nvis, (c + 1) * block); ++i) {
      const auto f = detail::to_size(vis[i]);
      if (s.dirty_[f]) {
        s.dirty_[f] = 0;
        const float sc = s.scales_[detail::to_size(s.level_[f])];
        const auto& a = s.atlas_.uv[f];
        for (std::size_t k = 0; k < 6; ++k) s.uv_[f][k] = a[k] * sc;
      }
      if (!measure) continue;
      const std::uint8_t seam = s.atlas_.seam[f];
      const std::int32_t lf = s.level_[f];
      for (int k = 0; k < 3; ++k) {
        const std::int32_t n = mesh.neighbors[f][detail::to_size(k)];
        if (n <= vis[i] || s.seen_[detail::to_size(n)] != fr) continue;
        ++p.shared;
        p.jump = std::max(p.jump, std::abs(lf - s.level_[detail::to_size(n)]));
        const bool same = ((seam >> k) & 1) == 0;
        p.same += same ? 1 : 0;
      }
    }
  });
  for (const partial& p : part) {
    out.common += p.common;
    out.stable_faces += p.stable;
    out.level_changes += p.changes;
    out.resynthesized += p.resyn;
    out.blending += p.blending;
    out.shared_edges += p.shared;
    out.continuous_edges += p.same;
    out.max_level_jump = std::max(out.max_level_jump, p.jump);
  }
  out.stable_fraction = out.common > 0 ? static_cast<double>(out.stable_faces) / static_cast<double>(out.common) : 1.0;
  out.continuous_fraction =
      out.shared_edges > 0 ? static_cast<double>(out.continuous_edges) / static_cast<double>(out.shared_edges) : 1.0;
  return {};
}

TESSERA_NAMESPACE_END
