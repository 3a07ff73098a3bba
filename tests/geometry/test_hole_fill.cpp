// Hole filling after mesh quilting (geometry/detail/hole_fill.hpp, quilt_engine.hpp fill_holes): the
// distance transform against brute force, hole sites, the exemplar's clearance and coverage on a lattice
// whose answers are known, the relaxation's pushes (hole_relax.hpp), and the whole step on a stone
// quilt (holes gone, density and covered area as the exemplar's, no intersections, deterministic).
#include <tessera/geometry/detail/hole_fill.hpp>
#include <tessera/geometry/detail/hole_relax.hpp>
#include <tessera/geometry/detail/hole_replace.hpp>

#include <tessera/core/random.hpp>
#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/texture_quality.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
// flat rings (major 0.6, minor 0.1: footprint radius 0.7) centred at (s i + 1, s j + 1)
std::vector<texture_element> ring_lattice(int n, double s) {
  std::vector<texture_element> out;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      texture_element e;
      detail::add_torus(e.mesh, {s * i + 1, s * j + 1, 0.1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.6, 0.1, 32, 8);
      e.update_box();
      out.push_back(std::move(e));
    }
  return out;
}
/// An exemplar quilted over size x size with options `a` and with `b`, each quilt's quality against
/// the exemplar (every step required to succeed).
struct stone_quilts {
  tri_mesh stones;
  quilt_exemplar ex;
  mesh_quilt_result a, b;
  texture_quality_comparison qa, qb;
};
stone_quilts quilt_twice(const stone_exemplar_options& kind, double size, const mesh_quilt_options& a,
                         const mesh_quilt_options& b) {
  auto stones = make_stone_exemplar(kind);
  REQUIRE(stones.ok());
  auto ex = prepare_quilt_exemplar(*stones);
  REQUIRE(ex.ok());
  auto qa = mesh_quilt(*ex, size, size, a);
  auto qb = mesh_quilt(*ex, size, size, b);
  REQUIRE(qa.ok());
  REQUIRE(qb.ok());
  auto ca = compare_texture_quality(*stones, qa->mesh, {0, 0, size, size});
  auto cb = compare_texture_quality(*stones, qb->mesh, {0, 0, size, size});
  REQUIRE(ca.ok());
  REQUIRE(cb.ok());
  return {std::move(*stones), std::move(*ex), std::move(*qa), std::move(*qb), std::move(*ca), std::move(*cb)};
}
/// The stone exemplar (seed 7), as above.
stone_quilts quilt_stones(double size, const mesh_quilt_options& a, const mesh_quilt_options& b) {
  return quilt_twice({.seed = 7}, size, a, b);
}
/// Issue 17's goal on quilt `a`: density and covered area within 5 % of the exemplar's, no more empty
/// cells, no intersecting elements, every element closed.
void check_like_exemplar(const stone_quilts& q) {
  CHECK(q.qa.density_ratio >= 0.95);
  CHECK(q.qa.density_ratio <= 1.05);
  CHECK(q.qa.coverage_ratio >= 0.95);
  CHECK(q.qa.coverage_ratio <= 1.05);
  CHECK(q.qa.output.empty_cell_rate <= q.qa.exemplar.empty_cell_rate);
  const auto check = check_geometric_texture(q.a.mesh);
  REQUIRE(check.ok());
  CHECK(check->intersecting_pairs == 0);
  CHECK(check->open_edges_inside == 0);
  CHECK(check->nonmanifold_edges == 0);
}
}  // namespace

