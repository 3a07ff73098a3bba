// tessera/surface/remesh_isotropic.hpp: isotropic remeshing of a closed triangle mesh that keeps its
// sharp features (Botsch & Kobbelt 2004, "A remeshing approach to multiresolution modeling", §3):
// rounds of (1) split every edge longer than 4/3 L, (2) collapse every edge shorter than 4/5 L,
// (3) flip edges where that brings the four vertices' valences closer to 6, (4) move every vertex
// toward the centroid of its neighbours within its tangent plane and project it back onto the input
// surface. Edges whose faces meet at a dihedral angle above `feature_angle` are creases: never
// flipped, split along themselves, collapsed only along themselves, their vertices relaxed along
// the crease and projected onto the input's creases; where creases meet or turn sharply the vertex
// is a corner and stays where it is. Each round ends with (5) flips that remove slivers left along
// bent creases (a face of three crease vertices), and relaxation never makes a sliver.
//
// Why it is here: the polycube map and the shell map follow the base mesh's worst triangles. CAD
// output (OpenSCAD, STL exports) triangulates each flat or ruled face between its boundary loops
// only: faces 45 units long beside slivers 10^-3 wide. Their shells fold at any height; remeshed to
// even triangles of about a tenth of a tile they map (docs/surface.md, "CAD parts").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "../geometry/bvh.hpp"
#include "detail/remesh_ops.hpp"
#include "polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of remesh_isotropic.
struct remesh_options {
  /// Target edge length L in mesh units; 0 (default): the bounding box's longest side / edges_across.
  double edge_length = 0;
  /// Edges along the bounding box's longest side when edge_length is 0 (1 to 100000).
  int edges_across = 64;
  /// Dihedral angle in degrees (between the two faces' normals, 0 to 180) at or above which an edge
  /// is a sharp feature (crease) that the remeshing keeps.
  double feature_angle = 40;
  /// Rounds of split, collapse, flip and relaxation (0 to 100; Botsch & Kobbelt use 5).
  int iterations = 10;
  /// Refuses target lengths whose result would need more faces than this (estimated from the area).
  index_t max_faces = 4'000'000;
  /// Progress (one report per round) and cancellation.
  tessera::progress progress = {};
};

/// What remesh_isotropic did and how even the result is.
struct remesh_stats {
  /// The target edge length L used.
  double edge_length = 0;
  /// Crease edges of the input (dihedral angle at or above feature_angle).
  index_t feature_edges = 0;
  /// Edges split, collapsed and flipped over all rounds.
  index_t splits = 0, collapses = 0, flips = 0;
  /// Smallest triangle angle, in degrees, of the input and of the result.
  double min_angle_input = 0, min_angle = 0;
  /// Root mean square of (edge length / L - 1) over the result's edges.
  double edge_length_rms = 0;
  /// Largest distance of a result vertex from the input surface, relative to L.
  double max_deviation = 0;
};

/// The remeshed surface (new vertices and faces; closed, manifold, oriented like the input) and stats.
struct remesh_result {
  /// The remeshed mesh.
  tri_mesh mesh;
  /// Figures of the run.
  remesh_stats stats;
};

namespace detail {

/// Closest point to p on segment [a, b].
inline vec3 closest_point_on_segment(vec3 p, vec3 a, vec3 b) noexcept {
  const vec3 ab = b - a;
  const double l2 = squared_norm(ab);
  if (!(l2 > 0)) return a;
  return a + std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) * ab;
}

/// The input's crease segments in a uniform grid of cells of side `cell`, for projecting crease
/// vertices back onto the creases (a segment is listed in every cell its samples at cell / 2 touch).
class crease_grid {
 public:
  crease_grid(std::vector<std::array<vec3, 2>> segments, vec3 origin, double cell)
      : segs_(std::move(segments)), origin_(origin), cell_(cell) {
    for (std::size_t s = 0; s < segs_.size(); ++s) {
      const vec3 a = segs_[s][0], b = segs_[s][1];
      const auto steps = static_cast<long>(std::ceil(2 * norm(b - a) / cell_));
      std::uint64_t last = ~std::uint64_t{0};
      for (long i = 0; i <= steps; ++i) {
        const std::uint64_t k =
            cell_key(a + (static_cast<double>(i) / static_cast<double>(std::max(1L, steps))) * (b - a));
        if (k == last) continue;
        auto& l = cells_[k];
        if (l.empty() || l.back() != static_cast<index_t>(s)) l.push_back(static_cast<index_t>(s));
        last = k;
      }
    }
  }
  /// The closest point on a crease within about `radius` of p (searched cells), or p when none.
  [[nodiscard]] vec3 project(vec3 p, double radius) const {
    const int r = static_cast<int>(std::ceil(radius / cell_));
    const auto c = coords(p);
    vec3 best = p;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int dx = -r; dx <= r; ++dx)
      for (int dy = -r; dy <= r; ++dy)
        for (int dz = -r; dz <= r; ++dz) {
          const auto it = cells_.find(pack(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == cells_.end()) continue;
          for (index_t s : it->second) {
            const vec3 q = closest_point_on_segment(p, segs_[to_size(s)][0], segs_[to_size(s)][1]);
            const double d2 = squared_norm(q - p);
            if (d2 < best_d2) best_d2 = d2, best = q;
          }
        }
    return best;
  }

