#include <tessera/terrain/render_terrain_frame.hpp>
#include <tessera/terrain/render_tiled_frame.hpp>
#include <tessera/terrain/export_corner_uvs.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

#include <tessera/core/image_view.hpp>
#include <tessera/image/exemplars.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

namespace {
struct frame_scene {
  tessera::terrain_camera cam;
  tessera::terrain_mesh mesh;
  tessera::screen_projection proj;
  tessera::scale_field field;
  tessera::triangle_synthesis syn;
  tessera::exemplar_pyramid<std::uint8_t, 3> pyramid;
};
frame_scene make_frame_scene(tessera::terrain_mesh mesh, const tessera::terrain_camera& cam);
frame_scene make_frame_scene(tessera::camera_preset p = tessera::camera_preset::grazing, index_t cells = 32,
                             index_t w = 160, index_t h = 90) {
  return make_frame_scene(terrain_test::prepared_terrain(cells),
                          terrain_test::preset_camera(terrain_test::prepared_terrain(cells), p, w, h));
}
frame_scene make_frame_scene(tessera::terrain_mesh mesh, const tessera::terrain_camera& cam) {
  frame_scene s;
  s.mesh = std::move(mesh);
  s.cam = cam;
  s.proj = tessera::project_mesh(s.mesh, s.cam).value();
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::grass, {.width = 48, .height = 48}).value();
  s.pyramid = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.5, .levels = 16}).value();
  s.field = tessera::assign_scale_field(s.mesh, s.proj, {.min_scale = 0.5, .max_levels = 16}).value();
  s.syn = tessera::synthesize_triangles(s.mesh, s.proj, s.field, 48, 48).value();
  return s;
}
tessera::detail::visibility_buffer visibility(const frame_scene& s) {
  tessera::detail::visibility_buffer vb;
  tessera::serial_executor ex;
  REQUIRE(tessera::detail::render_visibility(s.mesh, s.proj, vb, false, 64, ex));
  return vb;
}
std::array<float, 3> expected_colour(const frame_scene& s, std::int32_t f, index_t x, index_t y) {
  const auto i = static_cast<std::size_t>(f);
  const double sc = s.field.scale[i];
  return s.pyramid.sample(sc, static_cast<double>(x) + 0.5 + s.syn.offset[i].x + 24 * sc,
                          static_cast<double>(y) + 0.5 + s.syn.offset[i].y + 24 * sc);
}
// An independent visibility oracle: a ray from the eye through the pixel centre, intersected
// (Moller-Trumbore, world space) with every face of the mesh, culled or not; the nearest hit whose
// clip-space depth lies inside [-w, w] (between the near and far planes) wins. The answer counts
// only where the centre and four points 0.03 px around it agree (the rasterizer snaps vertices to
// 1/256 px, so pixel centres closer than that to an edge may go either way); -2 marks those.
std::int32_t oracle_face(const tessera::terrain_mesh& mesh, const tessera::terrain_camera& cam, double px, double py,
                         int& hits) {
  const glm::dmat4 vp = cam.projection * cam.view, inv = glm::inverse(vp);
  const tessera::vec3 eye = tessera::camera_eye(cam);
  std::int32_t answer = -3;
  for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, {0.03, 0.03}, {-0.03, 0.03}, {0.03, -0.03}, {-0.03, -0.03}}) {
    const double nx = 2 * (px + dx) / static_cast<double>(cam.width) - 1,
                 ny = 1 - 2 * (py + dy) / static_cast<double>(cam.height);
    const glm::dvec4 q = inv * glm::dvec4(nx, ny, 0.5, 1.0);
    const tessera::vec3 dir = tessera::normalized(tessera::vec3{q.x / q.w, q.y / q.w, q.z / q.w} - eye);
    double best = INFINITY;
    std::int32_t face = -1;
    bool edge = false;
    for (index_t f = 0; f < mesh.num_faces(); ++f) {
      const auto& fv = mesh.faces[static_cast<std::size_t>(f)];
      const tessera::vec3 a = mesh.position(fv[0]), e1 = mesh.position(fv[1]) - a, e2 = mesh.position(fv[2]) - a;
      const tessera::vec3 p = tessera::cross(dir, e2);
      const double det = tessera::dot(e1, p);
      if (std::abs(det) < 1e-15) continue;
      const tessera::vec3 t0 = eye - a, qv = tessera::cross(t0, e1);
      const double u = tessera::dot(t0, p) / det, v = tessera::dot(dir, qv) / det, t = tessera::dot(e2, qv) / det;
      if (u < 0 || v < 0 || u + v > 1 || !(t > 0)) continue;
      const tessera::vec3 hit = eye + dir * t;
      const glm::dvec4 c = vp * glm::dvec4(hit.x, hit.y, hit.z, 1.0);
      const double zlo = cam.depth == tessera::clip_depth::zero_to_one ? 0.0 : -c.w;
      if (c.z < zlo || c.z > c.w) continue;
      if (std::abs(c.z - zlo) < 1e-7 * c.w || std::abs(c.z - c.w) < 1e-7 * c.w) edge = true;
      if (t < best) best = t, face = static_cast<std::int32_t>(f);
      hits += dx == 0 && dy == 0 ? 1 : 0;
    }
    if (edge) return -2;
    if (answer == -3)
      answer = face;
    else if (answer != face)
      return -2;
  }
  return answer;
}
// a member-style user image
struct rgba_canvas {
  index_t w, h;
  std::vector<std::array<std::uint16_t, 4>> px;
  rgba_canvas(index_t w_, index_t h_) : w(w_), h(h_), px(static_cast<std::size_t>(w_ * h_)) {}
  [[nodiscard]] index_t width() const { return w; }
  [[nodiscard]] index_t height() const { return h; }
  [[nodiscard]] std::array<std::uint16_t, 4> read(index_t x, index_t y) const {
    return px[static_cast<std::size_t>(y * w + x)];
  }
  void write(index_t x, index_t y, const std::array<std::uint16_t, 4>& p) {
    px[static_cast<std::size_t>(y * w + x)] = p;
  }
};
}  // namespace

