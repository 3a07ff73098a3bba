#include <catch2/catch.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/geometry/bvh.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/map_tiles_to_shell.hpp>

#include "ring_tiles.hpp"
#include "shapes.hpp"

using namespace tessera;

namespace {

struct fixture {
  polycube_map map;
  shell sh;
  double H = 0;
};

fixture make(const tri_mesh& m, index_t tiles_across, double height_in_tiles = 0.25) {
  polycube_options o;
  o.tiles_across = tiles_across;
  auto map = build_polycube_map(m, o);
  REQUIRE(map);
  fixture f;
  f.H = height_in_tiles * map->tile_size;
  auto sh = build_shell(m, f.H);
  REQUIRE(sh);
  f.map = std::move(*map);
  f.sh = std::move(*sh);
  return f;
}

// Per-quad tiles as a vector; the callable map_tiles_to_shell takes.
struct tile_list {
  std::vector<tri_mesh> meshes;
  const tri_mesh* operator()(index_t q) const {
    const auto& m = meshes[static_cast<std::size_t>(q)];
    return m.faces.empty() ? nullptr : &m;
  }
};

double signed_volume(const tri_mesh& m, const mesh_components& c, index_t comp) {
  double v = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (c.face_component[f] == comp) {
      const auto& t = m.faces[f];
      v += dot(m.position(t[0]), cross(m.position(t[1]), m.position(t[2]))) / 6;
    }
  return v;
}

// closed, edge- and vertex-manifold, consistently oriented, every component of positive volume, no
// two faces crossing, every vertex within the shell
void check_elements(const fixture& f, const shell_map_result& r, index_t components) {
  REQUIRE(r.element_faces > 0);
  INFO("elements: " << r.element_vertices << " vertices, " << r.element_faces << " faces");
  const auto valid = validate_polycube_input(r.mesh, "mapped elements");
  INFO(valid.message());
  CHECK(valid.ok());
  CHECK(boundary_edges(r.mesh).empty());
  CHECK(count_nonmanifold_edges(r.mesh) == 0);
  const auto cc = connected_components(r.mesh);
  CHECK(cc.count == components);
  for (index_t c = 0; c < cc.count; ++c) CHECK(signed_volume(r.mesh, cc, c) > 0);
  const triangle_bvh base(f.map.base);
  double worst = 0;
  for (const vec3& p : r.mesh.positions) worst = std::max(worst, std::sqrt(base.closest_point(p).squared_distance));
  CHECK(worst <= f.H * (1 + 1e-6));
  const triangle_bvh out(r.mesh);
  index_t crossings = 0;
  out.for_each_self_intersection(
      [&](index_t a, index_t b) {
        for (index_t x : r.mesh.faces[static_cast<std::size_t>(a)])
          for (index_t y : r.mesh.faces[static_cast<std::size_t>(b)])
            if (x == y) return true;
        return false;
      },
      [&](index_t, index_t) { ++crossings; });
  CHECK(crossings == 0);
}

// a quad and side whose neighbour lies in the same chart (same_chart) or across a polycube edge
std::pair<index_t, int> find_side(const polycube_map& m, bool same_chart, const std::vector<index_t>& avoid) {
  const auto& Q = m.layout.quads;
  for (index_t q = 0; q < static_cast<index_t>(Q.size()); ++q)
    for (int k = 0; k < 4; ++k) {
      const index_t n = Q[static_cast<std::size_t>(q)].neighbors[static_cast<std::size_t>(k)];
      if ((Q[static_cast<std::size_t>(n)].chart == Q[static_cast<std::size_t>(q)].chart) != same_chart) continue;
      if (std::find(avoid.begin(), avoid.end(), q) != avoid.end() ||
          std::find(avoid.begin(), avoid.end(), n) != avoid.end())
        continue;
      return {q, k};
    }
  FAIL("no such side");
  return {-1, 0};
}

}  // namespace

TEST_CASE("shell mapping: rings inside a quad, across a quad border and across a polycube edge stay closed") {
  for (const auto& base : {shapes::sphere(12), shapes::torus(2, 0.7, 48, 16)}) {
    const auto f = make(base, 6);
    const polycube_projector pj(f.map);
    const double T = f.map.tile_size;
    tile_list tiles;
    tiles.meshes.resize(f.map.layout.quads.size());
    tiles.meshes[0] = ring_tiles::ring(0.5, 0.5, 0.25, 0.08, 0.1 * T, 0.06 * T);
    const auto [qa, ka] = find_side(f.map, true, {0});
    const auto na = f.map.layout.quads[static_cast<std::size_t>(qa)].neighbors[static_cast<std::size_t>(ka)];
    const auto [qb, kb] = find_side(f.map, false, {0, qa, na});
    const auto nb = f.map.layout.quads[static_cast<std::size_t>(qb)].neighbors[static_cast<std::size_t>(kb)];
    for (const auto& [q, k, n] : {std::tuple{qa, ka, na}, std::tuple{qb, kb, nb}}) {
      auto halves = ring_tiles::ring_across_side(f.map.layout.quads[static_cast<std::size_t>(q)], k, 0.2, 0.06, 0.1 * T,
                                                 0.06 * T);
      tiles.meshes[static_cast<std::size_t>(q)] = halves[0];
      tiles.meshes[static_cast<std::size_t>(n)] = halves[1];
    }
    // both modes: closed and welded across quad borders and polycube edges, no crossing
    for (const auto mode : {shell_clip::midpoint, shell_clip::exact}) {
      shell_map_options o;
      o.clip = mode;
      auto r = map_tiles_to_shell(f.map, pj, f.sh, tiles, o);
      REQUIRE(r);
      CHECK(r->quads == 5);
      CHECK(r->welded_vertices == 2 * 2 * 8);  // two cut columns of 8 vertices per crossing ring
      CHECK(r->dropped_faces == 0);
      check_elements(f, *r, 3);
    }
  }
}

