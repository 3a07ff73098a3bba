// tessera/surface/detail/remesh_ops.hpp: the editable triangle mesh of the isotropic remesher
// (remesh_isotropic.hpp) and its local operations, after Botsch & Kobbelt 2004 (§3): edge split,
// edge collapse with the link condition, edge flip toward valence 6, each keeping sharp feature
// edges (creases) and feature corners where they are. Faces and vertices are killed in place, not
// erased, so indices stay stable within a pass; compact() writes the live part out in order.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_set>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// How a vertex may move: freely on the surface, along its crease (two feature edges), or not at all.
enum class remesh_vertex_kind : unsigned char { smooth = 0, crease = 1, corner = 2 };

/// A face whose normal, after an operation, turns by more than this cosine from before is refused.
inline constexpr double remesh_min_normal_cos = 0.5;
/// A face whose doubled area falls below this fraction of L^2 is refused as degenerate.
inline constexpr double remesh_min_area = 1e-10;

class remesh_mesh {
 public:
  std::vector<vec3> pos;
  std::vector<std::array<index_t, 3>> faces;
  std::vector<char> face_alive;
  std::vector<remesh_vertex_kind> kind;

  [[nodiscard]] static std::uint64_t key(index_t a, index_t b) noexcept {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }
  [[nodiscard]] bool is_feature(index_t a, index_t b) const { return feature_.count(key(a, b)) != 0; }
  void set_feature(index_t a, index_t b) { feature_.insert(key(a, b)); }
  [[nodiscard]] index_t live_faces() const noexcept { return live_faces_; }
  [[nodiscard]] index_t live_vertices() const noexcept { return live_vertices_; }

  /// Takes a valid closed mesh's positions and faces.
  void assign(std::vector<vec3> p, std::vector<std::array<index_t, 3>> f) {
    pos = std::move(p);
    faces = std::move(f);
    face_alive.assign(faces.size(), 1);
    kind.assign(pos.size(), remesh_vertex_kind::smooth);
    live_faces_ = static_cast<index_t>(faces.size());
    live_vertices_ = static_cast<index_t>(pos.size());
    rebuild_incidence();
  }

  /// The faces around every vertex, from the live faces.
  void rebuild_incidence() {
    vf_.assign(pos.size(), {});
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (face_alive[f] != 0)
        for (index_t v : faces[f]) vf_[to_size(v)].push_back(static_cast<index_t>(f));
  }
  [[nodiscard]] const std::vector<index_t>& faces_of(index_t v) const { return vf_[to_size(v)]; }
  [[nodiscard]] bool vertex_alive(index_t v) const { return !vf_[to_size(v)].empty(); }

  /// The live face holding the directed side a -> b, or -1.
  [[nodiscard]] index_t face_with_side(index_t a, index_t b) const {
    for (index_t f : vf_[to_size(a)]) {
      const auto& t = faces[to_size(f)];
      for (int k = 0; k < 3; ++k)
        if (t[to_size(k)] == a && t[to_size((k + 1) % 3)] == b) return f;
    }
    return -1;
  }
  /// The corner of face f that is neither a nor b.
  [[nodiscard]] index_t opposite(index_t f, index_t a, index_t b) const {
    for (index_t v : faces[to_size(f)])
      if (v != a && v != b) return v;
    return -1;
  }
  /// The two faces of edge (a, b), f holding side a -> b and g side b -> a, and their third corners c
  /// and d; f = -1 when the edge has not two faces.
  struct edge_quad {
    index_t f = -1, g = -1, c = -1, d = -1;
  };
  [[nodiscard]] edge_quad quad(index_t a, index_t b) const {
    const index_t f = face_with_side(a, b), g = face_with_side(b, a);
    if (f < 0 || g < 0) return {};
    return {f, g, opposite(f, a, b), opposite(g, a, b)};
  }
  /// The vertices joined to v by an edge, sorted.
  [[nodiscard]] std::vector<index_t> neighbours(index_t v) const {
    std::vector<index_t> n;
    for (index_t f : vf_[to_size(v)])
      for (index_t w : faces[to_size(f)])
        if (w != v) n.push_back(w);
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    return n;
  }
  /// Neighbours of v: on a closed manifold mesh as many as the faces around it.
  [[nodiscard]] index_t valence(index_t v) const { return static_cast<index_t>(vf_[to_size(v)].size()); }