TEST_CASE("render_terrain_frame: every pixel shows the nearest face's texture (brute-force ray casting oracle)",
          "[terrain][render]") {
  // small frames, every face of the mesh tested against every pixel: a low view over a coarse
  // terrain has large faces under and behind the eye (clipped at the near plane), the oblique one
  // hills hiding each other
  for (const int view : {0, 1}) {
    const frame_scene s =
        view == 0
            ? make_frame_scene(terrain_test::prepared_terrain(6, 1, 6), terrain_test::low_camera(64, 40))
            : make_frame_scene(terrain_test::prepared_terrain(12, 2, 30),
                               tessera::make_camera({.eye = {-50, -50, 24}, .target = {10, 10, 8}}, 64, 40).value());
    tessera::image_buffer<float, 3> out(64, 40);
    REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, out, {.feather = 0}));
    const auto vb = visibility(s);
    index_t checked = 0, covered = 0, hidden = 0;
    for (index_t y = 0; y < 40; ++y)
      for (index_t x = 0; x < 64; ++x) {
        int hits = 0;
        const std::int32_t f =
            oracle_face(s.mesh, s.cam, static_cast<double>(x) + 0.5, static_cast<double>(y) + 0.5, hits);
        hidden += hits > 1 ? 1 : 0;  // the ray passes through a hill in front of the face it shows
        if (f == -2) continue;       // an edge within 0.03 px of the pixel centre
        ++checked;
        INFO("view " << view << " pixel " << x << ", " << y << " oracle face " << f);
        REQUIRE(vb.face[static_cast<std::size_t>(y * 64 + x)] == f);
        const auto c = out.read(x, y);
        if (f < 0) {
          REQUIRE(c == std::array<float, 3>{0.62f, 0.74f, 0.88f});  // background
          continue;
        }
        ++covered;
        REQUIRE(s.proj.is_visible(f));
        const auto e = expected_colour(s, f, x, y);
        for (std::size_t k = 0; k < 3; ++k) REQUIRE(c[k] == Approx(e[k]).margin(1e-6));
      }
    INFO("view " << view << ": " << checked << " pixels checked, " << covered << " covered");
    REQUIRE(checked > 64 * 40 * 8 / 10);
    REQUIRE(covered > 64 * 40 / 4);
    REQUIRE(checked - covered > 64 * 40 / 10);  // background checked too
    if (view == 0) REQUIRE(s.proj.near_clipped > 0);
    if (view == 1) REQUIRE(hidden > 50);  // the depth test decides
  }
}

