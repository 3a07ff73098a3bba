#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include <tessera/core/mesh_topology.hpp>
#include <tessera/geometry/bvh.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/build_shell.hpp>
#include <tessera/surface/polycube_distortion.hpp>
#include <tessera/surface/remesh_isotropic.hpp>

#include "shapes.hpp"

using namespace tessera;

namespace {

index_t genus_of(const tri_mesh& m) {
  const auto edges = static_cast<index_t>(mesh_edges(m).size());
  return (2 - (m.num_vertices() - edges + m.num_faces())) / 2;
}

/// Total length of the edges whose faces meet at a dihedral angle of at least `degrees`.
double crease_length(const tri_mesh& m, double degrees) {
  const double c = std::cos(degrees * 3.14159265358979323846 / 180);
  double sum = 0;
  for (const auto& e : mesh_edges(m)) {
    if (e.faces.size() != 2) continue;
    const vec3 n0 = normalized(face_area_normal(m, e.faces[0][0])), n1 = normalized(face_area_normal(m, e.faces[1][0]));
    if (dot(n0, n1) <= c) sum += distance(m.positions[detail::to_size(e.v0)], m.positions[detail::to_size(e.v1)]);
  }
  return sum;
}

tri_mesh plate() {
  auto m = read_mesh(std::string(TESSERA_TEST_DATA_DIR) + "/surface/openscad_plate_three_holes.off");
  REQUIRE(m);
  return std::move(*m);
}

}  // namespace

TEST_CASE("remesh: a CAD plate of slivers becomes even triangles on the same surface with its creases") {
  // OpenSCAD's plate with three holes (genus 3): faces 45 units long beside slivers 10^-3 wide
  const tri_mesh in = plate();
  const tri_mesh copy = in;
  remesh_options o;
  o.edges_across = 32;
  const auto r = remesh_isotropic(in, o);
  REQUIRE(r);
  CHECK(in.positions == copy.positions);  // the input is not modified
  const auto& st = r->stats;
  CHECK(st.min_angle_input < 1);
  CHECK(st.min_angle > 15);
  CHECK(st.edge_length_rms < 0.2);
  CHECK(st.max_deviation < 1e-6);
  CHECK(st.feature_edges > 0);
  CHECK(validate_polycube_input(r->mesh));
  CHECK(genus_of(r->mesh) == 3);
  // the creases are kept: as long in all as the input's, every output vertex on the input
  CHECK(crease_length(r->mesh, 40) == Approx(crease_length(in, 40)).epsilon(0.01));
  const triangle_bvh surface(in);
  for (const vec3& p : r->mesh.positions) CHECK(surface.closest_point(p).squared_distance < 1e-12);
  // same input, same output
  const auto again = remesh_isotropic(in, o);
  REQUIRE(again);
  CHECK(again->mesh.positions == r->mesh.positions);
  CHECK(again->mesh.faces == r->mesh.faces);
}

TEST_CASE("remesh: remeshed CAD parts have a shell and a less distorted polycube map") {
  // scripts/meshes/three_holes.scad (an ellipsoid with three holes, genus 3, OpenSCAD, CC0): the shell at
  // the height the ring tiles ask for folds along the holes' rims, and the refusal says why
  const auto ellipsoid = read_mesh(std::string(TESSERA_TEST_DATA_DIR) + "/surface/openscad_ellipsoid_three_holes.off");
  REQUIRE(ellipsoid);
  const auto folded = build_shell(*ellipsoid, 1.6);
  REQUIRE_FALSE(folded);
  CHECK(folded.error().message().find("slivers") != std::string::npos);
  const auto even = remesh_isotropic(*ellipsoid, {.edges_across = 64});
  REQUIRE(even);
  CHECK(genus_of(even->mesh) == 3);
  CHECK(build_shell(even->mesh, 1.6));
  // the plate's polycube map at 8 tiles across: area / angle distortion 2.6 / 6.7 on the slivers
  const tri_mesh in = plate();
  const auto r = remesh_isotropic(in, {.edges_across = 64});
  REQUIRE(r);
  polycube_options po;
  po.tiles_across = 8;
  const auto before = build_polycube_map(in, po);
  const auto after = build_polycube_map(r->mesh, po);
  REQUIRE(before);
  REQUIRE(after);
  const auto db = polycube_distortion(*before), da = polycube_distortion(*after);
  CHECK(da.area_distortion < 0.7 * db.area_distortion);
  CHECK(da.angle_distortion < 0.5 * db.angle_distortion);
}

