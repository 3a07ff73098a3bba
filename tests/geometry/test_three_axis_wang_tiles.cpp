// Three-axis geometric Wang tile sets (paper 000 §3.1 Fig. 2-3, §5), built by build_geometric_wang_tiles
// with geometric_wang_options::axis_colors.
#include <tessera/geometry/geometric_wang_tiles.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/tile_set_edges.hpp>

#include <catch2/catch.hpp>

#include "tile_set_checks.hpp"

#include <map>
#include <set>

using namespace tessera;

namespace {
const quilt_exemplar& rings() {
  static const quilt_exemplar ex = *prepare_quilt_exemplar(
      *make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 12, .tube_segments = 5, .seed = 3}));
  return ex;
}
geometric_tile_set build(axis_color_counts n, std::uint64_t seed = 11, int threads = 1) {
  geometric_wang_options o;
  o.axis_colors = n;
  o.tile_size = 4.0;
  o.quilt.seed = seed;
  thread_pool_executor pool(threads);
  auto r = build_geometric_wang_tiles(rings(), o, pool);
  INFO(r.error().message());
  REQUIRE(r.ok());
  return std::move(*r);
}
const geometric_tile_set& set222() {
  static const geometric_tile_set set = build({2, 2, 2});
  return set;
}

vec3 unit(int axis, int sign = 1) {
  vec3 v;
  v[axis] = sign;
  return v;
}
vec3 face_normal(int face) { return unit(face / 2, face % 2 == 0 ? 1 : -1); }

// A tile side in "edge frame" coordinates: along the edge (+axis), across it (> 0 into the quad on
// the left of +axis, < 0 into the quad on its right), height. Tile sides: the left quad of an edge
// along +axis meets it with its south side (axis = the face's first axis) or east side (second), the
// right quad with north or west (tiling/axis_tile_set.hpp, quad sides 0-1 run along +axis, 2-3 back).
vec3 to_edge_frame(vec3 p, int side, double w) {
  switch (side) {
    case side_south: return {p.x, p.y, p.z};
    case side_east: return {p.y, w - p.x, p.z};
    case side_north: return {p.x, p.y - w, p.z};
    default: return {p.y, 0.0 - p.x, p.z};  // west
  }
}

struct joined {
  index_t line_vertices_left = 0, line_vertices_right = 0, welded = 0, open_on_line = 0;
};
// Places tile a (left quad, its side sa) and tile b (right quad, side sb) on both sides of an edge line,
// welds vertices on the line by exact (along, height), and counts edges on the line with one face.
joined join(const tri_mesh& a, int sa, const tri_mesh& b, int sb, double w) {
  tri_mesh m;
  std::map<std::pair<double, double>, index_t> on_line;
  joined j;
  auto add = [&](const tri_mesh& t, int side, index_t& count) {
    std::vector<index_t> id(t.positions.size());
    for (std::size_t v = 0; v < t.positions.size(); ++v) {
      const vec3 p = to_edge_frame(t.positions[v], side, w);
      if (p.y == 0) {
        ++count;
        auto [it, fresh] = on_line.emplace(std::pair{p.x, p.z}, m.num_vertices());
        if (!fresh) {
          ++j.welded;
          id[v] = it->second;
          continue;
        }
      }
      id[v] = m.add_vertex(p);
    }
    for (const auto& f : t.faces) m.add_face(id[f[0]], id[f[1]], id[f[2]]);
  };
  add(a, sa, j.line_vertices_left);
  add(b, sb, j.line_vertices_right);
  std::map<std::pair<index_t, index_t>, int> edges;
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const index_t x = f[k], y = f[(k + 1) % 3];
      ++edges[std::minmax(x, y)];
    }
  for (const auto& [e, n] : edges)
    if (n == 1 && m.positions[e.first].y == 0 && m.positions[e.second].y == 0) ++j.open_on_line;
  return j;
}
}  // namespace