TEST_CASE("render_terrain_frame: every pixel shows its triangle's texture at its scale and coordinates",
          "[terrain][render]") {
  const frame_scene s = make_frame_scene();
  const auto vb = visibility(s);
  tessera::image_buffer<float, 3> out(160, 90);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, out, {.feather = 0}));
  index_t covered = 0;
  for (index_t y = 0; y < 90; ++y)
    for (index_t x = 0; x < 160; ++x) {
      const std::int32_t f = vb.face[static_cast<std::size_t>(y * 160 + x)];
      const auto c = out.read(x, y);
      if (f < 0) {
        REQUIRE(c[2] == Approx(0.88f));  // background
        continue;
      }
      ++covered;
      const auto e = expected_colour(s, f, x, y);
      for (std::size_t k = 0; k < 3; ++k) REQUIRE(c[k] == Approx(e[k]).margin(1e-6));
    }
  REQUIRE(covered > 160 * 30);
}

TEST_CASE("render_terrain_frame: feathering blends only near seams and softens them", "[terrain][render]") {
  const frame_scene s = make_frame_scene();
  const auto vb = visibility(s);
  tessera::image_buffer<float, 3> hard(160, 90), soft(160, 90);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, hard, {.feather = 0}));
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, soft, {.feather = 3}));
  auto label = [&](index_t x, index_t y) -> std::int64_t {
    const std::int32_t f = vb.face[static_cast<std::size_t>(y * 160 + x)];
    return f < 0 ? -1
                 : std::int64_t{s.syn.region[static_cast<std::size_t>(f)]} * 65536 +
                       s.field.level[static_cast<std::size_t>(f)];
  };
  // label pairs that meet across a mesh edge (the only ones blended)
  std::set<std::pair<std::int64_t, std::int64_t>> adjacent;
  auto face_label = [&](std::int32_t f) {
    return std::int64_t{s.syn.region[static_cast<std::size_t>(f)]} * 65536 + s.field.level[static_cast<std::size_t>(f)];
  };
  for (const std::int32_t f : s.proj.visible)
    for (const std::int32_t n : s.mesh.neighbors[static_cast<std::size_t>(f)])
      if (n >= 0 && s.proj.is_visible(n)) adjacent.insert({face_label(f), face_label(n)});
  auto labels_around = [&](index_t x, index_t y) {
    std::set<std::int64_t> l;
    for (auto [dx, dy] : {std::pair{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}})
      if (x + dx >= 0 && y + dy >= 0 && x + dx < 160 && y + dy < 90) l.insert(label(x + dx, y + dy));
    return l;
  };
  index_t changed = 0, pairs = 0;
  double diff_hard = 0, diff_soft = 0;
  for (index_t y = 0; y < 90; ++y)
    for (index_t x = 0; x < 160; ++x) {
      if (label(x, y) < 0) continue;
      bool near_boundary = false;  // a pixel of another label within the feather radius
      for (index_t dy = -3; dy <= 3; ++dy)
        for (index_t dx = -3; dx <= 3; ++dx) {
          const index_t xx = x + dx, yy = y + dy;
          if (xx >= 0 && yy >= 0 && xx < 160 && yy < 90 && label(xx, yy) >= 0 && label(xx, yy) != label(x, y))
            near_boundary = true;
        }
      const bool differs = hard.read(x, y) != soft.read(x, y);
      if (differs) {
        ++changed;
        REQUIRE(near_boundary);
      }
      // contrast across horizontal pixel pairs straddling a coordinate seam between exactly two adjacent labels
      if (x + 1 < 160 && label(x + 1, y) >= 0 && label(x + 1, y) / 65536 != label(x, y) / 65536 &&
          adjacent.count({label(x, y), label(x + 1, y)}) && labels_around(x, y).size() == 2 &&
          labels_around(x + 1, y).size() == 2) {
        ++pairs;
        for (std::size_t k = 0; k < 3; ++k) {
          diff_hard += std::abs(hard.read(x, y)[k] - hard.read(x + 1, y)[k]);
          diff_soft += std::abs(soft.read(x, y)[k] - soft.read(x + 1, y)[k]);
        }
      }
    }
  REQUIRE(changed > 100);
  REQUIRE(pairs > 20);
  REQUIRE(diff_soft < 0.5 * diff_hard);
}

