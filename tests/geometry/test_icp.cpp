#include <tessera/geometry/icp.hpp>

#include <tessera/core/tri_mesh.hpp>

#include <catch2/catch.hpp>

#include <vector>

using namespace tessera;

namespace {
// a wavy sheet: enough structure to pin a translation in x and y
tri_mesh sheet(int n) {
  tri_mesh m;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) {
      const double u = 4.0 * x / n, v = 4.0 * y / n;
      m.add_vertex({u, v, 0.3 * std::sin(2.1 * u) * std::cos(1.7 * v)});
    }
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const index_t a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      m.add_face(a, b, d);
      m.add_face(a, d, c);
    }
  return m;
}
}  // namespace

TEST_CASE("translation ICP recovers a small translation", "[icp]") {
  const tri_mesh m = sheet(40);
  const triangle_bvh bvh(m);
  const vec3 t{0.12, -0.09, 0.0};
  std::vector<vec3> pts;
  for (index_t v = 0; v < m.num_vertices(); v += 7) {
    const vec3 p = m.positions[std::size_t(v)];
    if (p.x > 1 && p.x < 3 && p.y > 1 && p.y < 3) pts.push_back(p + t);
  }
  const auto r =
      icp_translation(pts, bvh, {}, {.max_iterations = 500, .tolerance = 1e-6, .free_axes = {true, true, false}});
  REQUIRE(r.ok());
  INFO(r->iterations << " " << r->translation.x << " " << r->translation.y);
  REQUIRE(r->converged);
  REQUIRE(norm(r->translation - t) < 5e-3);
  REQUIRE(r->mean_distance < 5e-3);
  REQUIRE(r->translation.z == 0.0);  // z was not free
}

TEST_CASE("translation ICP: free z moves a lifted point set down onto the surface", "[icp]") {
  const tri_mesh m = sheet(20);
  const triangle_bvh bvh(m);
  std::vector<vec3> pts;
  for (const vec3& p : m.positions) pts.push_back(p + vec3{0, 0, 0.25});
  const auto r = icp_translation(pts, bvh, {});
  REQUIRE(r.ok());
  REQUIRE(r->translation.z == Approx(0.25).margin(1e-3));
}

TEST_CASE("translation ICP rejects bad input", "[icp]") {
  const tri_mesh m = sheet(4);
  const triangle_bvh bvh(m), empty;
  std::vector<vec3> pts{{1, 1, 0}};
  REQUIRE(icp_translation(pts, empty, {}).error().code() == status_code::invalid_argument);
  REQUIRE_FALSE(icp_translation(pts, bvh, {}, {.max_iterations = 0}).ok());
  REQUIRE_FALSE(icp_translation(pts, bvh, {}, {.tolerance = 0}).ok());
  REQUIRE_FALSE(icp_translation(pts, bvh, {std::nan(""), 0, 0}).ok());
  std::vector<vec3> bad{{std::nan(""), 0, 0}};
  REQUIRE(icp_translation(bad, bvh, {}).error().message().find("point 0") != std::string::npos);
  // no pairs within max_distance: returns the start unchanged
  std::vector<vec3> far{{100, 100, 100}};
  const auto r = icp_translation(far, bvh, {}, {.max_distance = 1});
  REQUIRE(r.ok());
  REQUIRE(r->pairs == 0);
  REQUIRE(r->translation == vec3{});
}
