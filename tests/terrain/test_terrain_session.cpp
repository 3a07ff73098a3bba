#include <tessera/terrain/terrain_session.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

namespace {
// A low fly-through over the terrain along +y: frame i moves eye and target by `step` times the
// view distance per frame (and turns by `turn` radians per frame about the vertical).
std::vector<tessera::terrain_camera> fly(const tessera::terrain_mesh& m, int frames, double step, double turn = 0,
                                         index_t w = 160, index_t h = 90) {
  const tessera::aabb b = tessera::bounding_box(m);
  const tessera::vec3 e = b.extent();
  tessera::look_at_camera l;
  l.eye = {b.min.x + 0.5 * e.x, b.min.y + 0.1 * e.y, b.max.z + 0.05 * e.x};
  tessera::vec3 dir{0, 0.3 * e.y, -0.06 * e.x - (l.eye.z - b.min.z)};
  l.fov_y_degrees = 60;
  l.near = 0.01;
  l.far = 10 * e.x;
  const double dist = tessera::norm(dir);
  std::vector<tessera::terrain_camera> out;
  for (int i = 0; i < frames; ++i) {
    const double a = turn * i;
    const tessera::vec3 d{dir.x * std::cos(a) - dir.y * std::sin(a), dir.x * std::sin(a) + dir.y * std::cos(a), dir.z};
    l.target = l.eye + d;
    out.push_back(tessera::make_camera(l, w, h).value());
    l.eye = l.eye + tessera::vec3{0, step * dist, 0};
  }
  return out;
}
struct snapshot {
  std::vector<std::array<float, 6>> uv;
  std::vector<std::int32_t> level;
  std::vector<bool> visible;
};
snapshot take(const tessera::terrain_session& s) {
  snapshot o{s.corner_uv(), s.level(), {}};
  for (index_t f = 0; f < static_cast<index_t>(o.uv.size()); ++f) o.visible.push_back(s.visible(f));
  return o;
}
}  // namespace

TEST_CASE("terrain_session: a camera moving 1 % of the view distance per frame keeps the texture on the ground",
          "[terrain][session]") {
  const auto mesh = terrain_test::prepared_terrain(64, 3, 6);
  auto s = tessera::make_terrain_session(mesh, 128, 128, {.synthesis = {.seed = 4}}).value();
  REQUIRE(s.frame() == -1);
  const auto cams = fly(mesh, 12, 0.01, 0.002);
  snapshot prev;
  for (std::size_t i = 0; i < cams.size(); ++i) {
    REQUIRE(s.update(mesh, cams[i]));
    const auto& st = s.stats();
    REQUIRE(st.frame == static_cast<index_t>(i));
    REQUIRE(st.visible > 1000);
    REQUIRE(st.warning.ok());
    REQUIRE(st.max_level_jump <= 1);
    // the issue's continuity goal, met by the default max_stretch (docs/terrain.md, "Slope
    // stretch"): 96.6 % here, 92 % with max_stretch 1.05
    REQUIRE(st.continuous_fraction >= 0.95);
    const snapshot cur = take(s);
    if (i == 0) {
      REQUIRE(st.resynthesized == st.visible);
      REQUIRE(st.common == 0);
    } else {
      REQUIRE(st.stable_fraction >= 0.95);
      REQUIRE(st.resynthesized < st.visible / 4);
      // the promise: every face visible in both frames at the same level keeps its coordinates bit for bit
      index_t common = 0, same = 0, resyn = 0;
      for (std::size_t f = 0; f < cur.uv.size(); ++f) {
        if (!cur.visible[f]) continue;
        if (!prev.visible[f] || prev.level[f] != cur.level[f]) ++resyn;
        if (!prev.visible[f]) continue;
        ++common;
        if (prev.level[f] != cur.level[f]) continue;
        ++same;
        REQUIRE(std::memcmp(prev.uv[f].data(), cur.uv[f].data(), sizeof(float) * 6) == 0);
      }
      REQUIRE(common == st.common);
      REQUIRE(same == st.stable_faces);
      REQUIRE(resyn == st.resynthesized);
    }
    prev = cur;
  }
  REQUIRE(s.memory_bytes() > 0);
}

