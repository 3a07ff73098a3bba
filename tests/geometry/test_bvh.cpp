#include <tessera/geometry/bvh.hpp>

#include <tessera/core/mesh_view.hpp>
#include <tessera/core/random.hpp>
#include <tessera/core/tri_mesh.hpp>

#include <catch2/catch.hpp>

#include <set>

using namespace tessera;

namespace {
// A random soup of small triangles in the unit cube.
tri_mesh random_soup(std::uint64_t seed, int n, double size) {
  counter_rng rng(seed);
  tri_mesh m;
  for (int i = 0; i < n; ++i) {
    const vec3 c{rng.uniform(i, 0), rng.uniform(i, 1), rng.uniform(i, 2)};
    index_t v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = m.add_vertex(c + vec3{rng.uniform(i, k, 3) - 0.5, rng.uniform(i, k, 4) - 0.5, rng.uniform(i, k, 5) - 0.5} *
                                  size);
    m.add_face(v[0], v[1], v[2]);
  }
  return m;
}
std::array<vec3, 3> corners(const tri_mesh& m, index_t f) {
  return {m.position(m.face_vertex(f, 0)), m.position(m.face_vertex(f, 1)), m.position(m.face_vertex(f, 2))};
}
}  // namespace

TEST_CASE("closest point on a triangle matches dense sampling", "[bvh]") {
  counter_rng rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const vec3 a{rng.uniform(trial, 0), rng.uniform(trial, 1), rng.uniform(trial, 2)};
    const vec3 b{rng.uniform(trial, 3), rng.uniform(trial, 4), rng.uniform(trial, 5)};
    const vec3 c{rng.uniform(trial, 6), rng.uniform(trial, 7), rng.uniform(trial, 8)};
    const vec3 p =
        vec3{rng.uniform(trial, 9), rng.uniform(trial, 10), rng.uniform(trial, 11)} * 2.0 - vec3{0.5, 0.5, 0.5};
    const auto r = detail::closest_point_on_triangle(p, a, b, c);
    const vec3 rebuilt = a * r.bary.x + b * r.bary.y + c * r.bary.z;
    REQUIRE(norm(rebuilt - r.point) < 1e-9);
    REQUIRE(r.bary.x >= -1e-12);
    REQUIRE(r.bary.y >= -1e-12);
    REQUIRE(r.bary.z >= -1e-12);
    double best = 1e300;
    const int n = 60;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double u = double(i) / n, v = double(j) / n;
        best = std::min(best, norm(a + (b - a) * u + (c - a) * v - p));
      }
    REQUIRE(norm(r.point - p) <= best + 1e-12);
    REQUIRE(norm(r.point - p) >= best - 0.05);
  }
}

TEST_CASE("BVH closest point equals brute force", "[bvh]") {
  const tri_mesh m = random_soup(3, 300, 0.1);
  const triangle_bvh bvh(m);
  REQUIRE(bvh.num_faces() == 300);
  counter_rng rng(11);
  for (int q = 0; q < 300; ++q) {
    const vec3 p{rng.uniform(q, 0) * 1.4 - 0.2, rng.uniform(q, 1) * 1.4 - 0.2, rng.uniform(q, 2) * 1.4 - 0.2};
    double best = 1e300;
    index_t best_f = -1;
    for (index_t f = 0; f < m.num_faces(); ++f) {
      const auto c = corners(m, f);
      const double d2 = squared_norm(detail::closest_point_on_triangle(p, c[0], c[1], c[2]).point - p);
      if (d2 < best) best = d2, best_f = f;
    }
    const auto hit = bvh.closest_point(p);
    REQUIRE(hit.face == best_f);
    REQUIRE(hit.squared_distance == Approx(best).epsilon(1e-12));
    // a radius smaller than the answer finds nothing
    const auto none = bvh.closest_point(p, best * 0.5);
    REQUIRE(none.face == -1);
  }
}