TEST_CASE("render_terrain_frame: identical for any executor, any output type", "[terrain][render]") {
  const frame_scene s = make_frame_scene(tessera::camera_preset::oblique, 24);
  tessera::image_buffer<std::uint8_t, 3> a(160, 90), b(160, 90);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, a));
  tessera::thread_pool_executor pool(3);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, b, {.tile_size = 16}, pool));
  REQUIRE(a == b);
  std::vector<std::uint8_t> raw(160 * 90 * 4);
  auto view = tessera::make_image_view<4>(raw.data(), 160, 90).value();
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, view));
  rgba_canvas canvas(160, 90);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, canvas));
  for (index_t y = 0; y < 90; y += 7)
    for (index_t x = 0; x < 160; x += 5) {
      REQUIRE(view.read(x, y)[0] == a.read(x, y)[0]);
      REQUIRE(view.read(x, y)[3] == 255);
      REQUIRE(std::abs(canvas.read(x, y)[1] / 257.0 - a.read(x, y)[1]) <= 1.0);
    }
}

TEST_CASE("render_terrain_frame: diagnostic shadings", "[terrain][render]") {
  const frame_scene s = make_frame_scene();
  const auto vb = visibility(s);
  tessera::image_buffer<float, 3> scale(160, 90), regions(160, 90);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, scale,
                                        {.shading = tessera::terrain_shading::scale_field}));
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, regions,
                                        {.shading = tessera::terrain_shading::regions}));
  std::map<float, std::array<float, 3>> by_scale;
  std::map<std::int32_t, std::array<float, 3>> by_region;
  for (index_t y = 0; y < 90; ++y)
    for (index_t x = 0; x < 160; ++x) {
      const std::int32_t f = vb.face[static_cast<std::size_t>(y * 160 + x)];
      if (f < 0) continue;
      const auto fi = static_cast<std::size_t>(f);
      auto [it, fresh] = by_scale.emplace(s.field.scale[fi], scale.read(x, y));
      REQUIRE(it->second == scale.read(x, y));
      auto [jt, fresh2] = by_region.emplace(s.syn.region[fi], regions.read(x, y));
      REQUIRE(jt->second == regions.read(x, y));
    }
  REQUIRE(by_scale.size() > 3);
  REQUIRE(by_scale.rbegin()->second[0] > 0.9f);  // scale 1: yellow
  REQUIRE(by_region.size() > 3);
  REQUIRE(by_region.begin()->second != std::next(by_region.begin())->second);
}

