#include <tessera/geometry/quilt_exemplar.hpp>

#include <tessera/core/mesh_view.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

TEST_CASE("prepared exemplar: elements, faces, cell size and long elements", "[quilt_exemplar]") {
  const auto rings = prepare_quilt_exemplar(*make_ring_exemplar({.size = 5}));
  REQUIRE(rings.ok());
  REQUIRE(rings->num_elements() == 9);
  REQUIRE(rings->element_diameter() == Approx(1.24).margin(0.15));
  REQUIRE(rings->cell_size() == Approx(0.5 * rings->element_diameter()));
  for (index_t e = 0; e < rings->num_elements(); ++e) {
    REQUIRE_FALSE(rings->is_long(e));
    for (index_t f = rings->first_face(e); f < rings->first_face(e + 1); ++f) REQUIRE(rings->element_of_face(f) == e);
  }
  const auto weave = prepare_quilt_exemplar(*make_weave_exemplar({.size = 4, .segments_per_spacing = 4, .around = 4}));
  REQUIRE(weave.ok());
  for (index_t e = 0; e < weave->num_elements(); ++e) REQUIRE(weave->is_long(e));
  REQUIRE(weave->element_diameter() < 1.0);  // thread width, not length
  const auto custom = prepare_quilt_exemplar(*make_ring_exemplar({.size = 5}), {.cell_size = 0.4});
  REQUIRE(custom->cell_size() == 0.4);
}

TEST_CASE("prepared exemplar rejects bad exemplars", "[quilt_exemplar]") {
  tri_mesh open = *make_ring_exemplar({.size = 3});
  open.faces.pop_back();
  REQUIRE(prepare_quilt_exemplar(open).error().message().find("open edges") != std::string::npos);
  tri_mesh flat;
  flat.add_vertex({0, 0, 0}), flat.add_vertex({0, 0, 1}), flat.add_vertex({0, 0, 2}), flat.add_vertex({0, 0, 3});
  flat.add_face(0, 1, 2), flat.add_face(0, 2, 1), flat.add_face(0, 1, 3), flat.add_face(1, 2, 3);
  REQUIRE_FALSE(prepare_quilt_exemplar(flat, {}).ok());
  REQUIRE_FALSE(prepare_quilt_exemplar(*make_ring_exemplar({.size = 3}), {.cell_size = -1}).ok());
  REQUIRE(prepare_quilt_exemplar(*make_ring_exemplar({.size = 3}), {.cell_size = 5})
              .error()
              .message()
              .find("two grid cells") != std::string::npos);
}
