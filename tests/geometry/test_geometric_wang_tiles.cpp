#include <tessera/geometry/geometric_wang_tiles.hpp>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>

#include <catch2/catch.hpp>

#include "tile_set_checks.hpp"

#include <array>
#include <map>
#include <set>

using namespace tessera;

namespace {
// a small, fast ring exemplar and its 2 x 2-colour tile set, shared by the tests of this file
const quilt_exemplar& rings() {
  static const quilt_exemplar ex = *prepare_quilt_exemplar(
      *make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 12, .tube_segments = 5, .seed = 3}));
  return ex;
}
const geometric_tile_set& ring_set() {
  static const geometric_tile_set set = [] {
    geometric_wang_options o;
    o.tile_size = 4.0;
    o.quilt.seed = 11;
    auto r = build_geometric_wang_tiles(rings(), o);
    REQUIRE(r.ok());
    return std::move(*r);
  }();
  return set;
}
}  // namespace

TEST_CASE("geometric Wang tiles: complete set, identical borders, continuous tiled plane", "[geometric_wang]") {
  const auto& set = ring_set();
  REQUIRE(set.tiles.size() == 16);
  REQUIRE(set.crossing_elements > 0);  // some edges are crossed by elements
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    const wang_edges e = complete_tile_edges(static_cast<index_t>(t), 2, 2);
    REQUIRE(set.edges[t] == e);
  }
  REQUIRE(*tile_set_border_mismatch(set, 0.0) == 0);  // bit-identical, not just within 1e-6
  // merges happen in the interiors (rates: docs/geometry.md; in small tiles whose strips split many
  // elements, like this one, most merges fail, mostly at pairing the cut loops)
  INFO("interior merges " << set.stats.merges_succeeded << " / " << set.stats.merges_attempted << "; frame merges "
                          << set.frame_merged << " merged, " << set.frame_dropped << " dropped of "
                          << set.frame_merges_attempted << " merge_pair calls");
  REQUIRE(set.stats.elements_skipped > 0);  // exemplar rings where a ring (or a border half) already stands
  REQUIRE(set.frame_merged <= set.frame_merges_attempted);
  // no element crosses a tile corner: none touches two adjacent sides, and every border vertex keeps
  // the corner margin (0.15 x the element size by default) from both ends of its side
  const double margin = 0.15 * rings().element_diameter();
  REQUIRE(tile_set_corner_crossings(set) == 0);
  for (const auto& tile : set.tiles) {
    REQUIRE(tile_corner_crossings(tile, set.tile_size) == 0);
    for (const vec3& p : tile.positions) {
      if (p.x == 0 || p.x == set.tile_size) REQUIRE((p.y >= margin && p.y <= set.tile_size - margin));
      if (p.y == 0 || p.y == set.tile_size) REQUIRE((p.x >= margin && p.x <= set.tile_size - margin));
    }
  }
  // every tile: inside its square, closed except on the border, manifold, no intersections
  require_valid_tiles(set);
  // the border of a colour is the same set of cut vertices on both sides:
  // tile 0 north colour c vs any tile with south colour c: same (x, z) points, north at y = w
  for (std::size_t a = 0; a < set.tiles.size(); ++a)
    for (std::size_t b = 0; b < set.tiles.size(); ++b) {
      if (set.edges[a].north != set.edges[b].south) continue;
      std::multiset<std::pair<double, double>> na, sb;
      for (const vec3& p : set.tiles[a].positions)
        if (p.y == set.tile_size) na.insert({p.x, p.z});
      for (const vec3& p : set.tiles[b].positions)
        if (p.y == 0) sb.insert({p.x, p.z});
      REQUIRE(na == sb);
    }
  // a tiled plane from closed elements is closed, manifold and free of intersections
  const index_t cols = 4, rows = 3;
  stored_tile_coloring c{2, 2, {}};
  // a valid colouring: random horizontal/vertical edge colours
  counter_rng rng(5);
  std::vector<int> h((rows + 1) * cols), v(rows * (cols + 1));
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = int(rng.below(2, i, 0));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = int(rng.below(2, i, 1));
  for (index_t r = 0; r < rows; ++r)
    for (index_t col = 0; col < cols; ++col)
      c.colors.push_back({h[std::size_t(r * cols + col)], v[std::size_t(r * (cols + 1) + col + 1)],
                          h[std::size_t((r + 1) * cols + col)], v[std::size_t(r * (cols + 1) + col)]});
  const auto plane = tile_geometric_plane(set, c, cols, rows);
  REQUIRE(plane.ok());
  const double w = set.tile_size;
  const auto rep = check_geometric_texture(*plane, {0, 0, cols * w, rows * w});
  REQUIRE(rep->open_edges_inside == 0);
  REQUIRE(rep->nonmanifold_edges == 0);
  REQUIRE(rep->intersecting_pairs == 0);
  // welding: vertex count = sum of tiles minus the shared border vertices
  index_t sum = 0;
  for (index_t f = 0; f < cols * rows; ++f)
    sum += set.tiles[std::size_t(complete_tile_index({c.colors[std::size_t(f)][0], c.colors[std::size_t(f)][1],
                                                      c.colors[std::size_t(f)][2], c.colors[std::size_t(f)][3]},
                                                     2, 2))]
               .num_vertices();
  REQUIRE(plane->num_vertices() < sum);
  // the same with a thread pool
  thread_pool_executor pool(3);
  REQUIRE(*tile_geometric_plane(set, c, cols, rows, pool) == *plane);
  // oracle: lay the tiles out unwelded and weld by exact position; same vertices, same faces
  {
    std::map<std::array<double, 3>, index_t> weld;
    for (std::size_t v = 0; v < plane->positions.size(); ++v) {
      const vec3 p = plane->positions[v];
      REQUIRE(weld.emplace(std::array<double, 3>{p.x, p.y, p.z}, index_t(v)).second);  // no duplicate left unwelded
    }
    std::size_t fi = 0;
    for (index_t f = 0; f < cols * rows; ++f) {
      const auto& col = c.colors[std::size_t(f)];
      const tri_mesh& tile = set.tiles[std::size_t(complete_tile_index({col[0], col[1], col[2], col[3]}, 2, 2))];
      const vec3 off{double(f % cols) * w, double(rows - 1 - f / cols) * w, 0};
      for (const auto& tf : tile.faces) {
        REQUIRE(fi < plane->faces.size());
        for (std::size_t k = 0; k < 3; ++k) {
          const vec3 p = tile.positions[std::size_t(tf[k])] + off;
          const auto it = weld.find({p.x, p.y, p.z});
          REQUIRE(it != weld.end());
          REQUIRE(plane->faces[fi][k] == it->second);
        }
        ++fi;
      }
    }
    REQUIRE(fi == plane->faces.size());
  }
  // the two-step form writes the same mesh into caller storage; wrong sizes are refused
  {
    const auto layout = plan_geometric_plane(set, c, cols, rows);
    REQUIRE(layout.ok());
    REQUIRE(layout->num_vertices() == plane->num_vertices());
    std::vector<vec3> pos(std::size_t(layout->num_vertices()), vec3{-7, -7, -7});
    std::vector<std::array<index_t, 3>> faces(std::size_t(layout->num_faces()), {-1, -1, -1});
    REQUIRE(layout->write(pos, faces, pool).ok());
    REQUIRE(pos == plane->positions);
    REQUIRE(faces == plane->faces);
    pos.pop_back();
    REQUIRE(layout->write(pos, faces).message().find("vertices") != std::string::npos);
  }
  // bad colourings
  stored_tile_coloring bad{2, 2, {{0, 0, 0, 0}, {1, 1, 1, 1}}};  // touching sides disagree
  REQUIRE_FALSE(tile_geometric_plane(set, bad, 2, 1).ok());
  stored_tile_coloring three{3, 2, {{0, 0, 0, 0}}};
  REQUIRE(tile_geometric_plane(set, three, 1, 1).error().message().find("colours") != std::string::npos);
  REQUIRE_FALSE(tile_geometric_plane(set, stored_tile_coloring{2, 2, {{0, 0, 0, 0}}}, 2, 2).ok());  // wrong face count
}

