// tessera/image/axis_wang_tiles.hpp: three-axis image Wang tile sets, the image tiles that cover
// polycube surfaces (Fu & Leung 2005, "Texture tiling on arbitrary topological surfaces using Wang
// tiles", paper 000's ref. [5]; the combinatorics of tiling/axis_tile_set.hpp, paper 000 §3.1 Fig. 2).
//
// A polycube's grid edges run along X, Y or Z and draw from nX, nY, nZ colours. An edge colour of
// axis a stands for ONE edge sample S(a, c) (detail/wang_edge_samples.hpp): a strip of tile_size
// pixels along the edge, running towards +a, and 2·overlap across it. Whichever two quads meet at a
// grid edge, in one plane or around a convex or concave polycube edge, they traverse it in opposite
// directions (surface/quad_layout.hpp); seen from outside, the quad that runs along +a (the edge is
// its south or east side) lies to the left of the edge and takes the strip's first half, the other
// quad its second half. So the strip is "unrolled" across every polycube edge (paper 000 §3.1 Fig. 3:
// each strip split half and half across the edge) and the two tiles continue each other without a
// seam, whatever faces they sit on.
//
// In a tile of face f (built in its quads' frame: image x along the face's first in-plane axis,
// image rows downwards = its second axis backwards, north = +v), a north or south side uses S(a, c)
// as a planar horizontal strip, and an east or west side uses it turned: column r, row y of the
// vertical strip is S at (along = tile_size − 1 − y, across = r). One corner sample K is shared by
// every tile corner, as in planar sets, but made invariant under quarter turns so that the strip ends
// agree both ways and polycube corners (three or five tile corners) see the same corner from every
// side. Within `border` of a side a tile then depends on that side's colour and axis only, and within
// `border` of a corner not at all: an atlas of the set (image/axis_wang_atlas.hpp) samples exactly
// across every quad border of a polycube.
//
// The set is six complete planar sets, one per face: face f's is the planar nh × nv set with nh =
// colours of its first axis, nv = of its second, in complete_tile_index order, so the planar set is
// the special case and every planar tool (compose_tiles, build_wang_atlas) applies to one face.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/image_buffer.hpp"
#include "../core/image_view.hpp"
#include "../core/status.hpp"
#include "../tiling/axis_tile_set.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "../tiling/tile_set_edges.hpp"
#include "detail/wang_edge_samples.hpp"
#include "wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN

/// A complete three-axis image Wang tile set: 2 (nX² nY² + nX² nZ² + nY² nZ²) square tiles, numbered
/// as tiling/axis_tile_set.hpp numbers them (face by face, +X first). Made by build_axis_wang_tiles or
/// the checked create(); immutable; thread-safe reads.
template <Channel T, int C>
class axis_wang_tile_set {
 public:
  /// An empty set (size() == 0).
  axis_wang_tile_set() = default;

  /// Wraps six planar sets, one per cube face: face f's must be the complete set of
  /// (colours of f's first axis) × (of its second) colours in complete_tile_index order, all of one
  /// tile size. Errors: invalid colour counts (naming the axis), a face set of other colour counts,
  /// incomplete or out of order (naming the face), tile sizes that differ. O(tiles).
  static result<axis_wang_tile_set> create(const axis_color_counts& colors, std::array<wang_tile_set<T, C>, 6> faces) {
    if (auto s = validate_axis_color_counts(colors); !s)
      return status(s.code(), detail::cat("axis_wang_tile_set: ", s.message()));
    for (int f = 0; f < cube_faces; ++f) {
      const auto& set = faces[detail::to_size(f)];
      const auto ax = cube_face_axes(f);
      const int nh = colors[detail::to_size(ax[0])], nv = colors[detail::to_size(ax[1])];
      if (set.size() != complete_tile_count(nh, nv) || set.edges().horizontal_colors() != nh ||
          set.edges().vertical_colors() != nv)
        return status::invalid_argument(detail::cat("axis_wang_tile_set: face ", cube_face_name(f), " holds ",
                                                    set.size(), " tiles of ", set.edges().horizontal_colors(), " x ",
                                                    set.edges().vertical_colors(), " colours, expected the complete ",
                                                    nh, " x ", nv, " set"));
      for (index_t i = 0; i < set.size(); ++i)
        if (set.edges()[i] != complete_tile_edges(i, nh, nv))
          return status::invalid_argument(detail::cat("axis_wang_tile_set: tile ", i, " of face ", cube_face_name(f),
                                                      " is not the complete set's tile ", i));
      if (set.tile_size() != faces[0].tile_size())
        return status::invalid_argument(detail::cat("axis_wang_tile_set: face ", cube_face_name(f), " has tiles of ",
                                                    set.tile_size(), " pixels, face +X of ", faces[0].tile_size()));
    }
    axis_wang_tile_set out;
    out.colors_ = colors;
    out.faces_ = std::move(faces);
    return out;
  }

