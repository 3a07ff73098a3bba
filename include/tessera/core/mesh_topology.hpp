// tessera/core/mesh_topology.hpp: connectivity of any Mesh: undirected edges with their faces, face
// adjacency across edges, boundary and non-manifold edges, connected components (a geometric
// texture's "elements"). All deterministic: edges are sorted by vertex pair, components numbered in
// order of their first face. They expect a valid mesh (validate_mesh) but never read or write out of
// bounds on an invalid one: a face naming a vertex outside [0, V) is ignored (not an edge, no
// component), so a bad index costs a wrong answer about that face, never memory safety.
#pragma once

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>
#include <vector>

#include "config.hpp"
#include "mesh.hpp"

TESSERA_NAMESPACE_BEGIN

/// One undirected edge (v0 < v1) and the faces using it. `faces` lists (face, corner k) pairs: the
/// edge is the face's side from corner k to corner k + 1 (mod 3).
struct mesh_edge {
  /// The edge's two vertices, v0 < v1.
  index_t v0 = 0, v1 = 0;
  /// The faces using the edge, as (face, corner) pairs.
  std::vector<std::array<index_t, 2>> faces;
  /// True when one face uses the edge.
  [[nodiscard]] bool is_boundary() const noexcept { return faces.size() == 1; }
  /// True when at most two faces use the edge.
  [[nodiscard]] bool is_manifold() const noexcept { return faces.size() <= 2; }
};

