// Woven threads (issue 17): two pieces of one thread joined across a plane
// (geometry/detail/plane_cut_join.hpp), and weave quilts and tile planes that cover the exemplar's
// area with threads continuing across patch and tile borders (mesh_quilt_options::thread_joins).
#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/texture_quality.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
// a straight flattened tube along x from 0 to 6 (a thread), cut to [x0, x1] and capped there
texture_element thread_piece(double x0, double x1, double dy = 0) {
  tri_mesh m;
  std::vector<vec3> path;
  for (int k = 0; k <= 48; ++k) path.push_back({6.0 * k / 48, 0.5 + dy, 0.3});
  detail::add_tube(m, path, 0.36, 0.11, 8);
  for (const auto& [value, keep_above] : {std::pair{x0, true}, std::pair{x1, false}}) {
    auto sp = detail::split_mesh_by_plane(m, 0, value, 1e-9);
    m = keep_above ? std::move(sp.above) : std::move(sp.below);
    detail::compact_vertices(m);
    REQUIRE(detail::cap_plane_loops(m, 0, value));
  }
  texture_element e;
  e.mesh = std::move(m);
  e.fixed.assign(e.mesh.positions.size(), 0);
  e.update_box();
  return e;
}

std::optional<texture_element> join(const texture_element& a, const texture_element& b) {
  const xy_rect domain{-1, -1, 7, 2};
  const std::vector<unsigned char> none_a(a.mesh.positions.size(), 0), none_b(b.mesh.positions.size(), 0);
  return detail::join_across_plane(
      a, none_a, b, none_b, {.domain = domain, .gap = 0.09, .max_offset = 0.18}, [](const texture_element& e) {
        const auto d = count_edge_defects(e.mesh);
        return d.open_edges == 0 && d.nonmanifold_edges == 0 && !detail::self_intersects(e.mesh);
      });
}

double plane_coverage(const tri_mesh& exemplar, const geometric_tile_set& set) {
  const auto hash = hash_coloring::create(set.horizontal_colors, set.vertical_colors, 5);
  REQUIRE(hash.ok());
  const auto coloring = hash->window(0, 0, 3, 3);
  REQUIRE(coloring.ok());
  const auto plane = tile_geometric_plane(set, *coloring, 3, 3);
  REQUIRE(plane.ok());
  const double w = set.tile_size;
  const auto rep = check_geometric_texture(*plane, {0, 0, 3 * w, 3 * w});
  REQUIRE(rep.ok());
  REQUIRE(rep->open_edges_inside == 0);
  REQUIRE(rep->nonmanifold_edges == 0);
  REQUIRE(rep->intersecting_pairs == 0);
  const auto q = compare_texture_quality(exemplar, *plane, {0, 0, 3 * w, 3 * w}, {.tile_size = w});
  REQUIRE(q.ok());
  return q->coverage_ratio;
}
}  // namespace

TEST_CASE("two overlapping or abutting pieces of one thread join across a plane into one closed element",
          "[thread_joins]") {
  // overlapping: [0, 3.5] and [2.5, 6] become one thread from 0 to 6
  const auto a = thread_piece(0, 3.5), b = thread_piece(2.5, 6);
  const auto j = join(a, b);
  REQUIRE(j.has_value());
  const auto d = count_edge_defects(j->mesh);
  REQUIRE(d.open_edges == 0);
  REQUIRE(d.nonmanifold_edges == 0);
  REQUIRE_FALSE(detail::self_intersects(j->mesh));
  const aabb box = bounding_box(j->mesh);
  REQUIRE(box.min.x == Approx(0).margin(1e-9));
  REQUIRE(box.max.x == Approx(6).margin(1e-9));
  REQUIRE(connected_components(j->mesh).count == 1);
  // either order: C_in may come from either side
  REQUIRE(join(b, a).has_value());
  // abutting (cap against cap, as after an earlier failed merge): joined at the meeting point
  REQUIRE(join(thread_piece(0, 3), thread_piece(3, 6)).has_value());
  // not one thread: sideways apart, or one piece inside the other
  REQUIRE_FALSE(join(a, thread_piece(2.5, 6, 0.5)).has_value());
  REQUIRE_FALSE(join(thread_piece(0, 6), thread_piece(2, 4)).has_value());
}

