// tessera/terrain/detail/anchored_vertex_table.hpp: the coordinate of each vertex in each placement
// of a region while it grows (synthesize_anchored_region.hpp) and while it is relaxed
// (relax_anchored_region.hpp). A placement's faces read their corners from it, so they agree bit
// for bit on every shared corner however often a coordinate is moved.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// The coordinate of each vertex in each placement of the region being grown. Vertices are
/// numbered in the region (anchored_face_geometry::vertices); a vertex has a short list of entries
/// (placement, coordinate), usually one (more where it lies on a seam between placements), linked
/// from `head`. Entries are numbered in insertion order, their coordinates (double) stored densely,
/// with the number of faces whose corner they are. Kept per thread between calls.
class anchored_vertex_table {
 public:
  /// Empties the table for `vertices` region vertices.
  void reset(std::size_t vertices) {
    head_.assign(vertices, -1);
    coords_.clear();
    patch_.clear();
    next_.clear();
    uses_.clear();
  }
  /// The entry of region vertex v in placement p, or -1.
  [[nodiscard]] std::int32_t find(std::int32_t v, std::int32_t p) const noexcept {
    for (std::int32_t e = head_[to_size(v)]; e >= 0; e = next_[to_size(e)])
      if (patch_[to_size(e)] == p) return e;
    return -1;
  }
  /// Inserts (v, p) (not yet present) with coordinate c, used by no face yet; returns its entry.
  std::int32_t insert(std::int32_t v, std::int32_t p, vec2 c) {
    const auto e = static_cast<std::int32_t>(coords_.size());
    coords_.push_back(c);
    patch_.push_back(p);
    next_.push_back(head_[to_size(v)]);
    uses_.push_back(0);
    head_[to_size(v)] = e;
    return e;
  }
  /// The coordinate of entry e.
  [[nodiscard]] const vec2& coord(std::int32_t e) const noexcept { return coords_[to_size(e)]; }
  /// The corners of a face whose corners are entries `e`, rounded to float as the atlas holds them
  /// (u0 v0 u1 v1 u2 v2); corner `moved` (0..2; -1 none) first displaced by d.
  [[nodiscard]] std::array<float, 6> face_uv(const std::array<std::int32_t, 3>& e, int moved = -1,
                                             vec2 d = {0, 0}) const noexcept {
    std::array<float, 6> t;
    for (std::size_t k = 0; k < 3; ++k) {
      const vec2 c = static_cast<int>(k) == moved ? coord(e[k]) + d : coord(e[k]);
      t[2 * k] = static_cast<float>(c.x), t[2 * k + 1] = static_cast<float>(c.y);
    }
    return t;
  }
  /// Moves entry e to c (every face using it follows).
  void move(std::int32_t e, vec2 c) noexcept { coords_[to_size(e)] = c; }
  /// Counts one more face corner using entry e.
  void use(std::int32_t e) noexcept { ++uses_[to_size(e)]; }
  /// Face corners using entry e.
  [[nodiscard]] std::int32_t uses(std::int32_t e) const noexcept { return uses_[to_size(e)]; }
  /// The newest entry of region vertex v (-1: none).
  [[nodiscard]] std::int32_t head(std::int32_t v) const noexcept { return head_[to_size(v)]; }
  /// The entry of the same vertex inserted before e (-1: none).
  [[nodiscard]] std::int32_t next(std::int32_t e) const noexcept { return next_[to_size(e)]; }
  /// Number of entries.
  [[nodiscard]] std::size_t size() const noexcept { return coords_.size(); }

 private:
  std::vector<std::int32_t> head_, patch_, next_, uses_;
  std::vector<vec2> coords_;
};

}  // namespace detail
TESSERA_NAMESPACE_END