namespace detail {
struct half_edge_key {
  index_t a, b;  // vertex pair, a < b
  index_t f;
  int k;
};
/// All 3F face sides keyed by their sorted vertex pair, sorted by (a, b, f, k): one flat array, so
/// the edge queries below cost one sort and no per-edge allocation. Faces out of range are skipped.
template <Mesh M>
std::vector<half_edge_key> sorted_half_edges(const M& m) {
  const index_t nv = tessera::num_vertices(m), nf = std::max<index_t>(0, tessera::num_faces(m));
  std::vector<half_edge_key> hs;
  hs.reserve(to_size(3 * nf));
  for (index_t f = 0; f < nf; ++f) {
    if (!face_in_range(m, f, nv)) continue;
    const index_t v[3] = {tessera::face_vertex(m, f, 0), tessera::face_vertex(m, f, 1), tessera::face_vertex(m, f, 2)};
    for (int k = 0; k < 3; ++k) {
      const index_t a = v[k], b = v[(k + 1) % 3];
      hs.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  }
  std::sort(hs.begin(), hs.end(), [](const half_edge_key& x, const half_edge_key& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.f != y.f ? x.f < y.f : x.k < y.k;
  });
  return hs;
}
/// Calls fn(first, count) for each run of half-edges sharing a vertex pair (one undirected edge).
template <class F>
void for_each_edge_group(const std::vector<half_edge_key>& hs, F&& fn) {
  for (std::size_t i = 0; i < hs.size();) {
    std::size_t j = i + 1;
    while (j < hs.size() && hs[j].a == hs[i].a && hs[j].b == hs[i].b) ++j;
    fn(i, j - i);
    i = j;
  }
}
}  // namespace detail

/// All undirected edges, sorted by (v0, v1); each edge's faces sorted by (face, corner).
/// O(F log F) time; allocates one small vector per edge (use face_adjacency or boundary_edges when
/// only those are needed: they avoid the per-edge allocations).
template <Mesh M>
std::vector<mesh_edge> mesh_edges(const M& m) {
  const auto hs = detail::sorted_half_edges(m);
  std::vector<mesh_edge> edges;
  edges.reserve(hs.size() / 2 + 1);
  detail::for_each_edge_group(hs, [&](std::size_t first, std::size_t count) {
    mesh_edge e{hs[first].a, hs[first].b, {}};
    e.faces.reserve(count);
    for (std::size_t i = first; i < first + count; ++i) e.faces.push_back({hs[i].f, static_cast<index_t>(hs[i].k)});
    edges.push_back(std::move(e));
  });
  return edges;
}

/// Face adjacency: `neighbor[f][k]` is the face across side k of face f (corner k to k + 1), or -1
/// on a boundary or non-manifold edge. Also counts boundary edges (one face) and non-manifold edges
/// (three or more faces).
struct face_adjacency_result {
  /// neighbor[f][k]: the face across side k of face f, or -1 (boundary or non-manifold edge).
  std::vector<std::array<index_t, 3>> neighbor;
  /// Edges with one face.
  index_t boundary_edges = 0;
  /// Edges with more than two faces.
  index_t nonmanifold_edges = 0;
};

/// Computes face adjacency of a valid mesh. O(F log F) time, O(F) memory.
template <Mesh M>
face_adjacency_result face_adjacency(const M& m) {
  face_adjacency_result r;
  r.neighbor.assign(detail::to_size(std::max<index_t>(0, tessera::num_faces(m))), {-1, -1, -1});
  const auto hs = detail::sorted_half_edges(m);
  detail::for_each_edge_group(hs, [&](std::size_t first, std::size_t count) {
    if (count == 2) {
      const auto& a = hs[first];
      const auto& b = hs[first + 1];
      r.neighbor[detail::to_size(a.f)][detail::to_size(a.k)] = b.f;
      r.neighbor[detail::to_size(b.f)][detail::to_size(b.k)] = a.f;
    } else if (count == 1) {
      ++r.boundary_edges;
    } else {
      ++r.nonmanifold_edges;
    }
  });
  return r;
}

/// Boundary edges (used by exactly one face) as vertex pairs oriented as in their face, listed in
/// (face, side) order. O(F log F).
template <Mesh M>
std::vector<std::array<index_t, 2>> boundary_edges(const M& m) {
  const auto hs = detail::sorted_half_edges(m);
  std::vector<std::array<index_t, 2>> found;  // (face, side)
  detail::for_each_edge_group(hs, [&](std::size_t first, std::size_t count) {
    if (count == 1) found.push_back({hs[first].f, static_cast<index_t>(hs[first].k)});
  });
  std::sort(found.begin(), found.end());
  for (auto& fs : found) {
    const int k = static_cast<int>(fs[1]);
    fs = {tessera::face_vertex(m, fs[0], k), tessera::face_vertex(m, fs[0], (k + 1) % 3)};
  }
  return found;
}

/// Number of edges shared by more than two faces. O(F log F).
template <Mesh M>
index_t count_nonmanifold_edges(const M& m) {
  index_t n = 0;
  detail::for_each_edge_group(detail::sorted_half_edges(m),
                              [&](std::size_t, std::size_t count) { n += count > 2 ? 1 : 0; });
  return n;
}

/// Connected components through shared vertices. Component ids run 0..count-1 in order of each
/// component's first face; vertices used by no face get -1 (so do faces out of range).
struct mesh_components {
  /// Number of connected components.
  index_t count = 0;
  /// Component of each vertex (0 to count - 1).
  std::vector<index_t> vertex_component;
  /// Component of each face (0 to count - 1).
  std::vector<index_t> face_component;
};

/// Connected components of a valid mesh by union-find. O(F alpha(V)) time, O(V + F) memory.
template <Mesh M>
mesh_components connected_components(const M& m) {
  const index_t nv = std::max<index_t>(0, tessera::num_vertices(m)), nf = std::max<index_t>(0, tessera::num_faces(m));
  std::vector<index_t> parent(detail::to_size(nv));
  std::iota(parent.begin(), parent.end(), index_t{0});
  auto find = [&](index_t v) {
    while (parent[detail::to_size(v)] != v) {
      auto& p = parent[detail::to_size(v)];
      p = parent[detail::to_size(p)];  // path halving
      v = p;
    }
    return v;
  };
  std::vector<index_t> size(detail::to_size(nv), 1);
  for (index_t f = 0; f < nf; ++f) {
    if (!detail::face_in_range(m, f, nv)) continue;
    for (int k = 1; k < 3; ++k) {
      index_t a = find(tessera::face_vertex(m, f, 0)), b = find(tessera::face_vertex(m, f, k));
      if (a == b) continue;
      if (size[detail::to_size(a)] < size[detail::to_size(b)]) std::swap(a, b);
      parent[detail::to_size(b)] = a;  // union by size
      size[detail::to_size(a)] += size[detail::to_size(b)];
    }
  }
  mesh_components c;
  c.vertex_component.assign(detail::to_size(nv), -1);
  c.face_component.assign(detail::to_size(nf), -1);
  std::vector<index_t> root_id(detail::to_size(nv), -1);
  for (index_t f = 0; f < nf; ++f) {
    if (!detail::face_in_range(m, f, nv)) continue;
    auto& id = root_id[detail::to_size(find(tessera::face_vertex(m, f, 0)))];
    if (id < 0) id = c.count++;
    c.face_component[detail::to_size(f)] = id;
    for (int k = 0; k < 3; ++k) c.vertex_component[detail::to_size(tessera::face_vertex(m, f, k))] = id;
  }
  return c;
}

TESSERA_NAMESPACE_END