TEST_CASE("terrain_session: coordinates are a pure function of mesh, exemplar, seed, face and level",
          "[terrain][session]") {
  const auto mesh = terrain_test::prepared_terrain(48, 2);
  const tessera::terrain_session_options o{.synthesis = {.seed = 11}, .hysteresis = 0};
  const auto path = fly(mesh, 20, 0.02, 0.01);
  // a session that flew the whole path, and one that jumped to its last camera: where both see a
  // face at the same level, they agree bit for bit (entering and leaving faces included)
  auto a = tessera::make_terrain_session(mesh, 96, 96, o).value();
  for (const auto& c : path) REQUIRE(a.update(mesh, c));
  auto b = tessera::make_terrain_session(mesh, 96, 96, o).value();
  REQUIRE(b.update(mesh, path.back()));
  index_t compared = 0;
  for (index_t f = 0; f < mesh.num_faces(); ++f) {
    if (!a.visible(f)) continue;
    REQUIRE(b.visible(f));
    const auto fi = static_cast<std::size_t>(f);
    REQUIRE(a.level()[fi] == b.level()[fi]);  // no hysteresis: the level is a function of the distance
    REQUIRE(a.corner_uv()[fi] == b.corner_uv()[fi]);
    ++compared;
  }
  REQUIRE(compared > 500);
  // the atlas of every region both grew is identical
  for (index_t f = 0; f < mesh.num_faces(); ++f) {
    const auto fi = static_cast<std::size_t>(f);
    if (a.atlas().patch[fi] >= 0 && b.atlas().patch[fi] >= 0) REQUIRE(a.atlas().uv[fi] == b.atlas().uv[fi]);
  }
  // a view of a camera turned away and back: faces that left and came back keep their coordinates
  const snapshot before = take(a);
  auto away = path.back();
  away.view = glm::rotate(glm::dmat4(1.0), 3.0, glm::dvec3(0, 1, 0)) * away.view;
  REQUIRE(a.update(mesh, away));
  REQUIRE(a.update(mesh, path.back()));
  for (index_t f = 0; f < mesh.num_faces(); ++f)
    if (before.visible[static_cast<std::size_t>(f)])
      REQUIRE(a.corner_uv()[static_cast<std::size_t>(f)] == before.uv[static_cast<std::size_t>(f)]);
}

TEST_CASE("terrain_session: the incremental frame equals a full recomputation of every face", "[terrain][session]") {
  // the session visits only blocks that may have changed; an oracle recomputes every face every
  // frame (project_mesh's culling rule on the clip coordinates, the level rule with hysteresis)
  const auto mesh = terrain_test::prepared_terrain(64, 8, 10);
  auto s =
      tessera::make_terrain_session(
          mesh, 64, 64, {.synthesis = {.region_size = 0.3}, .min_scale = 0.02, .hysteresis = 0.1, .blend_frames = 2})
          .value();
  REQUIRE(s.regions().num_regions() > 4);
  auto path = fly(mesh, 24, 0.03, 0.04);
  for (std::uint64_t k = 0; k < 4; ++k) path.push_back(terrain_test::random_camera(mesh, k));
  path.push_back(path.front());
  const auto nf = static_cast<std::size_t>(mesh.num_faces());
  std::vector<std::int32_t> level(nf, -1);
  std::vector<bool> was(nf, false);
  const double rho = s.options().level_ratio, beta = s.options().hysteresis, d0 = s.near_distance();
  const auto top = static_cast<std::int32_t>(s.levels() - 1);
  auto bound = [&](double l) { return std::pow(d0 * std::pow(rho, l), 2); };
  tessera::thread_pool_executor pool(2);
  for (const auto& cam : path) {
    REQUIRE(s.update(mesh, cam, pool));
    const glm::dmat4 m = cam.projection * cam.view;
    const tessera::vec3 eye = tessera::camera_eye(cam);
    index_t visible = 0, changes = 0;
    for (std::size_t f = 0; f < nf; ++f) {
      unsigned all = 63;
      for (const std::int32_t v : mesh.faces[f]) {
        const auto& p = mesh.positions[static_cast<std::size_t>(v)];
        const glm::dvec4 c = m * glm::dvec4(p.x, p.y, p.z, 1.0);
        all &= (c.x < -c.w ? 1u : 0u) | (c.x > c.w ? 2u : 0u) | (c.y < -c.w ? 4u : 0u) | (c.y > c.w ? 8u : 0u) |
               (c.z < -c.w ? 16u : 0u) | (c.z > c.w ? 32u : 0u);
      }
      const bool vis = all == 0;
      REQUIRE(s.visible(static_cast<index_t>(f)) == vis);
      if (vis) {
        const tessera::vec3 d = mesh.centroids[f] - eye;
        const double d2 = tessera::dot(d, d);
        std::int32_t l = 0;
        while (l < top && d2 >= bound(l + 1)) ++l;
        const std::int32_t old = level[f];
        if (was[f] && (old == 0 || d2 >= bound(old - beta)) && (old == top || d2 <= bound(old + 1 + beta))) l = old;
        changes += was[f] && l != old ? 1 : 0;
        level[f] = l;
        REQUIRE(s.level()[f] == l);
        const float sc = static_cast<float>(s.level_scale(l));
        for (std::size_t k = 0; k < 6; ++k) REQUIRE(s.corner_uv()[f][k] == s.atlas().uv[f][k] * sc);
        ++visible;
      }
      was[f] = vis;
    }
    REQUIRE(s.stats().visible == visible);
    REQUIRE(s.stats().level_changes == changes);
    // the visible list holds each visible face once
    auto list = s.projection().visible;
    REQUIRE(static_cast<index_t>(list.size()) == visible);
    std::sort(list.begin(), list.end());
    REQUIRE(std::adjacent_find(list.begin(), list.end()) == list.end());
    for (const std::int32_t f : list) REQUIRE(s.visible(f));
  }
}

