#include <tessera/geometry/mesh_elements.hpp>

#include <tessera/core/mesh_view.hpp>
#include <tessera/geometry/detail/mesh_clip.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
double volume(const tri_mesh& m) {
  double v = 0;
  for (const auto& f : m.faces)
    v += dot(m.positions[std::size_t(f[0])], cross(m.positions[std::size_t(f[1])], m.positions[std::size_t(f[2])])) / 6;
  return v;
}
double area(const tri_mesh& m) {
  double a = 0;
  for (index_t f = 0; f < m.num_faces(); ++f) a += face_area(m, f);
  return a;
}
tri_mesh one_torus(vec3 c) {
  tri_mesh m;
  detail::add_torus(m, c, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.15, 24, 10);
  return m;
}
}  // namespace

TEST_CASE("extract_elements splits a texture into closed components", "[elements]") {
  const auto m = make_ring_exemplar({.size = 4});
  REQUIRE(m.ok());
  const auto e = extract_elements(*m);
  REQUIRE(e.ok());
  REQUIRE(e->size() == 4);
  std::size_t nv = 0;
  for (const auto& el : *e) {
    REQUIRE(el.border == 0u);
    REQUIRE(el.fixed.size() == el.mesh.positions.size());
    REQUIRE_FALSE(el.has_fixed());
    REQUIRE(count_edge_defects(el.mesh).open_edges == 0);
    nv += el.mesh.positions.size();
  }
  REQUIRE(nv == m->positions.size());
  const tri_mesh back = combine_elements(*e);
  REQUIRE(back.num_faces() == m->num_faces());
  REQUIRE(area(back) == Approx(area(*m)));
}

TEST_CASE("extract_elements works through a mesh_view", "[elements]") {
  const tri_mesh t = one_torus({0, 0, 1});
  std::vector<double> pos;
  std::vector<std::int32_t> idx;
  for (const vec3& p : t.positions) pos.insert(pos.end(), {p.x, p.y, p.z});
  for (const auto& f : t.faces) idx.insert(idx.end(), {std::int32_t(f[0]), std::int32_t(f[1]), std::int32_t(f[2])});
  const auto view = make_mesh_view(pos.data(), t.num_vertices(), idx.data(), t.num_faces());
  const auto e = extract_elements(*view);
  REQUIRE(e.ok());
  REQUIRE(e->size() == 1);
  REQUIRE((*e)[0].mesh.num_faces() == t.num_faces());
  REQUIRE(area((*e)[0].mesh) == Approx(area(t)));
}

TEST_CASE("extract_elements rejects open, non-manifold, empty and NaN input", "[elements]") {
  tri_mesh open = one_torus({0, 0, 1});
  open.faces.pop_back();
  auto r = extract_elements(open);
  REQUIRE(r.error().code() == status_code::invalid_argument);
  REQUIRE(r.error().message().find("open edges") != std::string::npos);
  REQUIRE(extract_elements(open, {.require_closed = false}).ok());

  tri_mesh nm = one_torus({0, 0, 1});
  const index_t extra = nm.add_vertex({5, 5, 5});
  nm.add_face(nm.faces[0][0], nm.faces[0][1], extra);  // a third face on an edge
  r = extract_elements(nm, {.require_closed = false});
  REQUIRE(r.error().message().find("non-manifold") != std::string::npos);

  REQUIRE(extract_elements(tri_mesh{}).error().message().find("no faces") != std::string::npos);
  tri_mesh nan = one_torus({0, 0, 1});
  nan.positions[3].y = std::nan("");
  REQUIRE(extract_elements(nan).error().message().find("non-finite") != std::string::npos);
}

TEST_CASE("border triangles follow the border set B(C)", "[elements]") {
  texture_element e;
  e.mesh = one_torus({0, 2, 1});  // straddles the west side x = 0 of [0, 4]^2
  e.fixed.assign(e.mesh.positions.size(), 0);
  e.update_box();
  const xy_rect tile{0, 0, 4, 4};
  auto none = border_triangles(e, tile);
  REQUIRE(std::count(none.begin(), none.end(), 1) == 0);
  e.border = border_bit(side_west);
  const auto tri = border_triangles(e, tile);
  int count = 0;
  for (std::size_t f = 0; f < tri.size(); ++f) {
    aabb b;
    for (index_t v : e.mesh.faces[f]) b.extend(e.mesh.positions[std::size_t(v)]);
    REQUIRE(bool(tri[f]) == (b.min.x <= 0 && b.max.x >= 0));
    count += tri[f];
  }
  REQUIRE(count > 0);
  const auto verts = border_vertices(e, tile);
  for (std::size_t f = 0; f < tri.size(); ++f)
    if (tri[f])
      for (index_t v : e.mesh.faces[f]) REQUIRE(verts[std::size_t(v)] == 1);
  e.border = border_bit(side_east);
  const auto east = border_triangles(e, tile);
  REQUIRE(std::count(east.begin(), east.end(), 1) == 0);
}

TEST_CASE("splitting by a plane shares exact cut vertices, and caps close the halves", "[elements]") {
  const tri_mesh t = one_torus({0.1, 0.0, 1.0});
  for (int axis : {0, 1}) {
    for (double value : {0.0, 0.3, 0.55}) {
      auto s = detail::split_mesh_by_plane(t, axis, value, 1e-12);  // snap round-off onto the plane
      REQUIRE(area(s.below) + area(s.above) == Approx(area(t)));
      std::vector<vec3> cut_below, cut_above;
      for (const vec3& p : s.below.positions) {
        REQUIRE(p[axis] <= value);
        if (p[axis] == value) cut_below.push_back(p);
      }
      for (const vec3& p : s.above.positions) {
        REQUIRE(p[axis] >= value);
        if (p[axis] == value) cut_above.push_back(p);
      }
      auto less = [](vec3 a, vec3 b) { return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z; };
      std::sort(cut_below.begin(), cut_below.end(), less);
      std::sort(cut_above.begin(), cut_above.end(), less);
      REQUIRE(cut_below == cut_above);  // bit-identical
      index_t caps = 0;
      REQUIRE(detail::cap_plane_loops(s.below, axis, value, &caps));
      REQUIRE(detail::cap_plane_loops(s.above, axis, value, &caps));
      REQUIRE(caps >= 2);
      REQUIRE(count_edge_defects(s.below).open_edges == 0);
      REQUIRE(count_edge_defects(s.above).open_edges == 0);
      REQUIRE(volume(s.below) > 0);
      REQUIRE(volume(s.above) > 0);
      REQUIRE(volume(s.below) + volume(s.above) == Approx(volume(t)).epsilon(1e-9));
    }
  }
}

TEST_CASE("ear clipping triangulates a non-convex polygon", "[elements]") {
  const std::vector<vec2> poly{{0, 0}, {4, 0}, {4, 3}, {2, 1}, {0, 3}};
  std::vector<std::array<index_t, 3>> tris;
  REQUIRE(detail::ear_clip(poly, tris));
  REQUIRE(tris.size() == 3);
  double a = 0;
  for (const auto& t : tris) {
    const double s =
        cross(poly[std::size_t(t[1])] - poly[std::size_t(t[0])], poly[std::size_t(t[2])] - poly[std::size_t(t[0])]) / 2;
    REQUIRE(s > 0);  // same winding as the polygon
    a += s;
  }
  REQUIRE(a == Approx(4 * 3 - 0.5 * 4 * 2));
  std::vector<std::array<index_t, 3>> none;
  REQUIRE_FALSE(detail::ear_clip({{0, 0}, {1, 1}}, none));
}
