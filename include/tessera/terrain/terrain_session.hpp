// tessera/terrain/terrain_session.hpp: ground-anchored, incremental terrain synthesis for a moving
// camera (paper 003 made frame-coherent; see docs/terrain.md, "Ground-anchored mode").
//
// A terrain_session keeps the state between frames; update() takes the next camera and does work
// in proportion to what changed, not to the mesh: the mesh is cut once into BLOCKS (square pieces
// of the regions, about 192 faces each; detail/session_projection.hpp), and a block is visited
// only when something in it may change (see update_terrain_session). For the visited blocks it
//   1. decides which faces are visible (§2.1): regions, then blocks of regions partly in view, are
//      tested against the frustum by the box of their vertices (culled whole, inside whole, or
//      face by face); the session projects no vertices (a renderer does; projection() has the
//      per-face states and the visible list, updated in place);
//   2. gives each visible face a LEVEL from its view distance D on a fixed, camera-independent
//      scale (§2.2 made view-independent): g(D) = ln(max(D, D0) / D0) / ln(ratio), raw level
//      floor(g) clamped to [0, levels - 1]; level l has scale max(min_scale, ratio^-l), a mipmap-
//      like chain (the texture's size on screen follows perspective in this mode; the level is the
//      pre-filter). D0 (near_distance) is at least max centroid distance of adjacent faces /
//      ((1 - 2 hysteresis) ln ratio), so that g differs by less than 1 - 2 hysteresis between
//      neighbours and levels never differ by more than one, HYSTERESIS included: a face visible in
//      the previous frame keeps its level l while g stays in [l - hysteresis, l + 1 + hysteresis];
//      A block whose faces were all visible and stay inside the frustum is skipped while the eye is
//      within its SLACK of where it was at the block's last visit (the least distance any of its
//      faces then was from the edge of its band: a face's distance changes by at most the eye's
//      move), so levels are checked face by face only near band edges;
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
#include "anchored_region_geometry.hpp"
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
  /// The visibility of the current frame: viewport, eye, per-face `state` and the `visible` list.
  /// The list is kept up to date in place (a face leaving the view is swapped with the last
  /// entry, one entering is appended), so its ORDER depends on the frames before (ascending after
  /// the first frame); its set does not. Its clip, screen and bounds arrays are empty: the session
  /// does not project vertices (a renderer does; render_anchored_frame projects them with camera()).
  [[nodiscard]] const screen_projection& projection() const noexcept { return proj_; }
  /// The camera of the last successful update.
  [[nodiscard]] const terrain_camera& camera() const noexcept { return camera_; }
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
  /// Whether face f is visible in the current frame (the last successful update).
  [[nodiscard]] bool visible(index_t f) const noexcept { return frame_ >= 0 && proj_.state[detail::to_size(f)] != 0; }
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
    return plan_.memory_bytes() + geometry_.memory_bytes() + atlas_.memory_bytes() + blocks_.memory_bytes() +
           bytes(uv_) + bytes(level_) + bytes(blend_from_) + bytes(vpos_) + bytes(blend_left_) + bytes(dirty_) +
           bytes(proj_.state) + bytes(proj_.visible) + bytes(bframe_) + bytes(bchanged_) + bytes(bview_) +
           bytes(work_) + bytes(grow_) + bytes(bstats_) + bytes(rgrown_) + bytes(start2_) + bytes(lo2_) + bytes(hi2_) +
           bytes(lo_) + bytes(hi_) + bytes(scales_);
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
  bool rebuild_visible_ = true;  ///< the visible list must be rebuilt from the states (first frame, after an error)
  anchored_regions plan_;
  anchored_geometry geometry_;  ///< the regions' faces as their growth reads them
  anchored_atlas atlas_;
  detail::session_blocks blocks_;
  screen_projection proj_;
  terrain_camera camera_;
  std::vector<std::array<float, 6>> uv_;
  std::vector<std::int32_t> level_, blend_from_;
  std::vector<std::int32_t> vpos_;  ///< per face: its index in proj_.visible (-1: not visible)
  std::vector<std::uint8_t> blend_left_, dirty_;
  std::vector<detail::block_frame> bframe_;  ///< per block, between frames
  /// Per block, scratch of a frame: changed anything (bit 0), visibility changed (bit 1), needs
  /// growth (bit 2); how it lies (a region_view, 3: skipped).
  std::vector<std::uint8_t> bchanged_, bview_;
  std::vector<std::int32_t> work_, grow_;  ///< blocks visited and regions grown this frame
  /// Per visited block: common, stable, level changes, resynthesized.
  std::vector<std::array<index_t, 4>> bstats_;
  std::vector<anchored_region_stats> rgrown_;
  /// Per level: squared distance thresholds, and the hysteresis band as distances (see update).
  std::vector<double> start2_, lo2_, hi2_, lo_, hi_;
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
/// plans the regions (plan_anchored_regions), their blocks and the level width. Errors (invalid_argument naming
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
  // squared distance thresholds instead of a logarithm per face: level l >= 1 starts at D0 ratio^l;
  // a face keeps level l while D0 ratio^(l - hysteresis) <= D <= D0 ratio^(l + 1 + hysteresis)
  const double beta = opts.hysteresis, rho = opts.level_ratio;
  const index_t top = s.levels_ - 1;
  for (index_t l = 0; l <= top; ++l) {
    const double dl = static_cast<double>(l);
    s.start2_.push_back(std::pow(s.d0_ * std::pow(rho, dl), 2));
    s.lo2_.push_back(l == 0 ? -1.0 : std::pow(s.d0_ * std::pow(rho, dl - beta), 2));
    s.hi2_.push_back(l == top ? std::numeric_limits<double>::infinity()
                              : std::pow(s.d0_ * std::pow(rho, dl + 1 + beta), 2));
    s.lo_.push_back(l == 0 ? -std::numeric_limits<double>::infinity() : std::sqrt(s.lo2_.back()));
    s.hi_.push_back(std::sqrt(s.hi2_.back()));
  }
  s.plan_ = std::move(*plan);
  auto geometry = make_anchored_geometry(mesh, s.plan_);
  if (!geometry) return geometry.error();
  s.geometry_ = std::move(*geometry);
  reset_anchored_atlas(s.plan_, s.nf_, s.atlas_);
  s.blocks_ = detail::make_session_blocks(mesh, s.plan_);
  const auto nf = detail::to_size(s.nf_), nb = detail::to_size(s.blocks_.num_blocks());
  s.uv_.assign(nf, {});
  s.level_.assign(nf, -1);
  s.blend_from_.assign(nf, -1);
  s.vpos_.assign(nf, -1);
  s.blend_left_.assign(nf, 0);
  s.dirty_.assign(nf, 0);
  s.proj_.state.assign(nf, 0);
  s.bframe_.assign(nb, {});
  s.bchanged_.assign(nb, 0);
  s.bview_.assign(nb, 0);
  return s;
}

