// Image Wang tiles on surfaces (Fu & Leung 2005, paper 000 ref. [5]): three-axis image sets
// (image/axis_wang_tiles.hpp), their atlas, and the split of the base mesh with per-corner atlas
// coordinates (surface/map_wang_tiles_to_surface.hpp).
#include <tessera/surface/map_wang_tiles_to_surface.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/image/axis_wang_atlas.hpp>
#include <tessera/image/axis_wang_tiles.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/surface/build_polycube_map.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "tiling_maps.hpp"

using namespace tessera;

namespace {
using wst_rgb8 = image_buffer<std::uint8_t, 3>;

const axis_wang_tile_set<std::uint8_t, 3>& wst_image_set() {  // 96 tiles of 32², two colours per axis
  static const axis_wang_tile_set<std::uint8_t, 3> set = [] {
    auto ex = make_exemplar<std::uint8_t, 3>(exemplar_kind::cells, {.width = 96, .height = 96, .seed = 4});
    REQUIRE(ex.ok());
    thread_pool_executor pool(2);
    auto r = build_axis_wang_tiles(*ex, {2, 2, 2}, {.tile_size = 32, .seed = 9}, pool);
    REQUIRE(r.ok());
    return std::move(*r);
  }();
  return set;
}
const axis_wang_atlas<std::uint8_t, 3>& wst_image_atlas() {
  static const axis_wang_atlas<std::uint8_t, 3> a = *build_axis_wang_atlas(wst_image_set());
  return a;
}
// bilinear sample of the atlas at normalized (u, v), v upwards, texel centres at half integers
std::array<double, 3> wst_bilinear(const wst_rgb8& img, vec2 uv) {
  const double x = uv.x * static_cast<double>(img.width()) - 0.5;
  const double y = (1 - uv.y) * static_cast<double>(img.height()) - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  std::array<double, 3> r{};
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const auto px = std::clamp<index_t>(static_cast<index_t>(fx) + dx, 0, img.width() - 1);
      const auto py = std::clamp<index_t>(static_cast<index_t>(fy) + dy, 0, img.height() - 1);
      const double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
      for (int c = 0; c < 3; ++c) r[static_cast<std::size_t>(c)] += w * img.pixel_ptr(px, py)[c];
    }
  return r;
}
struct wst_seam_report {
  double worst = 0;         // largest difference of a bilinear sample across a shared edge (0..255)
  index_t edges = 0;        // shared edges checked
  index_t cross_quad = 0;   // of which between two quads
  index_t cross_chart = 0;  // of which between two charts (polycube edges)
  index_t open = 0;         // edges not shared by exactly two faces
};
wst_seam_report wst_seams(const wang_surface_mesh& r, const polycube_map& map, const wst_rgb8& atlas) {
  std::map<std::pair<index_t, index_t>, std::vector<std::pair<index_t, int>>> by_edge;
  const auto& m = r.mesh;
  for (index_t f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const index_t a = m.faces[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)];
      const index_t b = m.faces[static_cast<std::size_t>(f)][static_cast<std::size_t>((k + 1) % 3)];
      by_edge[{std::min(a, b), std::max(a, b)}].push_back({f, k});
    }
  wst_seam_report rep;
  for (const auto& [key, fs] : by_edge) {
    if (fs.size() != 2) {
      ++rep.open;
      continue;
    }
    ++rep.edges;
    const auto [f0, k0] = fs[0];
    const auto [f1, k1] = fs[1];
    const bool across = r.face_quad[static_cast<std::size_t>(f0)] != r.face_quad[static_cast<std::size_t>(f1)];
    rep.cross_quad += across;
    rep.cross_chart += map.face_chart[static_cast<std::size_t>(r.face_origin[static_cast<std::size_t>(f0)])] !=
                       map.face_chart[static_cast<std::size_t>(r.face_origin[static_cast<std::size_t>(f1)])];
    // face 0 runs a -> b along side k0, face 1 runs b -> a along k1
    const vec2 a0 = m.uvs[static_cast<std::size_t>(f0)][static_cast<std::size_t>(k0)];
    const vec2 b0 = m.uvs[static_cast<std::size_t>(f0)][static_cast<std::size_t>((k0 + 1) % 3)];
    const vec2 b1 = m.uvs[static_cast<std::size_t>(f1)][static_cast<std::size_t>(k1)];
    const vec2 a1 = m.uvs[static_cast<std::size_t>(f1)][static_cast<std::size_t>((k1 + 1) % 3)];
    for (int s = 0; s <= 8; ++s) {
      const double t = s / 8.0;
      const auto c0 = wst_bilinear(atlas, a0 + (b0 - a0) * t), c1 = wst_bilinear(atlas, a1 + (b1 - a1) * t);
      for (int c = 0; c < 3; ++c)
        rep.worst = std::max(rep.worst, std::abs(c0[static_cast<std::size_t>(c)] - c1[static_cast<std::size_t>(c)]));
    }
  }
  return rep;
}
double wst_area(const tri_mesh& m) {
  double a = 0;
  for (index_t f = 0; f < m.num_faces(); ++f) a += 0.5 * std::sqrt(squared_norm(face_area_normal(m, f)));
  return a;
}
}  // namespace

