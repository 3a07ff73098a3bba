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
#include <unordered_map>
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
};

/// Limits of refine_shell_mesh (mesh units).
struct shell_refine_limits {
  double chordal_tolerance = 0;  ///< largest distance of a mapped edge midpoint from the chord
  double min_edge = 0;           ///< edges shorter than this in texture space are kept
  int max_rounds = 0;            ///< most split rounds
};

inline bool faces_share_vertex(const std::array<index_t, 3>& a, const std::array<index_t, 3>& b) noexcept {
  for (index_t x : a)
    for (index_t y : b)
      if (x == y) return true;
  return false;
}

/// Refines `faces` in place (see the file comment); `points` and `mapped` grow by the new midpoints.
/// `map_point(texture point)` returns the shell_mapped_point of a texture point. Returns the number of
/// edges split. Deterministic for any executor.
template <class MapPoint, Executor E>
index_t refine_shell_mesh(std::vector<shell_texture_point>& points, std::vector<shell_mapped_point>& mapped,
                          std::vector<std::array<index_t, 3>>& faces,
                          const std::vector<std::array<index_t, 3>>& base_faces, const shell_refine_limits& lim,
                          MapPoint&& map_point, E& exec) {
  using tri = std::array<index_t, 3>;
  auto key_of = [](index_t a, index_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
  };
  auto len2 = [&](index_t x, index_t y) {
    const auto &px = points[to_size(x)], &py = points[to_size(y)];
    return squared_norm(px.p - py.p) + (px.h - py.h) * (px.h - py.h);
  };
  // the longest side of a triangle in texture space (ties: the smaller edge key), a function of the
  // triangle's vertex set only
  auto longest = [&](const tri& t) {
    int best = 0;
    double bl = -1;
    std::uint64_t bk = 0;
    for (int k = 0; k < 3; ++k) {
      const double l = len2(t[to_size(k)], t[to_size((k + 1) % 3)]);
      const std::uint64_t key = key_of(t[to_size(k)], t[to_size((k + 1) % 3)]);
      if (l > bl || (l == bl && key < bk)) {
        best = k;
        bl = l;
        bk = key;
      }
    }
    return best;
  };
  constexpr index_t kept = -1, marked = -2;  // edge states besides a midpoint vertex id
  std::unordered_map<std::uint64_t, index_t> state;
  std::vector<tri> cur, next;
  cur.swap(faces);
  index_t splits = 0;
  std::vector<std::uint64_t> fresh, closure;
  std::vector<char> split;
  std::vector<shell_texture_point> mid;
  std::vector<shell_mapped_point> mid_mapped;
  auto midpoint = [&](std::uint64_t key) {
    const auto &pa = points[to_size(key >> 32)], &pb = points[to_size(key & 0xffffffffu)];
    return shell_texture_point{0.5 * (pa.p + pb.p), 0.5 * (pa.h + pb.h)};
  };
  auto add_points = [&](const std::vector<std::uint64_t>& keys) {
    for (std::size_t i = 0; i < keys.size(); ++i) {
      index_t id = kept;
      if (split[i]) {
        id = static_cast<index_t>(points.size());
        points.push_back(mid[i]);
        mapped.push_back(mid_mapped[i]);
        ++splits;
      }
      state[keys[i]] = id;
    }
  };
  for (int round = 0; round < lim.max_rounds; ++round) {
    // 1. decide the edges not seen before (in parallel; a function of the edge's two vertices)
    fresh.clear();
    for (const tri& t : cur)
      for (int k = 0; k < 3; ++k) {
        const std::uint64_t key = key_of(t[to_size(k)], t[to_size((k + 1) % 3)]);
        if (state.find(key) == state.end()) fresh.push_back(key);
      }
    std::sort(fresh.begin(), fresh.end());
    fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
    split.assign(fresh.size(), 0);
    mid.resize(fresh.size());
    mid_mapped.resize(fresh.size());
    exec.parallel_for(0, static_cast<index_t>(fresh.size()), [&](index_t i) {
      const auto a = to_size(fresh[to_size(i)] >> 32), b = to_size(fresh[to_size(i)] & 0xffffffffu);
      const auto &ma = mapped[a], &mb = mapped[b];
      if (ma.face == mb.face && ma.tet == mb.tet) return;  // one tetrahedron: the map is affine
      if (len2(static_cast<index_t>(a), static_cast<index_t>(b)) < lim.min_edge * lim.min_edge) return;
      const shell_texture_point m = midpoint(fresh[to_size(i)]);
      const shell_mapped_point mm = map_point(m);
      const bool far = ma.face >= 0 && mb.face >= 0 &&
                       !faces_share_vertex(base_faces[to_size(ma.face)], base_faces[to_size(mb.face)]);
      if (far || norm(mm.x - 0.5 * (ma.x + mb.x)) > lim.chordal_tolerance) {
        split[to_size(i)] = 1;
        mid[to_size(i)] = m;
        mid_mapped[to_size(i)] = mm;
      }
    });
    add_points(fresh);
    // 2. longest-edge closure (Rivara): a triangle with a split side splits its longest side too,
    // so triangles keep their shape; repeated until no triangle asks for more
    closure.clear();
    for (bool changed = true; changed;) {
      changed = false;
      for (const tri& t : cur) {
        bool any = false;
        for (int k = 0; k < 3; ++k) any |= state[key_of(t[to_size(k)], t[to_size((k + 1) % 3)])] != kept;
        if (!any) continue;
        const int l = longest(t);
        auto& s = state[key_of(t[to_size(l)], t[to_size((l + 1) % 3)])];
        if (s == kept) {
          s = marked;
          closure.push_back(key_of(t[to_size(l)], t[to_size((l + 1) % 3)]));
          changed = true;
        }
      }
    }
    std::sort(closure.begin(), closure.end());
    split.assign(closure.size(), 1);
    mid.resize(closure.size());
    mid_mapped.resize(closure.size());
    exec.parallel_for(0, static_cast<index_t>(closure.size()), [&](index_t i) {
      mid[to_size(i)] = midpoint(closure[to_size(i)]);
      mid_mapped[to_size(i)] = map_point(mid[to_size(i)]);
    });
    add_points(closure);
    // 3. bisect the longest side, then the other split sides of the two halves
    next.clear();
    bool any_split = false;
    for (const tri& t : cur) {
      const int l = longest(t);
      const index_t a = t[to_size(l)], b = t[to_size((l + 1) % 3)], c = t[to_size((l + 2) % 3)];
      const index_t mab = state[key_of(a, b)];
      if (mab < 0) {
        next.push_back(t);
        continue;
      }
      any_split = true;
      const index_t mbc = state[key_of(b, c)], mca = state[key_of(c, a)];
      if (mbc >= 0) {
        next.push_back({mab, b, mbc});
        next.push_back({mab, mbc, c});
      } else {
        next.push_back({mab, b, c});
      }
      if (mca >= 0) {
        next.push_back({a, mab, mca});
        next.push_back({mab, c, mca});
      } else {
        next.push_back({a, mab, c});
      }
    }
    cur.swap(next);
    if (!any_split) break;
  }
  faces.swap(cur);
  return splits;
}

}  // namespace detail
TESSERA_NAMESPACE_END