TEST_CASE("render_terrain_frame: bad input and an empty view", "[terrain][render]") {
  frame_scene s = make_frame_scene(tessera::camera_preset::oblique, 8);
  tessera::image_buffer<float, 3> wrong(10, 10), out(160, 90);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, wrong).message().find("viewport") !=
          std::string::npos);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, out, {.feather = -1})
              .message()
              .find("feather") != std::string::npos);
  REQUIRE_FALSE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, out, {.tile_size = 2}));
  REQUIRE_FALSE(
      tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, tessera::exemplar_pyramid<std::uint8_t, 3>{}, out));
  std::fill(s.proj.state.begin(), s.proj.state.end(), std::uint8_t{0});
  s.proj.visible.clear();
  s.field = tessera::assign_scale_field(s.mesh, s.proj).value();
  s.syn = tessera::synthesize_triangles(s.mesh, s.proj, s.field, 48, 48).value();
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, out, {.background = {0, 0, 1, 1}}));
  for (index_t y = 0; y < 90; ++y)
    for (index_t x = 0; x < 160; ++x) REQUIRE(out.read(x, y) == std::array<float, 3>{0, 0, 1});
}

TEST_CASE("render_terrain_frame: flat Lambert lighting from a sun direction", "[terrain][render]") {
  const frame_scene s = make_frame_scene();
  const auto vb = visibility(s);
  tessera::image_buffer<float, 3> unlit(160, 90), lit(160, 90);
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, unlit));
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, lit,
                                        {.sun = {0, 0, 2}, .ambient = 0.25}));
  for (index_t y = 0; y < 90; y += 3)
    for (index_t x = 0; x < 160; x += 3) {
      const std::int32_t f = vb.face[static_cast<std::size_t>(y * 160 + x)];
      if (f < 0) {
        REQUIRE(lit.read(x, y) == unlit.read(x, y));  // the background is not lit
        continue;
      }
      const auto& fv = s.mesh.faces[static_cast<std::size_t>(f)];
      const tessera::vec3 n = tessera::normalized(tessera::cross(s.mesh.position(fv[1]) - s.mesh.position(fv[0]),
                                                                 s.mesh.position(fv[2]) - s.mesh.position(fv[0])));
      const double light = 0.25 + 0.75 * std::abs(n.z);  // heightfield faces look up, towards the eye
      for (std::size_t k = 0; k < 3; ++k)
        REQUIRE(lit.read(x, y)[k] == Approx(unlit.read(x, y)[k] * light).margin(1e-5));
    }
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, s.pyramid, lit, {.ambient = 2})
              .message()
              .find("ambient") != std::string::npos);
}

TEST_CASE("render_terrain_frame: empty and fully culled meshes run the whole pipeline to a background frame",
          "[terrain][render]") {
  // documented behaviour: nothing visible is not an error; every stage succeeds with empty output
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::sand, {.width = 32, .height = 32}).value();
  const auto pyramid = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.5, .levels = 4}).value();
  const auto tex = tessera::prepare_tiled_texture(ex).value();
  const auto terrain = terrain_test::prepared_terrain(6);
  // a camera on the terrain looking straight up, away from it: every face is behind or outside
  const auto away =
      tessera::make_camera({.eye = {50, 50, 200}, .target = {50, 50, 400}, .up = {0, 1, 0}}, 80, 60).value();
  const auto any = tessera::make_camera({.eye = {0, 0, 5}, .target = {0, 10, 0}}, 80, 60).value();
  const std::pair<tessera::terrain_mesh, tessera::terrain_camera> cases[] = {
      {tessera::prepare_terrain_mesh(tessera::tri_mesh{}).value(), any}, {terrain, away}};
  for (const auto& [mesh, cam] : cases) {
    const auto proj = tessera::project_mesh(mesh, cam).value();
    REQUIRE(proj.num_visible() == 0);
    const auto field = tessera::assign_scale_field(mesh, proj).value();
    REQUIRE(field.levels == 0);
    const auto syn = tessera::synthesize_triangles(mesh, proj, field, 32, 32).value();
    REQUIRE(syn.visible == 0);
    REQUIRE(syn.warning.ok());
    tessera::image_buffer<float, 3> out(80, 60), tiled(80, 60);
    REQUIRE(tessera::render_terrain_frame(mesh, proj, field, syn, pyramid, out, {.background = {1, 0, 0, 1}}));
    REQUIRE(tessera::render_tiled_frame(mesh, proj, tex, tiled, {.background = {1, 0, 0, 1}}));
    for (index_t y = 0; y < 60; ++y)
      for (index_t x = 0; x < 80; ++x) {
        REQUIRE(out.read(x, y) == std::array<float, 3>{1, 0, 0});
        REQUIRE(tiled.read(x, y) == std::array<float, 3>{1, 0, 0});
      }
  }
}

