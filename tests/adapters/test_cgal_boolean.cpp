// Mesh Booleans through CGAL's corefinement (adapters/cgal_boolean.hpp; paper 000 Fig. 7): volumes of
// unions, differences and intersections of boxes against their closed forms, closed outputs, inputs
// untouched, a clear status for every input corefinement cannot take, cancellation; and the texture
// elements of a surface joined with and engraved into their base (shell_options::sink).
#include <tessera/adapters/cgal_boolean.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/surface/map_geometric_tiles.hpp>

#include <catch2/catch.hpp>

#include <string>

using namespace tessera;

namespace {
// an axis-aligned box [lo, hi], 12 outward-facing triangles
tri_mesh box(vec3 lo, vec3 hi) {
  tri_mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.add_face(q[0], q[1], q[2]);
    m.add_face(q[0], q[2], q[3]);
  }
  return m;
}
double volume(const tri_mesh& m) {
  double v = 0;
  for (const auto& f : m.faces) v += dot(m.position(f[0]), cross(m.position(f[1]), m.position(f[2])));
  return v / 6;
}
tri_mesh joined(tri_mesh a, const tri_mesh& b) {
  a.append(b);
  return a;
}
void require_error(const result<tri_mesh>& r, status_code code, const std::string& text) {
  REQUIRE(!r);
  INFO(r.error().to_string());
  CHECK(r.error().code() == code);
  CHECK(r.error().message().find(text) != std::string::npos);
}
}  // namespace

TEST_CASE("mesh_boolean: volumes of box Booleans, closed outputs, inputs untouched", "[cgal]") {
  const tri_mesh a = box({0, 0, 0}, {2, 2, 2}), b = box({1, 1, 1}, {3, 4, 5});
  const tri_mesh a0 = a, b0 = b;
  struct expect {
    boolean_op op;
    double volume;
  };
  // |A| = 8, |B| = 2 * 3 * 4 = 24, |A ∩ B| = 1
  for (const auto& [op, v] :
       {expect{boolean_op::unite, 31}, expect{boolean_op::subtract, 7}, expect{boolean_op::intersect, 1}}) {
    INFO(static_cast<int>(op));
    auto r = mesh_boolean(a, b, op);
    REQUIRE(r);
    CHECK(validate_mesh(*r).ok());
    CHECK(boundary_edges(*r).empty());
    CHECK(volume(*r) == Approx(v).epsilon(1e-12));
  }
  CHECK(a.positions == a0.positions);
  CHECK(a.faces == a0.faces);
  CHECK(b.positions == b0.positions);
  // several components per mesh: B's two boxes, one overlapping A and one apart
  const tri_mesh two = joined(box({1, 1, 1}, {3, 3, 3}), box({5, 0, 0}, {6, 1, 1}));
  auto u = mesh_boolean(a, two, boolean_op::unite);
  REQUIRE(u);
  CHECK(volume(*u) == Approx(8 + 8 - 1 + 1).epsilon(1e-12));
  CHECK(connected_components(*u).count == 2);
  // B entirely inside A: a difference leaves a cavity (two shells, volume 8 - 1)
  auto cavity = mesh_boolean(a, box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}), boolean_op::subtract);
  REQUIRE(cavity);
  CHECK(volume(*cavity) == Approx(7).epsilon(1e-12));
  CHECK(connected_components(*cavity).count == 2);
}

