// tessera/geometry/detail/mesh_clip.hpp: splitting a triangle mesh by an axis-aligned plane (shared,
// bit-identical cut vertices on both halves, exactly on the plane), boundary loops, and capping planar
// boundary loops by ear clipping. Used to cut edge strips out of an exemplar (§3.1 of paper 000) and
// to close elements clipped at a patch or strip boundary.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// The two halves of a split: `below` keeps p[axis] <= value, `above` keeps p[axis] >= value.
struct plane_split {
  tri_mesh below, above;
};

/// Splits `m` by the plane p[axis] = value. Vertices within `snap` of the plane are moved onto it.
/// New vertices on cut edges get p[axis] = value exactly, and the same position in both halves.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
plane_split split_mesh_by_plane(const tri_mesh& m, int axis, double value, double snap = 0) {
  const std::size_t nv = m.positions.size();
  std::vector<double> s(nv);
  std::vector<vec3> pos = m.positions;
  for (std::size_t v = 0; v < nv; ++v) {
    s[v] = pos[v][axis] - value;
    if (std::abs(s[v]) <= snap) {
      s[v] = 0;
      pos[v][axis] = value;
    }
  }
  plane_split out;
  std::vector<index_t> map_below(nv, -1), map_above(nv, -1);
  std::map<std::pair<index_t, index_t>, std::pair<index_t, index_t>> cut;  // edge -> (below id, above id)
  auto vid = [&](tri_mesh& h, std::vector<index_t>& map, index_t v) {
    auto& id = map[to_size(v)];
    if (id < 0) id = h.add_vertex(pos[to_size(v)]);
    return id;
  };
  auto cut_vertex = [&](index_t a, index_t b, bool above) {
    const auto key = std::minmax(a, b);
    auto it = cut.find({key.first, key.second});
    if (it == cut.end()) {
      const vec3 pa = pos[to_size(key.first)], pb = pos[to_size(key.second)];
      const double sa = s[to_size(key.first)], sb = s[to_size(key.second)];
      vec3 p = pa + (pb - pa) * (sa / (sa - sb));
      p[axis] = value;
      it = cut.insert({{key.first, key.second}, {out.below.add_vertex(p), out.above.add_vertex(p)}}).first;
    }
    return above ? it->second.second : it->second.first;
  };
  for (const auto& f : m.faces) {
    const double d[3] = {s[to_size(f[0])], s[to_size(f[1])], s[to_size(f[2])]};
    const bool any_pos = d[0] > 0 || d[1] > 0 || d[2] > 0, any_neg = d[0] < 0 || d[1] < 0 || d[2] < 0;
    if (!any_neg) {  // all >= 0 (all on the plane counts as above)
      out.above.add_face(vid(out.above, map_above, f[0]), vid(out.above, map_above, f[1]),
                         vid(out.above, map_above, f[2]));
      continue;
    }
    if (!any_pos) {
      out.below.add_face(vid(out.below, map_below, f[0]), vid(out.below, map_below, f[1]),
                         vid(out.below, map_below, f[2]));
      continue;
    }
    // rotate so that corner r is on the plane (then the other two lie on opposite sides) or alone on its side
    int r = -1;
    for (int k = 0; k < 3; ++k)
      if (d[k] == 0) r = k;
    if (r < 0)
      for (int k = 0; k < 3; ++k)
        if ((d[k] > 0) != (d[(k + 1) % 3] > 0) && (d[k] > 0) != (d[(k + 2) % 3] > 0)) r = k;
    const index_t v0 = f[to_size(r)], v1 = f[to_size((r + 1) % 3)], v2 = f[to_size((r + 2) % 3)];
    const double d0 = d[r], d1 = d[(r + 1) % 3];
    if (d0 == 0) {
      // v0 on the plane, v1 and v2 on opposite sides: one triangle each side
      const bool v1_above = d1 > 0;
      tri_mesh& h1 = v1_above ? out.above : out.below;
      tri_mesh& h2 = v1_above ? out.below : out.above;
      auto& m1 = v1_above ? map_above : map_below;
      auto& m2 = v1_above ? map_below : map_above;
      const index_t c1 = cut_vertex(v1, v2, v1_above), c2 = cut_vertex(v1, v2, !v1_above);
      h1.add_face(vid(h1, m1, v0), vid(h1, m1, v1), c1);
      h2.add_face(vid(h2, m2, v0), c2, vid(h2, m2, v2));
      continue;
    }
    // v0 alone on one side, v1 and v2 strictly on the other: a triangle and a quad
    const bool v0_above = d0 > 0;
    tri_mesh& solo = v0_above ? out.above : out.below;
    tri_mesh& pair = v0_above ? out.below : out.above;
    auto& ms = v0_above ? map_above : map_below;
    auto& mp = v0_above ? map_below : map_above;
    solo.add_face(vid(solo, ms, v0), cut_vertex(v0, v1, v0_above), cut_vertex(v0, v2, v0_above));
    const index_t a_p = cut_vertex(v0, v1, !v0_above), b_p = cut_vertex(v0, v2, !v0_above);
    pair.add_face(a_p, vid(pair, mp, v1), vid(pair, mp, v2));
    pair.add_face(a_p, vid(pair, mp, v2), b_p);
  }
  return out;
}

