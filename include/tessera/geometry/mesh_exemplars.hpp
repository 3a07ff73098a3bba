// tessera/geometry/mesh_exemplars.hpp: procedural geometric-texture exemplars over the XY plane (height
// along +Z, base plane z = 0), for tests, examples, benchmarks and docs: rings (tori, optionally
// interlocked like European 4-in-1 chain mail), stones (seeded irregular pebbles) and weave (over-under
// threads). Every element is a closed, consistently oriented (outward normals), manifold surface, and
// no two elements intersect. Defaults give 4.5k-8k vertices, the range of the exemplars of paper 000
// (Ring 4608, Stone 6176, Weave 7704 vertices).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <vector>

#include "../core/config.hpp"
#include "../core/random.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "bvh.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of make_ring_exemplar.
struct ring_exemplar_options {
  double size = 8.0;     ///< the exemplar covers [0, size]^2
  double spacing = 1.6;  ///< distance between loose ring centres (density); chain mail uses a pitch of 1.3 major_radius
  double major_radius = 0.5;     ///< ring radius
  double minor_radius = 0.12;    ///< tube radius
  int ring_segments = 24;        ///< vertices around the ring (vertex count)
  int tube_segments = 8;         ///< vertices around the tube
  double jitter = 0.1;           ///< random centre offset, as a fraction of spacing (loose rings only)
  double max_tilt_degrees = 12;  ///< random tilt of loose rings
  bool chain_mail = false;       ///< interlock the rings like European 4-in-1 chain mail
  /// Seed of the layout.
  std::uint64_t seed = 1;
};

/// Options of make_stone_exemplar.
struct stone_exemplar_options {
  double size = 8.0;         ///< the exemplar covers [0, size]^2
  double min_radius = 0.35;  ///< pebble radius range in XY
  /// Largest pebble radius in XY.
  double max_radius = 0.65;
  double coverage = 0.55;   ///< fraction of the area the pebbles' footprints try to cover (density)
  double flatness = 0.55;   ///< height / width of a pebble
  double roughness = 0.12;  ///< relative amplitude of the shape noise
  double gap = 0.06;        ///< minimum distance between pebbles
  int subdivisions = 2;     ///< icosphere level: 2 = 162 vertices a pebble, 3 = 642 (vertex count)
  /// Seed of the layout.
  std::uint64_t seed = 1;
};

/// Options of make_weave_exemplar.
struct weave_exemplar_options {
  double size = 8.0;             ///< the exemplar covers [0, size]^2
  double spacing = 1.0;          ///< distance between parallel threads (density)
  double width = 0.36;           ///< thread half-width, fraction of spacing
  double thickness = 0.11;       ///< thread half-height, fraction of spacing
  double amplitude = 0.2;        ///< over-under amplitude, fraction of spacing
  int segments_per_spacing = 8;  ///< vertices along a thread per spacing (vertex count)
  int around = 8;                ///< vertices around a thread
  /// Seed of the layout.
  std::uint64_t seed = 1;
};

namespace detail {

inline void add_torus(tri_mesh& m, vec3 c, vec3 axis_u, vec3 axis_v, vec3 normal, double R, double r, int nu, int nv) {
  const index_t base = m.num_vertices();
  for (int i = 0; i < nu; ++i) {
    const double a = 2 * std::numbers::pi * i / nu;
    const vec3 dir = axis_u * std::cos(a) + axis_v * std::sin(a);
    for (int j = 0; j < nv; ++j) {
      const double b = 2 * std::numbers::pi * j / nv;
      m.add_vertex(c + dir * (R + r * std::cos(b)) + normal * (r * std::sin(b)));
    }
  }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const index_t a = base + i * nv + j, b = base + ((i + 1) % nu) * nv + j,
                    cc = base + ((i + 1) % nu) * nv + (j + 1) % nv, d = base + i * nv + (j + 1) % nv;
      m.add_face(a, b, cc);
      m.add_face(a, cc, d);
    }
}

