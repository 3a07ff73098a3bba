#include <tessera/geometry/mesh_exemplars.hpp>

#include <tessera/core/mesh_topology.hpp>
#include <tessera/geometry/mesh_elements.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
// every edge used by exactly two faces in opposite directions; positive volume per element
void require_closed_oriented_disjoint(const tri_mesh& m) {
  REQUIRE(validate_mesh(m).ok());
  for (const mesh_edge& e : mesh_edges(m)) {
    REQUIRE(e.faces.size() == 2);
    const auto& f0 = m.faces[std::size_t(e.faces[0][0])];
    const auto& f1 = m.faces[std::size_t(e.faces[1][0])];
    const index_t a0 = f0[std::size_t(e.faces[0][1])], a1 = f1[std::size_t(e.faces[1][1])];
    REQUIRE(a0 != a1);  // opposite directions
  }
  auto elems = extract_elements(m);
  REQUIRE(elems.ok());
  for (const auto& el : *elems) {
    double vol = 0;
    for (const auto& f : el.mesh.faces)
      vol += dot(el.mesh.positions[std::size_t(f[0])],
                 cross(el.mesh.positions[std::size_t(f[1])], el.mesh.positions[std::size_t(f[2])])) /
             6;
    REQUIRE(vol > 0);
    REQUIRE(el.box.min.z >= 0);
  }
  // no two elements intersect
  const auto comp = connected_components(m);
  const triangle_bvh bvh(m);
  index_t bad = 0;
  bvh.for_each_self_intersection(
      [&](index_t f, index_t g) { return comp.face_component[std::size_t(f)] == comp.face_component[std::size_t(g)]; },
      [&](index_t, index_t) { ++bad; });
  REQUIRE(bad == 0);
}
}  // namespace

TEST_CASE("ring exemplar: closed, oriented, disjoint tori in the paper's vertex range", "[exemplars]") {
  const auto m = make_ring_exemplar();
  REQUIRE(m.ok());
  REQUIRE(m->num_vertices() >= 4000);
  REQUIRE(m->num_vertices() <= 8000);
  require_closed_oriented_disjoint(*m);
  const auto b = bounding_box(*m);
  REQUIRE(b.min.x >= 0);
  REQUIRE(b.max.x <= 8);
  // same seed, same mesh; another seed, another mesh
  REQUIRE(*make_ring_exemplar() == *m);
  REQUIRE_FALSE(*make_ring_exemplar({.seed = 2}) == *m);
}

TEST_CASE("ring exemplar: chain mail interlocks without intersecting", "[exemplars]") {
  const auto m = make_ring_exemplar(
      {.size = 4, .minor_radius = 0.08, .ring_segments = 20, .tube_segments = 6, .chain_mail = true});
  REQUIRE(m.ok());
  require_closed_oriented_disjoint(*m);
  // interlocked: count how often the tube centre circle of one ring pierces the disk of another
  // (odd = linked). Rings away from the border link exactly four neighbours.
  const auto elems = extract_elements(*m);
  REQUIRE(elems->size() > 10);
  struct circle {
    vec3 c, n;
    std::vector<vec3> pts;
  };
  std::vector<circle> cs;
  for (const auto& e : *elems) {
    circle c;
    for (const vec3& p : e.mesh.positions) c.c += p / double(e.mesh.positions.size());
    // centre-line points: average of each tube ring of 6 vertices
    for (std::size_t i = 0; i < e.mesh.positions.size(); i += 6) {
      vec3 q;
      for (std::size_t k = 0; k < 6; ++k) q += e.mesh.positions[i + k] / 6.0;
      c.pts.push_back(q);
    }
    c.n = normalized(cross(c.pts[0] - c.c, c.pts[5] - c.c));
    cs.push_back(std::move(c));
  }
  int interior = 0;
  for (std::size_t a = 0; a < cs.size(); ++a) {
    if (cs[a].c.x < 1.3 || cs[a].c.x > 2.7 || cs[a].c.y < 1.3 || cs[a].c.y > 2.7) continue;
    ++interior;
    int linked = 0;
    for (std::size_t b = 0; b < cs.size(); ++b) {
      if (a == b) continue;
      int pierce = 0;
      for (std::size_t k = 0; k < cs[b].pts.size(); ++k) {
        const vec3 p0 = cs[b].pts[k], p1 = cs[b].pts[(k + 1) % cs[b].pts.size()];
        const double s0 = dot(p0 - cs[a].c, cs[a].n), s1 = dot(p1 - cs[a].c, cs[a].n);
        if ((s0 > 0) != (s1 > 0) && norm(p0 + (p1 - p0) * (s0 / (s0 - s1)) - cs[a].c) < 0.5) ++pierce;
      }
      linked += pierce % 2;
    }
    REQUIRE(linked == 4);
  }
  REQUIRE(interior >= 2);
}

TEST_CASE("stone exemplar: closed, oriented, disjoint pebbles", "[exemplars]") {
  const auto m = make_stone_exemplar();
  REQUIRE(m.ok());
  REQUIRE(m->num_vertices() >= 4000);
  REQUIRE(m->num_vertices() <= 9000);
  require_closed_oriented_disjoint(*m);
  const auto dense = make_stone_exemplar({.coverage = 0.7});
  const auto sparse = make_stone_exemplar({.coverage = 0.3});
  REQUIRE(dense->num_vertices() > sparse->num_vertices());
}

TEST_CASE("weave exemplar: closed, oriented, disjoint threads", "[exemplars]") {
  const auto m = make_weave_exemplar();
  REQUIRE(m.ok());
  REQUIRE(m->num_vertices() >= 4000);
  REQUIRE(m->num_vertices() <= 9000);
  require_closed_oriented_disjoint(*m);
  REQUIRE(extract_elements(*m)->size() == 16);
}

TEST_CASE("exemplar generators reject bad options", "[exemplars]") {
  REQUIRE_FALSE(make_ring_exemplar({.size = 0}).ok());
  REQUIRE_FALSE(make_ring_exemplar({.size = std::nan("")}).ok());
  REQUIRE_FALSE(make_ring_exemplar({.minor_radius = 0.6}).ok());
  REQUIRE_FALSE(make_ring_exemplar({.ring_segments = 2}).ok());
  REQUIRE(make_ring_exemplar({.spacing = 1.0}).error().message().find("touch") != std::string::npos);
  REQUIRE_FALSE(make_stone_exemplar({.min_radius = 0.8, .max_radius = 0.5}).ok());
  REQUIRE_FALSE(make_stone_exemplar({.coverage = 0}).ok());
  REQUIRE_FALSE(make_stone_exemplar({.subdivisions = 9}).ok());
  REQUIRE_FALSE(make_weave_exemplar({.thickness = 0.3}).ok());
  REQUIRE_FALSE(make_weave_exemplar({.around = 2}).ok());
}