TEST_CASE("geometric Wang tiles reject bad input", "[geometric_wang]") {
  const auto& ex = rings();
  geometric_wang_options o;
  o.tile_size = 4.0;
  o.horizontal_colors = 0;
  REQUIRE(build_geometric_wang_tiles(ex, o).error().message().find("horizontal") != std::string::npos);
  o.horizontal_colors = 2;
  o.tile_size = 0;
  REQUIRE(build_geometric_wang_tiles(ex, o).error().message().find("tile_size") != std::string::npos);
  o.tile_size = 4.0;
  o.edge_height = 50;  // taller than the exemplar
  REQUIRE(build_geometric_wang_tiles(ex, o).error().message().find("larger than the exemplar") != std::string::npos);
  o.edge_height = 0;
  o.tile_size = 40;  // the exemplar is smaller than a tile and may not be quilted larger
  o.quilt_larger_source = false;
  REQUIRE(build_geometric_wang_tiles(ex, o).error().message().find("cannot hold") != std::string::npos);
  tri_mesh nan = *make_ring_exemplar({.size = 4});
  nan.positions[0].x = std::nan("");
  o.tile_size = 3;
  REQUIRE(build_geometric_wang_tiles(nan, o).error().message().find("non-finite") != std::string::npos);
  tri_mesh nonmanifold = *make_ring_exemplar({.size = 4});
  nonmanifold.add_face(nonmanifold.faces[0][0], nonmanifold.faces[0][1], nonmanifold.add_vertex({9, 9, 9}));
  REQUIRE(build_geometric_wang_tiles(nonmanifold, o).error().message().find("non-manifold") != std::string::npos);
  tri_mesh open = *make_ring_exemplar({.size = 4});
  open.faces.pop_back();  // open exemplars are rejected, not repaired
  REQUIRE(build_geometric_wang_tiles(open, o).error().message().find("open edges") != std::string::npos);
  o.horizontal_colors = 2, o.vertical_colors = 0;
  REQUIRE(build_geometric_wang_tiles(ex, o).error().message().find("vertical") != std::string::npos);
}