/// The next frame of `s` for `camera` (see the file comment); stats() describes it. Errors: a mesh
/// other than the session's (sizes or sampled contents differ: invalid_argument), an invalid camera
/// (validate_camera), a face naming a vertex outside the mesh (out_of_range: the mesh changed in
/// place; every face is checked in the first frame, later the faces the frame reads). On an error
/// the visible list is emptied and the per-face state kept (the next frame continues from the last
/// good one). Nothing in view is not an error: stats().warning says so and the frame is empty.
/// O(regions + blocks + faces of the blocks visited), parallel through `exec`; bit-identical for
/// any executor. A block is visited when it may have changed: partly in view, entering or leaving
/// the view, blending, or the eye moved farther from where it was when the block was last visited
/// than its slack (the least distance of its faces from leaving their level's band).
template <Executor E>
status update_terrain_session(terrain_session& s, const terrain_mesh& mesh, const terrain_camera& camera, E&& exec) {
  if (mesh.num_faces() != s.nf_ || mesh.num_vertices() != s.nv_ ||
      detail::terrain_mesh_fingerprint(mesh) != s.fingerprint_)
    return status::invalid_argument(detail::cat("terrain_session: this mesh (", mesh.num_faces(), " faces, ",
                                                mesh.num_vertices(), " vertices) is not the session's (", s.nf_,
                                                " faces, ", s.nv_, " vertices): make a session per mesh"));
  auto fail = [&](status st) {
    s.proj_.visible.clear();
    s.rebuild_visible_ = true;
    return st;
  };
  if (auto st = validate_camera(camera); !st) return fail(st);
  const glm::dmat4 m = camera.projection * camera.view;
  const bool zo = camera.depth == clip_depth::zero_to_one, cull = s.opts_.projection.cull_back_faces;
  const vec3 eye = camera_eye(camera);
  const detail::session_blocks& bl = s.blocks_;
  const index_t nr = s.plan_.num_regions(), nb = bl.num_blocks(), nv = mesh.num_vertices();
  using detail::region_view;
  // pass 1 (O(regions + blocks)): how each region lies, each block of a region partly in view, and
  // which blocks to visit: a block is skipped when culled whole now and before, or inside now and
  // before with every face, nothing blending and the eye within its slack (back-face culling
  // visits every block in view)
  constexpr index_t rblock = 16;
  exec.parallel_for(0, (nr + rblock - 1) / rblock, [&](index_t c) {
    for (index_t r = c * rblock; r < std::min(nr, (c + 1) * rblock); ++r) {
      const auto b0 = bl.region_first[detail::to_size(r)], b1 = bl.region_first[detail::to_size(r) + 1];
      if (b0 == b1) continue;
      detail::box6 box = detail::empty_box();
      for (auto b = b0; b < b1; ++b) {
        const auto& q = bl.vertex_box[detail::to_size(b)];
        for (std::size_t k = 0; k < 3; ++k)
          box[k] = std::min(box[k], q[k]), box[k + 3] = std::max(box[k + 3], q[k + 3]);
      }
      const region_view rv = detail::classify_region_box(box, m, zo);
      for (auto b = b0; b < b1; ++b) {
        const auto bi = detail::to_size(b);
        const region_view v =
            rv == region_view::partial && b1 - b0 > 1 ? detail::classify_region_box(bl.vertex_box[bi], m, zo) : rv;
        const detail::block_frame& bf = s.bframe_[bi];
        bool skip = false;
        if (v == region_view::outside) {
          skip = bf.visible == 0;
        } else if (v == region_view::inside && !cull && bf.visible == bl.first[bi + 1] - bl.first[bi] && bf.near == 0 &&
                   bf.blending == 0) {
          skip = norm(eye - bf.eye) < bf.slack * (1 - detail::block_slack_margin);
        }
        s.bview_[bi] = static_cast<std::uint8_t>(skip ? 3 : static_cast<int>(v));
      }
    }
  });
  s.work_.clear();
  for (index_t b = 0; b < nb; ++b)
    if (s.bview_[detail::to_size(b)] != 3) s.work_.push_back(static_cast<std::int32_t>(b));
  const auto nwork = static_cast<index_t>(s.work_.size());
  // the faces about to be read must name vertices of the mesh (a mesh changed in place since the
  // session was made): all of them in the first frame, then those of the visited blocks
  {
    const bool all = s.frame_ < 0;
    const index_t tasks = all ? nb : nwork;
    std::vector<index_t> bad(detail::to_size(tasks), -1);
    exec.parallel_for(0, tasks, [&](index_t t) {
      const auto b = detail::to_size(all ? t : s.work_[detail::to_size(t)]);
      for (std::int32_t i = bl.first[b]; i < bl.first[b + 1]; ++i) {
        const std::int32_t f = bl.faces[detail::to_size(i)];
        const auto& face = mesh.faces[detail::to_size(f)];
        if (static_cast<std::uint32_t>(face[0]) >= static_cast<std::uint64_t>(nv) ||
            static_cast<std::uint32_t>(face[1]) >= static_cast<std::uint64_t>(nv) ||
            static_cast<std::uint32_t>(face[2]) >= static_cast<std::uint64_t>(nv)) {
          bad[detail::to_size(t)] = f;  // faces ascend within a block: the first is the smallest
          return;
        }
      }
    });
    index_t first_bad = -1;
    for (const index_t f : bad)
      if (f >= 0 && (first_bad < 0 || f < first_bad)) first_bad = f;
    if (first_bad >= 0)
      return fail(
          status::out_of_range(detail::cat("terrain_mesh face ", first_bad, " names a vertex outside the mesh's ", nv,
                                           " vertices (the mesh changed since the session was made)")));
  }
  const auto fr = static_cast<std::int32_t>(++s.frame_);
  s.camera_ = camera;
  s.proj_.width = camera.width;
  s.proj_.height = camera.height;
  s.proj_.depth = camera.depth;
  s.proj_.eye = eye;
  terrain_frame_stats& out = s.stats_;
  out = terrain_frame_stats{};
  out.frame = fr;
  const auto top = static_cast<std::int32_t>(s.levels_ - 1);
  const auto blend = static_cast<std::uint8_t>(s.opts_.blend_frames);
  s.bstats_.assign(detail::to_size(nwork), {});
  std::fill(s.bchanged_.begin(), s.bchanged_.end(), std::uint8_t{0});
  // pass 2 (parallel over the visited blocks, each touching only its own faces): visibility and
  // levels with hysteresis (§2.2 made view-independent, see the file comment)
  exec.parallel_for(0, nwork, [&](index_t w) {
    const auto bi = detail::to_size(s.work_[detail::to_size(w)]);
    const auto v = static_cast<region_view>(s.bview_[bi]);
    auto& counts = s.bstats_[detail::to_size(w)];  // common, stable, changes, resynthesized
    detail::block_frame& bf = s.bframe_[bi];
    bf.visible = bf.near = bf.blending = 0;
    bf.eye = eye;
    bf.slack = std::numeric_limits<double>::infinity();
    std::uint8_t flags = 0;
    for (std::int32_t i = bl.first[bi]; i < bl.first[bi + 1]; ++i) {
      const std::int32_t face = bl.faces[detail::to_size(i)];
      const auto f = detail::to_size(face);
      std::uint8_t st = 0;
      if (v == region_view::inside && !cull)
        st = static_cast<std::uint8_t>(face_visibility::inside);
      else if (v != region_view::outside)
        st = detail::face_view_state(mesh, face, m, zo, cull, eye);
      const bool was = s.proj_.state[f] != 0;
      s.proj_.state[f] = st;
      if (st == 0) {
        if (was) flags |= 3;
        continue;
      }
      if (!was) flags |= 2;
      bf.near += st == static_cast<std::uint8_t>(face_visibility::near_clipped) ? 1 : 0;
      const vec3 d = mesh.centroids[f] - eye;
      const double d2 = dot(d, d);
      std::int32_t raw = 0;
      while (raw < top && d2 >= s.start2_[detail::to_size(raw + 1)]) ++raw;
      const std::int32_t old = s.level_[f];
      std::int32_t l = raw;
      if (was && d2 >= s.lo2_[detail::to_size(old)] && d2 <= s.hi2_[detail::to_size(old)]) l = old;
      if (was) {
        ++counts[0];
        if (l == old) {
          ++counts[1];
          if (s.blend_left_[f] > 0) --s.blend_left_[f];
        } else {
          ++counts[2];
          s.blend_from_[f] = old;
          s.blend_left_[f] = blend;
        }
      } else {
        s.blend_left_[f] = 0;
      }
      bf.blending += s.blend_left_[f] > 0 ? 1 : 0;
      ++bf.visible;
      const double dist = std::sqrt(d2);
      bf.slack = std::min({bf.slack, dist - s.lo_[detail::to_size(l)], s.hi_[detail::to_size(l)] - dist});
      if (!was || l != old) {
        s.level_[f] = l;
        s.dirty_[f] = 1;
        ++counts[3];
        flags |= 1;
        if (!s.atlas_.region_done[detail::to_size(bl.region[bi])]) flags |= 4;
      }
    }
    s.bchanged_[bi] = flags;
  });
  // pass 3: grow the regions of faces seen for the first time (in parallel, independent), then
  // write the coordinates of the faces that became visible or changed level
  s.grow_.clear();
  for (const std::int32_t b : s.work_)
    if (s.bchanged_[detail::to_size(b)] & 4) s.grow_.push_back(bl.region[detail::to_size(b)]);
  s.grow_.erase(std::unique(s.grow_.begin(), s.grow_.end()), s.grow_.end());  // blocks are grouped by region
  s.rgrown_.assign(s.grow_.size(), {});
  auto write_uv = [&](std::size_t bi) {
    for (std::int32_t i = bl.first[bi]; i < bl.first[bi + 1]; ++i) {
      const auto f = detail::to_size(bl.faces[detail::to_size(i)]);
      if (!s.dirty_[f]) continue;
      s.dirty_[f] = 0;
      const float sc = s.scales_[detail::to_size(s.level_[f])];
      const auto& a = s.atlas_.uv[f];
      for (std::size_t k = 0; k < 6; ++k) s.uv_[f][k] = a[k] * sc;
    }
  };
  // a region grown here writes its blocks' coordinates while its atlas is in cache
  exec.parallel_for(0, static_cast<index_t>(s.grow_.size()), [&](index_t i) {
    const std::int32_t r = s.grow_[detail::to_size(i)];
    (void)synthesize_anchored_region(mesh, s.plan_, r, s.ew_, s.eh_, s.opts_.synthesis, s.atlas_,
                                     &s.rgrown_[detail::to_size(i)], &s.geometry_);
    for (auto b = bl.region_first[detail::to_size(r)]; b < bl.region_first[detail::to_size(r) + 1]; ++b)
      if (s.bchanged_[detail::to_size(b)] & 1) write_uv(detail::to_size(b));
  });
  exec.parallel_for(0, nwork, [&](index_t w) {
    const auto bi = detail::to_size(s.work_[detail::to_size(w)]);
    if ((s.bchanged_[bi] & 1) && !(s.bchanged_[bi] & 4)) write_uv(bi);
  });
  out.regions_grown = static_cast<index_t>(s.grow_.size());
  for (const auto& g : s.rgrown_) {
    out.faces_grown += g.faces;
    out.restarts += g.restarts;
  }
  index_t nvis = 0, near = 0;
  for (index_t b = 0; b < nb; ++b) {
    const auto& bf = s.bframe_[detail::to_size(b)];
    nvis += bf.visible;
    near += bf.near;
    out.blending += bf.blending;
    if (s.bview_[detail::to_size(b)] == 3) out.common += bf.visible, out.stable_faces += bf.visible;
  }
  for (const auto& c : s.bstats_) {
    out.common += c[0];
    out.stable_faces += c[1];
    out.level_changes += c[2];
    out.resynthesized += c[3];
  }
  out.visible = nvis;
  // pass 4: the visible list, in place: faces that left are swapped out, faces that entered are
  // appended (serial, in block order: O(faces of the blocks whose visibility changed)); rebuilt
  // ascending from the states in the first frame and after an error
  auto& list = s.proj_.visible;
  if (s.rebuild_visible_) {
    list.clear();
    list.reserve(detail::to_size(nvis));
    for (index_t f = 0; f < s.nf_; ++f) {
      const auto fi = detail::to_size(f);
      s.vpos_[fi] = -1;
      if (s.proj_.state[fi] == 0) continue;
      s.vpos_[fi] = static_cast<std::int32_t>(list.size());
      list.push_back(static_cast<std::int32_t>(f));
    }
    s.rebuild_visible_ = false;
  } else {
    for (const std::int32_t b : s.work_) {
      const auto bi = detail::to_size(b);
      if (!(s.bchanged_[bi] & 2)) continue;
      for (std::int32_t i = bl.first[bi]; i < bl.first[bi + 1]; ++i) {
        const std::int32_t f = bl.faces[detail::to_size(i)];
        const auto fi = detail::to_size(f);
        const bool now = s.proj_.state[fi] != 0, listed = s.vpos_[fi] >= 0;
        if (now && !listed) {
          s.vpos_[fi] = static_cast<std::int32_t>(list.size());
          list.push_back(f);
        } else if (!now && listed) {
          const std::int32_t last = list.back();
          list[detail::to_size(s.vpos_[fi])] = last;
          s.vpos_[detail::to_size(last)] = s.vpos_[fi];
          s.vpos_[fi] = -1;
          list.pop_back();
        }
      }
    }
  }
  s.proj_.near_clipped = near;
  // pass 5: continuity and level jumps, per block over the edges whose smaller face it holds;
  // recounted only for blocks that changed or border one that did
  if (s.opts_.measure_continuity) {
    exec.parallel_for(0, (nb + 63) / 64, [&](index_t c) {
      for (index_t b = c * 64; b < std::min(nb, (c + 1) * 64); ++b) {
        const auto bi = detail::to_size(b);
        bool recount = (s.bchanged_[bi] & 3) != 0;
        for (std::int32_t k = bl.nb_first[bi]; k < bl.nb_first[bi + 1] && !recount; ++k)
          recount = (s.bchanged_[detail::to_size(bl.nb[detail::to_size(k)])] & 3) != 0;
        if (!recount) continue;
        detail::block_frame& bf = s.bframe_[bi];
        bf.shared = bf.same = 0;
        bf.jump = 0;
        if (bf.visible == 0) continue;
        for (std::int32_t i = bl.first[bi]; i < bl.first[bi + 1]; ++i) {
          const std::int32_t f = bl.faces[detail::to_size(i)];
          const auto fi = detail::to_size(f);
          if (s.proj_.state[fi] == 0) continue;
          const std::uint8_t seam = s.atlas_.seam[fi];
          const std::int32_t lf = s.level_[fi];
          for (int k = 0; k < 3; ++k) {
            const std::int32_t n = mesh.neighbors[fi][detail::to_size(k)];
            if (n <= f || s.proj_.state[detail::to_size(n)] == 0) continue;
            ++bf.shared;
            bf.jump = std::max(bf.jump, std::abs(lf - s.level_[detail::to_size(n)]));
            bf.same += ((seam >> k) & 1) == 0 ? 1 : 0;
          }
        }
      }
    });
    for (const auto& bf : s.bframe_) {
      out.shared_edges += bf.shared;
      out.continuous_edges += bf.same;
      out.max_level_jump = std::max(out.max_level_jump, bf.jump);
    }
  }
  out.stable_fraction = out.common > 0 ? static_cast<double>(out.stable_faces) / static_cast<double>(out.common) : 1.0;
  out.continuous_fraction =
      out.shared_edges > 0 ? static_cast<double>(out.continuous_edges) / static_cast<double>(out.shared_edges) : 1.0;
  if (nvis == 0) out.warning = status::out_of_range(detail::cat("terrain_session frame ", fr, ": no face is in view"));
  return {};
}

TESSERA_NAMESPACE_END
