// tessera/geometry/bvh.hpp: a bounding-volume hierarchy over the triangles of a mesh, with the queries
// geometric-texture synthesis needs: closest point (eq. 2-3 of paper 000), closest face under a custom
// cost with a box lower bound (eq. 1), ray casts (the preview renderer, shell mapping), box queries,
// and triangle-triangle intersection pairs between two hierarchies or within one (the "no two
// elements intersect" check). nanoflann covers points only; this covers triangles.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/vec.hpp"
#include "detail/triangle_geometry.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// Added to each side of a box when the pair traversal compares volumes to pick the node to descend,
/// so flat (zero-thickness) boxes still compare by their other sides instead of all being 0.
inline constexpr double bvh_box_thickness_floor = 1e-12;
}  // namespace detail

/// Result of a closest-point query. `face` is -1 when the hierarchy is empty or nothing lies within
/// the search radius.
struct bvh_closest_hit {
  /// The closest face, or -1.
  index_t face = -1;
  /// The closest point on it.
  vec3 point;
  vec3 bary;  ///< barycentric weights of the face's corners 0, 1, 2 (eq. 3 of paper 000)
  /// Squared distance to the query point (infinity when none).
  double squared_distance = std::numeric_limits<double>::infinity();
};

/// Result of a ray cast: the nearest hit with t in [t_min, t_max], `face` -1 for a miss.
struct bvh_ray_hit {
  /// The face hit, or -1 for a miss.
  index_t face = -1;
  /// Ray parameter of the hit (infinity for a miss).
  double t = std::numeric_limits<double>::infinity();
  /// Barycentric weights of the hit point in the face.
  vec3 bary;
};

/// Bounding-volume hierarchy over triangles (binary, median split on the longest centroid axis, at
/// most 4 triangles a leaf). It copies the triangle corners, so the source mesh may change or go away
/// after construction. Build O(F log F); queries O(log F) typical. Queries are const and thread safe.
class triangle_bvh {
 public:
  triangle_bvh() = default;

  /// Builds over all faces of any valid Mesh (see validate_mesh).
  template <Mesh M>
  explicit triangle_bvh(const M& m) {
    std::vector<std::array<vec3, 3>> tris(detail::to_size(tessera::num_faces(m)));
    for (index_t f = 0; f < tessera::num_faces(m); ++f)
      for (int k = 0; k < 3; ++k)
        tris[detail::to_size(f)][detail::to_size(k)] = vertex_position(m, face_vertex(m, f, k));
    build(std::move(tris));
  }
  /// Builds over explicit triangles; face ids are their indices.
  explicit triangle_bvh(std::vector<std::array<vec3, 3>> triangles) { build(std::move(triangles)); }

  /// Number of faces.
  [[nodiscard]] index_t num_faces() const noexcept { return static_cast<index_t>(tris_.size()); }
  /// True when built over no face.
  [[nodiscard]] bool empty() const noexcept { return tris_.empty(); }
  /// Corners of face f (in the original face order).
  [[nodiscard]] const std::array<vec3, 3>& triangle(index_t f) const noexcept {
    return tris_[detail::to_size(slot_of_[detail::to_size(f)])];
  }
  /// Bounding box of everything.
  [[nodiscard]] aabb bounds() const noexcept { return nodes_.empty() ? aabb{} : nodes_[0].box; }

  /// Closest point on any triangle to p, within sqrt(max_squared_distance).
  [[nodiscard]] bvh_closest_hit closest_point(
      vec3 p, double max_squared_distance = std::numeric_limits<double>::infinity()) const {
    bvh_closest_hit best;
    best.squared_distance = max_squared_distance;
    if (nodes_.empty()) return best;
    visit_nearest_generic(
        [&](index_t slot) {
          const auto& t = tris_[detail::to_size(slot)];
          const auto c = detail::closest_point_on_triangle(p, t[0], t[1], t[2]);
          const double d2 = squared_norm(c.point - p);
          if (d2 < best.squared_distance ||
              (d2 == best.squared_distance && face_of_[detail::to_size(slot)] < best.face)) {
            best = {face_of_[detail::to_size(slot)], c.point, c.bary, d2};
          }
          return best.squared_distance;
        },
        [&](const aabb& b) { return detail::squared_distance_to_box(p, b); }, best.squared_distance);
    if (best.face < 0) best.squared_distance = std::numeric_limits<double>::infinity();
    return best;
  }

  /// Branch-and-bound minimum of a caller cost over faces. `cost(face, corners)` returns the face's
  /// cost; `bound(box)` must return a lower bound of the cost of every face inside `box`. Returns the
  /// face with the smallest cost (ties: smallest face id) and that cost, or {-1, limit}. Used for the
  /// distance-and-normal matching cost of eq. 1-2 of paper 000.
  template <class Cost, class Bound>
  [[nodiscard]] std::pair<index_t, double> min_cost_face(Cost&& cost, Bound&& bound,
                                                         double limit = std::numeric_limits<double>::infinity()) const {
    index_t best_face = -1;
    double best = limit;
    if (nodes_.empty()) return {best_face, best};
    visit_nearest_generic(
        [&](index_t slot) {
          const index_t f = face_of_[detail::to_size(slot)];
          const double c = cost(f, tris_[detail::to_size(slot)]);
          if (c < best || (c == best && best_face >= 0 && f < best_face)) {
            best = c;
            best_face = f;
          }
          return best;
        },
        bound, best);
    return {best_face, best};
  }

