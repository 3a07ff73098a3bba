#include <tessera/terrain/plan_anchored_regions.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

TEST_CASE("plan_anchored_regions: a partition of the faces into world cells, seeds nearest the centres",
          "[terrain][anchored]") {
  const auto mesh = terrain_test::prepared_terrain(40);
  const auto p = tessera::plan_anchored_regions(mesh, 128, 128, {.region_size = 0.3}).value();
  REQUIRE(p.axis_a == 0);
  REQUIRE(p.axis_b == 1);
  REQUIRE(p.texels_per_unit > 0);
  REQUIRE(p.num_regions() == p.cells_a * p.cells_b);
  REQUIRE(p.num_regions() > 1);
  REQUIRE(p.first.back() == mesh.num_faces());
  std::vector<int> hit(static_cast<std::size_t>(mesh.num_faces()), 0);
  for (index_t r = 0; r < p.num_regions(); ++r) {
    const auto b = p.first[static_cast<std::size_t>(r)], e = p.first[static_cast<std::size_t>(r) + 1];
    for (auto i = b; i < e; ++i) {
      const std::int32_t f = p.faces[static_cast<std::size_t>(i)];
      ++hit[static_cast<std::size_t>(f)];
      REQUIRE(p.region[static_cast<std::size_t>(f)] == r);
      if (i > b) REQUIRE(p.faces[static_cast<std::size_t>(i) - 1] < f);  // ascending
      // the face lies in its cell
      const auto& c = mesh.centroids[static_cast<std::size_t>(f)];
      const double a = (c.x - p.origin_a) / p.cell, bb = (c.y - p.origin_b) / p.cell;
      REQUIRE(static_cast<index_t>(std::floor(a)) == r % p.cells_a);
      REQUIRE(static_cast<index_t>(std::floor(bb)) == r / p.cells_a);
    }
    const std::int32_t s = p.seed[static_cast<std::size_t>(r)];
    REQUIRE((s >= 0) == (e > b));
    if (s < 0) continue;
    // the seed is the face nearest the cell centre, ties to the smallest id
    auto dist = [&](std::int32_t f) {
      const auto& c = mesh.centroids[static_cast<std::size_t>(f)];
      const double da = (c.x - p.origin_a) / p.cell - (static_cast<double>(r % p.cells_a) + 0.5),
                   db = (c.y - p.origin_b) / p.cell - (static_cast<double>(r / p.cells_a) + 0.5);
      return da * da + db * db;
    };
    for (auto i = b; i < e; ++i) {
      const std::int32_t f = p.faces[static_cast<std::size_t>(i)];
      REQUIRE((dist(f) > dist(s) || (dist(f) == dist(s) && f >= s)));
    }
  }
  for (int h : hit) REQUIRE(h == 1);
  // density: an exemplar width per auto_edges_per_exemplar mean edges; cells region_size of it
  REQUIRE(p.cell == Approx(0.3 * 128 / p.texels_per_unit));
  // a pure function of its inputs
  const auto q = tessera::plan_anchored_regions(mesh, 128, 128, {.region_size = 0.3}).value();
  REQUIRE(q.region == p.region);
  REQUIRE(q.seed == p.seed);
  REQUIRE(p.max_neighbor_distance > 0);
}

TEST_CASE("plan_anchored_regions: bad options and meshes are refused with a reason", "[terrain][anchored]") {
  auto mesh = terrain_test::prepared_terrain(4);
  auto msg = [&](index_t w, index_t h, tessera::anchored_synthesis_options o) {
    return tessera::plan_anchored_regions(mesh, w, h, o).error().message();
  };
  REQUIRE(msg(0, 8, {}).find("exemplar size") != std::string::npos);
  REQUIRE(msg(8, 8, {.texels_per_unit = -1}).find("texels_per_unit") != std::string::npos);
  REQUIRE(msg(8, 8, {.texels_per_unit = NAN}).find("texels_per_unit") != std::string::npos);
  REQUIRE(msg(8, 8, {.region_size = 0.01}).find("region_size") != std::string::npos);
  REQUIRE(msg(8, 8, {.margin = -1}).find("margin") != std::string::npos);
  REQUIRE(msg(8, 8, {.max_stretch = 0.99}).find("max_stretch") != std::string::npos);
  REQUIRE(msg(8, 8, {.max_stretch = NAN}).find("max_stretch") != std::string::npos);
  REQUIRE(msg(8, 8, {.relax_iterations = -1}).find("relax_iterations must be 0 (no relaxation) to 64, got -1") !=
          std::string::npos);
  REQUIRE(msg(8, 8, {.relax_iterations = 65}).find("relax_iterations") != std::string::npos);
  REQUIRE(msg(8, 8, {.relax_above = 0.9}).find("relax_above must be in [1, 2]") != std::string::npos);
  REQUIRE(msg(8, 8, {.relax_above = NAN}).find("relax_above") != std::string::npos);
  REQUIRE(msg(8, 8, {.relax_rings = 0}).find("relax_rings must be 1 to 16") != std::string::npos);
  REQUIRE(msg(8, 8, {.relax_passes = 9}).find("relax_passes must be 1 to 8") != std::string::npos);
  REQUIRE(msg(8, 8, {.relaxed_max_stretch = 2.5}).find("relaxed_max_stretch must be in [1, 2]") != std::string::npos);
  mesh.faces[3][1] = 100000;
  REQUIRE(msg(8, 8, {}).find("face 3") != std::string::npos);
  const tessera::terrain_mesh empty;
  const auto e = tessera::plan_anchored_regions(empty, 8, 8, {});
  REQUIRE(e);
  REQUIRE(e->num_regions() == 0);
}
