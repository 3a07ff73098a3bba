// tessera/geometry/detail/element_seam.hpp: the mesh plumbing of element merging (paper 000 §3.3.6):
// sub-meshes of the faces a cut keeps, the boundary loops a cut creates, a ladder of triangles joining
// two facing loops, the smoothing of the vertices around the seam, and the join step that runs them
// (join_cut_paths). The seam join is NOT the
// Poisson mesh merging of Yu et al. 2004 that the paper cites: it is a ladder of new triangles between
// the two cut paths, then a few Gauss-Seidel sweeps of uniform-Laplacian smoothing that pull the seam
// ring to the average of its neighbours (delta = 0) and keep the original uniform Laplacian
// coordinates of the rings around it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/mesh_topology.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../bvh.hpp"
#include "../mesh_elements.hpp"
#include "mesh_clip.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

inline vec3 centroid(const tri_mesh& m, index_t f) {
  const auto& t = m.faces[to_size(f)];
  return (m.positions[to_size(t[0])] + m.positions[to_size(t[1])] + m.positions[to_size(t[2])]) / 3.0;
}

/// Keeps the faces with keep[f] != 0; returns the sub-mesh and the old -> new vertex map.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
tri_mesh submesh(const tri_mesh& m, const std::vector<unsigned char>& keep, std::vector<index_t>& map) {
  tri_mesh out;
  map.assign(m.positions.size(), -1);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!keep[f]) continue;
    std::array<index_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const index_t v = m.faces[f][to_size(k)];
      auto& id = map[to_size(v)];
      if (id < 0) id = out.add_vertex(m.positions[to_size(v)]);
      t[to_size(k)] = id;
    }
    out.add_face(t[0], t[1], t[2]);
  }
  return out;
}

/// Boundary edges of `m` as a set of directed pairs.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<std::pair<index_t, index_t>> boundary_edge_set(const tri_mesh& m) {
  std::vector<std::pair<index_t, index_t>> e;
  for (const auto& b : boundary_edges(m)) e.push_back({std::min(b[0], b[1]), std::max(b[0], b[1])});
  std::sort(e.begin(), e.end());
  return e;
}

/// The boundary loops of a kept part that the cut created (`loops` of the part, `map` from the
/// original mesh to the part). Loops made only of the original's boundary edges are left out; a loop
/// mixing both makes the cut unusable (returns false). `out` may alias `loops`.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool cut_loops(const tri_mesh& original, const std::vector<index_t>& map,
               const std::vector<std::vector<index_t>>& loops, std::vector<std::vector<index_t>>& out) {
  const std::vector<std::pair<index_t, index_t>> orig = boundary_edge_set(original);
  std::vector<index_t> back;
  for (std::size_t v = 0; v < map.size(); ++v)
    if (map[v] >= 0) {
      if (back.size() <= to_size(map[v])) back.resize(to_size(map[v]) + 1);
      back[to_size(map[v])] = static_cast<index_t>(v);
    }
  std::vector<std::vector<index_t>> kept;
  for (const auto& l : loops) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
      const index_t a = back[to_size(l[i])], b = back[to_size(l[(i + 1) % l.size()])];
      n += std::binary_search(orig.begin(), orig.end(), std::pair{std::min(a, b), std::max(a, b)}) ? 1 : 0;
    }
    if (n == l.size()) continue;
    if (n != 0) return false;
    kept.push_back(l);
  }
  out = std::move(kept);
  return true;
}

/// True when any two faces of `m` that share no vertex intersect.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool self_intersects(const tri_mesh& m) {
  const triangle_bvh bvh(m);
  bool hit = false;
  bvh.for_each_self_intersection(
      [&](index_t f, index_t g) {
        if (hit) return true;
        const auto& a = m.faces[to_size(f)];
        const auto& b = m.faces[to_size(g)];
        for (index_t x : a)
          for (index_t y : b)
            if (x == y) return true;
        return false;
      },
      [&](index_t, index_t) { hit = true; });
  return hit;
}

