#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_distortion.hpp>

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

namespace {
/// Labels of a voxel surface from its face normals, and the chart set.
struct labelled {
  tri_mesh m;
  std::vector<std::array<index_t, 3>> nb;
  std::vector<std::uint8_t> lab;
  detail::polycube_chart_set cs;
};
labelled label_voxels(const std::set<shapes::voxel>& vox, int s) {
  labelled l;
  l.m = shapes::voxel_surface(vox, s);
  l.nb = face_adjacency(l.m).neighbor;
  for (index_t f = 0; f < l.m.num_faces(); ++f) {
    const vec3 n = normalized(face_area_normal(l.m, f));
    for (int k = 0; k < 6; ++k)
      if (dot(n, label_direction(static_cast<polycube_label>(k))) > 0.5) l.lab.push_back(static_cast<std::uint8_t>(k));
  }
  l.cs = detail::find_polycube_charts(l.m, l.nb, l.lab);
  return l;
}

/// The vertex at `p` (to 1e-12), or -1.
index_t vertex_at(const tri_mesh& m, vec3 p) {
  for (index_t v = 0; v < m.num_vertices(); ++v)
    if (distance(m.position(v), p) < 1e-12) return v;
  return -1;
}

vec3 centroid(const tri_mesh& m, index_t f) {
  return (m.position(m.face_vertex(f, 0)) + m.position(m.face_vertex(f, 1)) + m.position(m.face_vertex(f, 2))) / 3.0;
}

/// Gives each face on the cube's top (z = 1) the label `label_of(centroid x, y)` returns (-1: keep).
template <class LabelOf>
void relabel_top(labelled& l, LabelOf label_of) {
  for (index_t f = 0; f < l.m.num_faces(); ++f) {
    const vec3 c = centroid(l.m, f);
    if (const int k = c.z > 0.999 ? label_of(c.x, c.y) : -1; k >= 0)
      l.lab[detail::to_size(f)] = static_cast<std::uint8_t>(k);
  }
}
}  // namespace

TEST_CASE("polycube repair: edge paths run from corner to corner") {
  const auto l = label_voxels(shapes::cube(), 2);
  const auto paths = detail::find_polycube_edge_paths(l.m, l.nb, l.cs);
  REQUIRE(paths.size() == 12);
  for (const auto& p : paths) {
    CHECK(p.c < p.d);
    CHECK(p.vertices.size() == 3);  // two corners and the midpoint of the unit edge
    CHECK(l.cs.vertex_charts[detail::to_size(p.vertices.front())].size() == 3);
    CHECK(l.cs.vertex_charts[detail::to_size(p.vertices.back())].size() == 3);
    CHECK(l.cs.vertex_charts[detail::to_size(p.vertices[1])].size() == 2);
  }
  const auto loops = detail::chart_boundary_loops(l.cs.chart_label.size(), paths);
  for (const auto& cl : loops) {
    REQUIRE(cl.size() == 1);  // one loop of four sides per square chart
    CHECK(cl[0].size() == 4);
  }
}

TEST_CASE("polycube repair: quantization keeps the direction of every edge, and finds cycles") {
  // three charts of axis X whose continuous planes all round to 0; edges 0 -> 1 -> 2 raise them
  const std::vector<double> p{0.2, 0.1, 0.0};
  const std::vector<int> axis{0, 0, 0};
  auto q = detail::quantize_planes(p, axis, {{0, 1}, {1, 2}}, 0, 1.0);
  REQUIRE(q);
  CHECK(*q == std::vector<std::int64_t>{0, 1, 2});
  auto bad = index_t{-1};
  auto cyc = detail::quantize_planes(p, axis, {{0, 1}, {1, 2}, {2, 0}}, 0, 1.0, &bad);
  REQUIRE(!cyc);
  CHECK(cyc.error().message().find("cycle of directions") != std::string::npos);
  CHECK(bad >= 0);
}

