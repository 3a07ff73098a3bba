// tessera/terrain/prepare_terrain_mesh.hpp: the per-mesh preparation of terrain synthesis (paper
// 003), done once and reused every frame: flat vertex and face arrays, face centroids (the points
// whose view distance is D_i, step 1 of §2.2) and face adjacency across edges (the neighbours of
// steps 2 and 5 of §2.2 and of the stack order of §2.3).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// A triangle mesh prepared for per-frame terrain synthesis. Plain data, read-only after
/// preparation (share it between threads and frames freely).
struct terrain_mesh {
  std::vector<vec3> positions;                     ///< per vertex
  std::vector<std::array<std::int32_t, 3>> faces;  ///< three vertex indices per face
  std::vector<vec3> centroids;                     ///< per face
  /// neighbors[f][k]: the face across side k of f (corner k to corner k + 1), -1 on a boundary
  /// edge or an edge shared by more than two faces (non-manifold edges separate their faces).
  std::vector<std::array<std::int32_t, 3>> neighbors;
  index_t boundary_edges = 0;     ///< edges with one face
  index_t nonmanifold_edges = 0;  ///< edges with three or more faces
  index_t interior_edges = 0;     ///< edges with exactly two faces

  /// Vertex count.
  [[nodiscard]] index_t num_vertices() const noexcept { return static_cast<index_t>(positions.size()); }
  /// Face count.
  [[nodiscard]] index_t num_faces() const noexcept { return static_cast<index_t>(faces.size()); }
  /// Vertex index of corner k (0..2) of face f.
  [[nodiscard]] index_t face_vertex(index_t f, int k) const noexcept {
    return faces[detail::to_size(f)][detail::to_size(k)];
  }
  /// Position of vertex v.
  [[nodiscard]] const vec3& position(index_t v) const noexcept { return positions[detail::to_size(v)]; }
};

namespace detail {
/// Face adjacency in O(V + F): each undirected edge is filed under its smaller vertex (a CSR list),
/// and the faces filed under the same (vertex, other vertex) pair are the faces of that edge.
template <class Deferred = void>  // compiled only where meshes are prepared (see docs/architecture.md)
void build_terrain_adjacency(terrain_mesh& m) {
  const auto nv = to_size(m.num_vertices()), nf = to_size(m.num_faces());
  std::vector<std::int32_t> start(nv + 1, 0);
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) ++start[to_size(std::min(f[to_size(k)], f[to_size((k + 1) % 3)])) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  struct half {
    std::int32_t other, face_side;
  };
  std::vector<half> hs(3 * nf);
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = m.faces[f][to_size(k)], b = m.faces[f][to_size((k + 1) % 3)];
      hs[to_size(fill[to_size(std::min(a, b))]++)] = {std::max(a, b), static_cast<std::int32_t>(3 * f) + k};
    }
  m.neighbors.assign(nf, {-1, -1, -1});
  m.boundary_edges = m.nonmanifold_edges = m.interior_edges = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    half* first = hs.data() + start[v];
    half* last = hs.data() + start[v + 1];
    std::sort(first, last, [](const half& x, const half& y) {
      return x.other != y.other ? x.other < y.other : x.face_side < y.face_side;
    });
    for (half* i = first; i != last;) {
      half* j = i;
      while (j != last && j->other == i->other) ++j;
      if (j - i == 2) {
        m.neighbors[to_size(i[0].face_side / 3)][to_size(i[0].face_side % 3)] = i[1].face_side / 3;
        m.neighbors[to_size(i[1].face_side / 3)][to_size(i[1].face_side % 3)] = i[0].face_side / 3;
        ++m.interior_edges;
      } else if (j - i == 1) {
        ++m.boundary_edges;
      } else {
        ++m.nonmanifold_edges;
      }
      i = j;
    }
  }
}
}  // namespace detail