TEST_CASE("render_terrain_frame: a field, synthesis or pyramid from elsewhere is rejected before any pixel",
          "[terrain][render]") {
  // faces culled in another projection arrive with scale 0 / level -1 / region -1: sampling them
  // would divide by a zero scale and cast NaN to an index
  frame_scene s = make_frame_scene(tessera::camera_preset::oblique, 16);
  const auto other =
      tessera::project_mesh(s.mesh,
                            tessera::make_camera({.eye = {-60, -60, 30}, .target = {-40, -40, 0}}, 160, 90).value())
          .value();
  REQUIRE(other.num_visible() < s.proj.num_visible());
  const auto other_field = tessera::assign_scale_field(s.mesh, other, {.min_scale = 0.5, .max_levels = 16}).value();
  const auto other_syn = tessera::synthesize_triangles(s.mesh, other, other_field, 48, 48).value();
  tessera::image_buffer<float, 3> out(160, 90);
  const auto field_msg = tessera::render_terrain_frame(s.mesh, s.proj, other_field, s.syn, s.pyramid, out).message();
  REQUIRE(field_msg.find("must come from this projection") != std::string::npos);
  REQUIRE(field_msg.find("level -1") != std::string::npos);
  REQUIRE(
      tessera::render_terrain_frame(s.mesh, s.proj, s.field, other_syn, s.pyramid, out).message().find("region -1") !=
      std::string::npos);
  // the synthesis and the export refuse the foreign field / synthesis too
  REQUIRE(tessera::synthesize_triangles(s.mesh, s.proj, other_field, 48, 48)
              .error()
              .message()
              .find("scale 0 and level -1") != std::string::npos);
  REQUIRE(tessera::export_corner_uvs(s.mesh, s.proj, s.field, other_syn).error().message().find("region -1") !=
          std::string::npos);
  // a pyramid that does not reach the field's smallest scale
  const auto ex =
      tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::grass, {.width = 48, .height = 48}).value();
  const auto shallow = tessera::build_exemplar_pyramid(ex, {.min_scale = 0.75, .levels = 8}).value();
  REQUIRE(tessera::render_terrain_frame(s.mesh, s.proj, s.field, s.syn, shallow, out).message().find("min_scale") !=
          std::string::npos);
  // a visible list naming a face the projection culled, or no face at all
  auto bad = s.proj;
  bad.visible.back() = static_cast<std::int32_t>(s.mesh.num_faces());
  REQUIRE(tessera::render_terrain_frame(s.mesh, bad, s.field, s.syn, s.pyramid, out)
              .message()
              .find("is not a visible face") != std::string::npos);
  REQUIRE(tessera::assign_scale_field(s.mesh, bad).error().message().find("is not a visible face") !=
          std::string::npos);
  REQUIRE(tessera::synthesize_triangles(s.mesh, bad, s.field, 48, 48).error().message().find("is not a visible face") !=
          std::string::npos);
  // a scale field with NaN scales (hand-made) is refused, and sampling at NaN never indexes with it
  auto nan_field = s.field;
  nan_field.scale[static_cast<std::size_t>(s.proj.visible[0])] = std::nanf("");
  REQUIRE_FALSE(tessera::render_terrain_frame(s.mesh, s.proj, nan_field, s.syn, s.pyramid, out));
  const auto c = s.pyramid.sample(std::nan(""), std::nan(""), 1e300);
  REQUIRE(c.size() == 3);
  const auto z = s.pyramid.sample(0.0, 0.0, 0.0);  // 0 / 0
  REQUIRE(z.size() == 3);
}
