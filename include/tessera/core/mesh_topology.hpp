// tessera/core/mesh_topology.hpp: connectivity of any Mesh: undirected edges with their faces, face
// adjacency across edges, boundary and non-manifold edges, connected components (a geometric
// texture's "elements"). All deterministic: edges are sorted by vertex pair, components numbered in
// order of their first face. Inputs must be valid (validate_mesh); these functions do not re-check.
#pragma once

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include "config.hpp"
#include "mesh.hpp"

TESSERA_NAMESPACE_BEGIN

/// One undirected edge (v0 < v1) and the faces using it. `faces` lists (face, corner k) pairs: the
/// edge is the face's side from corner k to corner k + 1 (mod 3).
struct mesh_edge {
  index_t v0 = 0, v1 = 0;
  std::vector<std::array<index_t, 2>> faces;
  [[nodiscard]] bool is_boundary() const noexcept { return faces.size() == 1; }
  [[nodiscard]] bool is_manifold() const noexcept { return faces.size() <= 2; }
};

/// All undirected edges, sorted by (v0, v1). O(F log F).
template <Mesh M>
std::vector<mesh_edge> mesh_edges(const M& m) {
  struct half {
    index_t a, b, f;
    int k;
  };
  std::vector<half> hs;
  hs.reserve(static_cast<std::size_t>(3 * num_faces(m)));
  for (index_t f = 0; f < num_faces(m); ++f)
    for (int k = 0; k < 3; ++k) {
      const index_t a = face_vertex(m, f, k), b = face_vertex(m, f, (k + 1) % 3);
      hs.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  std::sort(hs.begin(), hs.end(), [](const half& x, const half& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.f != y.f ? x.f < y.f : x.k < y.k;
  });
  std::vector<mesh_edge> edges;
  for (std::size_t i = 0; i < hs.size();) {
    mesh_edge e{hs[i].a, hs[i].b, {}};
    for (; i < hs.size() && hs[i].a == e.v0 && hs[i].b == e.v1; ++i) e.faces.push_back({hs[i].f, hs[i].k});
    edges.push_back(std::move(e));
  }
  return edges;
}

/// Face adjacency: `neighbor[f][k]` is the face across side k of face f (corner k to k + 1), or -1
/// on a boundary or non-manifold edge.
struct face_adjacency_result {
  std::vector<std::array<index_t, 3>> neighbor;
  index_t boundary_edges = 0;
  index_t nonmanifold_edges = 0;
};

template <Mesh M>
face_adjacency_result face_adjacency(const M& m) {
  face_adjacency_result r;
  r.neighbor.assign(static_cast<std::size_t>(num_faces(m)), {-1, -1, -1});
  for (const mesh_edge& e : mesh_edges(m)) {
    if (e.faces.size() == 2) {
      const auto a = e.faces[0], b = e.faces[1];
      r.neighbor[static_cast<std::size_t>(a[0])][static_cast<std::size_t>(a[1])] = b[0];
      r.neighbor[static_cast<std::size_t>(b[0])][static_cast<std::size_t>(b[1])] = a[0];
    } else if (e.faces.size() == 1) {
      ++r.boundary_edges;
    } else {
      ++r.nonmanifold_edges;
    }
  }
  return r;
}

/// Boundary edges (used by exactly one face), oriented as in their face, in (face, side) order.
template <Mesh M>
std::vector<std::array<index_t, 2>> boundary_edges(const M& m) {
  std::vector<std::array<index_t, 2>> found;  // (face, side)
  for (const mesh_edge& e : mesh_edges(m))
    if (e.is_boundary()) found.push_back(e.faces[0]);
  std::sort(found.begin(), found.end());
  std::vector<std::array<index_t, 2>> out;
  out.reserve(found.size());
  for (const auto& fs : found) {
    const int k = static_cast<int>(fs[1]);
    out.push_back({face_vertex(m, fs[0], k), face_vertex(m, fs[0], (k + 1) % 3)});
  }
  return out;
}

/// Number of edges shared by more than two faces.
template <Mesh M>
index_t count_nonmanifold_edges(const M& m) {
  index_t n = 0;
  for (const mesh_edge& e : mesh_edges(m)) n += e.is_manifold() ? 0 : 1;
  return n;
}

/// Connected components through shared vertices. Component ids run 0..count-1 in order of each
/// component's first face; vertices used by no face get -1.
struct mesh_components {
  index_t count = 0;
  std::vector<index_t> vertex_component;
  std::vector<index_t> face_component;
};

template <Mesh M>
mesh_components connected_components(const M& m) {
  const index_t nv = num_vertices(m), nf = num_faces(m);
  std::vector<index_t> parent(static_cast<std::size_t>(nv));
  std::iota(parent.begin(), parent.end(), index_t{0});
  auto find = [&](index_t v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
      auto& p = parent[static_cast<std::size_t>(v)];
      p = parent[static_cast<std::size_t>(p)];  // path halving
      v = p;
    }
    return v;
  };
  for (index_t f = 0; f < nf; ++f) {
    for (int k = 1; k < 3; ++k) {
      const index_t a = find(face_vertex(m, f, 0)), b = find(face_vertex(m, f, k));
      if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  }
  mesh_components c;
  c.vertex_component.assign(static_cast<std::size_t>(nv), -1);
  c.face_component.resize(static_cast<std::size_t>(nf));
  std::vector<index_t> root_id(static_cast<std::size_t>(nv), -1);
  for (index_t f = 0; f < nf; ++f) {
    auto& id = root_id[static_cast<std::size_t>(find(face_vertex(m, f, 0)))];
    if (id < 0) id = c.count++;
    c.face_component[static_cast<std::size_t>(f)] = id;
    for (int k = 0; k < 3; ++k) c.vertex_component[static_cast<std::size_t>(face_vertex(m, f, k))] = id;
  }
  return c;
}

TESSERA_NAMESPACE_END