TEST_CASE("three-axis image set: complete, sides depend on axis and colour only, symmetric corners") {
  const auto& set = wst_image_set();
  CHECK(set.size() == 96);
  CHECK(set.shared_border() >= 1);
  const index_t ts = set.tile_size(), d = set.shared_border();
  // every tile side, read along +axis at depth j from the edge, left (south / east sides) or right
  // (north / west) of it: the same for every tile with that axis and colour, whatever its face
  std::map<std::array<int, 3>, std::vector<std::uint8_t>> seen;  // (axis, colour, left) -> pixels
  index_t compared = 0;
  for (index_t t = 0; t < set.size(); ++t) {
    const axis_tile info = set.tile_info(t);
    const auto view = set.tile(t);
    for (int side = 0; side < 4; ++side) {
      const int axis = cube_face_side_axis(info.face, side);
      const bool left = side == side_south || side == side_east;
      std::vector<std::uint8_t> px;
      for (index_t j = 0; j < d; ++j)
        for (index_t s = 0; s < ts; ++s) {
          index_t x = 0, y = 0;  // s along +axis, j from the edge inwards
          if (side == side_south) x = s, y = ts - 1 - j;
          if (side == side_north) x = s, y = j;
          if (side == side_east) x = ts - 1 - j, y = ts - 1 - s;
          if (side == side_west) x = j, y = ts - 1 - s;
          for (int c = 0; c < 3; ++c) px.push_back(view.read(x, y)[static_cast<std::size_t>(c)]);
        }
      auto [it, fresh] = seen.emplace(std::array<int, 3>{axis, info.edges[side], left ? 1 : 0}, px);
      if (!fresh) {
        CHECK(it->second == px);
        ++compared;
      }
    }
  }
  CHECK(seen.size() == 12);  // 3 axes x 2 colours x 2 sides
  CHECK(compared == 96 * 4 - 12);
}

TEST_CASE("image Wang tiles on surfaces: closed split, seam-free bilinear samples at every shared edge") {
  const auto& atlas = wst_image_atlas();
  for (const auto& [name, map] : tiling_maps::maps()) {
    INFO(name);
    auto tiling = tile_polycube(map, wst_image_set(), 5);
    REQUIRE(tiling.ok());
    auto r = map_wang_tiles_to_surface(map.base, map, *tiling, atlas);
    REQUIRE(r.ok());
    CHECK(validate_polycube_input(r->mesh).ok());  // closed, manifold, oriented, no zero-area face
    CHECK(wst_area(r->mesh) == Approx(wst_area(map.base)).epsilon(1e-9));
    // every face inside its quad, corners in [0, 1]²
    for (const auto& q : r->quad_uv)
      for (const auto& c : q) {
        CHECK(c.x >= 0);
        CHECK(c.x <= 1);
        CHECK(c.y >= 0);
        CHECK(c.y <= 1);
      }
    const auto rep = wst_seams(*r, map, atlas.image);
    CHECK(rep.open == 0);
    CHECK(rep.cross_quad > 0);
    CHECK(rep.cross_chart > 0);
    CHECK(rep.worst < 1e-6);
    CHECK(wst_image_set().exact_mip_levels() == 2);
    // every quad carries faces
    std::vector<char> has(map.layout.quads.size(), 0);
    for (index_t q : r->face_quad) has[static_cast<std::size_t>(q)] = 1;
    CHECK(std::count(has.begin(), has.end(), 1) == static_cast<long>(has.size()));
  }
}

