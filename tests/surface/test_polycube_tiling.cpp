// Colouring a polycube's grid edges and assigning three-axis geometric Wang tiles to its quads (paper 000
// §4): surface/polycube_tiling.hpp.
#include <tessera/surface/polycube_tiling.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/surface/build_polycube_map.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <vector>

#include "ring_tile_set.hpp"
#include "shapes.hpp"
#include "tiling_maps.hpp"

using namespace tessera;

namespace {
// does the map have concave grid edges (two quads whose faces turn inwards)?
bool has_concave(const polycube_map& m) {
  for (const auto& g : m.layout.edges) {
    const auto& a = m.layout.quads[static_cast<std::size_t>(g.quads[0])];
    const auto& b = m.layout.quads[static_cast<std::size_t>(g.quads[1])];
    const auto la = m.charts[static_cast<std::size_t>(a.chart)].label,
               lb = m.charts[static_cast<std::size_t>(b.chart)].label;
    if (la == lb) continue;
    // b's interior direction from the edge, against a's normal: above a's plane means concave
    vec3 ca, cb;
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) {
        ca[i] += 0.25 * static_cast<double>(a.corners[k][i]);
        cb[i] += 0.25 * static_cast<double>(b.corners[k][i]);
      }
    if (dot(cb - ca, label_direction(la)) > 0) return true;
  }
  return false;
}
}  // namespace

TEST_CASE("polycube colouring: every edge draws from its axis, keyed by the edge, same on any executor",
          "[polycube_tiling]") {
  for (const auto& [name, map] : tiling_maps::maps()) {
    INFO(name);
    const axis_color_counts n{2, 3, 4};
    auto serial = color_polycube_edges(map, n, 7);
    REQUIRE(serial.ok());
    thread_pool_executor pool(2);
    auto threaded = color_polycube_edges(map, n, 7, pool);
    REQUIRE(threaded->edge_colors == serial->edge_colors);
    REQUIRE(threaded->quad_colors == serial->quad_colors);
    std::set<std::pair<int, int>> used;
    for (std::size_t e = 0; e < map.layout.edges.size(); ++e) {
      const int c = serial->edge_colors[e], axis = map.layout.edges[e].axis;
      REQUIRE(c >= 0);
      REQUIRE(c < n[static_cast<std::size_t>(axis)]);
      used.insert({axis, c});
    }
    // quads see their grid edges' colours, sides in TileColoring order of the quad's frame
    for (std::size_t q = 0; q < map.layout.quads.size(); ++q)
      for (int k = 0; k < 4; ++k)
        REQUIRE(serial->edge_color(static_cast<index_t>(q), quad_tile_side(k)) ==
                serial->edge_colors[static_cast<std::size_t>(map.layout.quads[q].edges[k])]);
    REQUIRE(used.size() >= 6);  // most colours of every axis appear
    // another seed, another colouring
    REQUIRE(color_polycube_edges(map, n, 8)->edge_colors != serial->edge_colors);
    // independent of the order of the grid edges: a layout listing them backwards colours alike
    polycube_map reversed = map;
    const auto ne = static_cast<index_t>(map.layout.edges.size());
    std::reverse(reversed.layout.edges.begin(), reversed.layout.edges.end());
    for (auto& q : reversed.layout.quads)
      for (auto& e : q.edges) e = ne - 1 - e;
    REQUIRE(color_polycube_edges(reversed, n, 7)->quad_colors == serial->quad_colors);
  }
}