// A tube along a polyline with elliptical cross-section (half-width w in the horizontal direction
// normal to the curve, half-height h along z), closed by fans at both ends.
inline void add_tube(tri_mesh& m, const std::vector<vec3>& path, double w, double h, int around) {
  const index_t base = m.num_vertices();
  const auto n = static_cast<index_t>(path.size());
  for (index_t i = 0; i < n; ++i) {
    const vec3 t = normalized(path[to_size(std::min(i + 1, n - 1))] - path[to_size(std::max<index_t>(i - 1, 0))]);
    const vec3 side = normalized(cross(vec3{0, 0, 1}, t));
    const vec3 up = normalized(cross(t, side));
    for (int j = 0; j < around; ++j) {
      const double b = 2 * std::numbers::pi * j / around;
      m.add_vertex(path[to_size(i)] + side * (w * std::cos(b)) + up * (h * std::sin(b)));
    }
  }
  for (index_t i = 0; i + 1 < n; ++i)
    for (int j = 0; j < around; ++j) {
      const index_t a = base + i * around + j, b = base + (i + 1) * around + j,
                    c = base + (i + 1) * around + (j + 1) % around, d = base + i * around + (j + 1) % around;
      m.add_face(a, d, c);
      m.add_face(a, c, b);
    }
  const index_t c0 = m.add_vertex(path.front()), c1 = m.add_vertex(path.back());
  for (int j = 0; j < around; ++j) {
    m.add_face(c0, base + (j + 1) % around, base + j);
    m.add_face(c1, base + (n - 1) * around + j, base + (n - 1) * around + (j + 1) % around);
  }
}

inline tri_mesh icosphere(int level) {
  tri_mesh m;
  const double t = (1 + std::sqrt(5.0)) / 2;
  for (vec3 p : {vec3{-1, t, 0}, vec3{1, t, 0}, vec3{-1, -t, 0}, vec3{1, -t, 0}, vec3{0, -1, t}, vec3{0, 1, t},
                 vec3{0, -1, -t}, vec3{0, 1, -t}, vec3{t, 0, -1}, vec3{t, 0, 1}, vec3{-t, 0, -1}, vec3{-t, 0, 1}})
    m.add_vertex(normalized(p));
  const int f[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (const auto& x : f) m.add_face(x[0], x[1], x[2]);
  for (int l = 0; l < level; ++l) {
    tri_mesh n;
    n.positions = m.positions;
    std::map<std::pair<index_t, index_t>, index_t> mid;
    auto midpoint = [&](index_t a, index_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find({key.first, key.second});
      if (it != mid.end()) return it->second;
      const index_t id = n.add_vertex(normalized(n.positions[to_size(a)] + n.positions[to_size(b)]));
      mid[{key.first, key.second}] = id;
      return id;
    };
    for (const auto& fc : m.faces) {
      const index_t a = midpoint(fc[0], fc[1]), b = midpoint(fc[1], fc[2]), c = midpoint(fc[2], fc[0]);
      n.add_face(fc[0], a, c);
      n.add_face(fc[1], b, a);
      n.add_face(fc[2], c, b);
      n.add_face(a, b, c);
    }
    m = std::move(n);
  }
  return m;
}

// Checks that no two distinct elements (vertex ranges) of a generated exemplar intersect.
inline bool elements_disjoint(const tri_mesh& m, const std::vector<index_t>& element_of_vertex) {
  const triangle_bvh bvh(m);
  bool ok = true;
  bvh.for_each_self_intersection(
      [&](index_t f, index_t g) {
        return element_of_vertex[to_size(m.faces[to_size(f)][0])] == element_of_vertex[to_size(m.faces[to_size(g)][0])];
      },
      [&](index_t, index_t) { ok = false; });
  return ok;
}

inline status check_size(double size, double feature, const char* what) {
  if (!(size > 0) || !std::isfinite(size))
    return status::invalid_argument(detail::cat(what, ": size must be > 0, got ", size));
  if (size < feature)
    return status::invalid_argument(detail::cat(what, ": size ", size, " is smaller than one element (", feature, ")"));
  return {};
}

}  // namespace detail

/// Largest vertex count the procedural mesh exemplars build (2^24); exemplars are small. Each
/// generator estimates its vertex count from the options and refuses more before building anything.
inline constexpr index_t max_exemplar_mesh_vertices = index_t{1} << 24;

namespace detail {
inline status check_exemplar_vertices(double estimate, std::string_view what) {
  if (!(estimate <= static_cast<double>(max_exemplar_mesh_vertices)))
    return status::size_overflow(cat(what, ": the options ask for about ", estimate,
                                     " vertices, more than max_exemplar_mesh_vertices = ", max_exemplar_mesh_vertices,
                                     " (reduce size or the segment counts, or increase spacing)"));
  return {};
}
}  // namespace detail