TEST_CASE("polycube repair: a chart boundary that does not turn as a polycube face is named") {
  const auto l = label_voxels(shapes::l_shape(), 2);
  const auto paths = detail::find_polycube_edge_paths(l.m, l.nb, l.cs);
  const auto loops = detail::chart_boundary_loops(l.cs.chart_label.size(), paths);
  std::string why;
  CHECK(detail::find_unturnable_chart(l.cs, paths, loops, l.m.positions, 0.5, why) == -1);
  // all corners at one point: every side has length zero
  const std::vector<vec3> flat(l.m.positions.size());
  CHECK(detail::find_unturnable_chart(l.cs, paths, loops, flat, 0.5, why) == 0);
  CHECK(why.find("length zero") != std::string::npos);
  // mirrored along X: the loops of the charts facing Y and Z turn by -4, as holes without an outer loop
  auto mirrored = l.m.positions;
  for (auto& p : mirrored) p.x = -p.x;
  CHECK(detail::find_unturnable_chart(l.cs, paths, loops, mirrored, 0.5, why) >= 0);
  CHECK(why.find("0 outer boundary loops") != std::string::npos);
}

TEST_CASE("polycube repair: the L-shaped charts are cut into rectangles, then embedded unfolded") {
  const auto l = label_voxels(shapes::l_shape(), 4);
  const auto paths = detail::find_polycube_edge_paths(l.m, l.nb, l.cs);
  const auto loops = detail::chart_boundary_loops(l.cs.chart_label.size(), paths);
  std::array<detail::polycube_axis_classes, 3> cl;
  for (int a = 0; a < 3; ++a)
    cl[detail::to_size(a)] = *detail::polycube_classes(l.m, l.cs.face_chart, l.cs.chart_label, a);
  auto is_free = [&](std::size_t v, int a) {
    return cl[detail::to_size(a)].class_chart[detail::to_size(cl[detail::to_size(a)].vertex_class[v])] < 0;
  };
  std::vector<std::vector<index_t>> ring(l.m.positions.size());
  for (const auto& f : l.m.faces)
    for (int k = 0; k < 3; ++k) ring[detail::to_size(f[detail::to_size(k)])].push_back(f[detail::to_size((k + 1) % 3)]);
  // interior vertices scrambled: the cuts must not depend on them
  auto pos = l.m.positions;
  std::vector<std::uint8_t> fixed(pos.size(), 0);
  detail::polycube_path_pins pp;
  pp.arc.resize(paths.size());
  pp.pins.resize(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    for (index_t v : paths[i].vertices) fixed[detail::to_size(v)] = 1;
    pp.arc[i].assign(paths[i].vertices.size(), 0.0);
    for (std::size_t k = 0; k < paths[i].vertices.size(); ++k)
      pp.arc[i][k] = static_cast<double>(k) / static_cast<double>(paths[i].vertices.size() - 1);
  }
  const index_t cuts = detail::cut_charts_into_rectangles(l.m, l.cs, paths, loops, ring, 0.25, pp, pos, fixed, is_free);
  CHECK(cuts == 2);  // one reflex corner on the top and one on the bottom face
  // every cut vertex lies on its chart's plane and on a grid line through the reflex corner (x or y = 1)
  for (std::size_t v = 0; v < pos.size(); ++v)
    if (fixed[v] && l.cs.vertex_charts[v].size() == 1) {
      CHECK(std::abs(pos[v].z - l.m.positions[v].z) < 1e-12);
      CHECK(std::min(std::abs(pos[v].x - 1), std::abs(pos[v].y - 1)) < 1e-9);
    }
  // and the whole pipeline from these labels: valid, no folded face
  auto r = build_polycube_map_from_labels(l.m, l.lab, [] {
    polycube_options o;
    o.tile_size = 0.25;
    return o;
  }());
  INFO(r.error().to_string());
  REQUIRE(r);
  check_polycube(*r);
}

TEST_CASE("polycube repair: folded faces take a neighbouring chart's label") {
  const auto l = label_voxels(shapes::cube(), 2);
  auto lab = l.lab;
  std::vector<std::array<double, 6>> data(lab.size(), std::array<double, 6>{1, 1, 1, 1, 1, 1});
  // a face on an edge of the cube borders another chart; a face inside a chart borders none when s = 4
  index_t border = -1;
  for (std::size_t f = 0; f < lab.size() && border < 0; ++f)
    for (index_t g : l.nb[f])
      if (lab[detail::to_size(g)] != lab[f]) border = static_cast<index_t>(f);
  REQUIRE(border >= 0);
  const auto old = lab[detail::to_size(border)];
  CHECK(detail::relabel_folded_faces(l.nb, {border}, 100, data, lab));
  CHECK(lab[detail::to_size(border)] != old);
  CHECK((lab[detail::to_size(border)] ^ 1) != old);  // never the opposite label of a neighbour
  CHECK(data[detail::to_size(border)][old] == 101);  // the old label is tabu from now on
  const auto big = label_voxels(shapes::cube(), 4);
  auto lab4 = big.lab;
  std::vector<std::array<double, 6>> data4(lab4.size(), std::array<double, 6>{});
  index_t inner = -1;
  for (std::size_t f = 0; f < lab4.size() && inner < 0; ++f) {
    bool all = true;
    for (index_t g : big.nb[f]) all = all && lab4[detail::to_size(g)] == lab4[f];
    if (all) inner = static_cast<index_t>(f);
  }
  REQUIRE(inner >= 0);
  CHECK(!detail::relabel_folded_faces(big.nb, {inner}, 100, data4, lab4));
  const auto region = detail::grow_face_region(big.nb, {inner}, 1);
  CHECK(region.size() == 4);
  CHECK(std::is_sorted(region.begin(), region.end()));
}

