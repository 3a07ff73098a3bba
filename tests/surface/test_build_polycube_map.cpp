#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/surface/build_polycube_map.hpp>

#include "check_map.hpp"
#include "shapes.hpp"

using namespace tessera;

TEST_CASE("polycube: voxel solids become themselves, any genus") {
  struct shape {
    const char* name;
    std::set<shapes::voxel> vox;
    long long euler;
    std::size_t charts, quads;
  };
  for (const auto& s : {shape{"cube", shapes::cube(), 2, 6, 6 * 4}, shape{"L", shapes::l_shape(), 2, 8, 14 * 4},
                        shape{"ring", shapes::ring(), 0, 4 + 4 + 2, 32 * 4},
                        shape{"genus 2", shapes::genus2(), -2, 4 + 8 + 2, 50 * 4}}) {
    INFO(s.name);
    const auto m = shapes::voxel_surface(s.vox, 2);
    polycube_options o;
    o.tile_size = 0.5;
    auto r = build_polycube_map(m, o);
    INFO(r.error().to_string());
    REQUIRE(r);
    CHECK(check_polycube(*r) == s.euler);
    CHECK(r->charts.size() == s.charts);
    CHECK(r->layout.quads.size() == s.quads);
    for (std::size_t v = 0; v < m.positions.size(); ++v) CHECK(distance(r->polycube[v], m.positions[v]) < 1e-6);
    for (const auto& e : r->edges) CHECK(e.length >= 1);
    for (const auto& c : r->corners) CHECK(c.charts.size() >= 3);
  }
}

TEST_CASE("polycube: smooth sphere and torus (genus 0 and 1)") {
  polycube_options o;
  o.tiles_across = 6;
  auto s = build_polycube_map(shapes::sphere(8), o);
  INFO(s.error().to_string());
  REQUIRE(s);
  CHECK(check_polycube(*s) == 2);
  CHECK(s->charts.size() == 6);
  CHECK(s->corners.size() == 8);
  auto t = build_polycube_map(shapes::torus(2, 0.7, 48, 16), o);
  INFO(t.error().to_string());
  REQUIRE(t);
  CHECK(check_polycube(*t) == 0);
}

TEST_CASE("polycube: quantization never collapses an edge below one tile") {
  // a flat box 4 x 4 x 0.2 with tiles of 1: its thin sides round to zero but must keep one tile
  auto m = shapes::voxel_surface(shapes::cube(), 4);
  for (auto& p : m.positions) p = {p.x * 4, p.y * 4, p.z * 0.2};
  polycube_options o;
  o.tile_size = 1;
  auto r = build_polycube_map(m, o);
  INFO(r.error().to_string());
  REQUIRE(r);
  check_polycube(*r);
  for (const auto& e : r->edges) CHECK(e.length >= 1);
  for (const auto& c : r->charts)
    if (label_axis(c.label) == 2) CHECK(std::abs(c.plane) <= 1);
}

TEST_CASE("polycube: deterministic across thread counts") {
  const auto m = shapes::torus(2, 0.8, 40, 14);
  polycube_options o;
  o.tiles_across = 8;
  auto a = build_polycube_map(m, o);
  thread_pool_executor pool(3);
  auto b = build_polycube_map(m, o, pool);
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->polycube == b->polycube);
  CHECK(a->labels == b->labels);
  CHECK(a->layout.quads.size() == b->layout.quads.size());
}

TEST_CASE("polycube: raw-buffer input (mesh_view)") {
  const auto m = shapes::voxel_surface(shapes::l_shape(), 2);
  std::vector<float> pos;
  std::vector<std::uint32_t> idx;
  for (const auto& p : m.positions) pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
  for (const auto& f : m.faces)
    for (index_t v : f) idx.push_back(static_cast<std::uint32_t>(v));
  auto view = make_mesh_view(pos.data(), m.num_vertices(), idx.data(), m.num_faces());
  REQUIRE(view);
  polycube_options o;
  o.tile_size = 0.5;
  auto r = build_polycube_map(*view, o);
  REQUIRE(r);
  CHECK(check_polycube(*r) == 2);
}

TEST_CASE("polycube: user labels, used as given and checked") {
  const auto m = shapes::voxel_surface(shapes::cube(), 2);
  polycube_options o;
  o.tile_size = 0.5;
  auto ref = build_polycube_map(m, o);
  REQUIRE(ref);
  std::vector<std::uint8_t> lab;
  for (auto l : ref->labels) lab.push_back(static_cast<std::uint8_t>(l));
  auto r = build_polycube_map_from_labels(m, lab, o);
  REQUIRE(r);
  CHECK(r->polycube == ref->polycube);
  auto shorter = lab;
  shorter.pop_back();
  CHECK(build_polycube_map_from_labels(m, shorter, o).error().message().find("labels for") != std::string::npos);
  auto big = lab;
  big[5] = 7;
  CHECK(build_polycube_map_from_labels(m, big, o).error().message().find("face 5") != std::string::npos);
  auto island = lab;  // one face of another label inside a chart: an island, rejected (not repaired)
  island[0] = static_cast<std::uint8_t>(lab[0] ^ 1);
  auto bad = build_polycube_map_from_labels(m, island, o);
  CHECK(!bad);
  CHECK(bad.error().code() == status_code::not_converged);
}

TEST_CASE("polycube: user-supplied deformed mesh, validated") {
  const auto m = shapes::sphere(6);
  polycube_options o;
  o.tiles_across = 4;
  auto ref = build_polycube_map(m, o);
  REQUIRE(ref);
  auto r = polycube_map_from_deformed(m, ref->deformed_mesh(), ref->tile_size);
  INFO(r.error().to_string());
  REQUIRE(r);
  CHECK(r->layout.quads.size() == ref->layout.quads.size());
  CHECK(r->labels == ref->labels);
  // the sphere itself is not a polycube: the first face not axis-aligned is named
  auto notpc = polycube_map_from_deformed(m, m, ref->tile_size);
  CHECK(notpc.error().message().find("not axis-aligned") != std::string::npos);
  // off the tile grid
  auto off = polycube_map_from_deformed(m, ref->deformed_mesh(), ref->tile_size * 0.7);
  CHECK(!off);
  auto wrong = ref->deformed_mesh();
  wrong.faces.pop_back();
  CHECK(polycube_map_from_deformed(m, wrong, ref->tile_size).error().code() == status_code::invalid_argument);
  CHECK(!polycube_map_from_deformed(m, ref->deformed_mesh(), -1.0));
}

TEST_CASE("polycube: bad input and options never crash") {
  auto open = shapes::voxel_surface(shapes::cube(), 2);
  open.faces.pop_back();
  CHECK(build_polycube_map(open).error().message().find("not closed") != std::string::npos);
  polycube_options o;
  o.tile_size = 100;
  CHECK(!build_polycube_map(shapes::sphere(3), o));
  o.tile_size = 0.5;
  o.opposite_penalty = 5;
  CHECK(!build_polycube_map(shapes::sphere(3), o));
}