TEST_CASE("hole fill: the distance transform is the exact distance to the nearest covered pixel", "[hole_fill]") {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const counter_rng rng(seed, 1);
    const auto w = static_cast<index_t>(1 + rng.below(23, 0)), h = static_cast<index_t>(1 + rng.below(19, 1));
    const double density = seed % 4 == 0 ? 0.0 : 0.02 * static_cast<double>(seed);  // some rasters empty
    detail::coverage_raster r(0, 0, 1, w, h);
    for (index_t j = 0; j < h; ++j)
      for (index_t i = 0; i < w; ++i)
        if (rng.uniform(2, i, j) < density) r.cover(i, j);
    const auto d = detail::distance_to_covered(r);
    REQUIRE(d.size() == static_cast<std::size_t>(w * h));
    for (index_t j = 0; j < h; ++j)
      for (index_t i = 0; i < w; ++i) {
        // brute force, with the raster's outside counting as covered (the pixels around it)
        double best = static_cast<double>(std::min({i + 1, j + 1, w - i, h - j}));
        for (index_t b = 0; b < h; ++b)
          for (index_t a = 0; a < w; ++a)
            if (r.covered(a, b)) best = std::min(best, std::hypot(double(a - i), double(b - j)));
        INFO("seed " << seed << " pixel " << i << ", " << j);
        REQUIRE(d[static_cast<std::size_t>(j * w + i)] == Approx(best).margin(1e-5));
      }
  }
}

TEST_CASE("hole fill: sites are the local maxima, largest first, discs see what covers them", "[hole_fill]") {
  detail::coverage_raster r(0, 0, 1, 31, 21);
  // a wall at column 10: the left part (10 x 21) has its widest free disc smaller than the right's
  for (index_t j = 0; j < 21; ++j) r.cover(10, j);
  const auto d = detail::distance_to_covered(r);
  const auto sites = detail::hole_sites(d, 31, 21, 2.0f);
  REQUIRE(sites.size() >= 2);
  for (std::size_t k = 1; k < sites.size(); ++k) REQUIRE(sites[k - 1].radius >= sites[k].radius);
  CHECK(sites.front().i > 10);  // the largest hole is right of the wall
  CHECK(sites.front().radius == Approx(10.0).margin(0.6));
  CHECK(r.disc_free(r.centre(20, 10), 8.0));
  CHECK_FALSE(r.disc_free(r.centre(14, 10), 5.0));  // reaches the wall
  CHECK_FALSE(r.disc_free(r.centre(28, 10), 5.0));  // leaves the raster
  // counting: the wall is 21 of the 31 x 21 pixels; a rectangle of 5 x 5 more
  r.count_in({0, 0, 31, 21});
  CHECK(r.counted_share() == Approx(21.0 / (31 * 21)));
  for (index_t j = 0; j < 5; ++j)
    for (index_t i = 20; i < 25; ++i) r.cover(i, j);
  CHECK(r.counted_share() == Approx(46.0 / (31 * 21)));
}

TEST_CASE("hole fill: the exemplar's clearance and coverage on a ring lattice", "[hole_fill]") {
  // spacing 2.0 and footprint radius 0.7: the nearest neighbour's pixels are 1.3 away from a centre
  const auto rings = ring_lattice(6, 2.0);
  const std::vector<unsigned char> is_long(rings.size(), 0);
  const double h = 0.02;
  CHECK(detail::footprint_radius(rings[0]) == Approx(0.7).epsilon(1e-3));
  CHECK(detail::exemplar_clearance(rings, is_long, h, 1.4, 0.25) == Approx(2.0 - 2 * 0.7).margin(2 * h));
  CHECK(detail::exemplar_clearance(ring_lattice(4, 3.0), std::vector<unsigned char>(16, 0), h, 1.4, 0.5) ==
        Approx(3.0 - 2 * 0.7).margin(2 * h));
  // covered share: each 2 x 2 cell holds an annulus of radii 0.5 and 0.7
  const double annulus = 3.14159265358979 * (0.7 * 0.7 - 0.5 * 0.5) / 4.0;
  CHECK(detail::exemplar_coverage(rings, h, 1.4) == Approx(annulus).epsilon(0.05));
  // a lone element: no neighbour, no clearance figure
  CHECK(detail::exemplar_clearance(ring_lattice(1, 2.0), {0}, h, 1.4, 0.25) == 0.0);
}