 private:
  std::vector<std::array<vec3, 2>> segs_;
  vec3 origin_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<index_t>> cells_;

  [[nodiscard]] std::array<long, 3> coords(vec3 p) const {
    const vec3 q = (1 / cell_) * (p - origin_);
    auto c = [](double x) { return static_cast<long>(std::clamp(std::floor(x), -1.0e6, 1.0e6)); };
    return {c(q.x), c(q.y), c(q.z)};
  }
  [[nodiscard]] static std::uint64_t pack(long x, long y, long z) {
    auto u = [](long v) { return static_cast<std::uint64_t>(v + (1L << 20)) & 0x1FFFFF; };
    return (u(x) << 42) | (u(y) << 21) | u(z);
  }
  [[nodiscard]] std::uint64_t cell_key(vec3 p) const {
    const auto c = coords(p);
    return pack(c[0], c[1], c[2]);
  }
};

/// Smallest angle (degrees) of a mesh's triangles.
inline double remesh_min_angle(const tri_mesh& m) {
  double worst = 180;
  for (const auto& f : m.faces)
    worst = std::min(worst, smallest_angle_degrees(m.positions[to_size(f[0])], m.positions[to_size(f[1])],
                                                   m.positions[to_size(f[2])]));
  return worst;
}

/// Every undirected edge (a < b) of the live faces, each once, in face order.
inline std::vector<std::array<index_t, 2>> remesh_edges(const remesh_mesh& m) {
  std::vector<std::array<index_t, 2>> e;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (m.face_alive[f] != 0)
      for (int k = 0; k < 3; ++k) {
        const index_t a = m.faces[f][to_size(k)], b = m.faces[f][to_size((k + 1) % 3)];
        if (a < b) e.push_back({a, b});
      }
  return e;
}

/// Edges whose squared length passes `keep`, sorted by length (longest first when `longest_first`),
/// ties by vertex pair, so that passes are deterministic.
template <class Keep>
std::vector<std::array<index_t, 2>> remesh_sorted_edges(const remesh_mesh& m, bool longest_first, Keep keep) {
  std::vector<std::pair<double, std::array<index_t, 2>>> l;
  for (const auto& e : remesh_edges(m)) {
    const double d2 = squared_norm(m.pos[to_size(e[0])] - m.pos[to_size(e[1])]);
    if (keep(d2)) l.push_back({longest_first ? -d2 : d2, e});
  }
  std::sort(l.begin(), l.end());
  std::vector<std::array<index_t, 2>> out;
  out.reserve(l.size());
  for (const auto& x : l) out.push_back(x.second);
  return out;
}

/// Step 1: split edges longer than hi until none is (new halves are checked again).
inline status remesh_split_long(remesh_mesh& m, double hi, index_t face_limit, index_t& splits) {
  for (int pass = 0; pass < 64; ++pass) {
    const auto edges = remesh_sorted_edges(m, true, [&](double d2) { return d2 > hi * hi; });
    if (edges.empty()) return {};
    for (const auto& e : edges) {
      if (m.live_faces() > face_limit)
        return status::invalid_argument(cat("remesh: splitting passed ", face_limit, " faces; choose a longer edge"));
      if (m.split(e[0], e[1])) ++splits;
    }
  }
  return {};
}