TEST_CASE("BVH over a float mesh_view gives the same answers", "[bvh]") {
  const tri_mesh m = random_soup(5, 100, 0.2);
  std::vector<float> pos;
  std::vector<std::uint32_t> idx;
  for (const vec3& p : m.positions) pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
  for (const auto& f : m.faces) idx.insert(idx.end(), {std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
  auto view = make_mesh_view(pos.data(), m.num_vertices(), idx.data(), m.num_faces());
  REQUIRE(view.ok());
  const triangle_bvh a(m), b(*view);
  for (int q = 0; q < 50; ++q) {
    const vec3 p{0.02 * q, 0.5, 0.3};
    REQUIRE(a.closest_point(p).face == b.closest_point(p).face);
  }
}

TEST_CASE("BVH raycast equals brute force", "[bvh]") {
  const tri_mesh m = random_soup(9, 200, 0.15);
  const triangle_bvh bvh(m);
  counter_rng rng(13);
  int hits = 0;
  for (int q = 0; q < 300; ++q) {
    const vec3 o{rng.uniform(q, 0), rng.uniform(q, 1), -1.0};
    const vec3 d{rng.uniform(q, 2) * 0.2 - 0.1, rng.uniform(q, 3) * 0.2 - 0.1, 1.0};
    double best = std::numeric_limits<double>::infinity();
    index_t best_f = -1;
    for (index_t f = 0; f < m.num_faces(); ++f) {
      const auto c = corners(m, f);
      const auto h = detail::ray_triangle(o, d, c[0], c[1], c[2], 0, 1e300);
      if (h.t < best) best = h.t, best_f = f;
    }
    const auto hit = bvh.raycast(o, d);
    REQUIRE(hit.face == best_f);
    if (best_f >= 0) {
      ++hits;
      REQUIRE(hit.t == Approx(best));
    }
  }
  REQUIRE(hits > 50);
}

TEST_CASE("BVH min_cost_face with a box bound equals brute force", "[bvh]") {
  const tri_mesh m = random_soup(17, 250, 0.1);
  const triangle_bvh bvh(m);
  const auto normals = face_normals(m);
  const vec3 n{0, 0, 1};
  const double lambda = 0.7;
  for (int q = 0; q < 100; ++q) {
    const vec3 p{0.01 * q, 0.3 + 0.004 * q, 0.5};
    auto cost = [&](index_t f, const std::array<vec3, 3>& c) {
      const double d = norm(detail::closest_point_on_triangle(p, c[0], c[1], c[2]).point - p);
      return (1 + d) * (1 + lambda * (1 - dot(n, normals[static_cast<std::size_t>(f)])));
    };
    auto bound = [&](const aabb& b) { return 1 + std::sqrt(detail::squared_distance_to_box(p, b)); };
    double best = 1e300;
    index_t best_f = -1;
    for (index_t f = 0; f < m.num_faces(); ++f) {
      const double c = cost(f, corners(m, f));
      if (c < best) best = c, best_f = f;
    }
    const auto [f, c] = bvh.min_cost_face(cost, bound);
    REQUIRE(f == best_f);
    REQUIRE(c == Approx(best));
  }
}

TEST_CASE("triangle-triangle test agrees with the edge-crossing oracle", "[bvh]") {
  counter_rng rng(21);
  int positives = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::array<vec3, 3> t, u;
    for (int k = 0; k < 3; ++k) {
      t[static_cast<std::size_t>(k)] = {rng.uniform(trial, k, 0), rng.uniform(trial, k, 1), rng.uniform(trial, k, 2)};
      u[static_cast<std::size_t>(k)] = {rng.uniform(trial, k, 3), rng.uniform(trial, k, 4), rng.uniform(trial, k, 5)};
    }
    // non-coplanar in general position: intersect iff an edge of one crosses the other
    bool oracle = false;
    for (int k = 0; k < 3; ++k) {
      oracle = oracle || detail::segment_hits_triangle(t[k], t[(k + 1) % 3], u[0], u[1], u[2]);
      oracle = oracle || detail::segment_hits_triangle(u[k], u[(k + 1) % 3], t[0], t[1], t[2]);
    }
    REQUIRE(detail::triangles_intersect(t, u) == oracle);
    REQUIRE(detail::triangles_intersect(u, t) == oracle);
    positives += oracle;
  }
  REQUIRE(positives > 100);
}

TEST_CASE("triangle-triangle test: coplanar, touching and shared-vertex cases", "[bvh]") {
  const std::array<vec3, 3> a{vec3{0, 0, 0}, vec3{1, 0, 0}, vec3{0, 1, 0}};
  REQUIRE(detail::triangles_intersect(a, {vec3{0.2, 0.2, 0}, vec3{2, 0.2, 0}, vec3{0.2, 2, 0}}));  // coplanar overlap
  REQUIRE_FALSE(detail::triangles_intersect(a, {vec3{2, 2, 0}, vec3{3, 2, 0}, vec3{2, 3, 0}}));    // coplanar apart
  REQUIRE(detail::triangles_intersect(a, {vec3{1, 0, 0}, vec3{2, 0, 0}, vec3{2, 1, 0}}));          // share a vertex
  REQUIRE_FALSE(detail::triangles_intersect(a, {vec3{0, 0, 0.1}, vec3{1, 0, 0.1}, vec3{0, 1, 0.1}}));    // parallel
  REQUIRE(detail::triangles_intersect(a, {vec3{0.2, 0.2, -1}, vec3{0.2, 0.2, 1}, vec3{0.3, 0.25, 1}}));  // piercing
  REQUIRE_FALSE(detail::triangles_intersect(a, {vec3{0.8, 0.8, -1}, vec3{0.8, 0.8, 1}, vec3{0.9, 0.85, 1}}));
}

TEST_CASE("triangle-triangle test: nearly parallel triangles apart", "[bvh]") {
  // two pieces of one flat facet of a mapped ring element (planes 1.7e-5 rad apart, 2.2e-4 apart in the
  // plane): Möller's intervals along the nearly degenerate intersection line called them crossing
  const std::array<vec3, 3> a{vec3{1.73839853, 1.73748816, 0.57849332}, vec3{1.73811791, 1.73757191, 0.57790904},
                              vec3{1.73781883, 1.73753307, 0.5782972}};
  const std::array<vec3, 3> b{vec3{1.73780035, 1.73741047, 0.57926964}, vec3{1.73809944, 1.73744931, 0.57888148},
                              vec3{1.7375105, 1.73743293, 0.57917158}};
  REQUIRE_FALSE(detail::triangles_intersect(a, b));
  REQUIRE_FALSE(detail::triangles_intersect(b, a));
  // an edge of one lying in the other's plane, inside it (the other's edges miss the first triangle)
  const std::array<vec3, 3> c{vec3{0, 0, 0}, vec3{4, 0, 0}, vec3{0, 4, 0}};
  REQUIRE(detail::triangles_intersect(c, {vec3{1, 1, 0}, vec3{1.5, 1, 0}, vec3{1.2, 1, 1}}));
  REQUIRE(detail::triangles_intersect({vec3{1, 1, 0}, vec3{1.5, 1, 0}, vec3{1.2, 1, 1}}, c));
  REQUIRE_FALSE(detail::triangles_intersect(c, {vec3{5, 1, 0}, vec3{5.5, 1, 0}, vec3{5.2, 1, 1}}));
}

TEST_CASE("BVH intersecting pairs equal brute force", "[bvh]") {
  const tri_mesh a = random_soup(31, 150, 0.15), b = random_soup(32, 150, 0.15);
  const triangle_bvh ba(a), bb(b);
  std::set<std::pair<index_t, index_t>> found, expected;
  for_each_intersecting_pair(ba, bb, [&](index_t f, index_t g) { REQUIRE(found.insert({f, g}).second); });
  for (index_t f = 0; f < a.num_faces(); ++f)
    for (index_t g = 0; g < b.num_faces(); ++g)
      if (detail::triangles_intersect(corners(a, f), corners(b, g))) expected.insert({f, g});
  REQUIRE(found == expected);
  REQUIRE(!expected.empty());

  std::set<std::pair<index_t, index_t>> self, self_expected;
  ba.for_each_self_intersection([](index_t, index_t) { return false; },
                                [&](index_t f, index_t g) {
                                  self.insert({f, g});
                                });
  for (index_t f = 0; f < a.num_faces(); ++f)
    for (index_t g = f + 1; g < a.num_faces(); ++g)
      if (detail::triangles_intersect(corners(a, f), corners(a, g))) self_expected.insert({f, g});
  REQUIRE(self == self_expected);
}

TEST_CASE("BVH box query and empty hierarchy", "[bvh]") {
  const triangle_bvh empty;
  REQUIRE(empty.closest_point({0, 0, 0}).face == -1);
  REQUIRE(empty.raycast({0, 0, 0}, {0, 0, 1}).face == -1);
  const tri_mesh m = random_soup(41, 120, 0.1);
  const triangle_bvh bvh(m);
  aabb q;
  q.extend(vec3{0.2, 0.2, 0.2});
  q.extend(vec3{0.6, 0.5, 0.7});
  std::set<index_t> got, want;
  bvh.for_each_overlapping(q, [&](index_t f) { got.insert(f); });
  for (index_t f = 0; f < m.num_faces(); ++f) {
    aabb b;
    for (const vec3& p : corners(m, f)) b.extend(p);
    if (detail::boxes_overlap(b, q)) want.insert(f);
  }
  REQUIRE(got == want);
  REQUIRE(bvh.triangle(5) == corners(m, 5));
}
