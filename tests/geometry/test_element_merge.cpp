// Element merging of paper 000 §3.3.5-3.3.6 (geometry/detail/element_merge.hpp): the eq. 8 dual-graph
// cut against a brute-force minimum, and merge_pair on two overlapping closed pebbles (cut sides,
// SOURCE/SINK, one seam, a closed manifold result without self-intersection), also against a tile
// border with fixed vertices, under both rule sets.
#include <tessera/geometry/detail/element_merge.hpp>

#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

#include <limits>
#include <set>

using namespace tessera;

namespace {
// a closed pebble: an icosphere scaled to radii (r, r, h) around c
texture_element pebble(vec3 c, double r, double h, int level = 2) {
  texture_element e;
  e.mesh = detail::icosphere(level);
  for (vec3& p : e.mesh.positions) p = c + vec3{p.x * r, p.y * r, p.z * h};
  e.fixed.assign(e.mesh.positions.size(), 0);
  e.update_box();
  return e;
}
double eq8(const tri_mesh& m, const std::vector<double>& dist, index_t a, index_t b) {
  const double len = norm(m.positions[std::size_t(a)] - m.positions[std::size_t(b)]);
  return (1 + len) * (1 + dist[std::size_t(a)] + dist[std::size_t(b)]);
}
// cost of a labelling: eq. 8 over dual edges between kept and removed faces, plus the terminal
// links (bias) of free faces on the side they do not prefer; infinite for a violated terminal
double cut_cost(const tri_mesh& m, const std::vector<double>& dist, const std::vector<signed char>& term,
                const std::vector<double>& bias, const std::vector<unsigned char>& keep) {
  double c = 0;
  for (std::size_t f = 0; f < keep.size(); ++f) {
    if ((term[f] > 0 && !keep[f]) || (term[f] < 0 && keep[f])) return std::numeric_limits<double>::infinity();
    if (term[f] == 0) c += keep[f] ? std::max(0.0, -bias[f]) : std::max(0.0, bias[f]);
  }
  for (const mesh_edge& e : mesh_edges(m))
    if (e.faces.size() == 2 && keep[std::size_t(e.faces[0][0])] != keep[std::size_t(e.faces[1][0])])
      c += eq8(m, dist, e.v0, e.v1);
  return c;
}
detail::merge_params regions(xy_rect domain, double old_x1, double patch_x0) {
  detail::merge_params p;
  p.domain = domain;
  p.corr_dist = 0.1;
  p.is_old = [old_x1](vec3 q) { return q.x < old_x1; };
  p.in_patch = [patch_x0](vec3 q) { return q.x > patch_x0; };
  return p;
}
bool closed_manifold(const tri_mesh& m) {
  const auto d = count_edge_defects(m);
  return d.open_edges == 0 && d.nonmanifold_edges == 0;
}
}  // namespace

TEST_CASE("the eq. 8 dual-graph cut is a minimum cut (brute force over an icosahedron)", "[element_merge]") {
  const tri_mesh m = detail::icosphere(0);  // 12 vertices, 20 faces, 30 dual edges
  std::vector<double> dist(12);
  for (std::size_t v = 0; v < 12; ++v) dist[v] = 0.05 * double((v * 7) % 12);  // Dist(v, C') of eq. 8
  for (int trial = 0; trial < 3; ++trial) {
    std::vector<signed char> term(20, 0);
    std::vector<double> bias(20, 0.0);
    term[0] = 1, term[std::size_t(12 + trial)] = -1, term[std::size_t(5 + trial)] = -1;
    for (std::size_t f = 0; f < 20; ++f)
      if (term[f] == 0 && trial > 0)
        bias[f] = 0.05 * (f % 3 == 0 ? 1 : f % 3 == 1 ? -1 : 0);  // the weak old/new preference
    const auto keep = detail::dual_graph_cut(m, dist, term, bias);
    REQUIRE(keep.has_value());
    const double got = cut_cost(m, dist, term, bias, *keep);
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::size_t> free;
    for (std::size_t f = 0; f < 20; ++f)
      if (term[f] == 0) free.push_back(f);
    std::vector<unsigned char> k(20);
    for (std::size_t f = 0; f < 20; ++f) k[f] = term[f] > 0;
    for (std::uint32_t mask = 0; mask < (1u << free.size()); ++mask) {
      for (std::size_t i = 0; i < free.size(); ++i) k[free[i]] = (mask >> i) & 1u;
      best = std::min(best, cut_cost(m, dist, term, bias, k));
    }
    REQUIRE(got == Approx(best).epsilon(1e-12));
    REQUIRE((*keep)[0] == 1);
    REQUIRE((*keep)[std::size_t(12 + trial)] == 0);
  }
}