/// Step 2: collapse edges shorter than lo where no edge longer than hi appears; the vertex of the
/// lower kind (smooth < crease < corner) goes, two of one kind meet at the midpoint; creases only
/// along themselves.
inline void remesh_collapse_short(remesh_mesh& m, double lo, double hi, double min_area2, index_t& collapses) {
  for (int pass = 0; pass < 16; ++pass) {
    index_t done = 0;
    for (const auto& e : remesh_sorted_edges(m, false, [&](double d2) { return d2 < lo * lo; })) {
      index_t a = e[0], b = e[1];
      if (!m.vertex_alive(a) || !m.vertex_alive(b)) continue;  // can_collapse checks the edge
      if (!(squared_norm(m.pos[to_size(a)] - m.pos[to_size(b)]) < lo * lo)) continue;
      const auto ka = m.kind[to_size(a)], kb = m.kind[to_size(b)];
      if (ka == remesh_vertex_kind::corner && kb == remesh_vertex_kind::corner) continue;
      if (kb != remesh_vertex_kind::smooth && ka != remesh_vertex_kind::smooth && !m.is_feature(a, b)) continue;
      if (ka < kb) std::swap(a, b);  // a keeps the higher kind
      const vec3 p = ka == kb ? 0.5 * (m.pos[to_size(a)] + m.pos[to_size(b)]) : m.pos[to_size(a)];
      if (!m.can_collapse(a, b, p, hi, min_area2)) continue;
      m.collapse(a, b, p);
      ++collapses, ++done;
    }
    if (done == 0) return;
  }
}

/// Step 3: flip edges where the squared deviation of the four valences from 6 drops.
inline void remesh_equalize_valences(remesh_mesh& m, double min_area2, index_t& flips) {
  for (const auto& e : remesh_edges(m)) {
    const index_t a = e[0], b = e[1];
    const auto [f, g, c, d] = m.quad(a, b);
    if (f < 0) continue;
    const index_t va = m.valence(a), vb = m.valence(b), vc = m.valence(c), vd = m.valence(d);
    auto dev = [](index_t x) { return (x - 6) * (x - 6); };
    const index_t before = dev(va) + dev(vb) + dev(vc) + dev(vd);
    const index_t after = dev(va - 1) + dev(vb - 1) + dev(vc + 1) + dev(vd + 1);
    if (after >= before || !m.can_flip(a, b, min_area2)) continue;
    m.flip(a, b);
    ++flips;
  }
}

/// A relaxation move that leaves a face with a smaller angle than this (degrees), and smaller than
/// before, is not taken.
inline constexpr double remesh_sliver_angle = 10;

/// Step 5 (not in Botsch & Kobbelt): an edge of a face with an angle below remesh_sliver_angle is
/// flipped where that raises the smallest angle of its two faces (three vertices of a bent crease
/// make such a face; no valence flip or move removes it).
inline void remesh_flip_slivers(remesh_mesh& m, double min_area2, index_t& flips) {
  for (const auto& e : remesh_edges(m)) {
    const index_t a = e[0], b = e[1];
    const auto [f, g, c, d] = m.quad(a, b);
    if (f < 0) continue;
    auto angle = [&](index_t x, index_t y, index_t z) {
      return smallest_angle_degrees(m.pos[to_size(x)], m.pos[to_size(y)], m.pos[to_size(z)]);
    };
    const double before = std::min(angle(a, b, c), angle(b, a, d));
    if (!(before < remesh_sliver_angle)) continue;
    if (std::min(angle(a, d, c), angle(d, b, c)) <= before || !m.can_flip(a, b, min_area2)) continue;
    m.flip(a, b);
    ++flips;
  }
}

/// Step 4: tangential relaxation (toward the neighbours' centroid in the tangent plane, or along
/// the crease) and projection onto the input (its surface, or its creases); a move that would turn
/// or flatten a face, or make a sliver of it, is not taken. With `relax` false only the projection
/// (after the last round: midpoints of the last collapses, moves refused as slivers). Gauss-Seidel in vertex order, so deterministic.
inline void remesh_relax_and_project(remesh_mesh& m, const triangle_bvh& surface, const crease_grid& creases,
                                     double edge, double min_area2, bool relax = true) {
  for (index_t v = 0; v < static_cast<index_t>(m.pos.size()); ++v) {
    if (!m.vertex_alive(v) || m.kind[to_size(v)] == remesh_vertex_kind::corner) continue;
    const vec3 p = m.pos[to_size(v)];
    const auto ring = m.neighbours(v);
    vec3 target = p;
    if (m.kind[to_size(v)] == remesh_vertex_kind::smooth) {
      vec3 q{0, 0, 0};
      for (index_t w : ring) q = q + m.pos[to_size(w)];
      q = (1.0 / static_cast<double>(ring.size())) * q;
      const vec3 n = m.vertex_normal(v);
      const vec3 moved = relax ? q + dot(n, p - q) * n : p;
      // the move is within about an edge of the surface: a bounded search prunes most of the BVH
      auto hit = surface.closest_point(moved, 4 * edge * edge);
      if (hit.face < 0) hit = surface.closest_point(moved);
      target = hit.face >= 0 ? hit.point : moved;
    } else {
      std::array<index_t, 2> line{-1, -1};
      int count = 0;
      for (index_t w : ring)
        if (m.is_feature(v, w) && count++ < 2) line[to_size(count - 1)] = w;
      if (count != 2) continue;
      const vec3 u = m.pos[to_size(line[0])], w = m.pos[to_size(line[1])];
      const vec3 t = normalized(w - u);
      target = creases.project(relax ? p + dot(t, 0.5 * (u + w) - p) * t : p, 2 * edge);
    }
    if (!is_finite(target) || target == p) continue;
    bool ok = true;
    for (index_t f : m.faces_of(v)) {
      const auto& tri = m.faces[to_size(f)];
      const auto q = m.moved_face(tri, v, v, target, min_area2);
      if (!q) {
        ok = false;
        break;
      }
      // nor may it make a sliver (a smooth vertex projected against a crease next to a corner)
      if (!relax) continue;
      const double angle = smallest_angle_degrees((*q)[0], (*q)[1], (*q)[2]);
      if (angle < remesh_sliver_angle &&
          angle < smallest_angle_degrees(m.pos[to_size(tri[0])], m.pos[to_size(tri[1])], m.pos[to_size(tri[2])])) {
        ok = false;
        break;
      }
    }
    if (ok) m.pos[to_size(v)] = target;
  }
}