  /// {nX, nY, nZ}; {0, 0, 0} for an empty set.
  [[nodiscard]] const axis_color_counts& axis_colors() const noexcept { return colors_; }
  /// Number of tiles: axis_tile_count(axis_colors()), 0 when empty.
  [[nodiscard]] index_t size() const noexcept {
    index_t n = 0;
    for (const auto& f : faces_) n += f.size();
    return n;
  }
  /// Side of every tile in pixels.
  [[nodiscard]] index_t tile_size() const noexcept { return faces_[0].tile_size(); }
  /// The planar set of one face (0..5: +X, -X, +Y, -Y, +Z, -Z). Precondition: 0 <= face < 6.
  [[nodiscard]] const wang_tile_set<T, C>& face_set(int face) const noexcept { return faces_[detail::to_size(face)]; }
  /// Face and edge colours of tile i (axis_tile_at). Precondition: 0 <= i < size().
  [[nodiscard]] axis_tile tile_info(index_t i) const noexcept { return axis_tile_at(i, colors_); }
  /// Tile i as a read-only view, in its face's frame. Precondition: 0 <= i < size().
  [[nodiscard]] image_view<const T, C> tile(index_t i) const noexcept {
    const int f = tile_info(i).face;
    return faces_[detail::to_size(f)].tile(i - axis_face_first_tile(f, colors_));
  }
  /// The smallest shared border of the six faces (wang_tile_set::shared_border): the depth within
  /// which every tile near a side depends on that side's axis and colour only, and every tile corner
  /// is the same.
  [[nodiscard]] index_t shared_border() const noexcept {
    index_t d = faces_[0].shared_border();
    for (const auto& f : faces_) d = std::min(d, f.shared_border());
    return d;
  }
  /// The mip levels all six faces sample exactly (wang_tile_set::exact_mip_levels).
  [[nodiscard]] int exact_mip_levels() const noexcept {
    int l = faces_[0].exact_mip_levels();
    for (const auto& f : faces_) l = std::min(l, f.exact_mip_levels());
    return l;
  }

 private:
  axis_color_counts colors_ = {0, 0, 0};
  std::array<wang_tile_set<T, C>, 6> faces_;
};

namespace detail {
/// The vertical strip (2·ov × ts) of an east or west side made from strip `s` (ts × 2·ov, along +axis
/// in x): column r, row y = s at (ts − 1 − y, r), so the strip still runs towards +axis in the tile's
/// frame, whose rows run along its second axis backwards.
template <Channel T, int C>
image_buffer<T, C> turned_strip(const image_buffer<T, C>& s) {
  const index_t ts = s.width(), w = s.height();
  image_buffer<T, C> v(w, ts);
  for (index_t y = 0; y < ts; ++y)
    for (index_t r = 0; r < w; ++r) std::memcpy(v.pixel_ptr(r, y), s.pixel_ptr(ts - 1 - y, r), sizeof(T) * C);
  return v;
}
}  // namespace detail