TEST_CASE("hole fill: relaxation pushes a neighbour straight away by the clearance it lacks", "[hole_fill]") {
  // two balls of radius 0.5, 1.1 apart: a gap of 0.1; asked for 0.3 the neighbour moves about 0.2
  // along +x (the pixels of side h sample the distance: at most a pixel or so more)
  auto ball = [](double x) {
    tri_mesh m = detail::icosphere(3);
    for (vec3& p : m.positions) p = vec3{x + 0.5 * p.x, 0.5 * p.y, 0.5 + 0.5 * p.z};
    return m;
  };
  const tri_mesh placed = ball(0), near = ball(1.1), far = ball(3);
  const double h = 0.02;
  const std::vector<detail::relax_neighbour> n{{&near, {1.1, 0, 0}, true}, {&far, {3, 0, 0}, true}};
  const auto s = detail::relax_pushes(placed, {0, 0, 0}, n, h, 0.3, 0.35);
  REQUIRE(s.has_value());
  REQUIRE(s->size() == 2);
  CHECK((*s)[0].x >= 0.2 - h);
  CHECK((*s)[0].x <= 0.2 + 3 * h);
  CHECK(std::abs((*s)[0].y) < 1e-12);
  CHECK((*s)[1].x == 0.0);  // far enough already: stays
  // a move farther than allowed, or of an element that may not move: no room made
  CHECK_FALSE(detail::relax_pushes(placed, {0, 0, 0}, n, h, 0.3, 0.1).has_value());
  const std::vector<detail::relax_neighbour> fixed{{&near, {1.1, 0, 0}, false}};
  CHECK_FALSE(detail::relax_pushes(placed, {0, 0, 0}, fixed, h, 0.3, 0.35).has_value());
  CHECK(detail::relax_pushes(placed, {0, 0, 0}, fixed, h, 0.05, 0.35).has_value());  // clear as it stands
  CHECK(detail::projected_area(placed) == Approx(3.14159265358979 * 0.25).epsilon(0.02));
}

TEST_CASE("hole fill: a large element displaces the small removable ones it comes near, when that pays",
          "[hole_fill]") {
  // a ball of radius 1 at the origin; balls of radius 0.3 at 1.35 (gap 0.05) on either side, one
  // at 2.0 (gap 0.7) and one far away; asked for a clearance of 0.2 the two near ones are displaced
  auto ball = [](double x, double y, double r) {
    tri_mesh m = detail::icosphere(3);
    for (vec3& p : m.positions) p = vec3{x + r * p.x, y + r * p.y, r + r * p.z};
    return m;
  };
  const tri_mesh big = ball(0, 0, 1), left = ball(-1.35, 0, 0.3), right = ball(1.35, 0, 0.3), up = ball(0, 2.0, 0.3),
                 far = ball(5, 5, 0.3);
  const double h = 0.02, a_big = detail::projected_area(big), a_small = detail::projected_area(left);
  CHECK(a_small == Approx(3.14159265358979 * 0.09).epsilon(0.02));
  std::vector<detail::replace_neighbour> n{
      {&left, a_small, true}, {&up, a_small, true}, {&right, a_small, true}, {&far, a_small, true}};
  const auto d = detail::displaced_neighbours(big, n, h, 0.2, 0.0, a_big);
  REQUIRE(d.size() == 2);
  CHECK(d[0] == 0);
  CHECK(d[1] == 2);
  // one of them may not go (a frame element, say): no exchange at all
  n[2].removable = false;
  CHECK(detail::displaced_neighbours(big, n, h, 0.2, 0.0, a_big).empty());
  n[2].removable = true;
  // a single one displaced does not pay (the count would not drop)
  CHECK(detail::displaced_neighbours(big, std::span(n).first(2), h, 0.2, 0.0, a_big).empty());
  // the covered area bounds: the two cover 0.57, less than the ball's 3.14
  CHECK(detail::displaced_neighbours(big, n, h, 0.2, a_big, 1.5 * a_big).empty());
  CHECK(detail::displaced_neighbours(big, n, h, 0.2, 0.0, 0.5).empty());
  // a larger clearance reaches the ball above too
  CHECK(detail::displaced_neighbours(big, n, h, 0.8, 0.0, a_big).size() == 3);
}