inline vec3 vector_area(const tri_mesh& m, const std::vector<index_t>& loop) {
  vec3 a;
  for (std::size_t i = 0; i < loop.size(); ++i)
    a += cross(m.positions[to_size(loop[i])], m.positions[to_size(loop[(i + 1) % loop.size()])]);
  return a * 0.5;
}

// Joins loop a (ids in `m`, running as the boundary half-edges of its side) to loop b (same, other
// side) with a ladder of triangles, choosing the shorter diagonal at each step.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
void stitch_loops(tri_mesh& m, const std::vector<index_t>& a, std::vector<index_t> b) {
  std::reverse(b.begin(), b.end());
  const std::size_t na = a.size(), nb = b.size();
  std::size_t start = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < nb; ++k) {
    const double d = squared_norm(m.positions[to_size(b[k])] - m.positions[to_size(a[0])]);
    if (d < best) {
      best = d;
      start = k;
    }
  }
  auto A = [&](std::size_t i) { return a[i % na]; };
  auto B = [&](std::size_t k) { return b[(start + k) % nb]; };
  auto P = [&](index_t v) { return m.positions[to_size(v)]; };
  std::size_t i = 0, k = 0;
  while (i < na || k < nb) {
    const bool adv_a =
        k == nb || (i < na && squared_norm(P(A(i + 1)) - P(B(k))) <= squared_norm(P(A(i)) - P(B(k + 1))));
    if (adv_a) {
      m.add_face(A(i + 1), A(i), B(k));
      ++i;
    } else {
      m.add_face(B(k), B(k + 1), A(i));
      ++k;
    }
  }
}

/// Smooths the `rings` vertex rings around `seam` (ids in out.mesh): Gauss-Seidel sweeps of
/// uniform-Laplacian smoothing, v = average(neighbours) + delta, with delta = 0 on the seam itself and
/// the original uniform Laplacian coordinate elsewhere (details kept). Fixed vertices and the border
/// vertices of `domain` (§3.3.5) stay put; `rings` < 0 smooths nothing. O(sweeps * ring size).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
void smooth_seam(texture_element& out, const std::vector<index_t>& seam_vertices, const xy_rect& domain, int rings) {
  if (rings < 0) return;
  const std::size_t nv = out.mesh.positions.size();
  std::vector<std::vector<index_t>> nbr(nv);
  for (const auto& f : out.mesh.faces)
    for (int k = 0; k < 3; ++k) {
      nbr[to_size(f[to_size(k)])].push_back(f[to_size((k + 1) % 3)]);
      nbr[to_size(f[to_size((k + 1) % 3)])].push_back(f[to_size(k)]);
    }
  for (auto& n : nbr) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  std::vector<int> ring(nv, -1);
  std::vector<index_t> frontier = seam_vertices;
  for (index_t v : frontier) ring[to_size(v)] = 0;
  for (int r = 1; r <= rings; ++r) {
    std::vector<index_t> next;
    for (index_t v : frontier)
      for (index_t w : nbr[to_size(v)])
        if (ring[to_size(w)] < 0) {
          ring[to_size(w)] = r;
          next.push_back(w);
        }
    frontier = std::move(next);
  }
  const auto bverts = border_vertices(out, domain);
  std::vector<vec3> delta(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    if (ring[v] <= 0 || nbr[v].empty()) continue;
    vec3 avg;
    for (index_t w : nbr[v]) avg += out.mesh.positions[to_size(w)];
    delta[v] = out.mesh.positions[v] - avg / double(nbr[v].size());
  }
  for (int sweep = 0; sweep < 30; ++sweep)
    for (std::size_t v = 0; v < nv; ++v) {
      if (ring[v] < 0 || out.fixed[v] || bverts[v] || nbr[v].empty()) continue;
      vec3 avg;
      for (index_t w : nbr[v]) avg += out.mesh.positions[to_size(w)];
      out.mesh.positions[v] = avg / double(nbr[v].size()) + delta[v];
    }
}

