#include <tessera/geometry/constrained_mesh_quilt.hpp>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/detail/mesh_clip.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

#include <set>

using namespace tessera;

TEST_CASE("constrained quilting never moves fixed frame vertices and keeps the tile border", "[constrained_quilt]") {
  const auto ex = prepare_quilt_exemplar(
      *make_ring_exemplar({.size = 6.4, .spacing = 1.6, .ring_segments = 12, .tube_segments = 5, .seed = 8}));
  REQUIRE(ex.ok());
  const double w = 4.8;
  // frame: a ring cut by the west side x = 0 (the half inside the tile), its border vertices fixed
  tri_mesh ring;
  detail::add_torus(ring, {0.0, 2.4, 0.3}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.12, 16, 6);
  auto halves = detail::split_mesh_by_plane(ring, 0, 0.0, 1e-12);
  detail::compact_vertices(halves.above);
  texture_element half;
  half.mesh = halves.above;
  half.border = border_bit(side_west);
  half.fixed = border_vertices(half, {0, 0, w, w});
  half.update_box();
  std::vector<vec3> fixed_before;
  for (std::size_t v = 0; v < half.mesh.positions.size(); ++v)
    if (half.fixed[v]) fixed_before.push_back(half.mesh.positions[v]);
  REQUIRE(fixed_before.size() > 4);
  quilt_frame frame{{half}, {{0, 1.7, 0.7, 3.1}}};
  thread_pool_executor pool(2);
  const auto r = constrained_mesh_quilt(*ex, {0, 0, w, w}, frame, {.seed = 4}, 0, pool);
  REQUIRE(r.ok());
  // fixed vertices come out bit-identical
  std::set<std::array<double, 3>> out;
  for (const vec3& p : r->mesh.positions) out.insert({p.x, p.y, p.z});
  for (const vec3& p : fixed_before) REQUIRE(out.count({p.x, p.y, p.z}) == 1);
  // everything inside the tile; only the cut (fixed) vertices on the side x = 0
  for (const vec3& p : r->mesh.positions) {
    REQUIRE(p.x >= 0);
    REQUIRE(p.x < w);
    REQUIRE(p.y > 0);
    REQUIRE(p.y < w);
  }
  const auto rep = check_geometric_texture(r->mesh, {0, 0, w, w});
  REQUIRE(rep->open_edges_inside == 0);
  REQUIRE(rep->nonmanifold_edges == 0);
  REQUIRE(rep->intersecting_pairs == 0);
  REQUIRE(rep->elements > 3);
  // same result serially
  REQUIRE(constrained_mesh_quilt(*ex, {0, 0, w, w}, frame, {.seed = 4})->mesh == r->mesh);
}

TEST_CASE("constrained quilting rejects bad frames and domains", "[constrained_quilt]") {
  const auto ex = prepare_quilt_exemplar(*make_ring_exemplar({.size = 4, .ring_segments = 8, .tube_segments = 4}));
  REQUIRE_FALSE(constrained_mesh_quilt(*ex, {0, 0, 0, 4}, {}).ok());
  REQUIRE_FALSE(constrained_mesh_quilt(*ex, {0, 0, std::nan(""), 4}, {}).ok());
  texture_element outside;
  detail::add_torus(outside.mesh, {9, 9, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.1, 8, 4);
  REQUIRE(constrained_mesh_quilt(*ex, {0, 0, 4, 4}, quilt_frame{{outside}, {}})
              .error()
              .message()
              .find("outside the domain") != std::string::npos);
  texture_element wrong = outside;
  for (vec3& p : wrong.mesh.positions) p -= vec3{7, 7, 0};
  wrong.fixed.assign(3, 1);
  REQUIRE(constrained_mesh_quilt(*ex, {0, 0, 4, 4}, quilt_frame{{wrong}, {}}).error().message().find("fixed flags") !=
          std::string::npos);
}