TEST_CASE("merge_pair joins two overlapping pebbles along one seam into one closed, manifold element",
          "[element_merge]") {
  // C_T: a pebble already in the output; C_in: the corresponding exemplar pebble, slightly offset.
  // Old region x < 0.1, patch P_T x > -0.2: the overlap is -0.2 < x < 0.1, the new region x >= 0.1.
  const texture_element ct = pebble({0, 0, 0.3}, 0.5, 0.3), cin = pebble({0.03, 0.02, 0.3}, 0.5, 0.3);
  const detail::merge_params p = regions({-5, -5, 5, 5}, 0.1, -0.2);
  for (const merge_rules rules : {merge_rules::tessera, merge_rules::paper}) {
    detail::merge_params pr = p;
    pr.rules = rules;
    detail::merge_counters mc;
    detail::merge_trace tr;
    const auto merged = detail::merge_pair(ct, cin, pr, mc, &tr);
    REQUIRE(merged.has_value());
    REQUIRE(mc.attempted == 1);
    REQUIRE(mc.merged == 1);
    REQUIRE(tr.seams == 1);
    REQUIRE(closed_manifold(merged->mesh));
    REQUIRE_FALSE(detail::self_intersects(merged->mesh));
    // the cut sides: C_T's faces outside the patch are SOURCE and kept; every SINK face is removed;
    // what C_T keeps lies on the old side, what C_in keeps on the new side
    const tri_mesh& t2 = tr.deformed_t;
    const tri_mesh& i2 = tr.deformed_in;
    REQUIRE(tr.term_t.size() == t2.faces.size());
    index_t sources = 0, sinks = 0;
    for (std::size_t f = 0; f < t2.faces.size(); ++f) {
      const vec3 c = detail::centroid(t2, index_t(f));
      if (c.x < -0.2) REQUIRE(tr.term_t[f] == 1);
      if (tr.term_t[f] > 0) {
        REQUIRE(tr.keep_t[f] == 1);
        ++sources;
      }
      if (tr.term_t[f] < 0) {
        REQUIRE(tr.keep_t[f] == 0);
        ++sinks;
      }
      if (tr.keep_t[f]) REQUIRE(c.x < 0.35);
    }
    REQUIRE(sources > 0);
    REQUIRE(sinks > 0);
    for (std::size_t f = 0; f < i2.faces.size(); ++f) {
      const vec3 c = detail::centroid(i2, index_t(f));
      if (tr.term_in[f] > 0) REQUIRE(tr.keep_in[f] == 1);
      if (tr.term_in[f] < 0) REQUIRE(tr.keep_in[f] == 0);
      if (c.x < -0.2) REQUIRE(tr.keep_in[f] == 0);  // exemplar content over old output outside P_T goes
      if (tr.keep_in[f]) REQUIRE(c.x > -0.35);
    }
    // eq. 8's Dist is C_T -> C_in and back, capped at 4 correspondence radii
    for (double d : tr.dist_t) REQUIRE((d >= 0 && d <= 4 * p.corr_dist));
    // the merged pebble spans both: C_T's far side and C_in's far side
    REQUIRE(merged->box.min.x < -0.45);
    REQUIRE(merged->box.max.x > 0.5);
  }
}

