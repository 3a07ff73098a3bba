#include <tessera/core/executor.hpp>
#include <tessera/core/random.hpp>
#include <tessera/terrain/anchored_region_geometry.hpp>
#include <tessera/terrain/synthesize_anchored_region.hpp>
#include <tessera/terrain/texture_stretch.hpp>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

TEST_CASE("make_anchored_geometry: region numbering, neighbours and shapes equal a direct computation",
          "[terrain][anchored]") {
  const auto mesh = terrain_test::prepared_terrain(24, 3, 9);
  const auto plan = tessera::plan_anchored_regions(mesh, 64, 64, {.region_size = 0.4}).value();
  REQUIRE(plan.num_regions() >= 4);
  const auto geo = tessera::make_anchored_geometry(mesh, plan).value();
  REQUIRE(geo.faces.size() == plan.faces.size());
  const double tpu = plan.texels_per_unit;
  for (index_t r = 0; r < plan.num_regions(); ++r) {
    const auto b = static_cast<std::size_t>(plan.first[static_cast<std::size_t>(r)]),
               e = static_cast<std::size_t>(plan.first[static_cast<std::size_t>(r) + 1]);
    std::map<std::int32_t, std::int32_t> number;  // mesh vertex -> region number, one to one
    std::map<std::int32_t, std::int32_t> seen;
    for (std::size_t i = b; i < e; ++i) {
      const auto f = static_cast<std::size_t>(plan.faces[i]);
      const auto& g = geo.faces[i];
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int32_t v = mesh.faces[f][k], lv = g.vertices[k];
        REQUIRE(lv >= 0);
        REQUIRE(lv < geo.vertex_count[static_cast<std::size_t>(r)]);
        if (number.count(v)) REQUIRE(number[v] == lv);
        if (seen.count(lv)) REQUIRE(seen[lv] == v);
        number[v] = lv, seen[lv] = v;
        // the neighbour across side k as an index in the region, or -1 outside it
        const std::int32_t n = mesh.neighbors[f][k];
        if (n < 0 || plan.region[static_cast<std::size_t>(n)] != r) {
          REQUIRE(g.neighbors[k] == -1);
        } else {
          REQUIRE(plan.faces[b + static_cast<std::size_t>(g.neighbors[k])] == n);
        }
      }
      // the shape: side k in the face's own plane (to_plane_triangle), C = A + a e + b perp(e)
      const auto& fv = mesh.faces[f];
      const tessera::vec3 p[3] = {mesh.position(fv[0]), mesh.position(fv[1]), mesh.position(fv[2])};
      const auto t = tessera::detail::to_plane_triangle(p[0], p[1], p[2]);
      const tessera::vec2 q[3] = {{0, 0}, {t.l1, 0}, {t.x2, t.y2}};
      for (std::size_t k = 0; k < 3; ++k) {
        const tessera::vec2 ev = q[(k + 1) % 3] - q[k], w = q[(k + 2) % 3] - q[k];
        const double len2 = tessera::dot(ev, ev);
        REQUIRE(g.len2[k] == Approx(len2).epsilon(1e-12));
        REQUIRE(g.a[k] == Approx(tessera::dot(w, ev) / len2).epsilon(1e-9).margin(1e-12));
        REQUIRE(g.area2 / g.len2[k] == Approx(tessera::cross(ev, w) / len2).epsilon(1e-9));
      }
      REQUIRE(g.inv_metric == Approx(1 / (tpu * tpu * g.area2 * g.area2)).epsilon(1e-12));
    }
    REQUIRE(static_cast<std::int32_t>(number.size()) == geo.vertex_count[static_cast<std::size_t>(r)]);
  }
  // the same bytes for any executor
  tessera::thread_pool_executor pool(3);
  const auto again = tessera::make_anchored_geometry(mesh, plan, pool).value();
  REQUIRE(again.vertex_count == geo.vertex_count);
  REQUIRE(std::memcmp(again.faces.data(), geo.faces.data(), geo.faces.size() * sizeof(geo.faces[0])) == 0);
}

