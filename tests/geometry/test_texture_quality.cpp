#include <tessera/geometry/texture_quality.hpp>

#include <tessera/core/random.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
// flat rings (major 0.6, minor 0.1: XY diameter 1.4) centred at (2i + 1, 2j + 1), skipping `skip`
template <class Skip>
tri_mesh ring_lattice(int n, Skip skip, double spacing = 2.0) {
  tri_mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (!skip(i, j))
        detail::add_torus(m, {spacing * i + 1, spacing * j + 1, 0.1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.6, 0.1, 24, 8);
  return m;
}
tri_mesh ring_lattice(int n) {
  return ring_lattice(n, [](int, int) { return false; });
}
// a closed flat box [x0, x1] x [y0, y1] x [0, 0.1]
void add_box(tri_mesh& m, double x0, double y0, double x1, double y1) {
  const index_t b = m.num_vertices();
  for (int k = 0; k < 8; ++k) m.add_vertex({k & 1 ? x1 : x0, k & 2 ? y1 : y0, k & 4 ? 0.1 : 0.0});
  const int f[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                        {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& x : f) m.add_face(b + x[0], b + x[1], b + x[2]);
}
}  // namespace

TEST_CASE("the reference of a ring lattice: diameter, smallest whole ring, torus topology, spacing", "[quality]") {
  const tri_mesh ex = ring_lattice(10);
  auto ref = quality_reference(ex);
  REQUIRE(ref.ok());
  CHECK(ref->diameter == Approx(1.4).epsilon(1e-3));
  REQUIRE(ref->euler == std::vector<int>{0});  // tori
  CHECK(ref->nn_median == Approx(2.0).epsilon(1e-3));
  CHECK(ref->nn_lo == Approx(1.9).epsilon(1e-3));
  CHECK(ref->nn_hi == Approx(2.1).epsilon(1e-3));
  CHECK(ref->smallest_area > 0);
}

TEST_CASE("density, coverage, partial and empty-cell figures of known lattices", "[quality]") {
  const tri_mesh ex = ring_lattice(10);
  auto ref = quality_reference(ex);
  REQUIRE(ref.ok());
  SECTION("the exemplar against itself") {
    auto q = measure_texture_quality(ex, *ref);
    REQUIRE(q.ok());
    // bounds [0.3, 19.7]², window shrunk by 1.4: [1.7, 18.3]², centres 3, 5, ..., 17 inside: 8 x 8
    CHECK(q->window_elements == 64);
    CHECK(q->density == Approx(0.25).epsilon(0.01));  // one ring per 2 x 2, smoothed, read 2.5 inside
    CHECK(q->elements == 100);
    CHECK(q->whole_elements == 64);  // the 36 rings reaching the bounds are not whole
    CHECK(q->partial_rate == 0);
    CHECK(q->empty_cell_rate == 0);  // any 2.1 cell holds a whole ring
    // projected annulus area per 2 x 2 cell: pi (0.7² - 0.5²) / 4 = 0.1885, less 1 % for the 24-gons
    // (pixels of 1/12 of 1.4, averaged under a Gaussian-edged window 2.5 inside)
    CHECK(q->covered_fraction == Approx(0.99 * 3.14159265 * (0.49 - 0.25) / 4).epsilon(0.03));
    CHECK(q->nn_outside == 0);
    auto c = compare_texture_quality(ex, ex);
    REQUIRE(c.ok());
    CHECK(c->density_ratio == Approx(1.0));
    CHECK(c->coverage_ratio == Approx(1.0));
    CHECK(c->partial_excess == 0);
  }
  SECTION("a small ring and a pebble in place of two rings are partial") {
    tri_mesh out = ring_lattice(10, [](int i, int j) { return (i == 4 && j == 4) || (i == 6 && j == 6); });
    detail::add_torus(out, {9, 9, 0.1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.4, 0.1, 24, 8);  // area 2/3 of a ring
    tri_mesh ball = detail::icosphere(2);
    for (auto& p : ball.positions) p = p * 0.6 + vec3{13, 13, 0.7};
    out.append(ball);
    auto q = measure_texture_quality(out, *ref);
    REQUIRE(q.ok());
    CHECK(q->whole_elements == 64);
    CHECK(q->partial_rate == Approx(2.0 / 64));
    CHECK(q->density == Approx(0.25).epsilon(0.01));  // still one centre each
  }
  SECTION("a 3 x 3 hole: empty cells, less coverage, fewer elements, wider spacing") {
    const tri_mesh out = ring_lattice(10, [](int i, int j) { return i >= 4 && i <= 6 && j >= 4 && j <= 6; });
    auto c = compare_texture_quality(ex, out);
    REQUIRE(c.ok());
    // cells of 2.1 from 1.7 (7 x 7): the empty square (7.7, 14.3)² holds the cells [8.0, 14.3)², 3 x 3
    CHECK(c->output.cells == 49);
    CHECK(c->output.empty_cell_rate == Approx(9.0 / 49));
    CHECK(c->empty_cell_excess == Approx(9.0 / 49));
    // the density window [2.8, 17.2]² (2.5 sigma inside) holds the whole hole: 9 rings of 14.4² / 4
    CHECK(c->density_ratio == Approx(1 - 36 / (14.4 * 14.4)).epsilon(0.02));
    CHECK(c->coverage_ratio == Approx(1 - 36 / (14.4 * 14.4)).epsilon(0.03));
    CHECK(c->output.nn_outside == 0);  // the rim's rings still have a neighbour 2 away
  }
}

TEST_CASE("spacing outside the exemplar's spread", "[quality]") {
  const tri_mesh ex = ring_lattice(10);
  auto ref = quality_reference(ex);
  REQUIRE(ref.ok());
  // row 5 moved up by 0.6: its rings and row 6's have their nearest neighbour 1.4 away (spread [1.9, 2.1])
  tri_mesh out = ring_lattice(10, [](int, int j) { return j == 5; });
  for (int i = 0; i < 10; ++i)
    detail::add_torus(out, {2.0 * i + 1, 11.6, 0.1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.6, 0.1, 24, 8);
  auto q = measure_texture_quality(out, *ref);
  REQUIRE(q.ok());
  CHECK(q->window_elements == 64);
  CHECK(q->nn_outside == Approx(16.0 / 64));
  // histogram over [0, 4) in 16 bins: 16 spacings of 1.4 in bin 5, 48 of 2.0 in bin 8
  CHECK(q->nn_histogram[5] == 16);
  CHECK(q->nn_histogram[7] + q->nn_histogram[8] == 48);  // 2.0 sits on the bin edge
}

TEST_CASE("border bands and corners of a tile grid", "[quality]") {
  // tile 8 = 4 periods; band 1.2: centres at 1 and 7 (mod 8) lie in the bands
  const tri_mesh full = ring_lattice(16);
  auto ref = quality_reference(ring_lattice(10));
  REQUIRE(ref.ok());
  texture_quality_options o;
  o.tile_size = 8;
  const xy_rect dom{0, 0, 32, 32};
  auto q = measure_texture_quality(full, *ref, dom, o);
  REQUIRE(q.ok());
  CHECK(q->band_density / q->interior_density == Approx(1.0).epsilon(0.05));
  CHECK(q->corner_density / q->interior_density == Approx(1.0).epsilon(0.05));
  // the rings in the bands removed (centre 1 or 7 mod 8 on either axis): a grid of gaps
  const tri_mesh gaps =
      ring_lattice(16, [](int i, int j) { return i % 4 == 0 || i % 4 == 3 || j % 4 == 0 || j % 4 == 3; });
  auto g = measure_texture_quality(gaps, *ref, dom, o);
  REQUIRE(g.ok());
  CHECK(g->band_density / g->interior_density < 0.6);
  CHECK(g->corner_density / g->interior_density < 0.3);
  CHECK(g->band_coverage < 0.6 * g->interior_coverage);
  // a quilt (no tile grid) reports no band figures
  auto n = measure_texture_quality(full, *ref, dom);
  REQUIRE(n.ok());
  CHECK(n->band_density == 0);
}

TEST_CASE("the nearest-neighbour search equals brute force", "[quality]") {
  const counter_rng rng(5, 1);
  std::vector<vec3> pts;
  for (int i = 0; i < 400; ++i) pts.push_back({rng.uniform(0, i) * 30, rng.uniform(1, i) * 10, 0});
  std::vector<std::size_t> q;
  for (std::size_t i = 0; i < pts.size(); i += 3) q.push_back(i);
  const auto nn = detail::nearest_neighbour_distances(pts, q, 0.7);
  REQUIRE(nn.size() == q.size());
  for (std::size_t k = 0; k < q.size(); ++k) {
    double best = INFINITY;
    for (std::size_t j = 0; j < pts.size(); ++j)
      if (j != q[k]) best = std::min(best, norm(pts[j] - pts[q[k]]));
    REQUIRE(nn[k] == best);
  }
}

TEST_CASE("quality figures reject bad input", "[quality]") {
  const tri_mesh ex = ring_lattice(4);
  auto ref = quality_reference(ex);
  REQUIRE(ref.ok());
  CHECK_FALSE(quality_reference(tri_mesh{}).ok());
  tri_mesh bad = ex;
  bad.positions[0].x = std::nan("");
  CHECK_FALSE(quality_reference(bad).ok());
  CHECK_FALSE(measure_texture_quality(bad, *ref).ok());
  texture_quality_options o;
  o.band_fraction = 0.7;
  CHECK_FALSE(measure_texture_quality(ex, *ref, {}, o).ok());
  o = {};
  o.margin_diameters = 10;  // nothing left of an 8 x 8 texture
  CHECK_FALSE(measure_texture_quality(ex, *ref, {}, o).ok());
  CHECK_FALSE(measure_texture_quality(ex, texture_quality_reference{}).ok());
  // a single box: coverage is its area, with no margin
  tri_mesh box;
  add_box(box, 2, 2, 6, 6);
  texture_quality_reference r1;
  r1.diameter = 1;
  o = {};
  o.margin_diameters = 0;
  auto q = measure_texture_quality(box, r1, {0, 0, 10, 10}, o);
  REQUIRE(q.ok());
  // the box's 16 over the 7.5² window [1.25, 8.75]² (2.5 sigma of 0.5 inside), whose Gaussian edges
  // reach the box's sides at 1.5 sigma: (3.985 / 7.5)²
  CHECK(q->covered_fraction == Approx(0.2823).epsilon(0.01));
  CHECK(q->whole_elements == 1);
}