  /// Nearest ray hit (either side of the triangles) with t in [t_min, t_max]; `dir` need not be unit.
  [[nodiscard]] bvh_ray_hit raycast(vec3 origin, vec3 dir, double t_min = 0,
                                    double t_max = std::numeric_limits<double>::infinity()) const {
    bvh_ray_hit hit;
    if (nodes_.empty()) return hit;
    const vec3 inv{1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z};
    index_t stack[64];
    int top = 0;
    stack[top++] = 0;
    double best_t = t_max;
    while (top > 0) {
      const node& n = nodes_[detail::to_size(stack[--top])];
      if (!ray_box(origin, inv, n.box, t_min, best_t)) continue;
      if (n.count > 0) {
        for (index_t s = n.first; s < n.first + n.count; ++s) {
          const auto& t = tris_[detail::to_size(s)];
          const auto h = detail::ray_triangle(origin, dir, t[0], t[1], t[2], t_min, best_t);
          const index_t f = face_of_[detail::to_size(s)];
          if (std::isfinite(h.t) && (h.t < best_t || (h.t == best_t && (hit.face < 0 || f < hit.face)))) {
            best_t = h.t;
            hit = {f, h.t, {1 - h.u - h.v, h.u, h.v}};
          }
        }
      } else {
        stack[top++] = n.first;
        stack[top++] = n.first + 1;
      }
    }
    return hit;
  }