/// Rings: tori lying on the plane (loose: jittered grid, small random tilts; chain mail: European
/// 4-in-1, rows of rings leaning alternately so each ring passes through four neighbours).
/// Errors: non-positive sizes or radii, fewer than 3 segments, a spacing too small for loose rings
/// not to touch, or parameters for which the generated rings would intersect.
inline result<tri_mesh> make_ring_exemplar(const ring_exemplar_options& o = {}) {
  const double R = o.major_radius, r = o.minor_radius;
  if (!(R > 0) || !(r > 0) || !(r < R))
    return status::invalid_argument(
        detail::cat("ring exemplar: need 0 < minor_radius < major_radius, got ", r, " and ", R));
  if (o.ring_segments < 3 || o.tube_segments < 3)
    return status::invalid_argument(detail::cat("ring exemplar: ring_segments and tube_segments must be >= 3, got ",
                                                o.ring_segments, " and ", o.tube_segments));
  if (!(o.spacing > 0))
    return status::invalid_argument(detail::cat("ring exemplar: spacing must be > 0, got ", o.spacing));
  if (auto s = detail::check_size(o.size, 2 * (R + r), "ring exemplar"); !s) return s;
  if (!(o.jitter >= 0 && o.jitter < 0.5))
    return status::invalid_argument(detail::cat("ring exemplar: jitter must be in [0, 0.5), got ", o.jitter));
  {
    const double per_ring = static_cast<double>(o.ring_segments) * o.tube_segments;
    const double rings =
        o.chain_mail ? std::pow(o.size / (1.3 * R) + 1, 2) : std::pow(std::floor(o.size / o.spacing), 2);
    if (auto s = detail::check_exemplar_vertices(rings * per_ring, "ring exemplar"); !s) return s;
  }
  const counter_rng rng(o.seed, stream_id("geometry.exemplar.rings"));
  tri_mesh m;
  std::vector<index_t> element;
  auto add = [&](vec3 c, vec3 u, vec3 v, vec3 n) {
    const index_t before = m.num_vertices();
    detail::add_torus(m, c, u, v, n, R, r, o.ring_segments, o.tube_segments);
    element.resize(detail::to_size(m.num_vertices()), static_cast<index_t>(before));
  };
  if (!o.chain_mail) {
    if (o.spacing * (1 - 2 * o.jitter) <= 2 * (R + r))
      return status::invalid_argument(detail::cat("ring exemplar: spacing ", o.spacing, " with jitter ", o.jitter,
                                                  " lets rings of outer radius ", R + r, " touch"));
    const int n = static_cast<int>(std::floor(o.size / o.spacing));
    const double margin = (o.size - n * o.spacing) / 2 + o.spacing / 2;
    const double max_tilt = o.max_tilt_degrees * std::numbers::pi / 180;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double jx = (rng.uniform(i, j, 0) * 2 - 1) * o.jitter * o.spacing,
                     jy = (rng.uniform(i, j, 1) * 2 - 1) * o.jitter * o.spacing;
        const double tilt = rng.uniform(i, j, 2) * max_tilt, dir = rng.uniform(i, j, 3) * 2 * std::numbers::pi;
        const double yaw = rng.uniform(i, j, 4) * 2 * std::numbers::pi;
        const vec3 n0{std::sin(tilt) * std::cos(dir), std::sin(tilt) * std::sin(dir), std::cos(tilt)};
        vec3 u = normalized(cross(n0, vec3{std::cos(yaw), std::sin(yaw), 0}));
        if (squared_norm(u) == 0) u = {1, 0, 0};
        const vec3 v = cross(n0, u);
        const double lift = r + R * std::sin(tilt) + 0.02;
        add({margin + i * o.spacing + jx, margin + j * o.spacing + jy, lift}, u, v, n0);
      }
  } else {
    // European 4-in-1: rows along x; ring i of row j at (i + j/2) * dx, j * dy, leaning about the y
    // axis by +theta (even rows) or -theta (odd rows), so neighbours in a row shingle and each ring
    // threads through two rings of the rows above and below.
    // pitch 1.3 R and lean 0.62 rad: each ring links exactly its four diagonal neighbours (checked
    // by the tests with a linking count) while the tubes stay apart for minor_radius <= 0.16 R.
    const double dx = 1.3 * R, dy = 1.3 * R;
    const double theta = 0.62;
    const int nx = static_cast<int>(std::floor((o.size - 2 * (R + r)) / dx)) + 1;
    const int ny = static_cast<int>(std::floor((o.size - 2 * (R + r)) / dy)) + 1;
    if (nx < 1 || ny < 1) return status::invalid_argument("ring exemplar: size too small for chain mail");
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i + (j % 2) < nx; ++i) {
        const double s = j % 2 == 0 ? 1.0 : -1.0;
        const vec3 n0{std::sin(theta) * s, 0, std::cos(theta)};
        const vec3 u{std::cos(theta), 0, -std::sin(theta) * s}, v{0, 1, 0};
        add({R + r + (i + 0.5 * (j % 2)) * dx, R + r + j * dy, (R + r) * std::sin(theta) + r}, u, v, n0);
      }
  }
  if (!detail::elements_disjoint(m, element))
    return status::invalid_argument(detail::cat("ring exemplar: with spacing ", o.spacing, ", radii ", R, " and ", r,
                                                " the rings intersect; increase spacing or reduce minor_radius"));
  return m;
}

