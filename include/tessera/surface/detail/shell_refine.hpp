// tessera/surface/detail/shell_refine.hpp: splits texture-space triangles until their mapped images follow
// the shell (paper 000 §4; the shell-map note: mapping only vertices lets long triangles cut across
// prisms). An edge is split at its texture-space midpoint when the mapped midpoint is farther than the
// chordal tolerance from the chord of its mapped ends, or when its ends lie in prisms of base faces that
// share no vertex; never when it is shorter than min_edge, and never when both ends lie in one
// tetrahedron (the map is affine there). The decision is a function of the edge alone (its two
// vertices), so the two triangles of an edge always agree: the result is conforming, and a closed mesh
// stays closed. A triangle with a split side also splits its longest side (Rivara's longest-edge
// bisection, closed over the mesh in each round), and is cut first across its longest side, so no
// slivers pile up next to kept edges; rounds repeat on the new edges. Midpoints are computed as
// 0.5 (a + b), the same bits in either order.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/executor.hpp"
#include "../../core/vec.hpp"
#include "shell_weld.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// A texture point carried to shell space: its position, the base face of its prism and its
/// tetrahedron there (0..2).
struct shell_mapped_point {
  vec3 x;
  index_t face = -1;
  int tet = 0;
  vec3 bary;  ///< barycentric weights in the base face
};

/// Limits of refine_shell_mesh (mesh units).
struct shell_refine_limits {
  double chordal_tolerance = 0;  ///< largest distance of a mapped edge midpoint from the chord
  double min_edge = 0;           ///< edges shorter than this in texture space are kept
  int max_rounds = 0;            ///< most split rounds
  /// Most triangles (live and replaced) the refinement may make; beyond it refine_shell_mesh stops.
  std::size_t max_triangles = std::size_t{1} << 26;
};

/// What the refinement knows of an edge: its state (undecided, kept, marked, or its midpoint vertex
/// once split) and the live triangles on it.
struct shell_edge_info {
  index_t state = 0;
  std::array<index_t, 2> owner{-1, -1};
};

/// Open-addressing table from edge keys (two vertex ids < 2^31) to dense edge ids 0, 1, 2, ... in
/// order of insertion.
class shell_edge_table {
 public:
  /// The id of `key`, a new one (the count so far) when absent.
  index_t id(std::uint64_t key, bool& inserted) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    std::size_t j = hash(key) & (keys_.size() - 1);
    while (keys_[j] != empty && keys_[j] != key) j = (j + 1) & (keys_.size() - 1);
    inserted = keys_[j] == empty;
    if (inserted) {
      keys_[j] = key;
      ids_[j] = static_cast<index_t>(size_++);
    }
    return ids_[j];
  }

 private:
  void grow() {
    const std::size_t cap = std::max<std::size_t>(64, 2 * keys_.size());
    std::vector<std::uint64_t> keys(cap, empty);
    std::vector<index_t> ids(cap);
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (keys_[i] != empty) {
        std::size_t j = hash(keys_[i]) & (cap - 1);
        while (keys[j] != empty) j = (j + 1) & (cap - 1);
        keys[j] = keys_[i];
        ids[j] = ids_[i];
      }
    keys_.swap(keys);
    ids_.swap(ids);
  }
  static constexpr std::uint64_t empty = ~std::uint64_t{0};
  static std::size_t hash(std::uint64_t x) noexcept {  // splitmix64 finalizer
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    return static_cast<std::size_t>(x ^ (x >> 31));
  }
  std::vector<std::uint64_t> keys_;
  std::vector<index_t> ids_;
  std::size_t size_ = 0;
};

inline bool faces_share_vertex(const std::array<index_t, 3>& a, const std::array<index_t, 3>& b) noexcept {
  for (index_t x : a)
    for (index_t y : b)
      if (x == y) return true;
  return false;
}