TEST_CASE("terrain_session: identical for any executor and thread count", "[terrain][session]") {
  const auto mesh = terrain_test::prepared_terrain(48, 5);
  const auto path = fly(mesh, 5, 0.03, 0.02);
  auto serial = tessera::make_terrain_session(mesh, 96, 96, {.blend_frames = 2}).value();
  auto two = serial, three = serial;
  tessera::thread_pool_executor p2(2), p3(3);
  for (const auto& c : path) {
    REQUIRE(serial.update(mesh, c));
    REQUIRE(two.update(mesh, c, p2));
    REQUIRE(three.update(mesh, c, p3));
    for (auto* t : {&two, &three}) {
      REQUIRE(t->corner_uv() == serial.corner_uv());
      REQUIRE(t->level() == serial.level());
      REQUIRE(t->stats().resynthesized == serial.stats().resynthesized);
      REQUIRE(t->stats().continuous_edges == serial.stats().continuous_edges);
      REQUIRE(t->stats().regions_grown == serial.stats().regions_grown);
      REQUIRE(t->projection().visible == serial.projection().visible);
    }
  }
}

TEST_CASE("terrain_session: levels change with hysteresis, stay within one of their neighbours, blend over frames",
          "[terrain][session]") {
  const auto mesh = terrain_test::prepared_terrain(48, 1);
  auto s = tessera::make_terrain_session(mesh, 96, 96, {.hysteresis = 0.2, .blend_frames = 3}).value();
  const auto base = fly(mesh, 1, 0).front();
  REQUIRE(s.update(mesh, base));
  const double d0 = s.near_distance(), ln = std::log(1.5);
  REQUIRE(d0 >= s.regions().max_neighbor_distance / (0.6 * ln));
  REQUIRE(s.levels() == 3);  // 1, 1 / 1.5, 0.5 (min_scale)
  REQUIRE(s.level_scale(1) == Approx(1 / 1.5));
  REQUIRE(s.level_scale(2) == 0.5);
  // sway back and forth along the view by a tenth of a level at the nearest boundary: nothing
  // changes level (hysteresis 0.2)
  const glm::dvec3 shift(0, 0, 0.1 * ln * d0);
  for (int i = 0; i < 6; ++i) {
    auto c = base;
    c.view = glm::translate(glm::dmat4(1.0), i % 2 ? shift : -shift) * base.view;
    REQUIRE(s.update(mesh, c));
    REQUIRE(s.stats().level_changes == 0);
  }
  // moving back by more than a level changes levels, blended over 3 frames
  auto far = base;
  far.view = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -1.5 * ln * d0 * 1.5)) * base.view;
  REQUIRE(s.update(mesh, far));
  REQUIRE(s.stats().level_changes > 0);
  REQUIRE(s.stats().max_level_jump <= 1);
  index_t changed = -1;
  for (index_t f = 0; f < mesh.num_faces() && changed < 0; ++f)
    if (s.visible(f) && s.blend_weight(f) < 1) changed = f;
  REQUIRE(changed >= 0);
  REQUIRE(s.blend_weight(changed) == Approx(0.25));
  REQUIRE(s.blend_from(changed) < s.level()[static_cast<std::size_t>(changed)]);
  REQUIRE(s.update(mesh, far));
  REQUIRE(s.blend_weight(changed) == Approx(0.5));
  REQUIRE(s.update(mesh, far));
  REQUIRE(s.update(mesh, far));
  REQUIRE(s.blend_weight(changed) == 1.0f);
  REQUIRE(s.stats().blending == 0);
  // random views: adjacent levels never more than one apart
  for (std::uint64_t k = 0; k < 8; ++k) {
    REQUIRE(s.update(mesh, terrain_test::random_camera(mesh, k)));
    REQUIRE(s.stats().max_level_jump <= 1);
  }
}