/// The join of §3.3.6 (a ladder of triangles, not the paper's Poisson merging; see the file
/// comment): the kept parts of both elements in one element, each new boundary loop of C_T
/// stitched to the nearest loop of C_in (greedy by centroid distance; opposite orientation
/// required), the seam relaxed over `smooth_rings` rings. Fixed flags follow the kept vertices,
/// B(C) = B(C_T) u B(C_in). Nothing when the cut paths do not pair up. Counts seams into `seams`.
template <class Deferred = void>
std::optional<texture_element> join_cut_paths(const texture_element& ct, const tri_mesh& t,
                                              const std::vector<unsigned char>& keep_t, const texture_element& cin,
                                              const tri_mesh& in, const std::vector<unsigned char>& keep_in,
                                              const xy_rect& domain, int smooth_rings, index_t* seams) {
  std::vector<index_t> map_t, map_in;
  const tri_mesh kt = submesh(t, keep_t, map_t), ki = submesh(in, keep_in, map_in);
  std::vector<std::vector<index_t>> loops_t, loops_in;
  if (!boundary_loops(kt, loops_t) || !boundary_loops(ki, loops_in)) return std::nullopt;
  // loops that were already boundary before the cut (tile-border cuts) stay open
  std::vector<std::vector<index_t>> new_t;
  if (!cut_loops(t, map_t, loops_t, new_t) || !cut_loops(in, map_in, loops_in, loops_in)) return std::nullopt;
  if (new_t.empty() || new_t.size() != loops_in.size()) return std::nullopt;
  texture_element out;
  out.mesh = kt;
  const auto base = static_cast<index_t>(kt.positions.size());
  out.mesh.append(ki);
  out.fixed.assign(out.mesh.positions.size(), 0);
  for (std::size_t v = 0; v < map_t.size(); ++v)
    if (map_t[v] >= 0 && v < ct.fixed.size() && ct.fixed[v]) out.fixed[to_size(map_t[v])] = 1;
  for (std::size_t v = 0; v < map_in.size(); ++v)
    if (map_in[v] >= 0 && v < cin.fixed.size() && cin.fixed[v]) out.fixed[to_size(base + map_in[v])] = 1;
  out.border = ct.border | cin.border;  // B(C) = B(C1) u B(C2)
  auto loop_centroid = [&](const std::vector<index_t>& l, index_t off) {
    vec3 c;
    for (index_t v : l) c += out.mesh.positions[to_size(v + off)];
    return c / double(l.size());
  };
  std::vector<std::tuple<double, std::size_t, std::size_t>> cand;
  for (std::size_t i = 0; i < new_t.size(); ++i)
    for (std::size_t j = 0; j < loops_in.size(); ++j)
      cand.push_back({norm(loop_centroid(new_t[i], 0) - loop_centroid(loops_in[j], base)), i, j});
  std::sort(cand.begin(), cand.end());
  std::vector<unsigned char> used_t(new_t.size(), 0), used_in(loops_in.size(), 0);
  std::vector<index_t> seam_vertices;
  for (const auto& [d, i, j] : cand) {
    if (used_t[i] || used_in[j]) continue;
    used_t[i] = used_in[j] = 1;
    std::vector<index_t> b = loops_in[j];
    for (index_t& v : b) v += base;
    if (dot(vector_area(out.mesh, new_t[i]), vector_area(out.mesh, b)) >= 0) return std::nullopt;
    stitch_loops(out.mesh, new_t[i], b);
    seam_vertices.insert(seam_vertices.end(), new_t[i].begin(), new_t[i].end());
    seam_vertices.insert(seam_vertices.end(), b.begin(), b.end());
    if (seams) ++*seams;
  }
  smooth_seam(out, seam_vertices, domain, smooth_rings);
  return out;
}

}  // namespace detail
TESSERA_NAMESPACE_END
