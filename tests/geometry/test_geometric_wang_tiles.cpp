#include <tessera/geometry/geometric_wang_tiles.hpp>

#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>

#include <catch2/catch.hpp>

#include <map>
#include <set>

using namespace tessera;

namespace {
// a small, fast ring exemplar and its 2 x 2-colour tile set, shared by the tests of this file
const quilt_exemplar& rings() {
  static const quilt_exemplar ex =
      *prepare_quilt_exemplar(*make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 12, .tube_segments = 5, .seed = 3}));
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
  // every tile: inside its square, closed except on the border, manifold, no intersections
  for (const auto& tile : set.tiles) {
    const auto rep = check_geometric_texture(tile, {0, 0, set.tile_size, set.tile_size});
    REQUIRE(rep.ok());
    REQUIRE(rep->open_edges_inside == 0);
    REQUIRE(rep->nonmanifold_edges == 0);
    REQUIRE(rep->intersecting_pairs == 0);
    REQUIRE(tile_border_vertices(tile, set.tile_size).ok());  // nothing on a corner, nothing outside
  }
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
      c.colors.push_back({h[std::size_t(r * cols + col)], v[std::size_t(r * (cols + 1) + col + 1)], h[std::size_t((r + 1) * cols + col)],
                          v[std::size_t(r * (cols + 1) + col)]});
  const auto plane = tile_geometric_plane(set, c, cols, rows);
  REQUIRE(plane.ok());
  const double w = set.tile_size;
  const auto rep = check_geometric_texture(*plane, {0, 0, cols * w, rows * w});
  REQUIRE(rep->open_edges_inside == 0);
  REQUIRE(rep->nonmanifold_edges == 0);
  REQUIRE(rep->intersecting_pairs == 0);
  // welding: vertex count = sum of tiles minus the shared border vertices
  index_t sum = 0;
  for (index_t f = 0; f < cols * rows; ++f) sum += set.tiles[std::size_t(complete_tile_index({c.colors[std::size_t(f)][0], c.colors[std::size_t(f)][1], c.colors[std::size_t(f)][2], c.colors[std::size_t(f)][3]}, 2, 2))].num_vertices();
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
  const auto ex = prepare_quilt_exemplar(*make_ring_exemplar({.size = 4.2, .spacing = 1.6, .ring_segments = 12, .tube_segments = 5}));
  geometric_wang_options o;
  o.horizontal_colors = o.vertical_colors = 1;
  o.tile_size = 4.8;
  auto r = build_geometric_wang_tiles(*ex, o);
  REQUIRE(r.ok());
  REQUIRE(r->quilted_source);
  REQUIRE(r->tiles.size() == 1);
  REQUIRE(*tile_set_border_mismatch(*r) == 0);
}
