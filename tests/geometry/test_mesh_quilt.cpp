#include <tessera/geometry/mesh_quilt.hpp>

#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
index_t intersecting_element_pairs(const tri_mesh& m) {
  const auto comp = connected_components(m);
  const triangle_bvh bvh(m);
  index_t n = 0;
  bvh.for_each_self_intersection(
      [&](index_t f, index_t g) { return comp.face_component[std::size_t(f)] == comp.face_component[std::size_t(g)]; },
      [&](index_t, index_t) { ++n; });
  return n;
}
const quilt_exemplar& small_rings() {
  static const quilt_exemplar ex = *prepare_quilt_exemplar(
      *make_ring_exemplar({.size = 5, .spacing = 1.6, .ring_segments = 16, .tube_segments = 6, .seed = 4}));
  return ex;
}
}  // namespace

TEST_CASE("mesh quilting grows a larger ring texture of closed, disjoint elements", "[mesh_quilt]") {
  const auto& ex = small_rings();
  const auto r = mesh_quilt(ex, 8, 6, {.seed = 2});
  REQUIRE(r.ok());
  REQUIRE(r->elements.size() > 8);
  const auto d = count_edge_defects(r->mesh);
  REQUIRE(d.open_edges == 0);
  REQUIRE(d.nonmanifold_edges == 0);
  REQUIRE(intersecting_element_pairs(r->mesh) == 0);
  const auto b = bounding_box(r->mesh);
  REQUIRE(b.extent().x > 6);
  REQUIRE(b.extent().y > 4);
  REQUIRE(r->stats.patches > 1);
  // deterministic
  const auto again = mesh_quilt(ex, 8, 6, {.seed = 2});
  REQUIRE(again->mesh == r->mesh);
  const auto other = mesh_quilt(ex, 8, 6, {.seed = 3});
  REQUIRE_FALSE(other->mesh == r->mesh);
}

TEST_CASE("mesh quilting rejects bad input", "[mesh_quilt]") {
  const auto& ex = small_rings();
  REQUIRE(mesh_quilt(ex, 0, 5).error().code() == status_code::invalid_argument);
  REQUIRE(mesh_quilt(ex, std::nan(""), 5).error().code() == status_code::invalid_argument);
  REQUIRE(mesh_quilt(ex, 1e9, 1e9).error().code() == status_code::size_overflow);
  REQUIRE_FALSE(mesh_quilt(ex, 5, 5, {.max_samples = 0}).ok());
  REQUIRE_FALSE(mesh_quilt(ex, 5, 5, {.deform_weight = -1}).ok());
  REQUIRE_FALSE(mesh_quilt(quilt_exemplar{}, 5, 5).ok());
  tri_mesh open = *make_ring_exemplar({.size = 3});
  open.faces.pop_back();
  REQUIRE(mesh_quilt(open, 5, 5).error().message().find("open edges") != std::string::npos);
  cancellation_token stop;
  stop.cancel();
  mesh_quilt_options o;
  o.progress.token = &stop;
  REQUIRE(mesh_quilt(ex, 5, 5, o).error().code() == status_code::cancelled);
}