TEST_CASE("polycube tiling: the 96-tile ring set, built once per process for its sections", "[polycube_tiling]") {
  SECTION("each quad gets the tile of its face whose edges match, borders meet exactly") {
    const auto& set = ring_tile_set();
    bool concave_seen = false;
    for (const auto& [name, map] : tiling_maps::maps()) {
      INFO(name);
      concave_seen = concave_seen || has_concave(map);
      auto tiling = tile_polycube(map, set, 3);
      REQUIRE(tiling.ok());
      const auto coloring = *color_polycube_edges(map, set.axis_colors, 3);
      REQUIRE(tiling->quads.size() == map.layout.quads.size());
      REQUIRE(tiling->tile_size == set.tile_size);
      std::set<index_t> used;
      for (std::size_t q = 0; q < map.layout.quads.size(); ++q) {
        const auto& p = tiling->quads[q];
        const auto label = map.charts[static_cast<std::size_t>(map.layout.quads[q].chart)].label;
        REQUIRE(p.face == label);
        REQUIRE(set.faces[static_cast<std::size_t>(p.tile)] == static_cast<int>(label));
        for (int s = 0; s < 4; ++s)
          REQUIRE(set.edges[static_cast<std::size_t>(p.tile)][s] == coloring.edge_color(static_cast<index_t>(q), s));
        // the tile's square lands on the quad's unit square, corner for corner, height along the normal
        REQUIRE(p.to_quad({0, 0, 0}) == vec3{0, 0, 0});
        REQUIRE(p.to_quad({set.tile_size, set.tile_size, 0}) == vec3{1, 1, 0});
        REQUIRE(p.to_quad({0, 0, set.tile_size}) == vec3{0, 0, 1});
        used.insert(p.tile);
      }
      REQUIRE(tiling->tiles_used == static_cast<index_t>(used.size()));
      // every grid edge: the border vertices both quads' tiles put on it coincide, as (position along the
      // edge, height), bit for bit, whether the edge is flat, convex or concave
      index_t crossed = 0;
      for (std::size_t e = 0; e < map.layout.edges.size(); ++e) {
        const auto& g = map.layout.edges[e];
        std::multiset<std::pair<double, double>> sides[2];
        for (int i = 0; i < 2; ++i) {
          const auto qi = static_cast<std::size_t>(g.quads[static_cast<std::size_t>(i)]);
          const auto& quad = map.layout.quads[qi];
          int k = 0;
          while (quad.edges[static_cast<std::size_t>(k)] != static_cast<index_t>(e)) ++k;
          const auto ax = cube_face_axes(static_cast<int>(map.charts[static_cast<std::size_t>(quad.chart)].label));
          const int along = ax[0] == g.axis ? 0 : 1;  // u or v runs along the edge
          REQUIRE(quad.corners[0][static_cast<std::size_t>(g.axis)] == g.origin[static_cast<std::size_t>(g.axis)]);
          const auto& p = tiling->quads[qi];
          const auto border = *tile_border_vertices(set.tiles[static_cast<std::size_t>(p.tile)], set.tile_size);
          for (index_t v : border.side[static_cast<std::size_t>(quad_tile_side(k))]) {
            const vec3 uvh =
                p.to_quad(set.tiles[static_cast<std::size_t>(p.tile)].positions[static_cast<std::size_t>(v)]);
            // on the quad's side k: the other coordinate is 0 or 1
            REQUIRE(uvh[1 - along] == (k >= 2 ? (along == 0 ? 1.0 : 0.0) : (along == 0 ? 0.0 : 1.0)));
            sides[i].insert({uvh[along], uvh.z});
          }
        }
        REQUIRE(sides[0] == sides[1]);
        crossed += sides[0].empty() ? 0 : 1;
      }
      REQUIRE(crossed > 0);
    }
    REQUIRE(concave_seen);
  }
  SECTION("any TileColoring over the quads may be passed") {
    const auto& set = ring_tile_set();
    const auto& map = tiling_maps::maps()[0].map;
    const auto own = *color_polycube_edges(map, set.axis_colors, 9);
    const stored_tile_coloring stored = store_coloring(own);
    auto a = assign_polycube_tiles(map, set, stored), b = tile_polycube(map, set, 9);
    REQUIRE(a.ok());
    for (std::size_t q = 0; q < a->quads.size(); ++q) REQUIRE(a->quads[q].tile == b->quads[q].tile);
    // a constant colouring (every edge colour 0) uses one tile per face
    stored_tile_coloring zero = stored;
    for (auto& c : zero.colors) c = {0, 0, 0, 0};
    auto z = assign_polycube_tiles(map, set, zero);
    REQUIRE(z.ok());
    REQUIRE(z->tiles_used == 6);
  }
  SECTION("bad input returns a clear status") {
    const auto& set = ring_tile_set();
    const auto& map = tiling_maps::maps()[0].map;
    const auto good = *color_polycube_edges(map, set.axis_colors, 1);
    // colour counts
    auto s = color_polycube_edges(map, {2, 0, 2}, 1);
    REQUIRE_FALSE(s.ok());
    REQUIRE(s.error().message().find("parallel to Y") != std::string::npos);
    // a planar set
    geometric_tile_set planar;
    planar.tile_size = 1;
    planar.horizontal_colors = planar.vertical_colors = 1;
    planar.tiles.resize(1);
    planar.edges.resize(1);
    REQUIRE(tile_polycube(map, planar, 1).error().message().find("planar") != std::string::npos);
    REQUIRE(assign_polycube_tiles(map, planar, good).error().message().find("planar") != std::string::npos);
    // a colouring of another layout, colours beyond an axis' range, edges coloured differently by their quads
    polycube_coloring fewer = good;
    fewer.quad_colors.pop_back();
    REQUIRE(assign_polycube_tiles(map, set, fewer).error().message().find("faces") != std::string::npos);
    polycube_coloring wide = good;
    wide.quad_colors[0][0] = 2;
    auto w = assign_polycube_tiles(map, set, wide);
    REQUIRE(w.error().code() == status_code::out_of_range);
    REQUIRE(w.error().message().find("quad 0 north side") != std::string::npos);
    polycube_coloring torn = good;
    torn.quad_colors[0][0] = 1 - torn.quad_colors[0][0];
    REQUIRE(assign_polycube_tiles(map, set, torn).error().message().find("give it colours") != std::string::npos);
    // a set with fewer colours than the colouring uses (axes that do not fit)
    const auto three = *color_polycube_edges(map, {3, 3, 3}, 1);
    REQUIRE(assign_polycube_tiles(map, set, three).error().code() == status_code::out_of_range);
    // an incomplete set: the tiles of one face gone
    geometric_tile_set cut = set;
    for (std::size_t t = cut.tiles.size(); t-- > 0;)
      if (cut.faces[t] == 4) {
        cut.tiles.erase(cut.tiles.begin() + static_cast<std::ptrdiff_t>(t));
        cut.edges.erase(cut.edges.begin() + static_cast<std::ptrdiff_t>(t));
        cut.faces.erase(cut.faces.begin() + static_cast<std::ptrdiff_t>(t));
      }
    REQUIRE(tile_polycube(map, cut, 1).error().message().find("no tile of the set has") != std::string::npos);
    geometric_tile_set odd = set;
    odd.faces.pop_back();
    REQUIRE_FALSE(tile_polycube(map, odd, 1).ok());
    // a map without a layout, or whose layout belongs to another map
    polycube_map empty = map;
    empty.layout = {};
    REQUIRE(tile_polycube(empty, set, 1).error().message().find("no quads") != std::string::npos);
    polycube_map wrong = map;
    wrong.layout = tiling_maps::maps()[1].map.layout;
    REQUIRE_FALSE(tile_polycube(wrong, set, 1).ok());
    polycube_map broken = map;
    broken.layout.quads[3].edges[1] = static_cast<index_t>(broken.layout.edges.size());
    REQUIRE(tile_polycube(broken, set, 1).error().message().find("quad 3 side 1") != std::string::npos);
  }
}