  /// Calls fn(face) for every face whose bounding box overlaps `box`.
  template <class Fn>
  void for_each_overlapping(const aabb& box, Fn&& fn) const {
    if (nodes_.empty()) return;
    index_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const node& n = nodes_[detail::to_size(stack[--top])];
      if (!detail::boxes_overlap(n.box, box)) continue;
      if (n.count > 0) {
        for (index_t s = n.first; s < n.first + n.count; ++s)
          if (detail::boxes_overlap(box_of(tris_[detail::to_size(s)]), box)) fn(face_of_[detail::to_size(s)]);
      } else {
        stack[top++] = n.first;
        stack[top++] = n.first + 1;
      }
    }
  }

  /// Calls fn(face_a, face_b) for every pair of intersecting triangles, face_a from `a` and face_b
  /// from `b` (touching counts). Pairs come in no particular order. O(pairs of overlapping leaves).
  template <class Fn>
  friend void for_each_intersecting_pair(const triangle_bvh& a, const triangle_bvh& b, Fn&& fn) {
    if (a.nodes_.empty() || b.nodes_.empty()) return;
    std::vector<std::pair<index_t, index_t>> stack{{0, 0}};
    while (!stack.empty()) {
      const auto [ia, ib] = stack.back();
      stack.pop_back();
      const node& na = a.nodes_[detail::to_size(ia)];
      const node& nb = b.nodes_[detail::to_size(ib)];
      if (!detail::boxes_overlap(na.box, nb.box)) continue;
      if (na.count > 0 && nb.count > 0) {
        for (index_t s = na.first; s < na.first + na.count; ++s)
          for (index_t u = nb.first; u < nb.first + nb.count; ++u)
            if (detail::triangles_intersect(a.tris_[detail::to_size(s)], b.tris_[detail::to_size(u)]))
              fn(a.face_of_[detail::to_size(s)], b.face_of_[detail::to_size(u)]);
      } else if (nb.count > 0 || (na.count == 0 && volume(na.box) >= volume(nb.box))) {
        stack.push_back({na.first, ib});
        stack.push_back({na.first + 1, ib});
      } else {
        stack.push_back({ia, nb.first});
        stack.push_back({ia, nb.first + 1});
      }
    }
  }

  /// Calls fn(f, g) once for every unordered pair f < g of intersecting triangles of this hierarchy
  /// for which skip(f, g) is false (use skip to ignore neighbours that share a vertex).
  template <class Skip, class Fn>
  void for_each_self_intersection(Skip&& skip, Fn&& fn) const {
    for_each_intersecting_pair(*this, *this, [&](index_t f, index_t g) {
      if (f < g && !skip(f, g)) fn(f, g);
    });
  }

 private:
  struct node {
    aabb box;
    index_t first = 0;  ///< leaf: first triangle slot; inner: index of the left child (right = first + 1)
    index_t count = 0;  ///< leaf: number of triangles; inner: 0
  };

  static aabb box_of(const std::array<vec3, 3>& t) noexcept {
    aabb b;
    for (const vec3& p : t) b.extend(p);
    return b;
  }
  static double volume(const aabb& b) noexcept {
    const vec3 e = b.extent();
    return (e.x + detail::bvh_box_thickness_floor) * (e.y + detail::bvh_box_thickness_floor) *
           (e.z + detail::bvh_box_thickness_floor);
  }
  static bool ray_box(vec3 o, vec3 inv, const aabb& b, double t0, double t1) noexcept {
    for (int i = 0; i < 3; ++i) {
      double ta = (b.min[i] - o[i]) * inv[i], tb = (b.max[i] - o[i]) * inv[i];
      if (std::isnan(ta) || std::isnan(tb)) {  // ray parallel and on the slab boundary
        if (o[i] < b.min[i] || o[i] > b.max[i]) return false;
        continue;
      }
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (t0 > t1) return false;
    }
    return true;
  }

  void build(std::vector<std::array<vec3, 3>> triangles) {
    const std::size_t n = triangles.size();
    if (n == 0) return;
    std::vector<index_t> order(n);
    std::vector<vec3> centroid(n);
    for (std::size_t i = 0; i < n; ++i) {
      order[i] = static_cast<index_t>(i);
      centroid[i] = (triangles[i][0] + triangles[i][1] + triangles[i][2]) / 3.0;
    }
    nodes_.reserve(2 * n / 2 + 2);
    nodes_.push_back({});
    struct task {
      index_t node, begin, end;
      int depth;
    };
    std::vector<task> todo{{0, 0, static_cast<index_t>(n), 0}};
    while (!todo.empty()) {
      const task tk = todo.back();
      todo.pop_back();
      aabb box, cbox;
      for (index_t i = tk.begin; i < tk.end; ++i) {
        box.extend(box_of(triangles[detail::to_size(order[detail::to_size(i)])]));
        cbox.extend(centroid[detail::to_size(order[detail::to_size(i)])]);
      }
      nodes_[detail::to_size(tk.node)].box = box;
      const vec3 e = cbox.extent();
      if (tk.end - tk.begin <= 4 || tk.depth >= 60 || (e.x <= 0 && e.y <= 0 && e.z <= 0)) {
        nodes_[detail::to_size(tk.node)].first = tk.begin;
        nodes_[detail::to_size(tk.node)].count = tk.end - tk.begin;
        continue;
      }
      const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
      const index_t mid = (tk.begin + tk.end) / 2;
      std::nth_element(order.begin() + tk.begin, order.begin() + mid, order.begin() + tk.end,
                       [&](index_t a, index_t b) {
                         const double ca = centroid[detail::to_size(a)][axis], cb = centroid[detail::to_size(b)][axis];
                         return ca != cb ? ca < cb : a < b;
                       });
      const auto left = static_cast<index_t>(nodes_.size());
      nodes_.push_back({});
      nodes_.push_back({});
      nodes_[detail::to_size(tk.node)].first = left;
      nodes_[detail::to_size(tk.node)].count = 0;
      todo.push_back({left + 1, mid, tk.end, tk.depth + 1});
      todo.push_back({left, tk.begin, mid, tk.depth + 1});
    }
    tris_.resize(n);
    face_of_.resize(n);
    slot_of_.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
      tris_[s] = triangles[detail::to_size(order[s])];
      face_of_[s] = order[s];
      slot_of_[detail::to_size(order[s])] = static_cast<index_t>(s);
    }
  }

  // Best-first-ish traversal: visit the nearer child first, prune boxes whose bound >= current best.
  template <class Leaf, class Bound>
  void visit_nearest_generic(Leaf&& leaf, Bound&& bound, double best) const {
    index_t stack[64];
    double stack_bound[64];
    int top = 0;
    stack[top] = 0;
    stack_bound[top++] = bound(nodes_[0].box);
    while (top > 0) {
      --top;
      if (stack_bound[top] > best) continue;
      const node& n = nodes_[detail::to_size(stack[top])];
      if (n.count > 0) {
        for (index_t s = n.first; s < n.first + n.count; ++s) best = leaf(s);
        continue;
      }
      const double bl = bound(nodes_[detail::to_size(n.first)].box);
      const double br = bound(nodes_[detail::to_size(n.first + 1)].box);
      // push the farther child first so the nearer is visited first
      if (bl <= br) {
        if (br <= best) {
          stack[top] = n.first + 1;
          stack_bound[top++] = br;
        }
        if (bl <= best) {
          stack[top] = n.first;
          stack_bound[top++] = bl;
        }
      } else {
        if (bl <= best) {
          stack[top] = n.first;
          stack_bound[top++] = bl;
        }
        if (br <= best) {
          stack[top] = n.first + 1;
          stack_bound[top++] = br;
        }
      }
    }
  }

  std::vector<node> nodes_;
  std::vector<std::array<vec3, 3>> tris_;  // in leaf order
  std::vector<index_t> face_of_;           // slot -> face
  std::vector<index_t> slot_of_;           // face -> slot
};

TESSERA_NAMESPACE_END