TEST_CASE(
    "merge_pair against a tile border keeps the fixed border bit-identical, the paper's SINK rule conflicts there",
    "[element_merge]") {
  // C_T: the half of a pebble inside a tile [0, 2]^2, cut by the west side x = 0 (a frame element:
  // border set {west}, the vertices of its triangles on the side fixed). C_in: a whole pebble
  // close to it, crossing the west side (an exemplar element placed by the quilting).
  const xy_rect tile{0, 0, 2, 2};
  texture_element whole = pebble({0, 1, 0.3}, 0.5, 0.3);
  auto halves = detail::split_mesh_by_plane(whole.mesh, 0, 0.0, 1e-12);
  detail::compact_vertices(halves.above);
  texture_element ct;
  ct.mesh = halves.above;
  ct.border = border_bit(side_west);
  ct.fixed = border_vertices(ct, tile);
  ct.update_box();
  const texture_element cin = pebble({0.04, 1.02, 0.3}, 0.5, 0.3);
  detail::merge_params p = regions(tile, 0.3, 0.15);
  p.constrained = true;
  p.margin = 1e-9;
  std::set<std::array<double, 3>> fixed_before;
  for (std::size_t v = 0; v < ct.fixed.size(); ++v)
    if (ct.fixed[v]) fixed_before.insert({ct.mesh.positions[v].x, ct.mesh.positions[v].y, ct.mesh.positions[v].z});
  REQUIRE(fixed_before.size() > 10);

  detail::merge_counters mc;
  detail::merge_trace tr;
  const auto merged = detail::merge_pair(ct, cin, p, mc, &tr);
  REQUIRE(merged.has_value());
  REQUIRE(tr.seams == 1);
  // open only along the tile side, manifold, no self-intersection, nothing non-fixed on or beyond it
  const auto d = count_edge_defects(merged->mesh);
  REQUIRE(d.nonmanifold_edges == 0);
  for (const auto& e : boundary_edges(merged->mesh)) {
    REQUIRE(merged->mesh.positions[std::size_t(e[0])].x == 0.0);
    REQUIRE(merged->mesh.positions[std::size_t(e[1])].x == 0.0);
  }
  REQUIRE_FALSE(detail::self_intersects(merged->mesh));
  std::set<std::array<double, 3>> fixed_after;
  for (std::size_t v = 0; v < merged->fixed.size(); ++v) {
    const vec3 q = merged->mesh.positions[v];
    if (merged->fixed[v])
      fixed_after.insert({q.x, q.y, q.z});
    else
      REQUIRE(q.x > 0);
  }
  REQUIRE(fixed_after == fixed_before);  // every fixed vertex of the border triangles, bit for bit
  REQUIRE(merged->border == border_bit(side_west));
  // C_in's border triangles (crossing the west side, B(C_in) = B(C_T)) are never kept
  for (std::size_t f = 0; f < tr.deformed_in.faces.size(); ++f)
    for (index_t v : tr.deformed_in.faces[f])
      if (tr.deformed_in.positions[std::size_t(v)].x <= 0) REQUIRE(tr.keep_in[f] == 0);

  // the paper's wording sends C_T's faces around vertices that correspond to C_in's border
  // triangles to SINK; those are C_T's own border triangles (SOURCE): an infinite cut
  p.rules = merge_rules::paper;
  detail::merge_counters paper;
  REQUIRE_FALSE(detail::merge_pair(ct, cin, p, paper).has_value());
  REQUIRE(paper.fail_cut == 1);
}

TEST_CASE("max_flow_graph::in_source_set is false out of range and before solve", "[element_merge]") {
  max_flow_graph g(2);
  g.add_terminal(0, 1, 0);
  g.add_terminal(1, 0, 1);
  g.add_edge(0, 1, 0.5, 0.5);
  REQUIRE_FALSE(g.in_source_set(0));  // not solved yet
  REQUIRE(*g.solve() == Approx(0.5));
  REQUIRE(g.in_source_set(0));
  REQUIRE_FALSE(g.in_source_set(1));
  REQUIRE_FALSE(g.in_source_set(-1));
  REQUIRE_FALSE(g.in_source_set(2));
  REQUIRE_FALSE(g.in_source_set(std::numeric_limits<index_t>::max()));
}