/// Stones: seeded irregular pebbles (noisy, flattened icospheres with random radii and orientation)
/// scattered without overlap by dart throwing until `coverage` is reached or no room is left.
/// Errors: non-positive sizes, min_radius > max_radius, coverage outside (0, 0.9], subdivisions
/// outside [0, 5].
inline result<tri_mesh> make_stone_exemplar(const stone_exemplar_options& o = {}) {
  if (!(o.min_radius > 0) || !(o.max_radius >= o.min_radius))
    return status::invalid_argument(
        detail::cat("stone exemplar: need 0 < min_radius <= max_radius, got ", o.min_radius, " and ", o.max_radius));
  if (auto s = detail::check_size(o.size, 2 * o.max_radius, "stone exemplar"); !s) return s;
  if (!(o.coverage > 0 && o.coverage <= 0.9))
    return status::invalid_argument(detail::cat("stone exemplar: coverage must be in (0, 0.9], got ", o.coverage));
  if (o.subdivisions < 0 || o.subdivisions > 5)
    return status::invalid_argument(
        detail::cat("stone exemplar: subdivisions must be in [0, 5], got ", o.subdivisions));
  if (!(o.flatness > 0) || !(o.roughness >= 0 && o.roughness < 0.5) || !(o.gap >= 0))
    return status::invalid_argument("stone exemplar: flatness must be > 0, roughness in [0, 0.5), gap >= 0");
  {
    const double per_pebble = 10 * std::pow(4.0, o.subdivisions) + 2;
    const double pebbles =
        std::min(20000.0, o.coverage * o.size * o.size / (std::numbers::pi * o.min_radius * o.min_radius) + 1);
    if (auto s = detail::check_exemplar_vertices(pebbles * per_pebble, "stone exemplar"); !s) return s;
  }
  const counter_rng rng(o.seed, stream_id("geometry.exemplar.stones"));
  const tri_mesh sphere = detail::icosphere(o.subdivisions);
  struct disk {
    double x, y, r;
  };
  std::vector<disk> placed;
  double covered = 0;
  const double target = o.coverage * o.size * o.size;
  tri_mesh m;
  for (std::uint64_t attempt = 0; attempt < 20000 && covered < target; ++attempt) {
    const double rad = o.min_radius + (o.max_radius - o.min_radius) * rng.uniform(attempt, 0);
    const double outer = rad * (1 + o.roughness);
    const double x = outer + (o.size - 2 * outer) * rng.uniform(attempt, 1),
                 y = outer + (o.size - 2 * outer) * rng.uniform(attempt, 2);
    bool free = true;
    for (const disk& d : placed)
      if ((d.x - x) * (d.x - x) + (d.y - y) * (d.y - y) < (d.r + outer + o.gap) * (d.r + outer + o.gap)) {
        free = false;
        break;
      }
    if (!free) continue;
    placed.push_back({x, y, outer});
    covered += std::numbers::pi * rad * rad;
    // shape: ellipsoid axes, yaw, and a smooth noise from a few random harmonics
    const double ax = rad, ay = rad * (0.7 + 0.3 * rng.uniform(attempt, 3)), az = rad * o.flatness;
    const double yaw = rng.uniform(attempt, 4) * 2 * std::numbers::pi;
    double k[3][4];
    for (int h = 0; h < 3; ++h)
      for (int c = 0; c < 4; ++c) k[h][c] = rng.uniform(attempt, 10 + h, c) * 2 - 1;
    const index_t base = m.num_vertices();
    for (const vec3& p : sphere.positions) {
      double noise = 0;
      for (int h = 0; h < 3; ++h)
        noise += std::sin((h + 1.5) * (k[h][0] * p.x + k[h][1] * p.y + k[h][2] * p.z) * 2.2 + 3 * k[h][3]) / (h + 1);
      const double s = 1 + o.roughness * noise / 1.84;
      const vec3 q{p.x * ax * s, p.y * ay * s, p.z * az * s};
      const double c = std::cos(yaw), sn = std::sin(yaw);
      m.add_vertex({x + c * q.x - sn * q.y, y + sn * q.x + c * q.y, q.z + az * (1 + o.roughness) + 0.01});
    }
    for (const auto& f : sphere.faces) m.add_face(base + f[0], base + f[1], base + f[2]);
  }
  if (m.faces.empty()) return status::invalid_argument("stone exemplar: no pebble fits; increase size or reduce radii");
  return m;
}

