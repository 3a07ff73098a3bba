// tessera/core/mesh_view.hpp: a non-owning triangle mesh over raw buffers, the way engines keep
// them: positions as float or double (x, y, z first in each vertex record, records `position_stride`
// scalars apart, so interleaved vertex buffers fit), 16- or 32-bit indices three per face, and optional
// per-corner uvs (two floats per corner, six per face). Models Mesh and UVMesh.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "config.hpp"
#include "mesh.hpp"
#include "status.hpp"

TESSERA_NAMESPACE_BEGIN

/// Non-owning triangle mesh over an engine's raw buffers (see the file comment). Build it with
/// make_mesh_view(), which validates counts, stride and index range; the constructor does not (like
/// std::span). Never copies or modifies the buffers.
template <class Scalar = float, class Index = std::uint32_t>
class mesh_view {
  static_assert(std::is_same_v<Scalar, float> || std::is_same_v<Scalar, double>,
                "mesh_view positions are float or double");
  static_assert(std::is_same_v<Index, std::uint32_t> || std::is_same_v<Index, std::int32_t> ||
                    std::is_same_v<Index, std::uint16_t>,
                "mesh_view indices are uint16_t, uint32_t or int32_t");

 public:
  mesh_view() = default;
  /// Unchecked: use make_mesh_view() to validate caller-supplied buffers.
  mesh_view(const Scalar* positions, index_t vertex_count, const Index* indices, index_t face_count,
            const float* corner_uvs = nullptr, index_t position_stride = 3) noexcept
      : positions_(positions),
        indices_(indices),
        uvs_(corner_uvs),
        num_vertices_(vertex_count),
        num_faces_(face_count),
        stride_(position_stride) {}

  /// Vertex count.
  [[nodiscard]] index_t num_vertices() const noexcept { return num_vertices_; }
  /// Face (triangle) count.
  [[nodiscard]] index_t num_faces() const noexcept { return num_faces_; }
  /// Vertex index of corner k (0..2) of face f.
  [[nodiscard]] index_t face_vertex(index_t f, int k) const noexcept {
    return static_cast<index_t>(indices_[3 * f + k]);
  }
  /// Position of vertex v.
  [[nodiscard]] std::array<Scalar, 3> position(index_t v) const noexcept {
    const Scalar* p = positions_ + v * stride_;
    return {p[0], p[1], p[2]};
  }
  /// True when per-corner texture coordinates were given.
  [[nodiscard]] bool has_uvs() const noexcept { return uvs_ != nullptr; }
  /// Texture coordinate of corner k of face f.
  [[nodiscard]] std::array<float, 2> corner_uv(index_t f, int k) const noexcept {
    const float* t = uvs_ + 6 * f + 2 * k;
    return {t[0], t[1]};
  }
  /// The caller's position buffer.
  [[nodiscard]] const Scalar* positions() const noexcept { return positions_; }
  /// The caller's index buffer.
  [[nodiscard]] const Index* indices() const noexcept { return indices_; }
  /// Scalars from one vertex to the next in the position buffer.
  [[nodiscard]] index_t position_stride() const noexcept { return stride_; }

 private:
  const Scalar* positions_ = nullptr;
  const Index* indices_ = nullptr;
  const float* uvs_ = nullptr;
  index_t num_vertices_ = 0;
  index_t num_faces_ = 0;
  index_t stride_ = 3;
};

/// Validates raw buffers and returns a view: non-negative counts, non-null pointers for non-zero
/// counts (`corner_uvs` may be null: no uvs), `position_stride` >= 3, a vertex count that `Index` can
/// address and buffer lengths whose element counts fit index_t. Index ranges, NaN positions and
/// degenerate faces are checked by validate_mesh() (core/tri_mesh.hpp), since that reads every element.
template <class Scalar, class Index>
result<mesh_view<Scalar, Index>> make_mesh_view(const Scalar* positions, index_t vertex_count, const Index* indices,
                                                index_t face_count, const float* corner_uvs = nullptr,
                                                index_t position_stride = 3) {
  if (vertex_count < 0 || face_count < 0)
    return status::invalid_argument(detail::cat("mesh_view: counts must be non-negative, got ", vertex_count,
                                                " vertices and ", face_count, " faces"));
  if (position_stride < 3)
    return status::invalid_argument(
        detail::cat("mesh_view: position_stride must be at least 3, got ", position_stride));
  constexpr auto index_limit = static_cast<index_t>(std::numeric_limits<Index>::max());
  if (vertex_count > index_limit)
    return status::size_overflow(detail::cat("mesh_view: ", vertex_count, " vertices exceed what ", 8 * sizeof(Index),
                                             "-bit indices can address (", index_limit, ")"));
  if (vertex_count > std::numeric_limits<index_t>::max() / position_stride)
    return status::size_overflow(
        detail::cat("mesh_view: ", vertex_count, " vertices x position_stride ", position_stride, " overflows"));
  if (face_count > std::numeric_limits<index_t>::max() / 6)
    return status::size_overflow(detail::cat("mesh_view: ", face_count, " faces overflow the index type"));
  if (vertex_count > 0 && positions == nullptr)
    return status::invalid_argument(detail::cat("mesh_view: positions is null for ", vertex_count, " vertices"));
  if (face_count > 0 && indices == nullptr)
    return status::invalid_argument(detail::cat("mesh_view: indices is null for ", face_count, " faces"));
  return mesh_view<Scalar, Index>(positions, vertex_count, indices, face_count, corner_uvs, position_stride);
}

TESSERA_NAMESPACE_END