TEST_CASE("remesh: a cube keeps its eight corners and twelve edges and a torus its genus") {
  const tri_mesh cube = shapes::voxel_surface(shapes::cube(), 1, 2.0);  // 12 faces
  remesh_options o;
  o.edge_length = 0.25;
  const auto r = remesh_isotropic(cube, o);
  REQUIRE(r);
  CHECK(r->stats.feature_edges == 12);
  CHECK(crease_length(r->mesh, 40) == Approx(24.0).epsilon(1e-9));
  for (const vec3& p : r->mesh.positions) {  // every vertex on a face of the cube
    const double d = std::min(
        {std::abs(p.x), std::abs(p.x - 2), std::abs(p.y), std::abs(p.y - 2), std::abs(p.z), std::abs(p.z - 2)});
    CHECK(d < 1e-12);
  }
  CHECK(r->mesh.num_faces() > 200);
  CHECK(r->stats.min_angle > 20);
  for (double x : {0.0, 2.0})  // the eight corners stay vertices
    for (double y : {0.0, 2.0})
      for (double z : {0.0, 2.0})
        CHECK(std::find(r->mesh.positions.begin(), r->mesh.positions.end(), vec3{x, y, z}) != r->mesh.positions.end());

  const tri_mesh t = shapes::torus(2, 0.5, 12, 24);  // long thin triangles along the tube
  const auto rt = remesh_isotropic(t, {.edge_length = 0.2});
  REQUIRE(rt);
  CHECK(rt->stats.feature_edges == 0);
  CHECK(genus_of(rt->mesh) == 1);
  CHECK(rt->stats.min_angle > 20);
  CHECK(rt->stats.edge_length_rms < 0.2);
}

TEST_CASE("remesh: tiny and huge coordinates give the same mesh up to scale") {
  // scales by powers of two (about 1e-9 and 1e9) are exact in floating point: every decision of the
  // remeshing is relative to L, so the result is the same mesh scaled
  const tri_mesh s = shapes::sphere(4);
  for (double scale : {0x1p-30, 0x1p30}) {
    INFO("scale " << scale);
    tri_mesh m = s;
    for (auto& p : m.positions) p = scale * p;
    const auto a = remesh_isotropic(s, {.edges_across = 12});
    const auto b = remesh_isotropic(m, {.edges_across = 12});
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->mesh.faces == b->mesh.faces);
    REQUIRE(a->mesh.num_vertices() == b->mesh.num_vertices());
    for (index_t v = 0; v < a->mesh.num_vertices(); ++v)
      CHECK(scale * a->mesh.positions[detail::to_size(v)] == b->mesh.positions[detail::to_size(v)]);
  }
}

TEST_CASE("remesh: bad input and options are refused with a message and zero rounds keep the mesh") {
  const tri_mesh cube = shapes::voxel_surface(shapes::cube(), 2);
  tri_mesh open = cube;
  open.faces.pop_back();
  CHECK(remesh_isotropic(open).error().message().find("not closed") != std::string::npos);
  tri_mesh nan = cube;
  nan.positions[0].x = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(remesh_isotropic(nan));
  CHECK(remesh_isotropic(tri_mesh{}).error().code() == status_code::invalid_argument);
  CHECK(remesh_isotropic(cube, {.edge_length = -1}).error().message().find("edge_length") != std::string::npos);
  CHECK_FALSE(remesh_isotropic(cube, {.edge_length = std::numeric_limits<double>::infinity()}));
  CHECK(remesh_isotropic(cube, {.edges_across = 0}).error().message().find("edges_across") != std::string::npos);
  CHECK(remesh_isotropic(cube, {.feature_angle = 200}).error().message().find("feature_angle") != std::string::npos);
  CHECK(remesh_isotropic(cube, {.iterations = -1}).error().message().find("iterations") != std::string::npos);
  // an edge so short it would need billions of faces is refused before any allocation
  const auto tiny = remesh_isotropic(cube, {.edge_length = 1e-7});
  REQUIRE_FALSE(tiny);
  CHECK(tiny.error().message().find("max_faces") != std::string::npos);
  const auto same = remesh_isotropic(cube, {.iterations = 0});
  REQUIRE(same);
  CHECK(same->mesh.faces == cube.faces);
  CHECK(same->mesh.positions == cube.positions);
  // cancellation
  remesh_options o;
  o.edges_across = 8;
  o.progress.callback = [](double f, std::string_view) { return f < 0.3; };
  CHECK(remesh_isotropic(cube, o).error().code() == status_code::cancelled);
}
