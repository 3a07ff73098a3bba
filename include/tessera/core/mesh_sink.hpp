// tessera/core/mesh_sink.hpp: meshes written straight into an engine's vertex and index buffers.
// A mesh_sink<Scalar, Index> writes positions as float or double (x, y, z at a byte offset inside
// each vertex record, records a byte stride apart, so interleaved vertex formats fit; unaligned
// offsets are fine, positions are stored with memcpy) and indices as uint16 or uint32, three per
// face. The buffers are either the caller's own, of fixed size (make_mesh_sink), or grown by a
// caller callback that can hand out memory from any allocator (make_growing_mesh_sink). Before
// anything is written the sink is told the vertex and face counts (prepare): a count that 16-bit
// indices cannot address, or buffers too short for it, is a status naming the count and the
// limit, and nothing is written. No write ever goes past a buffer.
//
// write_mesh() writes any Mesh into a sink; tile_geometric_plane and geometric_plane_layout::write
// (geometry/tile_geometric_plane.hpp) write tiled planes into a sink without building a tri_mesh.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "mesh.hpp"
#include "status.hpp"
#include "vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// Where positions sit in a vertex record, in bytes: x, y, z are consecutive Scalars starting
/// `offset` bytes into each record, and records are `stride` bytes apart (0: packed, 3 Scalars).
struct vertex_layout {
  std::size_t offset = 0;  ///< bytes from a record's start to its x
  std::size_t stride = 0;  ///< bytes from one record to the next; 0 = 3 * sizeof(Scalar)
};

/// The two buffers of a mesh_sink: `vertex_bytes` bytes of vertex records and `index_count` indices.
template <class Index>
struct mesh_buffers {
  void* vertices = nullptr;      ///< vertex records (positions written at the layout's offset)
  std::size_t vertex_bytes = 0;  ///< size of the vertex buffer in bytes
  Index* indices = nullptr;      ///< three indices per face
  std::size_t index_count = 0;   ///< size of the index buffer in indices (not faces, not bytes)
};

/// Writes a mesh into caller buffers (see the file comment). Build it with make_mesh_sink() or
/// make_growing_mesh_sink(). Writers call prepare(vertices, faces) once, then set_position and
/// set_face for every vertex and face (from any threads, each element once).
template <class Scalar = float, class Index = std::uint32_t>
class mesh_sink {
  static_assert(std::is_same_v<Scalar, float> || std::is_same_v<Scalar, double>,
                "mesh_sink positions are float or double");
  static_assert(std::is_same_v<Index, std::uint16_t> || std::is_same_v<Index, std::uint32_t>,
                "mesh_sink indices are uint16_t or uint32_t");

 public:
  using scalar_type = Scalar;  ///< position type written (float or double)
  using index_type = Index;    ///< index type written (uint16_t or uint32_t)
  /// Asked for buffers holding at least `vertex_bytes` bytes and `index_count` indices (their
  /// current contents may be dropped: nothing of the mesh being prepared has been written yet). Returns an error to refuse.
  using grow_function = std::function<status(std::size_t vertex_bytes, std::size_t index_count, mesh_buffers<Index>&)>;
  /// Most vertices a sink takes: 65535 for uint16, 2^32 - 1 for uint32 (the all-ones index stays
  /// unused: it is the primitive-restart index of OpenGL, Vulkan and Direct3D; as in make_mesh_view).
  static constexpr index_t max_vertices = static_cast<index_t>(std::numeric_limits<Index>::max());

  mesh_sink() = default;
  /// Unchecked: use make_mesh_sink() or make_growing_mesh_sink(), which validate the layout.
  explicit mesh_sink(mesh_buffers<Index> buffers, vertex_layout layout = {}, grow_function grow = {})
      : buf_(buffers),
        layout_(layout),
        stride_(layout.stride == 0 ? 3 * sizeof(Scalar) : layout.stride),
        grow_(std::move(grow)) {}