/// Boundary loops of a mesh, each as vertex ids in the direction of the boundary half-edges (as they
/// run in their faces). Returns false when a boundary vertex has several outgoing boundary
/// half-edges (a non-manifold boundary) or the boundary does not close.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool boundary_loops(const tri_mesh& m, std::vector<std::vector<index_t>>& loops) {
  loops.clear();
  std::map<std::pair<index_t, index_t>, int> he;
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) ++he[{f[to_size(k)], f[to_size((k + 1) % 3)]}];
  std::map<index_t, index_t> next;
  for (const auto& [e, count] : he) {
    if (he.count({e.second, e.first})) continue;
    if (count != 1) return false;
    if (!next.insert({e.first, e.second}).second) return false;
  }
  while (!next.empty()) {
    std::vector<index_t> loop;
    index_t v = next.begin()->first;
    const index_t start = v;
    do {
      auto it = next.find(v);
      if (it == next.end()) return false;
      loop.push_back(v);
      v = it->second;
      next.erase(it);
    } while (v != start);
    loops.push_back(std::move(loop));
  }
  return true;
}

/// Triangulates the planar polygon `poly` (2D points, simple, either winding) by ear clipping.
/// Emits index triples into `poly` with the same winding as the polygon. Returns false for a
/// polygon it cannot triangulate (self-intersecting or degenerate).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool ear_clip(const std::vector<vec2>& poly, std::vector<std::array<index_t, 3>>& tris) {
  const auto n = static_cast<index_t>(poly.size());
  if (n < 3) return false;
  double area2 = 0;
  for (index_t i = 0; i < n; ++i) area2 += cross(poly[to_size(i)], poly[to_size((i + 1) % n)]);
  if (!(std::abs(area2) > 0)) return false;
  const double sign = area2 > 0 ? 1.0 : -1.0;
  std::vector<index_t> idx(to_size(n));
  for (index_t i = 0; i < n; ++i) idx[to_size(i)] = i;
  auto P = [&](index_t i) { return poly[to_size(i)]; };
  std::size_t guard = 0;
  while (idx.size() > 3) {
    bool clipped = false;
    const std::size_t m = idx.size();
    // pick the best ear (largest minimum angle proxy: smallest |cross| ratio) for well shaped caps
    double best_q = -1;
    std::size_t best_i = m;
    for (std::size_t i = 0; i < m; ++i) {
      const index_t a = idx[(i + m - 1) % m], b = idx[i], c = idx[(i + 1) % m];
      const double turn = sign * cross(P(b) - P(a), P(c) - P(b));
      if (turn <= 0) continue;  // reflex or flat
      bool empty = true;
      for (std::size_t j = 0; j < m && empty; ++j) {
        const index_t q = idx[j];
        if (q == a || q == b || q == c) continue;
        const vec2 p = P(q);
        if (P(q) == P(a) || P(q) == P(b) || P(q) == P(c)) continue;
        const double c1 = sign * cross(P(b) - P(a), p - P(a)), c2 = sign * cross(P(c) - P(b), p - P(b)),
                     c3 = sign * cross(P(a) - P(c), p - P(c));
        if (c1 >= 0 && c2 >= 0 && c3 >= 0) empty = false;
      }
      if (!empty) continue;
      const double l = std::max({norm(P(b) - P(a)), norm(P(c) - P(b)), norm(P(a) - P(c))});
      const double q = turn / (l * l);
      if (q > best_q) {
        best_q = q;
        best_i = i;
      }
    }
    if (best_i < m) {
      const std::size_t i = best_i;
      tris.push_back({idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped || ++guard > to_size(4 * n)) return false;
  }
  tris.push_back({idx[0], idx[1], idx[2]});
  return true;
}

/// Closes every boundary loop of `m` whose vertices all lie on the plane p[axis] = value with a
/// planar cap (ear clipping), oriented consistently with the adjacent faces. Loops elsewhere are left
/// alone. Returns false (leaving `m` unchanged) when a loop on the plane cannot be capped: nested
/// loops, a self-intersecting section, or a non-manifold boundary. `capped` counts the caps added.
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
bool cap_plane_loops(tri_mesh& m, int axis, double value, index_t* capped = nullptr) {
  std::vector<std::vector<index_t>> loops;
  if (!boundary_loops(m, loops)) return false;
  const int a0 = axis == 0 ? 1 : 0, a1 = axis == 2 ? 1 : 2;
  std::vector<std::vector<index_t>> on_plane;
  for (auto& l : loops) {
    bool all = true;
    for (index_t v : l) all = all && m.positions[to_size(v)][axis] == value;
    if (all) on_plane.push_back(l);
  }
  // nested loops (holes) are not supported
  auto inside = [&](vec2 p, const std::vector<index_t>& l) {
    bool in = false;
    for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++) {
      const vec3 pi = m.positions[to_size(l[i])], pj = m.positions[to_size(l[j])];
      if ((pi[a1] > p.y) != (pj[a1] > p.y) && p.x < (pj[a0] - pi[a0]) * (p.y - pi[a1]) / (pj[a1] - pi[a1]) + pi[a0])
        in = !in;
    }
    return in;
  };
  for (std::size_t i = 0; i < on_plane.size(); ++i)
    for (std::size_t j = 0; j < on_plane.size(); ++j)
      if (i != j) {
        const vec3 p = m.positions[to_size(on_plane[i][0])];
        if (inside({p[a0], p[a1]}, on_plane[j])) return false;
      }
  std::vector<std::array<index_t, 3>> added;
  for (const auto& l : on_plane) {
    // the cap runs the loop backwards so that its half-edges oppose the boundary half-edges
    std::vector<index_t> rev(l.rbegin(), l.rend());
    std::vector<vec2> poly;
    for (index_t v : rev) poly.push_back({m.positions[to_size(v)][a0], m.positions[to_size(v)][a1]});
    std::vector<std::array<index_t, 3>> tris;
    if (!ear_clip(poly, tris)) return false;
    for (const auto& t : tris) added.push_back({rev[to_size(t[0])], rev[to_size(t[1])], rev[to_size(t[2])]});
  }
  for (const auto& t : added) m.add_face(t[0], t[1], t[2]);
  if (capped) *capped += static_cast<index_t>(on_plane.size());
  return true;
}

/// Removes vertices no face uses, renumbering faces; returns the old -> new map (-1 for removed).
template <class Deferred = void>  // compiled only where used (see docs/architecture.md)
std::vector<index_t> compact_vertices(tri_mesh& m) {
  std::vector<index_t> map(m.positions.size(), -1);
  std::vector<vec3> pos;
  for (auto& f : m.faces)
    for (auto& v : f) {
      auto& id = map[to_size(v)];
      if (id < 0) {
        id = static_cast<index_t>(pos.size());
        pos.push_back(m.positions[to_size(v)]);
      }
      v = id;
    }
  m.positions = std::move(pos);
  return map;
}

}  // namespace detail
TESSERA_NAMESPACE_END