TEST_CASE("mesh_boolean: inputs corefinement cannot take return a clear status", "[cgal]") {
  const tri_mesh a = box({0, 0, 0}, {2, 2, 2}), b = box({1, 1, 1}, {3, 3, 3});
  // open
  tri_mesh open = b;
  open.faces.pop_back();
  require_error(mesh_boolean(a, open, boolean_op::unite), status_code::invalid_argument, "B is not closed: 3 edges");
  // crossing itself: two overlapping boxes in one mesh
  require_error(mesh_boolean(joined(a, b), b, boolean_op::unite), status_code::invalid_argument, "A intersects itself");
  // a zero-area face: a box flattened to z = 0 (every face degenerate)
  require_error(mesh_boolean(box({0, 0, 0}, {2, 2, 0}), b, boolean_op::unite), status_code::invalid_argument,
                "is degenerate (zero area)");
  // huge and tiny coordinates: exact constructions scale
  auto huge =
      mesh_boolean(box({0, 0, 0}, {2e12, 2e12, 2e12}), box({1e12, 1e12, 1e12}, {3e12, 3e12, 3e12}), boolean_op::unite);
  REQUIRE(huge);
  CHECK(volume(*huge) == Approx(15e36).epsilon(1e-12));
  auto tiny =
      mesh_boolean(box({0, 0, 0}, {2e-9, 2e-9, 2e-9}), box({1e-9, 1e-9, 1e-9}, {3e-9, 3e-9, 3e-9}), boolean_op::unite);
  REQUIRE(tiny);
  CHECK(volume(*tiny) == Approx(15e-27).epsilon(1e-12));
  // inside out
  tri_mesh flipped = b;
  for (auto& f : flipped.faces) std::swap(f[1], f[2]);
  require_error(mesh_boolean(a, flipped, boolean_op::subtract), status_code::invalid_argument,
                "B does not bound a volume");
  // non-manifold: a face repeated
  tri_mesh twice = a;
  twice.faces.push_back(twice.faces.front());
  require_error(mesh_boolean(twice, b, boolean_op::unite), status_code::invalid_argument, "A: face 12");
  // empty, invalid indices, NaN
  require_error(mesh_boolean(tri_mesh{}, b, boolean_op::unite), status_code::invalid_argument, "need faces");
  tri_mesh bad = a;
  bad.faces[3][1] = 99;
  require_error(mesh_boolean(bad, b, boolean_op::unite), status_code::out_of_range, "A: face 3");
  tri_mesh nan = a;
  nan.positions[2].y = std::nan("");
  require_error(mesh_boolean(a, nan, boolean_op::unite), status_code::invalid_argument, "B: vertex 2");
  require_error(mesh_boolean(a, b, static_cast<boolean_op>(7)), status_code::invalid_argument, "op must be");
  // boxes sharing only an edge: the union would not be a manifold surface
  require_error(mesh_boolean(a, box({2, 2, 0}, {3, 3, 2}), boolean_op::unite), status_code::invalid_argument,
                "not be a manifold surface");
  // cancelled from inside the corefinement, and before it
  mesh_boolean_options o;
  int calls = 0;
  o.progress.callback = [&](double, std::string_view stage) { return ++calls < 3 || stage == "checking"; };
  require_error(mesh_boolean(a, b, boolean_op::unite, o), status_code::cancelled, "cancelled");
  cancellation_token token;
  token.cancel();
  o.progress = {};
  o.progress.token = &token;
  require_error(mesh_boolean(a, b, boolean_op::unite, o), status_code::cancelled, "cancelled");
}

TEST_CASE("mesh_boolean: texture elements joined with and engraved into their base (paper 000 Fig. 7)", "[cgal]") {
  thread_pool_executor pool(2);
  auto ex = prepare_quilt_exemplar(
      *make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 10, .tube_segments = 4, .seed = 3}));
  geometric_wang_options wo;
  wo.axis_colors = {1, 1, 1};
  wo.tile_size = 4.0;
  wo.quilt.seed = 5;
  auto set = build_geometric_wang_tiles(*ex, wo, pool);
  REQUIRE(set);
  const tri_mesh base = box({0, 0, 0}, {3, 3, 3});
  polycube_options po;
  po.tile_size = 1.0;
  auto map = build_polycube_map(base, po);
  REQUIRE(map);
  map_geometric_tiles_options o;
  o.height = 0.3;
  o.mapping.clip = shell_clip::exact;  // no crossing faces: corefinement needs none
  for (const auto& [op, sink] : {std::pair{boolean_op::unite, 0.1}, std::pair{boolean_op::subtract, 0.5}}) {
    INFO(static_cast<int>(op));
    o.shell.sink = sink;
    auto r = map_geometric_tiles(base, *map, *set, o, pool);
    INFO((r ? std::string() : r.error().to_string()));
    REQUIRE(r);
    const tri_mesh elements = r->elements();
    const double ve = volume(elements), vb = volume(map->base);
    REQUIRE(ve > 0);
    auto out = mesh_boolean(map->base, elements, op);
    INFO((out ? std::string() : out.error().to_string()));
    REQUIRE(out);
    CHECK(boundary_edges(*out).empty());
    if (op == boolean_op::unite) {
      // one solid: more than the base, less than base + elements (the sunk parts overlap it)
      CHECK(connected_components(*out).count < connected_components(elements).count);
      CHECK(volume(*out) > vb);
      CHECK(volume(*out) < vb + ve);
    } else {
      // engraved: the sunk halves of the elements are cut out of the base
      CHECK(volume(*out) < vb);
      CHECK(volume(*out) > vb - ve);
    }
  }
}
