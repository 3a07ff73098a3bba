#include <tessera/geometry/mesh_quilt.hpp>

#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
index_t intersecting_element_pairs(const tri_mesh& m) {
  const auto comp = connected_components(m);
  const triangle_bvh bvh(m);
  index_t n = 0;
  bvh.for_each_self_intersection(
      [&](index_t f, index_t g) { return comp.face_component[std::size_t(f)] == comp.face_component[std::size_t(g)]; },
      [&](index_t, index_t) { ++n; });
  return n;
}
const quilt_exemplar& small_rings() {
  static const quilt_exemplar ex = *prepare_quilt_exemplar(
      *make_ring_exemplar({.size = 5, .spacing = 1.6, .ring_segments = 16, .tube_segments = 6, .seed = 4}));
  return ex;
}
}  // namespace

TEST_CASE("mesh quilting grows a larger ring texture of closed, disjoint elements", "[mesh_quilt]") {
  const auto& ex = small_rings();
  const auto r = mesh_quilt(ex, 8, 6, {.seed = 2});
  REQUIRE(r.ok());
  REQUIRE(r->elements.size() > 8);
  const auto d = count_edge_defects(r->mesh);
  REQUIRE(d.open_edges == 0);
  REQUIRE(d.nonmanifold_edges == 0);
  REQUIRE(intersecting_element_pairs(r->mesh) == 0);
  const auto b = bounding_box(r->mesh);
  REQUIRE(b.extent().x > 6);
  REQUIRE(b.extent().y > 4);
  REQUIRE(r->stats.patches > 1);
  // deterministic
  const auto again = mesh_quilt(ex, 8, 6, {.seed = 2});
  REQUIRE(again->mesh == r->mesh);
  const auto other = mesh_quilt(ex, 8, 6, {.seed = 3});
  REQUIRE_FALSE(other->mesh == r->mesh);
}

TEST_CASE("mesh quilting rejects bad input", "[mesh_quilt]") {
  const auto& ex = small_rings();
  REQUIRE(mesh_quilt(ex, 0, 5).error().code() == status_code::invalid_argument);
  REQUIRE(mesh_quilt(ex, std::nan(""), 5).error().code() == status_code::invalid_argument);
  REQUIRE(mesh_quilt(ex, 1e9, 1e9).error().code() == status_code::size_overflow);
  REQUIRE_FALSE(mesh_quilt(ex, 5, 5, {.max_samples = 0}).ok());
  REQUIRE_FALSE(mesh_quilt(ex, 5, 5, {.deform_weight = -1}).ok());
  REQUIRE_FALSE(mesh_quilt(quilt_exemplar{}, 5, 5).ok());
  tri_mesh open = *make_ring_exemplar({.size = 3});
  open.faces.pop_back();
  REQUIRE(mesh_quilt(open, 5, 5).error().message().find("open edges") != std::string::npos);
  cancellation_token stop;
  stop.cancel();
  mesh_quilt_options o;
  o.progress.token = &stop;
  REQUIRE(mesh_quilt(ex, 5, 5, o).error().code() == status_code::cancelled);
}

namespace {
// the exemplar's elements moved by t, as a frame of the quilting engine
std::vector<texture_element> moved_elements(const quilt_exemplar& ex, vec3 t) {
  std::vector<texture_element> out = ex.elements();
  for (auto& e : out) {
    for (vec3& p : e.mesh.positions) p += t;
    e.update_box();
  }
  return out;
}
}  // namespace

TEST_CASE("translation search (eq. 1-4) recovers a known grid offset, ICP (eq. 5) recovers the rest", "[mesh_quilt]") {
  const auto& ex = small_rings();
  const double cell = ex.cell_size();
  const aabb& eb = ex.bounds();
  const xy_rect domain{0, 0, 20, 20};
  // output = the exemplar shifted by a grid translation t0 (candidates are x0 + i cell - min.x)
  const vec3 t0{7 * cell - eb.min.x, 6 * cell - eb.min.y, 0};
  const xy_rect window{t0.x + eb.min.x + 1.2, t0.y + eb.min.y + 1.2, t0.x + eb.min.x + 3.2, t0.y + eb.min.y + 3.0};
  detail::mesh_quilt_params p;
  p.tolerance = 0;
  p.icp = false;
  {
    detail::quilt_engine engine(ex, domain, p);
    engine.add_frame(moved_elements(ex, t0), {});
    const vec3 t = engine.find_translation(window, 0);
    REQUIRE(norm(t - t0) < 1e-12);
    REQUIRE(engine.stats().icp_iterations == 0);
  }
  // off the grid by (0.35, -0.25) cells: the grid search lands on a neighbour, ICP slides to it
  const vec3 off = t0 + vec3{0.35 * cell, -0.25 * cell, 0};
  detail::quilt_engine grid_only(ex, domain, p);
  grid_only.add_frame(moved_elements(ex, off), {});
  const vec3 tg = grid_only.find_translation(window, 0);
  REQUIRE(norm(tg - off) > 0.2 * cell);
  REQUIRE(norm(tg - off) < 0.8 * cell);
  p.icp = true;
  detail::quilt_engine refined(ex, domain, p);
  refined.add_frame(moved_elements(ex, off), {});
  const vec3 ti = refined.find_translation(window, 0);
  REQUIRE(norm(ti - off) < 0.01 * cell);
  REQUIRE(ti.z == tg.z);  // ICP moves in XY only
  REQUIRE(refined.stats().icp_iterations > 1);
  REQUIRE(refined.stats().icp_discarded == 0);
}