TEST_CASE("geometric Wang tiles from an exemplar smaller than the tile quilt a larger source", "[geometric_wang]") {
  const auto ex = prepare_quilt_exemplar(
      *make_ring_exemplar({.size = 4.2, .spacing = 1.6, .ring_segments = 12, .tube_segments = 5}));
  geometric_wang_options o;
  o.horizontal_colors = o.vertical_colors = 1;
  o.tile_size = 4.8;
  auto r = build_geometric_wang_tiles(*ex, o);
  REQUIRE(r.ok());
  REQUIRE(r->quilted_source);
  REQUIRE(r->tiles.size() == 1);
  REQUIRE(*tile_set_border_mismatch(*r) == 0);
}

TEST_CASE("tile_corner_crossings counts elements touching two adjacent sides", "[geometric_wang]") {
  const double w = 4;
  tri_mesh t;
  t.add_face(t.add_vertex({w, 1, 0}), t.add_vertex({1, w, 0}),
             t.add_vertex({w - 0.5, w - 0.5, 1}));  // north and east: a corner
  t.add_face(t.add_vertex({0, 2, 0}), t.add_vertex({w, 2.2, 0}), t.add_vertex({2, 2.5, 1}));  // west and east: a thread
  t.add_face(t.add_vertex({1, 0, 0}), t.add_vertex({2, 0, 0}), t.add_vertex({1.5, 1, 1}));    // south only
  REQUIRE(tile_corner_crossings(t, w) == 1);
  t.add_face(t.add_vertex({0, 0.5, 0}), t.add_vertex({0.5, 0, 0}), t.add_vertex({0.5, 0.5, 1}));  // south and west
  REQUIRE(tile_corner_crossings(t, w) == 2);
}