TEST_CASE("image Wang tiles on surfaces: the same result on 1 and 2 threads") {
  const auto& map = tiling_maps::maps()[1].map;
  auto tiling = tile_polycube(map, wst_image_set(), 3);
  REQUIRE(tiling.ok());
  auto a = map_wang_tiles_to_surface(map.base, map, *tiling, wst_image_atlas());
  thread_pool_executor pool(2);
  auto b = map_wang_tiles_to_surface(map.base, map, *tiling, wst_image_atlas(), pool);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a->mesh.positions == b->mesh.positions);
  CHECK(a->mesh.faces == b->mesh.faces);
  CHECK(a->mesh.uvs == b->mesh.uvs);
  // and the tile set too
  auto ex = make_exemplar<std::uint8_t, 3>(exemplar_kind::weave, {.width = 64, .height = 64, .seed = 2});
  auto s1 = build_axis_wang_tiles(*ex, {1, 2, 1}, {.tile_size = 16, .seed = 3});
  auto s2 = build_axis_wang_tiles(*ex, {1, 2, 1}, {.tile_size = 16, .seed = 3}, pool);
  REQUIRE(s1.ok());
  REQUIRE(s2.ok());
  CHECK(s1->size() == 2 * (4 + 1 + 4));
  for (index_t t = 0; t < s1->size(); ++t)
    for (index_t y = 0; y < 16; ++y)
      for (index_t x = 0; x < 16; ++x) CHECK(s1->tile(t).read(x, y) == s2->tile(t).read(x, y));
}

TEST_CASE("image Wang tiles on surfaces: bad input") {
  const auto& map = tiling_maps::maps()[0].map;
  auto tiling = tile_polycube(map, wst_image_set(), 5);
  REQUIRE(tiling.ok());
  const auto& atlas = wst_image_atlas();
  SECTION("open base") {
    tri_mesh open = map.base;
    open.faces.pop_back();
    auto r = map_wang_tiles_to_surface(open, map, *tiling, atlas);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().message().find("not closed") != std::string::npos);
  }
  SECTION("polycube of another mesh") {
    auto r = map_wang_tiles_to_surface(tiling_maps::maps()[1].map.base, map, *tiling, atlas);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().message().find("another mesh") != std::string::npos);
    tri_mesh moved = map.base;
    moved.positions[3].x += 0.01;
    auto r2 = map_wang_tiles_to_surface(moved, map, *tiling, atlas);
    REQUIRE_FALSE(r2.ok());
    CHECK(r2.error().message().find("vertex 3") != std::string::npos);
  }
  SECTION("a tiling of another polycube") {
    auto other = tile_polycube(tiling_maps::maps()[1].map, wst_image_set(), 5);
    auto r = map_wang_tiles_to_surface(map.base, map, *other, atlas);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().message().find("another polycube") != std::string::npos);
  }
  SECTION("a set that does not fit") {
    auto ex = make_exemplar<std::uint8_t, 3>(exemplar_kind::cells, {.width = 64, .height = 64, .seed = 1});
    auto small = build_axis_wang_tiles(*ex, {1, 1, 1}, {.tile_size = 16});
    REQUIRE(small.ok());
    CHECK(small->size() == 6);
    auto small_atlas = build_axis_wang_atlas(*small);
    REQUIRE(small_atlas.ok());
    auto r = map_wang_tiles_to_surface(map.base, map, *tiling, *small_atlas);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().message().find("does not fit") != std::string::npos);
    // a colouring with more colours than the set has
    auto coloring = color_polycube_edges(map, {2, 2, 2}, 1);
    REQUIRE(coloring.ok());
    auto t = assign_polycube_tiles(map, *small, *coloring);
    REQUIRE_FALSE(t.ok());
    CHECK(t.error().code() == status_code::out_of_range);
  }
  SECTION("bad set options") {
    auto ex = make_exemplar<std::uint8_t, 3>(exemplar_kind::cells, {.width = 64, .height = 64});
    CHECK_FALSE(build_axis_wang_tiles(*ex, {0, 2, 2}, {.tile_size = 16}).ok());
    CHECK(build_axis_wang_tiles(*ex, {2, 2, 5000}, {.tile_size = 16}).error().message().find("Z") != std::string::npos);
    CHECK_FALSE(build_axis_wang_tiles(*ex, {2, 2, 2}, {.tile_size = 128}).ok());
    wang_tile_options o;
    o.tile_size = 16;
    o.tiles = {{0, 0, 0, 0}};
    CHECK_FALSE(build_axis_wang_tiles(*ex, {1, 1, 1}, o).ok());
  }
}