TEST_CASE("polycube repair: relabel rounds and compactness retries are bounded and checked") {
  polycube_options o;
  o.max_relabel_rounds = -1;
  auto r = build_polycube_map(shapes::sphere(3), o);
  REQUIRE(!r);
  CHECK(r.error().message().find("max_relabel_rounds") != std::string::npos);
  o.max_relabel_rounds = 0;  // no relabelling: the sphere needs none
  o.tiles_across = 6;
  CHECK(build_polycube_map(shapes::sphere(8), o));
  o.max_compactness_retries = -1;
  r = build_polycube_map(shapes::sphere(3), o);
  REQUIRE(!r);
  CHECK(r.error().message().find("max_compactness_retries") != std::string::npos);
  // the first attempt succeeds on the sphere: retries change nothing
  o.max_compactness_retries = 0;
  const auto a = build_polycube_map(shapes::sphere(8), o);
  o.max_compactness_retries = 5;
  const auto b = build_polycube_map(shapes::sphere(8), o);
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->labels == b->labels);
  CHECK(a->polycube == b->polycube);
}

TEST_CASE("polycube repair: a chart is never turned to face the other way unless allowed") {
  // the top of a cube borders +-X and +-Y: every label but its own and -Z is opposite to a neighbour
  auto l = label_voxels(shapes::cube(), 2);
  std::vector<std::array<double, 6>> data(l.lab.size(), std::array<double, 6>{1, 1, 1, 1, 1, 1});
  index_t top = 0;
  while (l.cs.chart_label[detail::to_size(top)] != 4) ++top;
  auto lab = l.lab;
  CHECK(!detail::relabel_chart(l.cs, top, data, lab, false, false));
  CHECK(lab == l.lab);  // nothing changed
  REQUIRE(detail::relabel_chart(l.cs, top, data, lab, false, true));
  for (std::size_t f = 0; f < lab.size(); ++f) CHECK(lab[f] == (l.cs.face_chart[f] == top ? 5 : l.lab[f]));
}

TEST_CASE("polycube: distortion retries keep the least distorted of several valid maps") {
  polycube_options o;
  o.tiles_across = 6;
  const auto torus = shapes::torus(1.0, 0.45, 48, 20);
  const auto first = build_polycube_map(torus, o);
  o.distortion_retries = 5;
  const auto best = build_polycube_map(torus, o);
  REQUIRE(first);
  REQUIRE(best);
  check_polycube(*best);
  const auto d0 = polycube_distortion(*first), d1 = polycube_distortion(*best);
  CHECK(d1.area_distortion + d1.angle_distortion <= d0.area_distortion + d0.angle_distortion);
  thread_pool_executor pool(3);  // the same choice on any number of threads
  const auto again = build_polycube_map(torus, o, pool);
  REQUIRE(again);
  CHECK(again->polycube == best->polycube);
  o.distortion_retries = -1;
  const auto bad = build_polycube_map(torus, o);
  REQUIRE(!bad);
  CHECK(bad.error().message().find("distortion_retries") != std::string::npos);
}

TEST_CASE("polycube repair: two charts of one axis meeting at a vertex are named by that vertex") {
  auto l = label_voxels(shapes::cube(), 2);
  // on the top face, the squares at (0, 1) and (1, 0) take label +X: the two +Z squares left meet at
  // the face centre only
  const index_t centre = vertex_at(l.m, {0.5, 0.5, 1});
  REQUIRE(centre >= 0);
  relabel_top(l, [](double x, double y) { return (x < 0.5) != (y < 0.5) ? 0 : -1; });
  const auto cs = detail::find_polycube_charts(l.m, l.nb, l.lab);
  index_t bad = -1, pinch = -1;
  auto r = detail::polycube_classes(l.m, cs.face_chart, cs.chart_label, 2, &bad, &pinch);
  REQUIRE(!r);
  CHECK(pinch == centre);
  CHECK(bad == -1);  // with pinch_vertex given, the faces around it are relabelled, not a whole chart
  CHECK(r.error().message().find("joined through vertex " + std::to_string(centre)) != std::string::npos);
}