TEST_CASE("geometric Wang tiles: every fixed vertex of the real frames comes out bit-identical", "[geometric_wang]") {
  // rebuild the frames the set was made from (same options, same strips) and look up every fixed
  // vertex, the corners of all border triangles, not only those on the side lines
  const auto& set = ring_set();
  geometric_wang_options o;
  o.tile_size = 4.0;
  o.quilt.seed = 11;
  const auto plan = detail::plan_wang_strips(rings(), o, serial_executor{});
  REQUIRE(plan.ok());
  index_t on_line = 0, off_line = 0;
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    const auto fr =
        detail::build_frame(plan->hs, plan->vs, set.edges[t], o.tile_size, plan->sp.half_height, rings().cell_size());
    std::set<std::array<double, 3>> out;
    for (const vec3& p : set.tiles[t].positions) out.insert({p.x, p.y, p.z});
    for (const auto& e : fr.frame.elements)
      for (std::size_t v = 0; v < e.fixed.size(); ++v) {
        if (!e.fixed[v]) continue;
        const vec3 p = e.mesh.positions[v];
        REQUIRE(out.count({p.x, p.y, p.z}) == 1);
        (p.x == 0 || p.y == 0 || p.x == o.tile_size || p.y == o.tile_size ? on_line : off_line)++;
      }
  }
  REQUIRE(on_line > 0);
  REQUIRE(off_line > 0);
}

namespace {
// tile set -> plane checks shared by the stone and weave sets
void check_set_and_plane(const geometric_tile_set& set, int nh, int nv) {
  REQUIRE(set.tiles.size() == std::size_t(nh * nh * nv * nv));
  REQUIRE(*tile_set_border_mismatch(set) == 0);
  REQUIRE(tile_set_corner_crossings(set) == 0);
  for (const auto& tile : set.tiles) {
    const auto rep = check_geometric_texture(tile, {0, 0, set.tile_size, set.tile_size});
    REQUIRE(rep->open_edges_inside == 0);
    REQUIRE(rep->nonmanifold_edges == 0);
    REQUIRE(rep->intersecting_pairs == 0);
  }
  const auto edges = complete_tile_set_edges(nh, nv);
  const index_t cols = 3, rows = 3;
  stored_tile_coloring c{nh, nv, {}};
  std::vector<int> h((rows + 1) * cols), v(rows * (cols + 1));
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = int(i % std::size_t(nh));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = int((i / 2) % std::size_t(nv));
  for (index_t r = 0; r < rows; ++r)
    for (index_t col = 0; col < cols; ++col)
      c.colors.push_back({h[std::size_t(r * cols + col)], v[std::size_t(r * (cols + 1) + col + 1)],
                          h[std::size_t((r + 1) * cols + col)], v[std::size_t(r * (cols + 1) + col)]});
  const auto plane = tile_geometric_plane(set, c, cols, rows);
  REQUIRE(plane.ok());
  const double w = set.tile_size;
  const auto rep = check_geometric_texture(*plane, {0, 0, cols * w, rows * w});
  REQUIRE(rep->open_edges_inside == 0);
  REQUIRE(rep->nonmanifold_edges == 0);
  REQUIRE(rep->intersecting_pairs == 0);
}
}  // namespace

namespace {
// Builds an nh x nv set of `tile_size` tiles from `exemplar` (elements must cross tile edges) and
// checks it with check_set_and_plane.
void build_and_check(const tessera::tri_mesh& exemplar, int nh, int nv, double tile_size) {
  const auto ex = prepare_quilt_exemplar(exemplar);
  REQUIRE(ex.ok());
  geometric_wang_options o;
  o.horizontal_colors = nh, o.vertical_colors = nv;
  o.tile_size = tile_size;
  o.quilt.seed = 3;
  const auto set = build_geometric_wang_tiles(*ex, o);
  REQUIRE(set.ok());
  REQUIRE(set->crossing_elements > 0);
  check_set_and_plane(*set, nh, nv);
}
}  // namespace

TEST_CASE("geometric Wang tiles from stones: set and plane are closed, manifold, disjoint, matching",
          "[geometric_wang]") {
  build_and_check(*make_stone_exemplar({.size = 7, .subdivisions = 1, .seed = 5}), 2, 1, 3.6);
}

TEST_CASE("geometric Wang tiles from a weave: set and plane are closed, manifold, disjoint, matching",
          "[geometric_wang]") {
  build_and_check(*make_weave_exemplar({.size = 7, .segments_per_spacing = 4, .around = 4}), 1, 2, 3.0);
}