namespace detail {
/// O(1) part of validate_terrain_mesh: the per-face arrays have one entry per face.
inline status check_terrain_mesh_sizes(const terrain_mesh& m) {
  const std::size_t nf = m.faces.size();
  if (m.centroids.size() != nf || m.neighbors.size() != nf)
    return status::invalid_argument(detail::cat("terrain_mesh has ", nf, " faces but ", m.centroids.size(),
                                                " centroids and ", m.neighbors.size(),
                                                " neighbour triples: build it with prepare_terrain_mesh"));
  constexpr std::size_t limit = std::numeric_limits<std::int32_t>::max() / 3;
  if (nf > limit || m.positions.size() > limit)
    return status::size_overflow(
        detail::cat("terrain_mesh: ", m.positions.size(), " vertices / ", nf, " faces exceed ", limit));
  return {};
}
/// Whether n names a face of a mesh of nf faces (neighbour entries are -1 or a face).
inline bool is_face_index(std::int32_t n, index_t nf) noexcept { return n >= 0 && n < nf; }
/// The structural problem of face f (vertex indices, neighbours, centroid), or ok.
inline status terrain_face_problem(const terrain_mesh& m, index_t f) {
  const auto i = to_size(f);
  const index_t nv = m.num_vertices(), nf = m.num_faces();
  for (std::size_t k = 0; k < 3; ++k) {
    if (m.faces[i][k] < 0 || m.faces[i][k] >= nv)
      return status::out_of_range(
          detail::cat("terrain_mesh face ", f, " corner ", k, " names vertex ", m.faces[i][k], " of ", nv));
    if (m.neighbors[i][k] < -1 || m.neighbors[i][k] >= nf)
      return status::out_of_range(detail::cat("terrain_mesh face ", f, " side ", k, " names neighbour ",
                                              m.neighbors[i][k], " of ", nf, " faces (-1 for none)"));
  }
  if (!is_finite(m.centroids[i]))
    return status::invalid_argument(detail::cat("terrain_mesh face ", f, " has a non-finite centroid"));
  return {};
}
}  // namespace detail

/// Checks a terrain_mesh filled or changed by hand (prepare_terrain_mesh's output always passes):
/// one centroid and one neighbour triple per face, vertex indices in range, neighbours -1 or a
/// face, finite positions and centroids. project_mesh runs the same checks (folded into its own
/// passes); the later stages check sizes and never index through an out-of-range neighbour.
/// Errors: invalid_argument / out_of_range naming the array, the element and the value (the
/// smallest bad index). O(V + F); thread-safe.
inline status validate_terrain_mesh(const terrain_mesh& m) {
  if (auto s = detail::check_terrain_mesh_sizes(m); !s) return s;
  for (index_t v = 0; v < m.num_vertices(); ++v)
    if (!is_finite(m.position(v)))
      return status::invalid_argument(detail::cat("terrain_mesh vertex ", v, " is not finite"));
  for (index_t f = 0; f < m.num_faces(); ++f)
    if (auto s = detail::terrain_face_problem(m, f); !s) return s;
  return {};
}

/// Prepares any Mesh for terrain synthesis: validates it (finite positions, indices in range, no
/// face repeating a vertex), copies it into flat arrays, computes face centroids and face adjacency.
/// Errors: invalid_argument / out_of_range from validation, size_overflow beyond 2^31 - 1 vertices
/// or faces. An empty mesh is valid (every later stage then reports it). O(V + F) time and memory.
/// Thread-safe (reads `mesh` only).
template <Mesh M>
result<terrain_mesh> prepare_terrain_mesh(const M& mesh, std::string_view what = "mesh") {
  if (auto s = validate_mesh(mesh, what); !s) return s;
  const index_t nv = num_vertices(mesh), nf = num_faces(mesh);
  constexpr index_t limit = std::numeric_limits<std::int32_t>::max() / 3;
  if (nv > limit || nf > limit)
    return status::size_overflow(
        detail::cat(what, ": ", nv, " vertices / ", nf, " faces exceed the terrain limit of ", limit));
  terrain_mesh m;
  m.positions.resize(detail::to_size(nv));
  for (index_t v = 0; v < nv; ++v) m.positions[detail::to_size(v)] = vertex_position(mesh, v);
  m.faces.resize(detail::to_size(nf));
  m.centroids.resize(detail::to_size(nf));
  for (index_t f = 0; f < nf; ++f) {
    auto& face = m.faces[detail::to_size(f)];
    for (int k = 0; k < 3; ++k) face[detail::to_size(k)] = static_cast<std::int32_t>(face_vertex(mesh, f, k));
    m.centroids[detail::to_size(f)] = (m.position(face[0]) + m.position(face[1]) + m.position(face[2])) * (1.0 / 3.0);
  }
  detail::build_terrain_adjacency(m);
  return m;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_prepare_terrain_mesh.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