TEST_CASE("anchored_within equals the stretch measure's bound, anchored_unfold places a congruent copy",
          "[terrain][anchored][stretch]") {
  const tessera::counter_rng rng(11, 0);
  index_t within = 0, outside = 0;
  for (std::uint64_t i = 0; i < 4000; ++i) {
    auto u = [&](std::uint64_t j) { return 2 * rng.uniform(i, j) - 1; };
    const std::array<tessera::vec3, 3> p = {tessera::vec3{u(0), u(1), u(2)}, tessera::vec3{u(3), u(4), u(5)},
                                            tessera::vec3{u(6), u(7), u(8)}};
    const double tpu = 3 + 20 * rng.uniform(i, 9);
    tessera::anchored_face_geometry g;
    tessera::detail::anchored_face_shape(p, tpu, g);
    if (!(g.area2 > 1e-3)) continue;
    // a random texture: the face in its plane, rotated, shifted and stretched by up to 30 % per axis
    const auto t = tessera::detail::to_plane_triangle(p[0], p[1], p[2]);
    const double ang = 6.283185307179586 * rng.uniform(i, 10), sx = 0.7 + 0.6 * rng.uniform(i, 11),
                 sy = 0.7 + 0.6 * rng.uniform(i, 12), mirror = rng.uniform(i, 13) < 0.05 ? -1 : 1;
    const tessera::vec2 q[3] = {{0, 0}, {t.l1, 0}, {t.x2, t.y2}};
    std::array<float, 6> uv{};
    for (std::size_t k = 0; k < 3; ++k) {
      const double x = q[k].x * tpu * sx, y = q[k].y * tpu * sy * mirror;
      uv[2 * k] = static_cast<float>(std::cos(ang) * x - std::sin(ang) * y + 17);
      uv[2 * k + 1] = static_cast<float>(std::sin(ang) * x + std::cos(ang) * y - 5);
    }
    const double s = tessera::triangle_stretch(p[0], p[1], p[2], uv, tpu);
    for (const double m : {1.05, 1.2, 1.4}) {
      if (std::abs(s - m) < 1e-9) continue;
      REQUIRE(tessera::detail::anchored_within(g, uv, m) == (s <= m));
      (s <= m ? within : outside) += 1;
    }
    // unfolded across each side from the side's own length in the texture: congruent
    for (int k = 0; k < 3; ++k) {
      const tessera::vec2 ta{3, 4};
      const double len = std::sqrt(g.len2[static_cast<std::size_t>(k)]) * tpu;
      const tessera::vec2 tb = ta + tessera::vec2{std::cos(ang), std::sin(ang)} * len;
      std::array<tessera::vec2, 3> c3;
      REQUIRE(tessera::detail::anchored_unfold(g, k, ta, tb, tpu, false, c3));
      std::array<float, 6> w{};
      for (std::size_t c = 0; c < 3; ++c)
        w[2 * c] = static_cast<float>(c3[c].x), w[2 * c + 1] = static_cast<float>(c3[c].y);
      REQUIRE(tessera::triangle_stretch(p[0], p[1], p[2], w, tpu) == Approx(1).margin(1e-4));
    }
  }
  REQUIRE(within > 1000);
  REQUIRE(outside > 1000);
  // degenerate faces: no side to unfold across, no placement within any bound
  tessera::anchored_face_geometry flat;
  tessera::detail::anchored_face_shape({tessera::vec3{0, 0, 0}, tessera::vec3{1, 1, 1}, tessera::vec3{2, 2, 2}}, 4,
                                       flat);
  std::array<tessera::vec2, 3> c3;
  REQUIRE_FALSE(tessera::detail::anchored_unfold(flat, 0, {0, 0}, {1, 0}, 4, false, c3));
  REQUIRE_FALSE(tessera::detail::anchored_within(flat, {0, 0, 1, 0, 0, 1}, 2));
}

TEST_CASE("synthesize_anchored_region: the same atlas with a gathered geometry or without", "[terrain][anchored]") {
  const auto mesh = terrain_test::prepared_terrain(40, 4, 10);
  const tessera::anchored_synthesis_options opts{.seed = 4, .region_size = 0.5};
  const auto plan = tessera::plan_anchored_regions(mesh, 64, 64, opts).value();
  const auto geo = tessera::make_anchored_geometry(mesh, plan).value();
  tessera::anchored_atlas a, b;
  tessera::reset_anchored_atlas(plan, mesh.num_faces(), a);
  tessera::reset_anchored_atlas(plan, mesh.num_faces(), b);
  for (index_t r = 0; r < plan.num_regions(); ++r) {
    tessera::anchored_region_stats sa, sb;
    REQUIRE(tessera::synthesize_anchored_region(mesh, plan, r, 64, 64, opts, a, &sa));
    REQUIRE(tessera::synthesize_anchored_region(mesh, plan, r, 64, 64, opts, b, &sb, &geo));
    REQUIRE(sa.patches == sb.patches);
    REQUIRE(sa.restarts == sb.restarts);
  }
  REQUIRE(a.uv == b.uv);
  REQUIRE(a.patch == b.patch);
  REQUIRE(a.seam == b.seam);

  // bad input: a geometry of another plan, a plan of another mesh
  const auto other = tessera::plan_anchored_regions(mesh, 64, 64, {.region_size = 0.2}).value();
  tessera::anchored_atlas c;
  tessera::reset_anchored_atlas(other, mesh.num_faces(), c);
  const auto s = tessera::synthesize_anchored_region(mesh, other, 0, 64, 64, opts, c, nullptr, &geo);
  REQUIRE(s.code() == tessera::status_code::invalid_argument);
  REQUIRE(s.message().find("geometry") != std::string::npos);
  const auto small = terrain_test::prepared_terrain(8);
  const auto bad = tessera::make_anchored_geometry(small, plan);
  REQUIRE_FALSE(bad);
  REQUIRE(bad.error().message().find("plan") != std::string::npos);
}