TEST_CASE("geometric Wang tiles reject absurd tile counts and cell sizes before looping", "[geometric_wang]") {
  geometric_wang_options o;
  o.tile_size = 4.0;
  o.horizontal_colors = o.vertical_colors = 4096;  // 2^48 tiles
  const auto many = build_geometric_wang_tiles(rings(), o);
  REQUIRE(many.error().code() == status_code::size_overflow);
  REQUIRE(many.error().message().find("2^26") != std::string::npos);
  o.horizontal_colors = o.vertical_colors = 2;
  const auto ring_exemplar =
      *make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 12, .tube_segments = 5, .seed = 3});
  // a cell this small is refused when the exemplar is prepared (its grid would be ~1e20 cells)...
  const auto tiny = prepare_quilt_exemplar(ring_exemplar, {.cell_size = 1e-9});
  REQUIRE(tiny.error().code() == status_code::size_overflow);
  REQUIRE(tiny.error().message().find("grid cells of 1e-09") != std::string::npos);
  // ...and one the exemplar accepts is refused by the Wang tile builder when a tile is too many cells
  const auto fine = prepare_quilt_exemplar(ring_exemplar, {.cell_size = 0.005});
  REQUIRE(fine.ok());
  o.tile_size = 50;  // 10^8 cells a tile
  const auto r = build_geometric_wang_tiles(*fine, o);
  REQUIRE(r.error().code() == status_code::size_overflow);
  REQUIRE(r.error().message().find("cell_size 0.005") != std::string::npos);
}

TEST_CASE("tile frames merge a free strip element into a border element it hits, the tile border fixed",
          "[geometric_wang]") {
  // south strip: a border element, the half of a pebble cut by the south side y = 0 (its triangles
  // on the side fixed); west strip: a free pebble that reaches into it near the south-west corner
  const double w = 4, hh = 0.8;
  auto pebble = [](vec3 c, double r, double h) {
    tri_mesh m = detail::icosphere(2);
    for (vec3& p : m.positions) p = c + vec3{p.x * r, p.y * r, p.z * h};
    return m;
  };
  auto halves = detail::split_mesh_by_plane(pebble({0.9, 0, 0.3}, 0.5, 0.3), 1, 0.0, 1e-12);
  detail::compact_vertices(halves.above);
  texture_element border;
  border.mesh = halves.above;
  border.border = 1;
  border.fixed.assign(border.mesh.positions.size(), 0);
  for (const auto& f : border.mesh.faces) {
    bool on = false;
    for (index_t v : f) on = on || border.mesh.positions[std::size_t(v)].y == 0.0;
    if (on)
      for (index_t v : f) border.fixed[std::size_t(v)] = 1;
  }
  border.update_box();
  texture_element free_el;
  free_el.mesh = pebble({0.5, 0.7, 0.3}, 0.35, 0.25);
  free_el.fixed.assign(free_el.mesh.positions.size(), 0);
  free_el.update_box();
  detail::edge_strip h, v;
  h.horizontal = true, h.positive = {border};
  v.horizontal = false, v.positive = {free_el};
  const auto fr = detail::build_frame({h}, {v}, {0, 0, 0, 0}, w, hh, 0.25);
  REQUIRE(fr.merges_attempted >= 1);
  REQUIRE(fr.merged == 1);
  REQUIRE(fr.dropped == 0);
  REQUIRE(fr.frame.elements.size() == 1);  // the free pebble became part of the border element
  const texture_element& m = fr.frame.elements[0];
  REQUIRE(m.border == border_bit(side_south));
  REQUIRE(m.box.max.y > 0.9);  // it reaches up into the free pebble's top
  std::set<std::array<double, 3>> fixed_before, fixed_after;
  for (std::size_t i = 0; i < border.fixed.size(); ++i)
    if (border.fixed[i])
      fixed_before.insert({border.mesh.positions[i].x, border.mesh.positions[i].y, border.mesh.positions[i].z});
  for (std::size_t i = 0; i < m.fixed.size(); ++i)
    if (m.fixed[i]) fixed_after.insert({m.mesh.positions[i].x, m.mesh.positions[i].y, m.mesh.positions[i].z});
  REQUIRE(fixed_after == fixed_before);
  const auto rep = check_geometric_texture(m.mesh, {0, 0, w, w});
  REQUIRE(rep->open_edges_inside == 0);
  REQUIRE(rep->nonmanifold_edges == 0);
  REQUIRE_FALSE(detail::self_intersects(m.mesh));
}