TEST_CASE("a weave quilt covers the exemplar's area, its threads joined across the patches", "[thread_joins]") {
  const auto weave = make_weave_exemplar();
  REQUIRE(weave.ok());
  const auto ex = prepare_quilt_exemplar(*weave);
  REQUIRE(ex.ok());
  const double size = 7;
  auto coverage = [&](const mesh_quilt_result& r) {
    const auto rep = check_geometric_texture(r.mesh);
    REQUIRE(rep.ok());
    REQUIRE(rep->open_edges_inside == 0);
    REQUIRE(rep->nonmanifold_edges == 0);
    REQUIRE(rep->intersecting_pairs == 0);
    const auto q = compare_texture_quality(*weave, r.mesh, {0, 0, size, size});
    REQUIRE(q.ok());
    return q->coverage_ratio;
  };
  const auto joined = mesh_quilt(*ex, size, size, {.seed = 7});
  REQUIRE(joined.ok());
  const auto before = mesh_quilt(*ex, size, size, {.thread_joins = false, .seed = 7});
  REQUIRE(before.ok());
  const double c_joined = coverage(*joined), c_before = coverage(*before);
  INFO("covered area / exemplar's: " << c_before << " -> " << c_joined << "; plane-cut joins "
                                     << joined->stats.merges_plane_cut << " of " << joined->stats.merges_succeeded);
  CHECK(c_before < 0.85);  // pieces dropped where their merges failed (0.73)
  REQUIRE(c_joined > 0.95);
  REQUIRE(joined->stats.merges_plane_cut > 0);
  // nearly every thread merge succeeds (27 of 28; 14 of 50 without the joins), and pieces that add
  // nothing to a thread standing there are skipped, not merged and dropped
  CHECK(2 * before->stats.merges_succeeded < before->stats.merges_attempted);
  REQUIRE(10 * joined->stats.merges_succeeded >= 9 * joined->stats.merges_attempted);
  REQUIRE(joined->stats.elements_skipped > 0);
  REQUIRE(10 * joined->stats.elements_dropped < before->stats.elements_dropped);
  REQUIRE(joined->stats.merges_attempted == joined->stats.merges_succeeded + joined->stats.merge_fail_correspondence +
                                                joined->stats.merge_fail_deform + joined->stats.merge_fail_cut +
                                                joined->stats.merge_fail_loops + joined->stats.merge_fail_check);
  // the same on any thread count
  thread_pool_executor pool(3);
  const auto threaded = mesh_quilt(*ex, size, size, {.seed = 7}, pool);
  REQUIRE(threaded.ok());
  REQUIRE((threaded->mesh.positions == joined->mesh.positions));
  REQUIRE((threaded->mesh.faces == joined->mesh.faces));
}

TEST_CASE("a weave tile set keeps its threads across tile borders and covers the exemplar's area", "[thread_joins]") {
  const auto weave = make_weave_exemplar();
  REQUIRE(weave.ok());
  const auto ex = prepare_quilt_exemplar(*weave);
  REQUIRE(ex.ok());
  geometric_wang_options o;
  o.tile_size = 4.0;        // two periods of the over-under
  o.horizontal_colors = 2;  // two horizontal strips: the second must leave a vertical strip fitting both
  o.vertical_colors = 1;
  o.quilt.seed = 3;
  const auto set = build_geometric_wang_tiles(*ex, o);
  REQUIRE(set.ok());
  REQUIRE(*tile_set_border_mismatch(*set) == 0);
  REQUIRE(tile_set_corner_crossings(*set) == 0);
  REQUIRE(set->crossing_elements > 0);  // threads cross the tile edges
  REQUIRE(plane_coverage(*weave, *set) > 0.93);
}