TEST_CASE("hole fill: a pebble quilt of mixed sizes gets the exemplar's density by replacing small pebbles",
          "[hole_fill]") {
  // issue 17 on a small case: the patches hold more, smaller pebbles than the exemplar, and filling
  // that only adds leaves the density above 1.10; replacing small ones by large ones brings density
  // and covered area within 5 % (0.99 / 1.01 here, 1.12 / 0.98 without, measured)
  mesh_quilt_options with{.seed = 7};
  mesh_quilt_options without = with;
  without.fill_replace = false;
  const auto q = quilt_twice({.min_radius = 0.2, .max_radius = 0.8, .coverage = 0.5, .seed = 3}, 10, with, without);
  INFO("density " << q.qb.density_ratio << " -> " << q.qa.density_ratio << ", covered area " << q.qb.coverage_ratio
                  << " -> " << q.qa.coverage_ratio << ", empty cells " << q.qb.output.empty_cell_rate << " -> "
                  << q.qa.output.empty_cell_rate << " (exemplar " << q.qa.exemplar.empty_cell_rate << "), replaced "
                  << q.a.stats.elements_replaced);
  CHECK(q.b.stats.elements_replaced == 0);
  CHECK(q.a.stats.elements_replaced > 0);
  CHECK(q.qb.density_ratio > 1.05);
  check_like_exemplar(q);
  // (the same on a pool of threads: the stone quilt's test below, which replaces elements too)
}

TEST_CASE("hole fill: a small stone quilt has the exemplar's density and covered area within 5 %", "[hole_fill]") {
  // issue 17's goal on a small case: filling by size class with relaxation brings both ratios to
  // 1.00 +- 0.05 (filling as holes stand, fill_relax = false, overshoots the density: small elements)
  mesh_quilt_options o{.seed = 7};
  mesh_quilt_options old = o;
  old.fill_relax = false;
  const auto q = quilt_stones(14, o, old);
  INFO("density " << q.qb.density_ratio << " -> " << q.qa.density_ratio << ", covered area " << q.qb.coverage_ratio
                  << " -> " << q.qa.coverage_ratio << ", empty cells " << q.qb.output.empty_cell_rate << " -> "
                  << q.qa.output.empty_cell_rate << " (exemplar " << q.qa.exemplar.empty_cell_rate << "), filled "
                  << q.a.stats.elements_filled << ", moved " << q.a.stats.elements_relaxed);
  check_like_exemplar(q);
}

TEST_CASE("hole fill: a stone quilt keeps no holes, no intersections, and is deterministic", "[hole_fill]") {
  const double size = 10;
  mesh_quilt_options with{.seed = 7};
  mesh_quilt_options without = with;
  without.fill_holes = false;
  const auto q = quilt_stones(size, with, without);
  const auto* a = &q.a;
  const auto* b = &q.b;
  const auto* qa = &q.qa;
  const auto* qb = &q.qb;
  CHECK(a->stats.elements_filled > 0);
  CHECK(a->stats.elements_replaced > 0);  // so that the thread-pool run below covers replacement
  CHECK(b->stats.elements_filled == 0);
  INFO("coverage " << qb->coverage_ratio << " -> " << qa->coverage_ratio << ", empty cells "
                   << qb->output.empty_cell_rate << " -> " << qa->output.empty_cell_rate);
  CHECK(qa->coverage_ratio > qb->coverage_ratio);
  CHECK(qa->coverage_ratio < 1.15);  // not crowded past the exemplar
  CHECK(qa->output.empty_cell_rate <= qb->output.empty_cell_rate);
  const auto check = check_geometric_texture(a->mesh);
  REQUIRE(check.ok());
  CHECK(check->intersecting_pairs == 0);
  CHECK(check->nonmanifold_edges == 0);
  // the same on a pool of threads
  thread_pool_executor pool(2);
  const auto c = mesh_quilt(q.ex, size, size, with, pool);
  REQUIRE(c.ok());
  REQUIRE(c->mesh.positions == a->mesh.positions);
  REQUIRE(c->mesh.faces == a->mesh.faces);
}