TEST_CASE("polycube repair: a label meeting itself at a vertex is freed by a local relabelling") {
  // a cube, 8 x 8 squares per face; on the top, a +Y tongue (squares x 4-5, y 4-7, joined to the +Y
  // side) and a +X / -Y island below it (x 2-3, y 3 and y 2): the top chart's faces around the vertex
  // (4, 4) form two fans, between the tongue's corner square and the island's
  auto l = label_voxels(shapes::cube(), 8);
  const index_t centre = vertex_at(l.m, {0.5, 0.5, 1});
  REQUIRE(centre >= 0);
  relabel_top(l, [](double x, double y) {
    const int i = static_cast<int>(x * 8), j = static_cast<int>(y * 8);
    if (i >= 4 && i < 6 && j >= 4) return 2;  // +Y
    if (i >= 2 && i < 4 && j == 3) return 0;  // +X
    if (i >= 2 && i < 4 && j == 2) return 3;  // -Y
    return -1;
  });
  auto cs = detail::find_polycube_charts(l.m, l.nb, l.lab);
  const auto pinch = detail::find_pinched_vertex(l.m, l.nb, cs);
  REQUIRE(pinch[1] == centre);
  const index_t top = pinch[0];
  CHECK(cs.chart_label[detail::to_size(top)] == 4);
  // (the island's corner faces are pinned faces, found first by find_label_problem)
  const detail::polycube_label_problem p{detail::polycube_label_problem::pinched, top, -1, centre};
  CHECK(p.to_status().message().find("chart " + std::to_string(top) + " meets itself") != std::string::npos);
  CHECK(p.to_status().message().find("at vertex " + std::to_string(centre)) != std::string::npos);

  const detail::vertex_face_table vf(l.m);
  std::vector<index_t> ring(vf.of(centre).begin(), vf.of(centre).end());
  CHECK(ring.size() == 6);
  const auto problems = detail::label_problems_near(l.m, l.nb, vf, l.lab, ring);
  CHECK(problems > 0);
  std::vector<std::array<double, 6>> data(l.lab.size());
  for (index_t f = 0; f < l.m.num_faces(); ++f)
    for (int k = 0; k < 6; ++k)
      data[detail::to_size(f)][detail::to_size(k)] =
          1 - dot(normalized(face_area_normal(l.m, f)), label_direction(static_cast<polycube_label>(k)));
  auto lab = l.lab;
  std::vector<std::uint8_t> barred(lab.size(), 0);
  REQUIRE(detail::repair_pinched_vertex(l.m, l.nb, vf, cs, data, lab, barred, top, centre));
  CHECK(lab != l.lab);
  std::size_t changed = 0;
  for (std::size_t f = 0; f < lab.size(); ++f) {
    CHECK((lab[f] != l.lab[f]) == (barred[f] != 0));
    if (lab[f] != l.lab[f]) {
      ++changed;
      CHECK(barred[f] == 1u << l.lab[f]);  // its old label is barred from the pinned-face repair
    }
  }
  CHECK(changed <= 8);  // local: a few faces at the vertex, not a chart
  cs = detail::find_polycube_charts(l.m, l.nb, lab);
  CHECK(detail::find_pinched_vertex(l.m, l.nb, cs)[1] != centre);
  CHECK(detail::label_problems_near(l.m, l.nb, vf, lab, ring) < problems);
  // the whole repair loop leaves no label meeting itself anywhere
  lab = l.lab;
  const auto after = detail::repair_polycube_labels(l.m, l.nb, data, lab, 200);
  CHECK(after.kind != detail::polycube_label_problem::pinched);
  CHECK(detail::find_pinched_vertex(l.m, l.nb, detail::find_polycube_charts(l.m, l.nb, lab))[0] < 0);
}