TEST_CASE("the normal term of eq. 1 (lambda) changes the chosen translation", "[mesh_quilt]") {
  // exemplar: site A = a flat ring whose tube is 0.03 thicker (every point of the output ring is
  // 0.03 from it); site B, three cells to the east = the same ring as the output but tilted by 14
  // degrees (farther on average, but with more face orientations near each vertex: eq. 2 takes the
  // best face within a cell). Two small rings pad the exemplar's box so both placements cover the
  // window. Output: one flat ring.
  const double cell = 0.5;
  auto ring = [](tri_mesh& m, vec3 c, double tilt_deg, double tube) {
    const double a = tilt_deg * 3.14159265358979323846 / 180;
    detail::add_torus(m, c, {std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}, 0.5, tube, 32,
                      12);
  };
  tri_mesh exm;
  ring(exm, {1.5, 1.5, 0.2}, 0, 0.15);   // A
  ring(exm, {3.0, 1.5, 0.2}, 14, 0.12);  // B
  detail::add_torus(exm, {0.2, 0.2, 0.2}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.12, 0.04, 8, 4);
  detail::add_torus(exm, {4.4, 2.9, 0.2}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.12, 0.04, 8, 4);
  const auto ex = prepare_quilt_exemplar(exm, {.cell_size = cell});
  REQUIRE(ex.ok());
  const aabb& eb = ex->bounds();
  // the output ring sits where A lands under the grid translation tA = 8 cells - min
  const vec3 tA{8 * cell - eb.min.x, 8 * cell - eb.min.y, 0};
  const vec3 c0 = vec3{1.5, 1.5, 0.2} + tA;
  texture_element out_ring;
  ring(out_ring.mesh, c0, 0, 0.12);
  out_ring.fixed.assign(out_ring.mesh.positions.size(), 0);
  const xy_rect window{c0.x - 0.7, c0.y - 0.7, c0.x + 0.7, c0.y + 0.7};
  const std::vector<vec3> normals = vertex_normals(out_ring.mesh);
  // brute-force eq. 4 at translation t: every output vertex in the window, every exemplar face
  // within one cell (eq. 2 as tessera restricts it), eq. 1 per face
  auto eq4 = [&](vec3 t, double lambda) {
    const auto fn = face_normals(ex->mesh());
    double sum = 0;
    for (std::size_t v = 0; v < out_ring.mesh.positions.size(); ++v) {
      const vec3 x = out_ring.mesh.positions[v] - t;
      double best = (1 + cell) * (1 + lambda);
      for (index_t f = 0; f < ex->mesh().num_faces(); ++f) {
        const auto& tri = ex->mesh().faces[std::size_t(f)];
        const auto h = detail::closest_point_on_triangle(x, ex->mesh().positions[std::size_t(tri[0])],
                                                         ex->mesh().positions[std::size_t(tri[1])],
                                                         ex->mesh().positions[std::size_t(tri[2])]);
        const double d = norm(h.point - x);
        if (d > cell) continue;
        best = std::min(best, (1 + d) * (1 + lambda * (1 - dot(normals[v], fn[std::size_t(f)]))));
      }
      sum += best;
    }
    return sum;
  };
  const vec3 tB = tA - vec3{3 * cell, 0, 0};  // maps the output ring onto B
  std::vector<vec3> chosen;
  for (const double lambda : {0.0, 12.0}) {
    detail::mesh_quilt_params p;
    p.lambda = lambda;
    p.max_samples = 1000;  // every vertex in the window, as the oracle
    p.tolerance = 0;
    p.icp = false;
    detail::quilt_engine engine(*ex, {0, 0, 12, 12}, p);
    engine.add_frame({out_ring}, {});
    chosen.push_back(engine.find_translation(window, 0));
    // the oracle: the choice is the brute-force minimum of eq. 4 over the candidates (the grid
    // translations that cover the window with the margin: 4 cells west of tA to tA, one row below)
    const double mine = eq4(chosen.back(), lambda);
    for (int di = -4; di <= 0; ++di)
      for (int dj = -1; dj <= 0; ++dj) REQUIRE(mine <= eq4(tA + vec3{di * cell, dj * cell, 0}, lambda) + 1e-9);
  }
  REQUIRE(norm(chosen[0] - tA) < 1e-12);  // lambda = 0: distance only, the thicker ring is closer
  REQUIRE(norm(chosen[1] - tB) < 1e-12);  // lambda = 12: normals matter, the tilted ring matches them better
}

TEST_CASE("mesh quilting merges elements, and most merges succeed", "[mesh_quilt]") {
  const auto& ex = small_rings();
  const auto r = mesh_quilt(ex, 8, 6, {.merge_whole = true, .seed = 2});  // the paper's merging of every pair
  REQUIRE(r.ok());
  const auto& s = r->stats;
  REQUIRE(s.merges_attempted > 0);
  REQUIRE(s.merges_succeeded > 0);
  REQUIRE(s.elements_merged > 0);
  REQUIRE(s.elements_added > 0);
  REQUIRE(s.icp_iterations > 0);
  // the failure counters add up, and at least half the merges succeed
  REQUIRE(s.merges_attempted == s.merges_succeeded + s.merge_fail_correspondence + s.merge_fail_deform +
                                    s.merge_fail_cut + s.merge_fail_loops + s.merge_fail_check);
  INFO("merges " << s.merges_succeeded << " / " << s.merges_attempted << ", elements merged " << s.elements_merged
                 << ", dropped " << s.elements_dropped);
  REQUIRE(2 * s.merges_succeeded >= s.merges_attempted);
  REQUIRE(s.elements_skipped == 0);
  // by default a whole element standing where an exemplar element corresponds is kept as it is
  const auto d = mesh_quilt(ex, 8, 6, {.seed = 2});
  REQUIRE(d.ok());
  REQUIRE(d->stats.elements_skipped > 0);
  REQUIRE(d->stats.merges_attempted == 0);  // rings are not long: nothing to continue
}