/// Refines `faces` in place (see the file comment); `points` and `mapped` grow by the new midpoints.
/// `map_point(texture point, face a, face b)` returns the shell_mapped_point of a texture point (the
/// faces of the edge's ends as hints), `map_in_face(face, bary, h)` that of a point of a known face.
/// Each round looks only at the triangles made in the previous one and at those a longest-edge
/// closure reaches. Returns the number of edges split, or -1 (faces unspecified) when a round would
/// make more than lim.max_triangles triangles. Deterministic for any executor.
template <class MapPoint, class MapInFace, Executor E>
index_t refine_shell_mesh(std::vector<shell_texture_point>& points, std::vector<shell_mapped_point>& mapped,
                          std::vector<std::array<index_t, 3>>& faces,
                          const std::vector<std::array<index_t, 3>>& base_faces, const shell_refine_limits& lim,
                          MapPoint&& map_point, MapInFace&& map_in_face, E& exec) {
  using tri = std::array<index_t, 3>;
  constexpr index_t kept = -1, marked = -2, undecided = 0;  // edge states besides a midpoint id (>= 1)
  auto key_of = [](index_t a, index_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
  };
  auto ends = [](std::uint64_t key) { return std::pair{to_size(key >> 32), to_size(key & 0xffffffffu)}; };
  auto len2 = [&](std::size_t x, std::size_t y) {
    return squared_norm(points[x].p - points[y].p) + (points[x].h - points[y].h) * (points[x].h - points[y].h);
  };
  struct triangle {
    tri v;
    std::array<index_t, 3> slot;  // edge ids of sides k = (v[k], v[k + 1])
    std::int8_t longest = 0;      // longest side in texture space (ties: the smaller key)
    bool alive = true;
  };
  std::vector<triangle> tris;
  shell_edge_table ids;
  std::vector<shell_edge_info> table;  // per edge id
  std::vector<index_t> active, work, splitting;
  std::vector<std::pair<std::uint64_t, index_t>> fresh, closure;
  std::vector<char> split;
  std::vector<shell_texture_point> mid;
  std::vector<shell_mapped_point> mid_mapped;
  index_t splits = 0;
  // registers triangle `t` (replacing `parent` on the edges it inherits)
  auto add_triangle = [&](const tri& v, index_t parent) {
    const auto t = static_cast<index_t>(tris.size());
    triangle x;
    x.v = v;
    double best = -1;
    std::uint64_t best_key = 0;
    for (int k = 0; k < 3; ++k) {
      const index_t a = v[to_size(k)], b = v[to_size((k + 1) % 3)];
      const std::uint64_t key = key_of(a, b);
      bool inserted = false;
      x.slot[to_size(k)] = ids.id(key, inserted);
      if (inserted) {
        table.emplace_back();
        fresh.emplace_back(key, x.slot[to_size(k)]);
      }
      auto& o = table[to_size(x.slot[to_size(k)])].owner;
      if (o[0] == parent && parent >= 0)
        o[0] = t;
      else if (o[1] == parent && parent >= 0)
        o[1] = t;
      else
        o[o[0] < 0 ? 0 : 1] = t;
      const double l = len2(to_size(a), to_size(b));
      if (l > best || (l == best && key < best_key)) {
        best = l;
        best_key = key;
        x.longest = static_cast<std::int8_t>(k);
      }
    }
    tris.push_back(x);
    active.push_back(t);
  };
  auto midpoint = [&](std::uint64_t key) {
    const auto [a, b] = ends(key);
    return shell_texture_point{0.5 * (points[a].p + points[b].p), 0.5 * (points[a].h + points[b].h)};
  };
  // in one prism a midpoint's weights are the mean of the ends' (β is affine on the chart plane)
  auto map_midpoint = [&](std::uint64_t key, const shell_texture_point& m) {
    const auto [a, b] = ends(key);
    const auto &ma = mapped[a], &mb = mapped[b];
    return ma.face == mb.face ? map_in_face(ma.face, 0.5 * (ma.bary + mb.bary), m.h) : map_point(m, ma.face, mb.face);
  };
  auto prepare = [&](std::size_t n, char fill) {  // per-edge scratch of one batch
    split.assign(n, fill);
    mid.resize(n);
    mid_mapped.resize(n);
  };
  auto add_points = [&](const std::vector<std::pair<std::uint64_t, index_t>>& edges) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
      index_t id = kept;
      if (split[i]) {
        id = static_cast<index_t>(points.size());
        points.push_back(mid[i]);
        mapped.push_back(mid_mapped[i]);
        ++splits;
      }
      table[to_size(edges[i].second)].state = id;
    }
  };
  // an edge kept outright: ends in one tetrahedron (the map is affine there) or shorter than min_edge
  const auto trivially_kept = [&](std::size_t a, std::size_t b) {
    return (mapped[a].face == mapped[b].face && mapped[a].tet == mapped[b].tet) ||
           len2(a, b) < lim.min_edge * lim.min_edge;
  };
  // the decision of one edge (a function of its two vertices): split[i] and its midpoint
  auto decide = [&](index_t i, std::uint64_t key) {
    const auto [a, b] = ends(key);
    if (trivially_kept(a, b)) return;
    const auto &ma = mapped[a], &mb = mapped[b];
    const shell_texture_point m = midpoint(key);
    const shell_mapped_point mm = map_midpoint(key, m);
    const bool far =
        ma.face >= 0 && mb.face >= 0 && !faces_share_vertex(base_faces[to_size(ma.face)], base_faces[to_size(mb.face)]);
    if (far || norm(mm.x - 0.5 * (ma.x + mb.x)) > lim.chordal_tolerance) {
      split[to_size(i)] = 1;
      mid[to_size(i)] = m;
      mid_mapped[to_size(i)] = mm;
    }
  };
  if (lim.max_rounds <= 0) return 0;
  // Round 0's decisions first, on the sorted distinct input edges that are not kept outright (ends in
  // two tetrahedra, not shorter than min_edge): when none is split (tiles fine enough for the shell,
  // the common case) the faces stay as they are and the triangle and edge tables below are never
  // built (0.45-0.8x the mapping's time on bench_surface's 655k faces); otherwise round 0 looks these
  // decisions up (the same decisions in the same order as deciding there: the same output).
  constexpr std::uint64_t none = ~std::uint64_t{0};
  std::vector<std::uint64_t> keys0(3 * faces.size());
  exec.parallel_for(0, static_cast<index_t>(faces.size()), [&](index_t f) {
    const tri& v = faces[to_size(f)];
    for (std::size_t k = 0; k < 3; ++k) {
      const index_t a = v[k], b = v[(k + 1) % 3];
      keys0[3 * to_size(f) + k] = trivially_kept(to_size(a), to_size(b)) ? none : key_of(a, b);
    }
  });
  std::sort(keys0.begin(), keys0.end());
  keys0.erase(std::unique(keys0.begin(), keys0.end()), keys0.end());
  if (!keys0.empty() && keys0.back() == none) keys0.pop_back();
  prepare(keys0.size(), 0);
  exec.parallel_for(0, static_cast<index_t>(keys0.size()), [&](index_t i) { decide(i, keys0[to_size(i)]); });
  if (std::find(split.begin(), split.end(), char{1}) == split.end()) return 0;
  std::vector<char> split0;
  std::vector<shell_texture_point> mid0;
  std::vector<shell_mapped_point> mid_mapped0;
  split0.swap(split);
  mid0.swap(mid);
  mid_mapped0.swap(mid_mapped);
  tris.reserve(faces.size());
  for (const tri& v : faces) add_triangle(v, -1);
  for (int round = 0; round < lim.max_rounds && !active.empty(); ++round) {
    // 1. decide the edges not seen before (in parallel; a function of the edge's two vertices)
    std::sort(fresh.begin(), fresh.end());
    prepare(fresh.size(), 0);
    if (round > 0) {
      exec.parallel_for(0, static_cast<index_t>(fresh.size()), [&](index_t i) { decide(i, fresh[to_size(i)].first); });
    } else {  // round 0: decided above (an edge not listed there is kept)
      exec.parallel_for(0, static_cast<index_t>(fresh.size()), [&](index_t i) {
        const auto it = std::lower_bound(keys0.begin(), keys0.end(), fresh[to_size(i)].first);
        if (it == keys0.end() || *it != fresh[to_size(i)].first) return;
        const auto j = static_cast<std::size_t>(it - keys0.begin());
        split[to_size(i)] = split0[j];
        mid[to_size(i)] = mid0[j];
        mid_mapped[to_size(i)] = mid_mapped0[j];
      });
    }
    add_points(fresh);
    fresh.clear();
    // 2. longest-edge closure (Rivara): a triangle with a split side splits its longest side too, so
    // triangles keep their shape; marking an edge sends the triangle across it (even a settled one)
    // to the worklist
    closure.clear();
    splitting.clear();
    work.clear();
    for (const index_t t : active) {
      const auto& x = tris[to_size(t)];
      if (table[to_size(x.slot[0])].state != kept || table[to_size(x.slot[1])].state != kept ||
          table[to_size(x.slot[2])].state != kept)
        work.push_back(t);
    }
    while (!work.empty()) {
      const index_t t = work.back();
      work.pop_back();
      const auto& x = tris[to_size(t)];
      splitting.push_back(t);
      const auto sl = to_size(x.slot[to_size(x.longest)]);
      if (table[sl].state != kept) continue;
      table[sl].state = marked;
      closure.emplace_back(key_of(x.v[to_size(x.longest)], x.v[to_size((x.longest + 1) % 3)]),
                           static_cast<index_t>(sl));
      for (const index_t u : table[sl].owner)
        if (u >= 0 && u != t) work.push_back(u);
    }
    std::sort(closure.begin(), closure.end());
    prepare(closure.size(), 1);
    exec.parallel_for(0, static_cast<index_t>(closure.size()), [&](index_t i) {
      const std::uint64_t key = closure[to_size(i)].first;
      mid[to_size(i)] = midpoint(key);
      mid_mapped[to_size(i)] = map_midpoint(key, mid[to_size(i)]);
    });
    add_points(closure);
    // 3. bisect the longest side, then the other split sides of the two halves (in triangle order)
    std::sort(splitting.begin(), splitting.end());
    splitting.erase(std::unique(splitting.begin(), splitting.end()), splitting.end());
    if (tris.size() + 4 * splitting.size() > lim.max_triangles) return -1;  // at most 4 halves each
    active.clear();
    for (const index_t t : splitting) {
      const triangle x = tris[to_size(t)];
      const int l = x.longest;
      const index_t mab = table[to_size(x.slot[to_size(l)])].state;
      if (mab < 0 || mab == undecided) continue;
      tris[to_size(t)].alive = false;
      const index_t a = x.v[to_size(l)], b = x.v[to_size((l + 1) % 3)], c = x.v[to_size((l + 2) % 3)];
      const index_t mbc = table[to_size(x.slot[to_size((l + 1) % 3)])].state;
      const index_t mca = table[to_size(x.slot[to_size((l + 2) % 3)])].state;
      if (mbc > 0) {
        add_triangle({mab, b, mbc}, t);
        add_triangle({mab, mbc, c}, t);
      } else {
        add_triangle({mab, b, c}, t);
      }
      if (mca > 0) {
        add_triangle({a, mab, mca}, t);
        add_triangle({mab, c, mca}, t);
      } else {
        add_triangle({a, mab, c}, t);
      }
    }
  }
  faces.clear();
  for (const auto& x : tris)
    if (x.alive) faces.push_back(x.v);
  return splits;
}

}  // namespace detail
TESSERA_NAMESPACE_END