/// A chain of sharp edges shorter than this is not a crease.
inline constexpr index_t remesh_min_crease_edges = 3;

/// Marks the input's creases (chains of at least remesh_min_crease_edges sharp edges) and classifies its vertices (smooth, crease, corner).
template <class Mesh_>
std::vector<std::array<vec3, 2>> remesh_mark_features(remesh_mesh& m, const Mesh_& input, double feature_angle) {
  const double cos_limit = std::cos(feature_angle * 3.14159265358979323846 / 180);
  std::vector<int> feature_degree(m.pos.size(), 0);
  std::vector<std::array<vec3, 2>> segments;
  // candidates, as a "mesh" of degenerate faces (v0, v1, v1) whose components are the crease chains
  tri_mesh sharp;
  sharp.positions.resize(m.pos.size());
  for (const auto& e : mesh_edges(input)) {
    if (e.faces.size() != 2) continue;
    const vec3 n0 = normalized(face_area_normal(input, e.faces[0][0])),
               n1 = normalized(face_area_normal(input, e.faces[1][0]));
    if (dot(n0, n1) <= cos_limit) sharp.faces.push_back({e.v0, e.v1, e.v1});
  }
  // chains of fewer than remesh_min_crease_edges edges are noise of a scan (a sliver's own normal),
  // not creases: kept, they would pin the sliver's vertices as corners
  const auto chains = connected_components(sharp);
  std::vector<index_t> chain_edges(to_size(chains.count), 0);
  for (index_t c : chains.face_component) ++chain_edges[to_size(c)];
  for (std::size_t i = 0; i < sharp.faces.size(); ++i) {
    if (chain_edges[to_size(chains.face_component[i])] < remesh_min_crease_edges) continue;
    const index_t v0 = sharp.faces[i][0], v1 = sharp.faces[i][1];
    m.set_feature(v0, v1);
    ++feature_degree[to_size(v0)], ++feature_degree[to_size(v1)];
    segments.push_back({m.pos[to_size(v0)], m.pos[to_size(v1)]});
  }
  for (index_t v = 0; v < static_cast<index_t>(m.pos.size()); ++v) {
    const int d = feature_degree[to_size(v)];
    if (d == 0) continue;
    m.kind[to_size(v)] = remesh_vertex_kind::corner;
    if (d != 2) continue;
    std::array<vec3, 2> dir{};
    int k = 0;
    for (index_t w : m.neighbours(v))
      if (m.is_feature(v, w)) dir[to_size(k++)] = normalized(m.pos[to_size(w)] - m.pos[to_size(v)]);
    // a crease that turns by more than the feature angle is a corner
    if (dot(dir[0], dir[1]) <= -cos_limit) m.kind[to_size(v)] = remesh_vertex_kind::crease;
  }
  return segments;
}

}  // namespace detail

