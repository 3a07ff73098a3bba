#include <tessera/terrain/prepare_terrain_mesh.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/core/random.hpp>
#include <tessera/terrain/assign_scale_field.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/synthesize_triangles.hpp>

using tessera::index_t;

namespace {
// The core's sort-based adjacency is the oracle.
void require_same_adjacency(const tessera::terrain_mesh& t, const tessera::tri_mesh& m) {
  const auto ref = tessera::face_adjacency(m);
  REQUIRE(t.neighbors.size() == ref.neighbor.size());
  for (std::size_t f = 0; f < ref.neighbor.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) REQUIRE(t.neighbors[f][k] == ref.neighbor[f][k]);
  REQUIRE(t.boundary_edges == ref.boundary_edges);
  REQUIRE(t.nonmanifold_edges == ref.nonmanifold_edges);
}
}  // namespace

TEST_CASE("prepare_terrain_mesh: adjacency of a heightfield matches the core oracle", "[terrain][prepare]") {
  const auto m = tessera::make_terrain({.cells_x = 9, .cells_y = 6}).value();
  const auto t = tessera::prepare_terrain_mesh(m).value();
  REQUIRE(t.num_faces() == 108);
  REQUIRE(t.num_vertices() == 70);
  require_same_adjacency(t, m);
  REQUIRE(t.boundary_edges == 2 * (9 + 6));
  REQUIRE(t.interior_edges == 3 * 108 / 2 - 15);
  for (index_t f = 0; f < t.num_faces(); ++f) {
    const auto& fv = t.faces[static_cast<std::size_t>(f)];
    const tessera::vec3 c =
        (m.positions[static_cast<std::size_t>(fv[0])] + m.positions[static_cast<std::size_t>(fv[1])] +
         m.positions[static_cast<std::size_t>(fv[2])]) /
        3.0;
    REQUIRE(tessera::norm(c - t.centroids[static_cast<std::size_t>(f)]) < 1e-12);
  }
}

TEST_CASE("prepare_terrain_mesh: random soups with boundary, non-manifold and mixed-orientation edges",
          "[terrain][prepare]") {
  const tessera::counter_rng rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    tessera::tri_mesh m;
    const index_t nv = 6 + static_cast<index_t>(rng.below(8, trial));
    for (index_t v = 0; v < nv; ++v) m.add_vertex({rng.uniform(trial, v, 0), rng.uniform(trial, v, 1), 0});
    for (int f = 0; f < 25; ++f) {
      const auto a = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(nv), trial, f, 0));
      const auto b = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(nv), trial, f, 1));
      const auto c = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(nv), trial, f, 2));
      if (a != b && b != c && a != c) m.add_face(a, b, c);
    }
    const auto t = tessera::prepare_terrain_mesh(m).value();
    require_same_adjacency(t, m);
  }
}

TEST_CASE("prepare_terrain_mesh: any Mesh type, and the empty mesh", "[terrain][prepare]") {
  const std::vector<float> pos = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
  const auto view = tessera::make_mesh_view(pos.data(), 4, idx.data(), 2).value();
  const auto t = tessera::prepare_terrain_mesh(view).value();
  REQUIRE(t.neighbors[0][2] == 1);  // side 2 of face 0 is 2 -> 0
  REQUIRE(t.neighbors[1][0] == 0);  // side 0 of face 1 is 0 -> 2
  REQUIRE(t.boundary_edges == 4);
  const auto empty = tessera::prepare_terrain_mesh(tessera::tri_mesh{});
  REQUIRE(empty);
  REQUIRE(empty->num_faces() == 0);
}

TEST_CASE("prepare_terrain_mesh: invalid meshes return a status naming the problem", "[terrain][prepare]") {
  tessera::tri_mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_face(0, 1, 5);
  auto r = tessera::prepare_terrain_mesh(m, "terrain");
  REQUIRE(r.error().code() == tessera::status_code::out_of_range);
  REQUIRE(r.error().message().find("terrain: face 0") != std::string::npos);
  m.faces[0] = {0, 1, 1};
  REQUIRE(tessera::prepare_terrain_mesh(m).error().code() == tessera::status_code::invalid_argument);
  m.faces[0] = {0, 1, 2};
  m.positions[1].x = std::nan("");
  REQUIRE(tessera::prepare_terrain_mesh(m).error().message().find("non-finite") != std::string::npos);
}

TEST_CASE("validate_terrain_mesh: a terrain_mesh filled by hand is checked before any stage indexes through it",
          "[terrain][prepare]") {
  const tessera::terrain_mesh good =
      tessera::prepare_terrain_mesh(tessera::make_terrain({.cells_x = 3, .cells_y = 3}).value()).value();
  REQUIRE(tessera::validate_terrain_mesh(good));
  const auto cam = tessera::make_camera({.eye = {0, -80, 40}, .target = {0, 0, 0}}, 64, 48).value();
  REQUIRE(tessera::project_mesh(good, cam));
  auto expect = [&](const tessera::terrain_mesh& m, const char* text) {
    const auto v = tessera::validate_terrain_mesh(m);
    INFO(v.message());
    REQUIRE_FALSE(v);
    REQUIRE(v.message().find(text) != std::string::npos);
    const auto p = tessera::project_mesh(m, cam);  // project_mesh makes the same checks in its own passes
    REQUIRE_FALSE(p);
    REQUIRE(p.error().message() == v.message());
  };
  tessera::terrain_mesh m = good;
  m.neighbors.clear();  // positions and faces only, as a caller might fill it
  expect(m, "0 neighbour triples");
  m = good;
  m.centroids.pop_back();
  expect(m, "centroids");
  m = good;
  m.neighbors[5][1] = 18;  // 18 faces: 0..17
  expect(m, "face 5 side 1 names neighbour 18 of 18");
  m = good;
  m.neighbors[7][2] = -2;
  expect(m, "face 7 side 2 names neighbour -2");
  m = good;
  m.faces[3][0] = 16;  // 16 vertices
  expect(m, "face 3 corner 0 names vertex 16 of 16");
  m = good;
  m.centroids[4].y = std::nan("");
  expect(m, "face 4 has a non-finite centroid");
  m = good;
  m.positions[2].z = INFINITY;
  expect(m, "vertex 2 is not finite");

  // a mesh changed after projection: the later stages check sizes and never follow a bad neighbour
  const auto proj = tessera::project_mesh(good, cam).value();
  REQUIRE(proj.num_visible() == 18);
  m = good;
  m.neighbors.resize(3);
  REQUIRE(tessera::assign_scale_field(m, proj).error().message().find("neighbour triples") != std::string::npos);
  const auto field = tessera::assign_scale_field(good, proj).value();
  REQUIRE(tessera::synthesize_triangles(m, proj, field, 64, 64).error().message().find("neighbour triples") !=
          std::string::npos);
  m = good;
  for (auto& nb : m.neighbors) nb = {1000, 2000, 3000};  // out of range: ignored as "no neighbour", no read
  const auto f2 = tessera::assign_scale_field(m, proj).value();
  REQUIRE(f2.adjacent_pairs == 0);
  const auto syn = tessera::synthesize_triangles(m, proj, f2, 64, 64).value();
  REQUIRE(syn.shared_edges == 0);
  REQUIRE(syn.components == 18);
}