/// Weave: plain over-under weave of threads along x and y (flattened elliptical tubes following a
/// sine over and under the crossing threads), each thread closed at both ends.
/// Errors: non-positive sizes, fewer than 4 vertices around or along, or a thickness too large for
/// the amplitude (crossing threads would touch).
inline result<tri_mesh> make_weave_exemplar(const weave_exemplar_options& o = {}) {
  if (!(o.spacing > 0))
    return status::invalid_argument(detail::cat("weave exemplar: spacing must be > 0, got ", o.spacing));
  if (auto s = detail::check_size(o.size, 2 * o.spacing, "weave exemplar"); !s) return s;
  if (o.around < 4 || o.segments_per_spacing < 4)
    return status::invalid_argument(detail::cat("weave exemplar: around and segments_per_spacing must be >= 4, got ",
                                                o.around, " and ", o.segments_per_spacing));
  if (!(o.width > 0 && o.width < 0.5) || !(o.thickness > 0) || !(o.amplitude > 0))
    return status::invalid_argument("weave exemplar: need width in (0, 0.5), thickness > 0, amplitude > 0");
  if (o.amplitude * (1 + std::cos(std::numbers::pi * o.width)) <= 2 * o.thickness * 1.05)
    return status::invalid_argument(detail::cat("weave exemplar: thickness ", o.thickness,
                                                " is too large for amplitude ", o.amplitude,
                                                "; crossing threads would touch"));
  {
    const double threads = std::floor(o.size / o.spacing);
    if (auto s = detail::check_exemplar_vertices(
            2 * threads * (threads * o.segments_per_spacing + 1) * static_cast<double>(o.around), "weave exemplar");
        !s)
      return s;
  }
  const double s = o.spacing;
  const int n = static_cast<int>(std::floor(o.size / s));
  const double margin = (o.size - n * s) / 2;
  const double end_gap = 0.05 * s;
  const double h0 = (o.amplitude + o.thickness) * s + 0.02 * s;
  tri_mesh m;
  for (int dir = 0; dir < 2; ++dir)
    for (int j = 0; j < n; ++j) {
      std::vector<vec3> path;
      const int steps = n * o.segments_per_spacing;
      for (int k = 0; k <= steps; ++k) {
        const double t = end_gap + (o.size - 2 * end_gap) * k / steps;
        const double across = margin + (j + 0.5) * s;
        // x-threads: over at even crossings when j is even; y-threads do the opposite
        const double phase =
            std::numbers::pi * ((t - margin) / s - 0.5) + std::numbers::pi * j + (dir == 1 ? std::numbers::pi : 0.0);
        const double z = h0 + o.amplitude * s * std::cos(phase);
        path.push_back(dir == 0 ? vec3{t, across, z} : vec3{across, t, z});
      }
      if (dir == 1) std::reverse(path.begin(), path.end());  // keep every tube outward oriented
      detail::add_tube(m, path, o.width * s, o.thickness * s, o.around);
    }
  return m;
}

TESSERA_NAMESPACE_END