  /// Checks that `vertices` and `faces` fit (index range, buffer sizes, growing them through the
  /// callback when there is one) and records the counts. Errors, with nothing written: negative
  /// counts (invalid_argument); more vertices than Index can address (size_overflow, naming the
  /// count and the limit); buffers too short, or a callback that fails or returns short buffers
  /// (out_of_range, naming the bytes or indices needed and available).
  status prepare(index_t vertices, index_t faces) {
    if (vertices < 0 || faces < 0)
      return status::invalid_argument(
          detail::cat("mesh_sink: counts must be non-negative, got ", vertices, " vertices and ", faces, " faces"));
    if (vertices > max_vertices)
      return status::size_overflow(detail::cat("mesh_sink: ", vertices, " vertices exceed the ", max_vertices, " that ",
                                               8 * sizeof(Index), "-bit indices can address",
                                               sizeof(Index) == 2 ? "; use 32-bit indices or split the mesh" : ""));
    constexpr index_t limit = index_t{1} << 40;
    if (faces > limit || vertices > limit)
      return status::size_overflow(detail::cat("mesh_sink: ", faces, " faces exceed the supported maximum"));
    const std::size_t need_bytes =
        vertices == 0 ? 0 : layout_.offset + detail::to_size(vertices - 1) * stride_ + 3 * sizeof(Scalar);
    const std::size_t need_indices = 3 * detail::to_size(faces);
    if ((need_bytes > buf_.vertex_bytes || need_indices > buf_.index_count) && grow_) {
      mesh_buffers<Index> b = buf_;
      if (auto s = grow_(need_bytes, need_indices, b); !s)
        return status(s.code(), detail::cat("mesh_sink: growing the buffers failed: ", s.message()));
      buf_ = b;
    }
    if (need_bytes > 0 && (buf_.vertices == nullptr || need_bytes > buf_.vertex_bytes))
      return status::out_of_range(detail::cat("mesh_sink: ", vertices, " vertices need ", need_bytes,
                                              " bytes of vertex buffer (offset ", layout_.offset, ", stride ", stride_,
                                              "), the buffer has ", buf_.vertices ? buf_.vertex_bytes : 0));
    if (need_indices > 0 && (buf_.indices == nullptr || need_indices > buf_.index_count))
      return status::out_of_range(detail::cat("mesh_sink: ", faces, " faces need ", need_indices,
                                              " indices, the index buffer has ", buf_.indices ? buf_.index_count : 0));
    vertices_ = vertices;
    faces_ = faces;
    return {};
  }

  /// Stores vertex v's position (converted to Scalar). Precondition: prepare() succeeded, v < num_vertices().
  void set_position(index_t v, const vec3& p) const noexcept {
    TESSERA_ASSERT(v >= 0 && v < vertices_);
    const Scalar xyz[3] = {static_cast<Scalar>(p.x), static_cast<Scalar>(p.y), static_cast<Scalar>(p.z)};
    std::memcpy(static_cast<std::byte*>(buf_.vertices) + layout_.offset + detail::to_size(v) * stride_, xyz,
                sizeof xyz);
  }
  /// Stores face f's three vertex indices. Precondition: prepare() succeeded, f < num_faces(),
  /// every index < num_vertices() (so it fits Index).
  void set_face(index_t f, index_t a, index_t b, index_t c) const noexcept {
    TESSERA_ASSERT(f >= 0 && f < faces_);
    TESSERA_ASSERT(a >= 0 && a < vertices_ && b >= 0 && b < vertices_ && c >= 0 && c < vertices_);
    Index* d = buf_.indices + 3 * f;
    d[0] = static_cast<Index>(a);
    d[1] = static_cast<Index>(b);
    d[2] = static_cast<Index>(c);
  }

  /// Vertex count recorded by the last successful prepare().
  [[nodiscard]] index_t num_vertices() const noexcept { return vertices_; }
  /// Face count recorded by the last successful prepare().
  [[nodiscard]] index_t num_faces() const noexcept { return faces_; }
  /// The buffers written (after growing, the callback's).
  [[nodiscard]] const mesh_buffers<Index>& buffers() const noexcept { return buf_; }
  /// Where positions sit in a vertex record (as given; stride() resolves a 0 stride).
  [[nodiscard]] const vertex_layout& layout() const noexcept { return layout_; }
  /// Bytes from one vertex record to the next (the layout's stride, or 3 * sizeof(Scalar) for 0).
  [[nodiscard]] std::size_t stride() const noexcept { return stride_; }
  /// Reads back vertex v's position (for tests and tools).
  [[nodiscard]] std::array<Scalar, 3> position(index_t v) const noexcept {
    std::array<Scalar, 3> p{};
    std::memcpy(p.data(), static_cast<const std::byte*>(buf_.vertices) + layout_.offset + detail::to_size(v) * stride_,
                sizeof p);
    return p;
  }