  [[nodiscard]] vec3 area_normal(const std::array<index_t, 3>& t) const {
    return cross(pos[to_size(t[1])] - pos[to_size(t[0])], pos[to_size(t[2])] - pos[to_size(t[0])]);
  }
  /// Area-weighted vertex normal: the sum of the area normals around v, normalized.
  [[nodiscard]] vec3 vertex_normal(index_t v) const {
    vec3 n{0, 0, 0};
    for (index_t f : vf_[to_size(v)]) n = n + area_normal(faces[to_size(f)]);
    return normalized(n);
  }

  /// Face t with vertices u and w (u may equal w) moved to p: its three corners, or nothing when it
  /// would flatten (doubled area squared at most min_area2) or turn by more than
  /// remesh_min_normal_cos from before. The test of every collapse and relaxation move.
  [[nodiscard]] std::optional<std::array<vec3, 3>> moved_face(const std::array<index_t, 3>& t, index_t u, index_t w,
                                                              vec3 p, double min_area2) const {
    std::array<vec3, 3> q;
    for (int k = 0; k < 3; ++k) {
      const index_t x = t[to_size(k)];
      q[to_size(k)] = x == u || x == w ? p : pos[to_size(x)];
    }
    const vec3 after = cross(q[1] - q[0], q[2] - q[0]);
    if (squared_norm(after) <= min_area2 || dot(normalized(area_normal(t)), normalized(after)) < remesh_min_normal_cos)
      return std::nullopt;
    return q;
  }

  /// Splits edge (a, b) at its midpoint (Botsch & Kobbelt's split); the new vertex is a crease when
  /// the edge is a feature. Returns false when the edge has not two faces.
  bool split(index_t a, index_t b) {
    const auto [f, g, c, d] = quad(a, b);
    if (f < 0) return false;
    const auto m = static_cast<index_t>(pos.size());
    pos.push_back(0.5 * (pos[to_size(a)] + pos[to_size(b)]));
    const bool feat = is_feature(a, b);
    kind.push_back(feat ? remesh_vertex_kind::crease : remesh_vertex_kind::smooth);
    vf_.emplace_back();
    ++live_vertices_;
    // f = (a, b, c) -> (a, m, c) + (m, b, c); g = (b, a, d) -> (m, a, d) + (b, m, d)
    faces[to_size(f)] = {a, m, c};
    faces[to_size(g)] = {m, a, d};
    const index_t f2 = add_face({m, b, c}), g2 = add_face({b, m, d});
    erase_incidence(b, f);
    erase_incidence(b, g);
    vf_[to_size(b)].insert(vf_[to_size(b)].end(), {f2, g2});
    vf_[to_size(m)].insert(vf_[to_size(m)].end(), {f, g, f2, g2});
    vf_[to_size(c)].push_back(f2);
    vf_[to_size(d)].push_back(g2);
    if (feat) {
      feature_.erase(key(a, b));
      feature_.insert(key(a, m));
      feature_.insert(key(m, b));
    }
    return true;
  }

  /// Whether edge (a, b) may collapse with b removed and a moved to p: the link condition (the
  /// vertices joined to both are exactly the two opposite corners), no vertex left with fewer than
  /// three neighbours, no new edge longer than max_len, no face turned or degenerate.
  [[nodiscard]] bool can_collapse(index_t a, index_t b, vec3 p, double max_len, double min_area2) const {
    const auto [f, g, c, d] = quad(a, b);
    if (f < 0 || live_vertices_ <= 4) return false;
    const auto na = neighbours(a), nb = neighbours(b);
    std::vector<index_t> common;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    if (common.size() != 2 || c == d) return false;
    if (valence(c) <= 3 || valence(d) <= 3) return false;
    const bool a_moves = !(pos[to_size(a)] == p);
    for (const auto* ring : {&na, &nb})
      if (ring == &nb || a_moves)
        for (index_t x : *ring)
          if (x != a && x != b && squared_norm(pos[to_size(x)] - p) > max_len * max_len) return false;
    for (index_t v : {a, b})
      for (index_t h : vf_[to_size(v)])
        if (h != f && h != g && !moved_face(faces[to_size(h)], a, b, p, min_area2)) return false;
    return true;
  }