TEST_CASE("polycube refinement: chords are split, the mesh stays closed, input indices are kept") {
  // a cube with 4 x 4 squares per face; on the top, the squares (2, 0), (3, 0) and (3, 1) take the +X
  // label: the diagonal of square (2, 1), from (2, 1) to (3, 2), then joins two vertices of the
  // boundary between the top chart and the +X chart while both its faces stay on the top: a chord
  auto l = label_voxels(shapes::cube(), 4);
  relabel_top(l, [](double x, double y) { return (x > 0.5 && y < 0.25) || (x > 0.75 && y < 0.5) ? 0 : -1; });
  const tri_mesh m0 = l.m;
  tri_mesh m = l.m;
  auto nb = l.nb;
  auto lab = l.lab;
  const auto lab0 = lab;
  const auto charts0 = detail::find_polycube_charts(m, nb, lab).chart_label;
  std::vector<std::array<double, 6>> data(lab.size(), std::array<double, 6>{1, 2, 3, 4, 5, 6});
  std::vector<index_t> origin;
  const index_t splits = detail::split_chart_chords(m, nb, lab, data, origin);
  REQUIRE(splits > 0);
  CHECK(m.num_vertices() == m0.num_vertices() + splits);
  CHECK(m.num_faces() == m0.num_faces() + 2 * splits);
  CHECK(std::equal(m0.positions.begin(), m0.positions.end(), m.positions.begin()));
  CHECK(nb == face_adjacency(m).neighbor);  // the adjacency followed every split
  CHECK(validate_polycube_input(m));        // closed, manifold, oriented, no degenerate face
  CHECK(detail::find_polycube_charts(m, nb, lab).chart_label == charts0);  // the same charts
  REQUIRE(origin.size() == m.faces.size());
  std::vector<double> area(m0.faces.size(), 0.0);
  for (index_t f = 0; f < m.num_faces(); ++f) {
    const auto o = detail::to_size(origin[detail::to_size(f)]);
    CHECK(lab[detail::to_size(f)] == lab0[o]);
    area[o] += face_area(m, f);
  }
  for (index_t f = 0; f < m0.num_faces(); ++f) CHECK(std::abs(area[detail::to_size(f)] - face_area(m0, f)) < 1e-12);
  // no chord is left: a second pass splits nothing
  CHECK(detail::split_chart_chords(m, nb, lab, data, origin) == 0);
  // the face (2, 1), (3, 1), (3, 2) had all three vertices on the +X chart; its split halves do not
  const auto before = detail::find_label_problem(m0, l.nb, detail::find_polycube_charts(m0, l.nb, lab0));
  CHECK(before.kind == detail::polycube_label_problem::pinned_face);
  const auto after = detail::find_label_problem(m, nb, detail::find_polycube_charts(m, nb, lab));
  CHECK(after.kind != detail::polycube_label_problem::pinned_face);
}

TEST_CASE("polycube verification: a degenerate map (a face squeezed to nothing) is refused, naming the chart") {
  const auto m = shapes::voxel_surface(shapes::cube(), 2);
  const index_t centre = vertex_at(m, {0.5, 0.5, 1});  // the centre of the top face
  REQUIRE(centre >= 0);
  auto deformed = m;
  deformed.positions[detail::to_size(centre)] = {0.5, 0.2, 1};  // still inside: a valid polycube
  auto ok = polycube_map_from_deformed(m, deformed, 0.5);
  INFO(ok.error().to_string());
  REQUIRE(ok);
  check_polycube(*ok);
  deformed.positions[detail::to_size(centre)] = {0.5, 1e-7, 1};  // positive areas, but almost none
  auto r = polycube_map_from_deformed(m, deformed, 0.5);
  REQUIRE(!r);
  CHECK(r.error().code() == status_code::not_converged);
  CHECK(r.error().message().find("degenerate map") != std::string::npos);
  std::size_t top = 0;  // the chart of the top face is named
  while (top < ok->charts.size() && ok->charts[top].label != polycube_label::pos_z) ++top;
  CHECK(r.error().message().find("in chart " + std::to_string(top) + ",") != std::string::npos);
  polycube_options o;
  o.min_area_ratio = 1;
  CHECK(build_polycube_map(m, o).error().code() == status_code::invalid_argument);
  o.min_area_ratio = 0;  // any positive area: the automatic map of the cube is still valid
  o.tile_size = 0.5;
  CHECK(build_polycube_map(m, o));
}