TEST_CASE("shell mapping: a plate over every quad welds into one closed offset surface, long edges are split") {
  const auto f = make(shapes::torus(2, 0.7, 48, 16), 6);
  const polycube_projector pj(f.map);
  tri_mesh plate;
  for (const vec3 p : {vec3{0, 0, 0}, vec3{1, 0, 0}, vec3{1, 1, 0}, vec3{0, 1, 0}})
    plate.add_vertex(p + vec3{0, 0, f.H / 2});
  plate.add_face(0, 1, 2);
  plate.add_face(0, 2, 3);
  const auto nq = static_cast<index_t>(f.map.layout.quads.size());
  shell_map_options exact;
  exact.clip = shell_clip::exact;
  for (const auto& mode : {shell_map_options{}, exact}) {
    auto r = map_tiles_to_shell(
        f.map, pj, f.sh, [&](index_t) { return &plate; }, mode);
    REQUIRE(r);
    CHECK(r->tile_vertices == 4 * nq);
    CHECK(r->welded_vertices == 3 * nq);  // one vertex per grid corner: V = E - F = F quads on a torus
    CHECK(r->split_edges > 0);
    CHECK(r->element_faces > 2 * nq);
    check_elements(f, *r, 1);
    // every vertex at half the local height above the base (up to the shell map's tilt)
    const triangle_bvh base(f.map.base);
    for (const vec3& p : r->mesh.positions) {
      const double d = std::sqrt(base.closest_point(p).squared_distance);
      CHECK(d <= 0.5 * f.H * (1 + 1e-9));
      CHECK(d >= 0.2 * f.H);
    }
  }
  // midpoint refinement without split rounds: every quad stays two triangles
  shell_map_options coarse;
  coarse.clip = shell_clip::midpoint;
  coarse.max_split_rounds = 0;
  auto c = map_tiles_to_shell(
      f.map, pj, f.sh, [&](index_t) { return &plate; }, coarse);
  REQUIRE(c);
  CHECK(c->split_edges == 0);
  CHECK(c->element_faces == 2 * nq);
}

TEST_CASE("shell mapping: same output on any number of threads") {
  const auto f = make(shapes::sphere(12), 6);
  const polycube_projector pj(f.map);
  const double T = f.map.tile_size;
  const auto ring = ring_tiles::ring(0.5, 0.5, 0.3, 0.1, 0.1 * T, 0.08 * T, 16, 6);
  shell_map_options o;
  o.with_base = true;
  o.clip = shell_clip::exact;
  auto a = map_tiles_to_shell(
      f.map, pj, f.sh, [&](index_t) { return &ring; }, o);
  REQUIRE(a);
  CHECK(a->mesh.num_faces() == a->element_faces + f.map.base.num_faces());
  CHECK(a->mesh.num_vertices() == a->element_vertices + f.map.base.num_vertices());
  for (int threads : {2, 3}) {
    thread_pool_executor pool(threads);
    auto b = map_tiles_to_shell(
        f.map, pj, f.sh, [&](index_t) { return &ring; }, o, pool);
    REQUIRE(b);
    CHECK(b->mesh == a->mesh);
  }
}

TEST_CASE("shell mapping: bad input returns a clear status") {
  const auto f = make(shapes::sphere(8), 4);
  const polycube_projector pj(f.map);
  tri_mesh ok = ring_tiles::ring(0.5, 0.5, 0.25, 0.08, 0.05 * f.map.tile_size, 0.04 * f.map.tile_size, 8, 4);
  // a shell of another mesh
  auto other = build_shell(shapes::sphere(6), f.H);
  REQUIRE(other);
  auto e1 = map_tiles_to_shell(f.map, pj, *other, [&](index_t) { return &ok; });
  REQUIRE(!e1);
  CHECK(e1.error().code() == status_code::invalid_argument);
  CHECK(e1.error().message().find("not built over") != std::string::npos);
  // a vertex outside the square, above the shell, an invalid tile mesh
  tri_mesh out = ok;
  out.positions[3].x = 1.2;
  auto e2 = map_tiles_to_shell(f.map, pj, f.sh, [&](index_t q) { return q == 2 ? &out : &ok; });
  REQUIRE(!e2);
  CHECK(e2.error().message().find("quad 2") != std::string::npos);
  tri_mesh high = ok;
  high.positions[0].z = 2 * f.H;
  CHECK(map_tiles_to_shell(f.map, pj, f.sh, [&](index_t) { return &high; }).error().code() ==
        status_code::invalid_argument);
  tri_mesh broken = ok;
  broken.faces[0][1] = 100000;
  CHECK(map_tiles_to_shell(f.map, pj, f.sh, [&](index_t) { return &broken; }).error().code() ==
        status_code::out_of_range);
  tri_mesh nan = ok;
  nan.positions[1].y = std::nan("");
  CHECK(!map_tiles_to_shell(f.map, pj, f.sh, [&](index_t) { return &nan; }));
  shell_map_options bad;
  bad.chordal_tolerance = 0;
  CHECK(map_tiles_to_shell(
            f.map, pj, f.sh, [&](index_t) { return &ok; }, bad)
            .error()
            .code() == status_code::invalid_argument);
  // no tiles at all: an empty mesh, not an error
  auto none = map_tiles_to_shell(f.map, pj, f.sh, [](index_t) -> const tri_mesh* { return nullptr; });
  REQUIRE(none);
  CHECK(none->mesh.num_faces() == 0);
}