  /// Collapses edge (a, b): b is removed, a moves to p; the faces of the edge die, b's other faces
  /// take a; b's feature edges become a's. Check can_collapse first.
  void collapse(index_t a, index_t b, vec3 p) {
    const auto nb = neighbours(b);
    for (index_t h : std::vector<index_t>(vf_[to_size(b)])) {
      auto& t = faces[to_size(h)];
      if (std::find(t.begin(), t.end(), a) != t.end()) {
        face_alive[to_size(h)] = 0;
        --live_faces_;
        for (index_t w : t) erase_incidence(w, h);
      } else {
        for (auto& w : t)
          if (w == b) w = a;
        vf_[to_size(a)].push_back(h);
      }
    }
    vf_[to_size(b)].clear();
    --live_vertices_;
    for (index_t x : nb)
      if (feature_.erase(key(b, x)) != 0 && x != a) feature_.insert(key(a, x));
    pos[to_size(a)] = p;
  }

  /// Whether flipping edge (a, b) to (c, d) keeps the surface valid: not a feature, (c, d) not an
  /// edge yet, a and b keep three neighbours, the two new faces not degenerate and not turned.
  [[nodiscard]] bool can_flip(index_t a, index_t b, double min_area2) const {
    if (is_feature(a, b)) return false;
    const auto [f, g, c, d] = quad(a, b);
    if (f < 0) return false;
    if (c == d || valence(a) <= 3 || valence(b) <= 3) return false;
    const auto nc = neighbours(c);
    if (std::binary_search(nc.begin(), nc.end(), d)) return false;
    const vec3 n0 = normalized(area_normal(faces[to_size(f)])), n1 = normalized(area_normal(faces[to_size(g)]));
    for (const std::array<index_t, 3>& t : {std::array<index_t, 3>{a, d, c}, std::array<index_t, 3>{d, b, c}}) {
      const vec3 n = area_normal(t);
      if (squared_norm(n) <= min_area2) return false;
      const vec3 u = normalized(n);
      if (dot(u, n0) < remesh_min_normal_cos || dot(u, n1) < remesh_min_normal_cos) return false;
    }
    return true;
  }

  /// Flips edge (a, b) of faces (a, b, c) and (b, a, d) to (a, d, c) and (d, b, c).
  void flip(index_t a, index_t b) {
    const auto [f, g, c, d] = quad(a, b);
    faces[to_size(f)] = {a, d, c};
    faces[to_size(g)] = {d, b, c};
    erase_incidence(b, f);
    erase_incidence(a, g);
    vf_[to_size(d)].push_back(f);
    vf_[to_size(c)].push_back(g);
  }

  /// The live vertices and faces, renumbered in their order, as a tri_mesh.
  [[nodiscard]] tri_mesh compact() const {
    tri_mesh out;
    std::vector<index_t> id(pos.size(), -1);
    for (std::size_t v = 0; v < pos.size(); ++v)
      if (!vf_[v].empty()) {
        id[v] = static_cast<index_t>(out.positions.size());
        out.positions.push_back(pos[v]);
      }
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (face_alive[f] != 0)
        out.faces.push_back({id[to_size(faces[f][0])], id[to_size(faces[f][1])], id[to_size(faces[f][2])]});
    return out;
  }

 private:
  std::vector<std::vector<index_t>> vf_;
  std::unordered_set<std::uint64_t> feature_;
  index_t live_faces_ = 0, live_vertices_ = 0;

  index_t add_face(std::array<index_t, 3> t) {
    faces.push_back(t);
    face_alive.push_back(1);
    ++live_faces_;
    return static_cast<index_t>(faces.size() - 1);
  }
  void erase_incidence(index_t v, index_t f) {
    auto& l = vf_[to_size(v)];
    l.erase(std::remove(l.begin(), l.end(), f), l.end());
  }
};

}  // namespace detail
TESSERA_NAMESPACE_END