TEST_CASE("terrain_session: bad input gets a clear status", "[terrain][session]") {
  const auto mesh = terrain_test::prepared_terrain(16);
  auto msg = [&](tessera::terrain_session_options o) {
    return tessera::make_terrain_session(mesh, 32, 32, o).error().message();
  };
  REQUIRE(msg({.min_scale = 0}).find("min_scale") != std::string::npos);
  REQUIRE(msg({.max_levels = 0}).find("max_levels") != std::string::npos);
  REQUIRE(msg({.hysteresis = 0.5}).find("hysteresis") != std::string::npos);
  REQUIRE(msg({.blend_frames = 300}).find("blend_frames") != std::string::npos);
  REQUIRE(msg({.level_ratio = 1}).find("level_ratio") != std::string::npos);
  REQUIRE(msg({.near_distance = NAN}).find("near_distance") != std::string::npos);
  REQUIRE(msg({.near_distance = 1e-9}).find("smallest that keeps") != std::string::npos);
  REQUIRE(msg({.synthesis = {.region_size = 9}}).find("region_size") != std::string::npos);

  auto s = tessera::make_terrain_session(mesh, 32, 32).value();
  const auto cam = terrain_test::preset_camera(mesh, tessera::camera_preset::oblique);
  // another mesh
  const auto other = terrain_test::prepared_terrain(16, 2);
  REQUIRE(s.update(other, cam).message().find("not the session's") != std::string::npos);
  const auto smaller = terrain_test::prepared_terrain(15);
  REQUIRE(s.update(smaller, cam).message().find("not the session's") != std::string::npos);
  // the session's mesh changed in place (a face not among the sampled ones): refused, no crash
  auto changed = mesh;
  changed.faces[5][0] = 1000000;
  REQUIRE(s.update(changed, cam).message().find("face 5 names a vertex outside") != std::string::npos);
  // a camera with NaN in it, a degenerate one
  auto nan_cam = cam;
  nan_cam.view[3][0] = std::numeric_limits<double>::quiet_NaN();
  REQUIRE(s.update(mesh, nan_cam).message().find("finite") != std::string::npos);
  auto flat = cam;
  flat.projection = glm::dmat4(0.0);
  REQUIRE(s.update(mesh, flat).message().find("singular") != std::string::npos);
  REQUIRE(s.frame() == -1);
  // an empty view is not an error, but says so
  auto away = cam;
  away.view = glm::rotate(glm::dmat4(1.0), 3.14159, glm::dvec3(0, 1, 0)) * cam.view;
  REQUIRE(s.update(mesh, away));
  REQUIRE(s.stats().visible == 0);
  REQUIRE(s.stats().warning.message().find("no face is in view") != std::string::npos);
  REQUIRE(s.update(mesh, cam));
  REQUIRE(s.stats().visible > 0);
  REQUIRE(s.stats().common == 0);
  REQUIRE(s.stats().warning.ok());
  // an error after frames empties the visible list and keeps the per-face state: the next good
  // frame continues from the last good one and lists every visible face again
  const index_t seen = s.stats().visible;
  REQUIRE(!s.update(mesh, nan_cam));
  REQUIRE(s.projection().visible.empty());
  REQUIRE(s.update(mesh, cam));
  REQUIRE(s.stats().visible == seen);
  REQUIRE(s.stats().common == seen);
  REQUIRE(s.stats().stable_faces == seen);
  REQUIRE(static_cast<index_t>(s.projection().visible.size()) == seen);
}