TEST_CASE("three-axis sets: the 96-tile ring set, built once per process for its sections", "[three_axis_wang]") {
  SECTION("counts, faces and edges of the complete set") {
    const auto& set = set222();
    REQUIRE(set.three_axis());
    REQUIRE(set.tiles.size() == 96);
    REQUIRE(set.horizontal_colors == 0);
    REQUIRE(set.vertical_colors == 0);
    for (std::size_t t = 0; t < set.tiles.size(); ++t) {
      const axis_tile at = axis_tile_at(static_cast<index_t>(t), {2, 2, 2});
      REQUIRE(set.faces[t] == at.face);
      REQUIRE(set.edges[t] == at.edges);
      for (int s = 0; s < 4; ++s)
        REQUIRE(set.side_class(static_cast<index_t>(t), s) == cube_face_side_axis(at.face, s));
    }
    REQUIRE(set.crossing_elements > 0);
    const auto one = build({1, 1, 1});
    REQUIRE(one.tiles.size() == 6);
    for (int f = 0; f < 6; ++f) REQUIRE(one.faces[static_cast<std::size_t>(f)] == f);
  }
  SECTION("every tile is valid and no element crosses a corner") {
    const auto& set = set222();
    REQUIRE(tile_set_corner_crossings(set) == 0);
    // every tile: inside its square, closed except on the border, manifold, no intersections
    require_valid_tiles(set);
    REQUIRE(*tile_set_border_mismatch(set, 0.0) == 0);  // per axis and colour, bit for bit
  }
  SECTION("tiles that can meet across any edge, flat, convex or concave, join exactly") {
    const auto& set = set222();
    const double w = set.tile_size;
    index_t convex = 0, concave = 0, flat = 0, pairs = 0, crossed = 0;
    for (int axis = 0; axis < 3; ++axis)
      for (int f1 = 0; f1 < 6; ++f1)
        for (int f2 = 0; f2 < 6; ++f2) {
          if (f1 / 2 == axis || f2 / 2 == axis || f1 == (f2 ^ 1)) continue;  // opposite faces never meet
          // the left quad's interior from the edge, the right quad's, and the kind of edge
          const vec3 e = unit(axis), d2 = cross(e, face_normal(f2));
          const int kind = f1 == f2 ? 0 : dot(d2, face_normal(f1)) < 0 ? 1 : 2;
          (kind == 0 ? flat : kind == 1 ? convex : concave) += 1;
          const int sa = cube_face_axes(f1)[0] == axis ? side_south : side_east;
          const int sb = cube_face_axes(f2)[0] == axis ? side_north : side_west;
          for (std::size_t a = 0; a < set.tiles.size(); ++a) {
            if (set.faces[a] != f1) continue;
            for (std::size_t b = 0; b < set.tiles.size(); ++b) {
              if (set.faces[b] != f2 || set.edges[a][sa] != set.edges[b][sb]) continue;
              ++pairs;
              const joined j = join(set.tiles[a], sa, set.tiles[b], sb, w);
              INFO("axis " << axis << " faces " << cube_face_name(f1) << " / " << cube_face_name(f2) << " tiles " << a
                           << " / " << b);
              // the same cut vertices on both sides (bit-identical: every one welds), and the halves of
              // each split element close up along the line
              REQUIRE(j.line_vertices_left == j.line_vertices_right);
              REQUIRE(j.welded == j.line_vertices_right);
              REQUIRE(j.open_on_line == 0);
              crossed += j.welded > 0 ? 1 : 0;
            }
          }
        }
    REQUIRE(flat == 12);
    REQUIRE(convex == 12);  // per axis: 4 ordered face pairs meet at convex edges, 4 at concave ones
    REQUIRE(concave == 12);
    REQUIRE(crossed > pairs / 2);  // most strips split elements on their line
  }
  SECTION("each face's tiles are a complete planar set that tiles a plane") {
    const auto& set = set222();
    for (int f = 0; f < 6; ++f) {
      auto planar = face_tile_set(set, f);
      REQUIRE(planar.ok());
      REQUIRE(planar->tiles.size() == 16);
      REQUIRE_FALSE(planar->three_axis());
      REQUIRE(*tile_set_border_mismatch(*planar, 0.0) == 0);
    }
    auto planar = *face_tile_set(set, 4);
    const auto edges = *tile_set_edges::create(2, 2, planar.edges);
    const auto coloring = *hash_coloring::for_set(edges, 5)->window(0, 0, 4, 3);
    auto plane = tile_geometric_plane(planar, coloring, 4, 3);
    REQUIRE(plane.ok());
    const auto rep = check_geometric_texture(*plane, {0, 0, 4 * set.tile_size, 3 * set.tile_size});
    REQUIRE(rep->open_edges_inside == 0);
    REQUIRE(rep->intersecting_pairs == 0);
    // the three-axis set itself is refused by the plane tiler, with the way out in the message
    auto refused = tile_geometric_plane(set, coloring, 4, 3);
    REQUIRE_FALSE(refused.ok());
    REQUIRE(refused.error().message().find("face_tile_set") != std::string::npos);
  }
  SECTION("bad colour counts and misuse return a clear status") {
    geometric_wang_options o;
    o.tile_size = 4.0;
    o.axis_colors = {2, 0, 2};
    auto r = build_geometric_wang_tiles(rings(), o);
    REQUIRE_FALSE(r.ok());
    REQUIRE(r.error().message().find("parallel to Y") != std::string::npos);
    o.axis_colors = {4096, 4096, 4096};
    REQUIRE(build_geometric_wang_tiles(rings(), o).error().code() == status_code::size_overflow);
    o.axis_colors = {1, -1, 1};
    REQUIRE(build_geometric_wang_tiles(rings(), o).error().code() == status_code::invalid_argument);
    // face_tile_set: a planar set, a face outside [0, 6), an incomplete set
    geometric_tile_set planar;
    planar.horizontal_colors = planar.vertical_colors = 1;
    REQUIRE_FALSE(face_tile_set(planar, 0).ok());
    REQUIRE(face_tile_set(set222(), 6).error().code() == status_code::out_of_range);
    geometric_tile_set cut = set222();
    cut.tiles.pop_back();
    cut.edges.pop_back();
    cut.faces.pop_back();
    REQUIRE_FALSE(face_tile_set(cut, 5).ok());
    cut = set222();
    cut.faces[3] = 7;
    REQUIRE(tile_set_border_mismatch(cut).error().code() == status_code::out_of_range);
  }
}

TEST_CASE("three-axis sets: same seed, same set, on any number of threads", "[three_axis_wang]") {
  const auto a = build({1, 1, 1}, 5, 1), b = build({1, 1, 1}, 5, 2);
  REQUIRE(a.tiles.size() == b.tiles.size());
  for (std::size_t t = 0; t < a.tiles.size(); ++t) {
    REQUIRE(a.tiles[t].positions == b.tiles[t].positions);
    REQUIRE(a.tiles[t].faces == b.tiles[t].faces);
  }
}