 private:
  mesh_buffers<Index> buf_{};
  vertex_layout layout_{};
  std::size_t stride_ = 3 * sizeof(Scalar);
  grow_function grow_;
  index_t vertices_ = 0, faces_ = 0;
};

namespace detail {
template <class Scalar>
status check_vertex_layout(const vertex_layout& layout) {
  const std::size_t stride = layout.stride == 0 ? 3 * sizeof(Scalar) : layout.stride;
  if (layout.offset > (std::size_t{1} << 20) || stride > (std::size_t{1} << 20))
    return status::invalid_argument(
        cat("mesh_sink: vertex offset ", layout.offset, " or stride ", stride, " bytes is implausibly large"));
  if (layout.offset + 3 * sizeof(Scalar) > stride)
    return status::invalid_argument(cat("mesh_sink: positions at byte offset ", layout.offset, " (", 3 * sizeof(Scalar),
                                        " bytes) do not fit a vertex stride of ", stride, " bytes"));
  return {};
}
}  // namespace detail

/// A sink over fixed caller buffers: `vertex_bytes` bytes at `vertices`, `index_count` indices at
/// `indices`. Errors: a layout whose positions (offset + 3 Scalars) do not fit its stride, or an
/// absurd offset or stride (invalid_argument). Buffer sizes are checked by prepare(), when the counts
/// are known; null buffers are accepted for an empty mesh.
template <class Scalar = float, class Index = std::uint32_t>
result<mesh_sink<Scalar, Index>> make_mesh_sink(void* vertices, std::size_t vertex_bytes, Index* indices,
                                                std::size_t index_count, vertex_layout layout = {}) {
  if (auto st = detail::check_vertex_layout<Scalar>(layout); !st) return st;
  return mesh_sink<Scalar, Index>({vertices, vertex_bytes, indices, index_count}, layout);
}

/// A sink whose buffers come from `grow` (called by prepare() when the current ones are too short;
/// it may allocate from any allocator, resize a std::vector, map a GPU buffer...). Errors: a null
/// callback or a bad layout (invalid_argument).
template <class Scalar = float, class Index = std::uint32_t>
result<mesh_sink<Scalar, Index>> make_growing_mesh_sink(typename mesh_sink<Scalar, Index>::grow_function grow,
                                                        vertex_layout layout = {}) {
  if (!grow) return status::invalid_argument("mesh_sink: the grow callback is empty");
  if (auto st = detail::check_vertex_layout<Scalar>(layout); !st) return st;
  return mesh_sink<Scalar, Index>({}, layout, std::move(grow));
}

/// Writes any Mesh into `sink`: prepare(num_vertices, num_faces), then every position and face.
/// Errors: those of prepare(); a face naming a vertex out of range (out_of_range); a non-finite
/// position, or one beyond float's range for a float sink (invalid_argument). All checks run before
/// anything is written. O(V + F). Per-corner uvs are not written (the sink holds positions and indices).
template <Mesh M, class Scalar, class Index>
status write_mesh(const M& mesh, mesh_sink<Scalar, Index>& sink) {
  const index_t nv = num_vertices(mesh), nf = num_faces(mesh);
  for (index_t v = 0; v < nv; ++v) {
    const vec3 p = vertex_position(mesh, v);
    const double lim = static_cast<double>(std::numeric_limits<Scalar>::max());
    if (!is_finite(p) || std::abs(p.x) > lim || std::abs(p.y) > lim || std::abs(p.z) > lim)
      return status::invalid_argument(detail::cat("write_mesh: vertex ", v, " position (", p.x, ", ", p.y, ", ", p.z,
                                                  ") is not finite or beyond the range of ",
                                                  sizeof(Scalar) == 4 ? "float" : "double"));
  }
  for (index_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (const index_t v = face_vertex(mesh, f, k); v < 0 || v >= nv)
        return status::out_of_range(detail::cat("write_mesh: face ", f, " corner ", k, " refers to vertex ", v,
                                                " but the mesh has ", nv, " vertices"));
  if (auto s = sink.prepare(nv, nf); !s) return s;
  for (index_t v = 0; v < nv; ++v) sink.set_position(v, vertex_position(mesh, v));
  for (index_t f = 0; f < nf; ++f)
    sink.set_face(f, face_vertex(mesh, f, 0), face_vertex(mesh, f, 1), face_vertex(mesh, f, 2));
  return {};
}

TESSERA_NAMESPACE_END