TEST_CASE("polycube refinement: a chart without interior vertices gets some for its cuts") {
  // the L-shaped top of the voxel L at one square per unit has its reflex corner's cut run along
  // interior vertices; the boundary-spanning edges of its charts are the edges a CAD mesh has only
  const auto l = label_voxels(shapes::l_shape(), 1);
  tri_mesh m = l.m;
  auto nb = l.nb;
  auto lab = l.lab;
  const auto cs0 = detail::find_polycube_charts(m, nb, lab);
  std::vector<index_t> charts(cs0.chart_label.size());
  for (std::size_t c = 0; c < charts.size(); ++c) charts[c] = static_cast<index_t>(c);
  auto spanning = [&](const tri_mesh& mm, const std::vector<std::array<index_t, 3>>& n,
                      const std::vector<std::uint8_t>& lb) {
    const auto cs = detail::find_polycube_charts(mm, n, lb);
    index_t count = 0;
    for (std::size_t f = 0; f < mm.faces.size(); ++f)
      for (std::size_t k = 0; k < 3; ++k) {
        const auto g = detail::to_size(n[f][k]);
        if (cs.face_chart[g] != cs.face_chart[f]) continue;
        if (cs.vertex_charts[detail::to_size(mm.faces[f][k])].size() >= 2 &&
            cs.vertex_charts[detail::to_size(mm.faces[f][(k + 1) % 3])].size() >= 2)
          ++count;
      }
    return count;
  };
  REQUIRE(spanning(m, nb, lab) > 0);  // every vertex of a one-square-per-unit voxel face is on its boundary
  std::vector<std::array<double, 6>> data(lab.size(), std::array<double, 6>{1, 2, 3, 4, 5, 6});
  std::vector<index_t> origin;
  const index_t splits = detail::split_boundary_spanning_edges(m, nb, lab, data, origin, charts);
  REQUIRE(splits > 0);
  CHECK(spanning(m, nb, lab) == 0);
  CHECK(m.num_faces() == l.m.num_faces() + 2 * splits);
  CHECK(nb == face_adjacency(m).neighbor);
  CHECK(validate_polycube_input(m));
  CHECK(detail::find_polycube_charts(m, nb, lab).chart_label == cs0.chart_label);
  // only the charts named are split
  tri_mesh m2 = l.m;
  auto nb2 = l.nb;
  auto lab2 = l.lab;
  std::vector<index_t> origin2;
  data.assign(lab2.size(), std::array<double, 6>{1, 2, 3, 4, 5, 6});
  const index_t one = detail::split_boundary_spanning_edges(m2, nb2, lab2, data, origin2, {0});
  CHECK(one > 0);
  CHECK(one < splits);
  for (index_t f = 0; f < m2.num_faces(); ++f)
    if (origin2[detail::to_size(f)] != f) CHECK(cs0.face_chart[detail::to_size(origin2[detail::to_size(f)])] == 0);
}

TEST_CASE("polycube: a CAD part (genus 5) whose flat-shaded faces have no interior vertices") {
  // OpenSCAD's example001 (a sphere less three cylinders, CC0, Debian's openscad package): the
  // walls of its holes are triangulated between their two boundary loops, so the cuts of their charts
  // into rectangles find no interior vertex to run along until the boundary-spanning edges are split
  const auto m = read_mesh(std::string(TESSERA_TEST_DATA_DIR) + "/surface/openscad_example001.off");
  REQUIRE(m);
  polycube_options o;
  o.tiles_across = 16;
  const auto r = build_polycube_map(*m, o);
  REQUIRE(r);
  CHECK(r->refined());
  CHECK(check_polycube(*r) == 2 - 2 * 5);
}

TEST_CASE("polycube: a CAD plate with three holes (genus 3) whose cuts would press faces onto their line") {
  // scripts/meshes/plate_three_holes.scad (OpenSCAD, CC0): the top and bottom are triangulated between
  // their four boundary loops only. The cuts from the corners of two holes side by side run along one
  // line; the shortest vertex paths between them would close faces onto it, so their edges to the
  // line are split (polycube_uncut::edges) until a path is free; without that 5 faces stay folded
  const auto m = read_mesh(std::string(TESSERA_TEST_DATA_DIR) + "/surface/openscad_plate_three_holes.off");
  REQUIRE(m);
  for (int n : {8, 16}) {
    INFO(n << " tiles across");
    polycube_options o;
    o.tiles_across = n;
    const auto r = build_polycube_map(*m, o);
    INFO((r ? std::string() : r.error().to_string()));
    REQUIRE(r);
    CHECK(r->refined());
    CHECK(check_polycube(*r) == 2 - 2 * 3);
  }
}