/// Builds the complete three-axis image Wang tile set for `colors` = {nX, nY, nZ} from `exemplar`
/// (Fu & Leung 2005 with paper 000 §3's frame + interior pipeline, see the file comment): one corner
/// sample, invariant under quarter turns; one edge sample per (axis, colour), nX + nY + nZ in all,
/// each used by every face whose plane contains its axis; then every tile framed by its four samples
/// in its face's frame and quilted (constrained, the border fixed), as build_wang_tiles does.
///
/// - options: as for build_wang_tiles (tile size, mip levels, quilting sizes, tolerance, seed,
///   progress); horizontal_colors and vertical_colors are not read, `tiles` must be empty (the set is
///   always complete). mip_levels = 0 with border = 0 means 2 here (1 for odd tile sizes): a 4 x 4
///   corner sample, since a larger symmetric one shows as a pinwheel at every tile corner.
/// - exec: strips and tiles in parallel; the output is bit-identical for any executor.
/// Errors: colour counts outside [1, 4096] (naming the axis); a non-empty options.tiles; and every
/// error of build_wang_tiles about sizes, the exemplar, tolerance, cancellation and set size.
/// Complexity: as build_wang_tiles with 2 (nX² nY² + nX² nZ² + nY² nZ²) tiles and nX + nY + nZ strips.
/// Thread safety: reads `exemplar` only.
template <Image E, Executor X = serial_executor>
[[nodiscard]] result<axis_wang_tile_set<channel_t<E>, channels_v<E>>> build_axis_wang_tiles(
    const E& exemplar, const axis_color_counts& colors, const wang_tile_options& options = {}, X&& exec = {}) {
  using T = channel_t<E>;
  constexpr int C = channels_v<E>;
  if (auto s =
          detail::validate_quilt_extent(exemplar, "exemplar", max_quilt_exemplar_pixels, "max_quilt_exemplar_pixels");
      !s)
    return s;
  if (auto s = validate_axis_color_counts(colors); !s)
    return status(s.code(), detail::cat("build_axis_wang_tiles: ", s.message()));
  if (!options.tiles.empty())
    return status::invalid_argument(
        "build_axis_wang_tiles: options.tiles must be empty (a three-axis set is always complete)");
  // The quarter-turn-symmetric corner sample is a visible pinwheel when large: unless told otherwise,
  // keep it 4 x 4 (2 exact mip levels; bilinear sampling at level 0 needs a border of 1 only).
  wang_tile_options o = options;
  if (o.mip_levels == 0 && o.border == 0) o.mip_levels = o.tile_size % 2 == 0 ? 2 : 1;
  auto sizes = detail::resolve_wang_sizes(o, width_of(exemplar), height_of(exemplar));
  if (!sizes) return sizes.error();
  const index_t count = axis_tile_count(colors);
  if (auto s = detail::validate_tile_set_extent(count, sizes->tile, sizeof(T) * C); !s) return s;
  auto ctx = detail::prepare_wang_build(exemplar, o, count);
  if (!ctx) return ctx.error();
  const index_t ts = ctx->sizes.tile;
  std::array<wang_tile_set<T, C>, 6> faces;
  for (int f = 0; f < cube_faces; ++f) {
    const auto ax = cube_face_axes(f);
    auto edges = tile_set_edges::complete(colors[detail::to_size(ax[0])], colors[detail::to_size(ax[1])]);
    if (!edges) return edges.error();
    auto set = detail::wang_tile_set_access::allocate<T, C>(std::move(*edges), ts);
    if (!set) return set.error();
    faces[detail::to_size(f)] = std::move(*set);
  }
  if (!options.progress.report(0.0, "wang tiles")) return status::cancelled();
  // Edge extraction: K (quarter-turn symmetric) and nX + nY + nZ strips along +axis, all of one
  // direction so they are chosen distinct from each other.
  const int total = colors[0] + colors[1] + colors[2];
  detail::wang_frame_samples<T, C> all;
  if (auto s = detail::build_frame_samples(ctx->src, ts, ctx->sizes.overlap, ctx->sizes.border, total, 0, ctx->prm,
                                           options.tolerance, exec, all, true);
      !s)
    return s;
  // per face: north/south sides from its first axis' strips, east/west from its second's, turned
  std::array<detail::wang_frame_samples<T, C>, 6> frames;
  for (int f = 0; f < cube_faces; ++f) {
    const auto ax = cube_face_axes(f);
    auto& fr = frames[detail::to_size(f)];
    fr.ts = ts;
    fr.ov = all.ov;
    fr.border = all.border;
    fr.corner = all.corner;
    auto first_strip = [&](int axis) { return axis == 0 ? 0 : axis == 1 ? colors[0] : colors[0] + colors[1]; };
    for (int c = 0; c < colors[detail::to_size(ax[0])]; ++c)
      fr.horizontal.push_back(all.horizontal[detail::to_size(first_strip(ax[0]) + c)]);
    for (int c = 0; c < colors[detail::to_size(ax[1])]; ++c)
      fr.vertical.push_back(detail::turned_strip(all.horizontal[detail::to_size(first_strip(ax[1]) + c)]));
  }
  auto split = [&](index_t t) {
    const int f = axis_tile_at(t, colors).face;
    return std::pair<int, index_t>{f, t - axis_face_first_tile(f, colors)};
  };
  if (auto s = detail::build_framed_tiles(
          *ctx, count, [&](index_t t) { return axis_tile_at(t, colors).edges; },
          [&](index_t t) -> const detail::wang_frame_samples<T, C>& { return frames[detail::to_size(split(t).first)]; },
          [&](index_t t) {
            const auto [f, i] = split(t);
            return detail::wang_tile_set_access::tile_data(faces[detail::to_size(f)], i);
          },
          options.progress, exec);
      !s)
    return s;
  for (auto& f : faces) detail::wang_tile_set_access::finish(f);
  return axis_wang_tile_set<T, C>::create(colors, std::move(faces));
}

TESSERA_NAMESPACE_END