/// Remeshes a closed, manifold, oriented triangle mesh (validate_polycube_input) into triangles of
/// edge length about L, keeping its creases and corners (see the file comment for the steps). The
/// result is a new mesh (the input's vertices are not kept in order). Errors: invalid_argument for
/// a refused mesh or an option out of range (the message names it), or a target length that would
/// need more than max_faces faces; cancelled from the progress callback. O(iterations * F log F).
template <Mesh M>
result<remesh_result> remesh_isotropic(const M& mesh, const remesh_options& opt = {}) {
  if (auto s = validate_polycube_input(mesh, "remesh: mesh"); !s) return s;
  if (!(opt.edge_length >= 0) || !std::isfinite(opt.edge_length))
    return status::invalid_argument(detail::cat("remesh: edge_length must be >= 0 and finite, got ", opt.edge_length));
  if (opt.edges_across < 1 || opt.edges_across > 100000)
    return status::invalid_argument(detail::cat("remesh: edges_across must be in [1, 100000], got ", opt.edges_across));
  if (!(opt.feature_angle >= 0 && opt.feature_angle <= 180))
    return status::invalid_argument(detail::cat("remesh: feature_angle must be in [0, 180], got ", opt.feature_angle));
  if (opt.iterations < 0 || opt.iterations > 100)
    return status::invalid_argument(detail::cat("remesh: iterations must be in [0, 100], got ", opt.iterations));
  if (opt.max_faces < 4)
    return status::invalid_argument(detail::cat("remesh: max_faces must be >= 4, got ", opt.max_faces));
  auto input = to_tri_mesh(mesh, "remesh: mesh");
  if (!input) return input.error();
  const tri_mesh& in = *input;
  const aabb box = bounding_box(in);
  const vec3 ext = box.extent();
  const double L =
      opt.edge_length > 0 ? opt.edge_length : std::max({ext.x, ext.y, ext.z}) / static_cast<double>(opt.edges_across);
  double area = 0;
  for (index_t f = 0; f < in.num_faces(); ++f) area += face_area(in, f);
  const double estimate = area / (std::sqrt(3.0) / 4 * L * L);
  if (!(L > 0) || !(estimate <= static_cast<double>(opt.max_faces)))
    return status::invalid_argument(detail::cat("remesh: edge length ", L, " would need about ", estimate,
                                                " faces, more than max_faces ", opt.max_faces,
                                                "; choose a longer edge"));

  remesh_result out;
  remesh_stats& st = out.stats;
  st.edge_length = L;
  st.min_angle_input = detail::remesh_min_angle(in);
  detail::remesh_mesh m;
  m.assign(in.positions, in.faces);
  const auto segments = detail::remesh_mark_features(m, in, opt.feature_angle);
  st.feature_edges = static_cast<index_t>(segments.size());
  const detail::crease_grid creases(segments, box.min, L);
  const triangle_bvh surface(in);
  const double lo = 0.8 * L, hi = 4.0 / 3.0 * L,
               min_area2 = detail::remesh_min_area * L * L * detail::remesh_min_area * L * L;
  const index_t face_limit =
      opt.max_faces > std::numeric_limits<index_t>::max() / 2 ? opt.max_faces : 2 * opt.max_faces;
  for (int it = 0; it < opt.iterations; ++it) {
    if (!opt.progress.report(static_cast<double>(it) / opt.iterations, "remesh")) return status::cancelled();
    if (auto s = detail::remesh_split_long(m, hi, face_limit, st.splits); !s) return s;
    detail::remesh_collapse_short(m, lo, hi, min_area2, st.collapses);
    detail::remesh_equalize_valences(m, min_area2, st.flips);
    detail::remesh_relax_and_project(m, surface, creases, L, min_area2);
    detail::remesh_flip_slivers(m, min_area2, st.flips);
  }
  // the last collapses' midpoints and the moves refused as slivers are put back onto the input
  if (opt.iterations > 0) detail::remesh_relax_and_project(m, surface, creases, L, min_area2, false);
  out.mesh = m.compact();
  if (auto s = validate_polycube_input(out.mesh, "remesh: result"); !s)
    return status::internal_error(detail::cat(s.message(), " (a remeshing bug: please report it)"));
  st.min_angle = detail::remesh_min_angle(out.mesh);
  double sum = 0;
  index_t count = 0;
  for (const auto& e : mesh_edges(out.mesh)) {
    const double r =
        distance(out.mesh.positions[detail::to_size(e.v0)], out.mesh.positions[detail::to_size(e.v1)]) / L - 1;
    sum += r * r, ++count;
  }
  st.edge_length_rms = count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0;
  for (const vec3& p : out.mesh.positions) {
    const auto hit = surface.closest_point(p);
    if (hit.face >= 0) st.max_deviation = std::max(st.max_deviation, std::sqrt(hit.squared_distance) / L);
  }
  opt.progress.report(1, "remesh");
  return out;
}

TESSERA_NAMESPACE_END
