#include <tessera/render/triangle_rasterizer.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <tessera/core/random.hpp>

using tessera::clip_triangle;
using tessera::fragment;
using tessera::index_t;
using tessera::pixel_rect;
using tessera::raster_triangle;
using tessera::raster_vertex;

namespace {

// Brute-force oracle with the same snapping and fill rule, evaluated independently at every pixel
// centre (no spans, no incremental stepping, no orientation swap).
bool oracle_covers(const raster_triangle& t, index_t px, index_t py) {
  std::int64_t x[3], y[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = static_cast<std::int64_t>(std::floor(t[static_cast<std::size_t>(k)].x * 256 + 0.5));
    y[k] = static_cast<std::int64_t>(std::floor(t[static_cast<std::size_t>(k)].y * 256 + 0.5));
  }
  const std::int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (area == 0) return false;
  const std::int64_t cx = px * 256 + 128, cy = py * 256 + 128;
  for (int k = 0; k < 3; ++k) {
    int a = (k + 1) % 3, b = (k + 2) % 3;
    if (area < 0) std::swap(a, b);  // walk the edges so that the interior is on the positive side
    const std::int64_t dx = x[b] - x[a], dy = y[b] - y[a];
    const std::int64_t e = dx * (cy - y[a]) - dy * (cx - x[a]);
    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
    if (e < 0 || (e == 0 && !top_left)) return false;
  }
  return true;
}

// A W x H rectangle (pixel-edge aligned outer border) split into jittered triangles; interior
// vertices are often placed exactly on pixel centres or pixel edges, and vertex order is random.
std::vector<raster_triangle> jittered_grid(int cells_x, int cells_y, double cell, std::uint64_t seed) {
  const tessera::counter_rng rng(seed);
  std::vector<std::array<double, 2>> v;
  for (int j = 0; j <= cells_y; ++j)
    for (int i = 0; i <= cells_x; ++i) {
      double x = i * cell, y = j * cell;
      if (i > 0 && i < cells_x && j > 0 && j < cells_y) {
        const auto mode = rng.below(3, i, j);
        x += (rng.uniform(i, j, 1) - 0.5) * cell * 0.6;
        y += (rng.uniform(i, j, 2) - 0.5) * cell * 0.6;
        if (mode == 0) x = std::floor(x) + 0.5, y = std::floor(y) + 0.5;  // on a pixel centre
        if (mode == 1) x = std::floor(x), y = std::floor(y) + 0.5;        // vertical edges through centres
      }
      v.push_back({x, y});
    }
  auto at = [&](int i, int j) { return v[static_cast<std::size_t>(j * (cells_x + 1) + i)]; };
  std::vector<raster_triangle> tris;
  for (int j = 0; j < cells_y; ++j)
    for (int i = 0; i < cells_x; ++i) {
      const auto a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      std::array<std::array<std::array<double, 2>, 3>, 2> q;
      if (rng.below(2, i, j, 7) == 0)
        q = {{{a, b, c}, {a, c, d}}};
      else
        q = {{{a, b, d}, {b, c, d}}};
      for (auto& t : q) {
        if (rng.below(2, i, j, 9) == 0) std::swap(t[1], t[2]);
        tris.push_back(
            {raster_vertex{t[0][0], t[0][1]}, raster_vertex{t[1][0], t[1][1]}, raster_vertex{t[2][0], t[2][1]}});
      }
    }
  return tris;
}

raster_triangle random_triangle(const tessera::counter_rng& rng, int i, double lo, double hi) {
  raster_triangle t;
  for (int k = 0; k < 3; ++k) {
    double x = lo + (hi - lo) * rng.uniform(i, k, 0), y = lo + (hi - lo) * rng.uniform(i, k, 1);
    if (rng.below(4, i, k, 2) == 0) x = std::floor(x) + 0.5;  // some vertices exactly on centres
    t[static_cast<std::size_t>(k)] = {x, y, rng.uniform(i, k, 3), 0.5 + rng.uniform(i, k, 4)};
  }
  return t;
}

}  // namespace

TEST_CASE("rasterizer: a jittered triangulation covers every pixel exactly once", "[rasterizer]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const int cx = 12, cy = 9;
    const double cell = 5;
    const auto tris = jittered_grid(cx, cy, cell, seed);
    const pixel_rect clip{0, 0, 70, 50};
    std::vector<int> hits(static_cast<std::size_t>(clip.width() * clip.height()), 0);
    for (const auto& t : tris)
      REQUIRE(tessera::rasterize_triangle(
          t, clip, [&](const fragment& f) { ++hits[static_cast<std::size_t>(f.y * 70 + f.x)]; }));
    for (index_t y = 0; y < clip.y1; ++y)
      for (index_t x = 0; x < clip.x1; ++x) {
        const bool inside = x < cx * cell && y < cy * cell;
        INFO("pixel " << x << ", " << y << " seed " << seed);
        REQUIRE(hits[static_cast<std::size_t>(y * 70 + x)] == (inside ? 1 : 0));
      }
  }
}

TEST_CASE("rasterizer: coverage equals a brute-force per-pixel oracle", "[rasterizer]") {
  const tessera::counter_rng rng(7);
  const pixel_rect clip{3, 2, 61, 47};
  for (int i = 0; i < 300; ++i) {
    // small, large and partly outside triangles
    const double lo = i % 3 == 0 ? -40.0 : 0.0, hi = i % 3 == 0 ? 110.0 : i % 3 == 1 ? 64.0 : 20.0;
    const raster_triangle t = random_triangle(rng, i, lo, hi);
    std::vector<std::uint8_t> got(64 * 64, 0);
    REQUIRE(tessera::rasterize_triangle(t, clip, [&](const fragment& f) {
      REQUIRE(f.x >= clip.x0);
      REQUIRE(f.x < clip.x1);
      REQUIRE(f.y >= clip.y0);
      REQUIRE(f.y < clip.y1);
      ++got[static_cast<std::size_t>(f.y * 64 + f.x)];
    }));
    for (index_t y = 0; y < 64; ++y)
      for (index_t x = 0; x < 64; ++x) {
        const bool in_clip = x >= clip.x0 && x < clip.x1 && y >= clip.y0 && y < clip.y1;
        INFO("triangle " << i << " pixel " << x << ", " << y);
        REQUIRE(got[static_cast<std::size_t>(y * 64 + x)] == (in_clip && oracle_covers(t, x, y) ? 1 : 0));
      }
  }
}

TEST_CASE("rasterizer: vertex order changes neither coverage nor corner weights", "[rasterizer]") {
  const tessera::counter_rng rng(11);
  const pixel_rect clip{0, 0, 40, 40};
  for (int i = 0; i < 40; ++i) {
    const raster_triangle t = random_triangle(rng, i, 0, 40);
    std::map<std::pair<index_t, index_t>, fragment> ref;
    (void)tessera::rasterize_triangle(t, clip, [&](const fragment& f) { ref[{f.x, f.y}] = f; });
    std::array<int, 3> perm = {0, 1, 2};
    do {
      const raster_triangle p = {t[static_cast<std::size_t>(perm[0])], t[static_cast<std::size_t>(perm[1])],
                                 t[static_cast<std::size_t>(perm[2])]};
      std::size_t n = 0;
      (void)tessera::rasterize_triangle(p, clip, [&](const fragment& f) {
        ++n;
        auto it = ref.find({f.x, f.y});
        REQUIRE(it != ref.end());
        for (int k = 0; k < 3; ++k)
          REQUIRE(f.bary[static_cast<std::size_t>(k)] ==
                  Approx(it->second.bary[static_cast<std::size_t>(perm[static_cast<std::size_t>(k)])]).margin(1e-12));
        REQUIRE(f.depth == Approx(it->second.depth).margin(1e-12));
      });
      REQUIRE(n == ref.size());
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
}

TEST_CASE("rasterizer: screen-linear weights reproduce the pixel centre and depth", "[rasterizer]") {
  // vertices on the 1/256 grid, so snapping is exact
  const raster_triangle t = {raster_vertex{1.25, 2.5, 0.0}, raster_vertex{37.75, 9.0, 1.0},
                             raster_vertex{12.5, 30.125, 0.5}};
  std::size_t n = 0;
  REQUIRE(tessera::rasterize_triangle(t, {0, 0, 40, 40}, [&](const fragment& f) {
    ++n;
    double x = 0, y = 0, z = 0, s = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      REQUIRE(f.bary[k] >= -1e-12);
      x += f.bary[k] * t[k].x, y += f.bary[k] * t[k].y, z += f.bary[k] * t[k].z, s += f.bary[k];
    }
    REQUIRE(s == Approx(1).margin(1e-12));
    REQUIRE(x == Approx(static_cast<double>(f.x) + 0.5).margin(1e-9));
    REQUIRE(y == Approx(static_cast<double>(f.y) + 0.5).margin(1e-9));
    REQUIRE(f.depth == Approx(z).margin(1e-12));
    REQUIRE(f.w == Approx(1).margin(1e-12));
  }));
  // area ~ 0.5 * |cross| = 466 pixels
  REQUIRE(n > 440);
  REQUIRE(n < 490);
}

namespace {
struct camera_fixture {
  glm::dmat4 view = glm::lookAt(glm::dvec3(0.3, 1.0, 0.2), glm::dvec3(0.1, 0.0, -5.0), glm::dvec3(0, 1, 0));
  glm::dmat4 proj = glm::perspective(glm::radians(70.0), 64.0 / 48.0, 0.5, 100.0);
  tessera::raster_viewport vp{0, 0, 64, 48};
  clip_triangle to_clip(const std::array<glm::dvec3, 3>& w) const {
    clip_triangle c;
    for (std::size_t k = 0; k < 3; ++k) {
      const glm::dvec4 p = proj * view * glm::dvec4(w[k], 1.0);
      c[k] = {p.x, p.y, p.z, p.w};
    }
    return c;
  }
  // ray through the pixel centre intersected with the triangle's plane: weights and view depth
  bool ray_cast(const std::array<glm::dvec3, 3>& w, index_t px, index_t py, std::array<double, 3>& bary,
                double& depth) const {
    const double nx = (static_cast<double>(px) + 0.5) / vp.width * 2 - 1,
                 ny = 1 - (static_cast<double>(py) + 0.5) / vp.height * 2;
    const glm::dmat4 inv = glm::inverse(proj * view);
    glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
    const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::normalize(glm::dvec3(b) / b.w - o);
    const glm::dvec3 e1 = w[1] - w[0], e2 = w[2] - w[0], p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) return false;
    const glm::dvec3 s = o - w[0];
    const double u = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
    bary = {1 - u - v, u, v};
    const glm::dvec3 hit = o + t * d;
    depth = -(view * glm::dvec4(hit, 1.0)).z;
    return true;
  }
};
}  // namespace

TEST_CASE("rasterizer: clip-space input gives perspective-correct weights", "[rasterizer]") {
  const camera_fixture cam;
  const std::array<glm::dvec3, 3> w = {glm::dvec3(-3, -0.5, -4), glm::dvec3(2.5, -0.8, -9), glm::dvec3(-0.5, 1.2, -25)};
  std::size_t n = 0;
  REQUIRE(tessera::rasterize_clip_triangle(cam.to_clip(w), cam.vp, {0, 0, 64, 48}, [&](const fragment& f) {
    ++n;
    std::array<double, 3> b;
    double depth = 0;
    REQUIRE(cam.ray_cast(w, f.x, f.y, b, depth));
    for (std::size_t k = 0; k < 3; ++k) REQUIRE(f.bary[k] == Approx(b[k]).margin(2e-3));
    REQUIRE(f.w == Approx(depth).epsilon(2e-3));
    REQUIRE(f.depth >= 0);
    REQUIRE(f.depth <= 1);
  }));
  REQUIRE(n > 100);
}

TEST_CASE("rasterizer: triangles crossing the near plane are clipped, not mirrored", "[rasterizer]") {
  const camera_fixture cam;
  // a ground triangle that passes under and behind the eye
  const std::array<glm::dvec3, 3> w = {glm::dvec3(-6, -0.6, 3), glm::dvec3(6, -0.6, 3), glm::dvec3(0.5, -0.2, -30)};
  std::vector<int> hits(64 * 48, 0);
  REQUIRE(tessera::rasterize_clip_triangle(cam.to_clip(w), cam.vp, {0, 0, 64, 48}, [&](const fragment& f) {
    ++hits[static_cast<std::size_t>(f.y * 64 + f.x)];
    std::array<double, 3> b;
    double depth = 0;
    REQUIRE(cam.ray_cast(w, f.x, f.y, b, depth));
    for (std::size_t k = 0; k < 3; ++k) {
      REQUIRE(b[k] >= -2e-2);
      REQUIRE(f.bary[k] == Approx(b[k]).margin(2e-3));
    }
    REQUIRE(depth >= 0.5 * (1 - 1e-6));
  }));
  int covered = 0;
  for (index_t y = 0; y < 48; ++y)
    for (index_t x = 0; x < 64; ++x) {
      std::array<double, 3> b;
      double depth = 0;
      const bool solid =
          cam.ray_cast(w, x, y, b, depth) && std::min({b[0], b[1], b[2]}) > 1e-2 && depth > 0.5 * 1.01 && depth < 99;
      if (solid) REQUIRE(hits[static_cast<std::size_t>(y * 64 + x)] == 1);
      REQUIRE(hits[static_cast<std::size_t>(y * 64 + x)] <= 1);
      covered += hits[static_cast<std::size_t>(y * 64 + x)];
    }
  REQUIRE(covered > 200);
  // entirely behind the eye: nothing
  const std::array<glm::dvec3, 3> behind = {glm::dvec3(-1, 0, 5), glm::dvec3(1, 0, 5), glm::dvec3(0, 1, 4)};
  std::size_t n = 0;
  REQUIRE(tessera::rasterize_clip_triangle(cam.to_clip(behind), cam.vp, {0, 0, 64, 48}, [&](const fragment&) { ++n; }));
  REQUIRE(n == 0);
}

TEST_CASE("rasterizer: zero-to-one clip depth maps the near plane to 0", "[rasterizer]") {
  // w = 2, z = 0 is the near plane in the 0..1 convention and the middle of the range in OpenGL's
  const clip_triangle t = {tessera::clip_vertex{-2, -2, 0, 2}, tessera::clip_vertex{2, -2, 0, 2},
                           tessera::clip_vertex{0, 2, 0, 2}};
  double d_zo = -1, d_gl = -1;
  REQUIRE(tessera::rasterize_clip_triangle(t, {0, 0, 8, 8, tessera::clip_depth::zero_to_one}, {0, 0, 8, 8},
                                           [&](const fragment& f) { d_zo = f.depth; }));
  REQUIRE(tessera::rasterize_clip_triangle(t, {0, 0, 8, 8}, {0, 0, 8, 8}, [&](const fragment& f) { d_gl = f.depth; }));
  REQUIRE(d_zo == Approx(0).margin(1e-12));
  REQUIRE(d_gl == Approx(0.5).margin(1e-12));
}

TEST_CASE("rasterizer: huge coordinates are clipped to the guard band exactly", "[rasterizer]") {
  const raster_triangle t = {raster_vertex{-3e9, -1e9, 0.0}, raster_vertex{4e9, -2e9, 1.0},
                             raster_vertex{1e7, 5e9, 0.5}};
  std::vector<int> hits(32 * 32, 0);
  REQUIRE(tessera::rasterize_triangle(t, {0, 0, 32, 32}, [&](const fragment& f) {
    ++hits[static_cast<std::size_t>(f.y * 32 + f.x)];
    double x = 0, s = 0;
    for (std::size_t k = 0; k < 3; ++k) x += f.bary[k] * t[k].x, s += f.bary[k];
    REQUIRE(s == Approx(1).margin(1e-9));
    REQUIRE(x == Approx(static_cast<double>(f.x) + 0.5).margin(0.05));
  }));
  for (int h : hits) REQUIRE(h == 1);
}

TEST_CASE("rasterizer: degenerate, non-finite and culled triangles produce nothing", "[rasterizer]") {
  const pixel_rect clip{0, 0, 16, 16};
  std::size_t n = 0;
  auto count = [&](const fragment&) { ++n; };
  REQUIRE(tessera::rasterize_triangle({raster_vertex{1, 1}, raster_vertex{5, 5}, raster_vertex{9, 9}}, clip, count));
  REQUIRE(tessera::rasterize_triangle({raster_vertex{1, 1}, raster_vertex{NAN, 5}, raster_vertex{9, 2}}, clip, count));
  REQUIRE(
      tessera::rasterize_triangle({raster_vertex{1, 1, 0, 0}, raster_vertex{9, 1}, raster_vertex{1, 9}}, clip, count));
  REQUIRE(
      tessera::rasterize_triangle({raster_vertex{1, 1, 0, -1}, raster_vertex{9, 1}, raster_vertex{1, 9}}, clip, count));
  REQUIRE(n == 0);
  // (1,1) -> (9,1) -> (1,9) turns clockwise on a y-down screen
  const raster_triangle cw = {raster_vertex{1, 1}, raster_vertex{9, 1}, raster_vertex{1, 9}};
  const raster_triangle ccw = {cw[0], cw[2], cw[1]};
  REQUIRE(tessera::rasterize_triangle(cw, clip, count, tessera::face_culling::cull_clockwise));
  REQUIRE(n == 0);
  REQUIRE(tessera::rasterize_triangle(ccw, clip, count, tessera::face_culling::cull_counter_clockwise));
  REQUIRE(n == 0);
  REQUIRE(tessera::rasterize_triangle(cw, clip, count, tessera::face_culling::cull_counter_clockwise));
  const std::size_t drawn = n;
  REQUIRE(drawn > 20);
  REQUIRE(tessera::rasterize_triangle(ccw, clip, count, tessera::face_culling::cull_clockwise));
  REQUIRE(n == 2 * drawn);
}

TEST_CASE("rasterizer: bad arguments return a status naming them", "[rasterizer]") {
  auto none = [](const fragment&) {};
  const raster_triangle t = {raster_vertex{1, 1}, raster_vertex{9, 1}, raster_vertex{1, 9}};
  auto s = tessera::rasterize_triangle(t, {5, 0, 2, 8}, none);
  REQUIRE(s.code() == tessera::status_code::invalid_argument);
  REQUIRE(s.message().find("clip") != std::string::npos);
  REQUIRE_FALSE(tessera::rasterize_triangle(t, {-1, 0, 2, 8}, none));
  REQUIRE_FALSE(tessera::rasterize_triangle(t, {0, 0, index_t{1} << 20, 8}, none));
  const clip_triangle c{};
  s = tessera::rasterize_clip_triangle(c, {0, 0, 0, 8}, {0, 0, 8, 8}, none);
  REQUIRE(s.message().find("viewport") != std::string::npos);
  REQUIRE_FALSE(tessera::rasterize_clip_triangle(c, {0, 0, NAN, 8}, {0, 0, 8, 8}, none));
  auto get = [&](index_t, raster_triangle& out) {
    out = t;
    return true;
  };
  auto fn = [](index_t, const fragment&) {};
  s = tessera::rasterize_triangles(-1, {0, 0, 8, 8}, get, fn);
  REQUIRE(s.message().find("count") != std::string::npos);
  s = tessera::rasterize_triangles(1, {0, 0, 8, 8}, get, fn, {.tile_size = 3});
  REQUIRE(s.message().find("tile_size") != std::string::npos);
  REQUIRE(tessera::rasterize_triangles(0, {0, 0, 8, 8}, get, fn));
  REQUIRE_FALSE(tessera::depth_buffer::create(0, 4));
  REQUIRE_FALSE(tessera::depth_buffer::create(4, -2));
}

TEST_CASE("rasterizer: batches give identical fragments for every executor and tile size", "[rasterizer]") {
  const auto tris = [] {
    auto g = jittered_grid(20, 14, 6.3, 5);
    const tessera::counter_rng rng(3);
    for (int i = 0; i < 60; ++i) g.push_back(random_triangle(rng, i, -20, 150));  // overlapping extras
    return g;
  }();
  const pixel_rect clip{2, 3, 130, 95};
  const index_t w = clip.x1;
  using log_t = std::vector<std::vector<std::pair<index_t, std::array<double, 4>>>>;
  auto run = [&](auto&& exec, index_t tile) {
    log_t log(static_cast<std::size_t>(w * clip.y1));
    REQUIRE(tessera::rasterize_triangles(
        static_cast<index_t>(tris.size()), clip,
        [&](index_t i, raster_triangle& out) {
          out = tris[static_cast<std::size_t>(i)];
          return i % 17 != 5;  // some skipped
        },
        [&](index_t i, const fragment& f) {
          log[static_cast<std::size_t>(f.y * w + f.x)].push_back({i, {f.bary[0], f.bary[1], f.bary[2], f.depth}});
        },
        {.tile_size = tile}, exec));
    return log;
  };
  // reference: one triangle after another
  log_t ref(static_cast<std::size_t>(w * clip.y1));
  for (std::size_t i = 0; i < tris.size(); ++i)
    if (i % 17 != 5)
      (void)tessera::rasterize_triangle(tris[i], clip, [&](const fragment& f) {
        ref[static_cast<std::size_t>(f.y * w + f.x)].push_back(
            {static_cast<index_t>(i), {f.bary[0], f.bary[1], f.bary[2], f.depth}});
      });
  REQUIRE(run(tessera::serial_executor{}, 64) == ref);
  tessera::thread_pool_executor pool(3);
  REQUIRE(run(pool, 8) == ref);
  REQUIRE(run(pool, 16) == ref);
  REQUIRE(run(pool, 4096) == ref);
}

TEST_CASE("rasterizer: clip-space batches match single calls", "[rasterizer]") {
  const camera_fixture cam;
  const tessera::counter_rng rng(21);
  std::vector<clip_triangle> tris;
  for (int i = 0; i < 80; ++i) {
    std::array<glm::dvec3, 3> w;
    for (int k = 0; k < 3; ++k)
      w[static_cast<std::size_t>(k)] = {rng.uniform(i, k, 0) * 12 - 6, rng.uniform(i, k, 1) * 4 - 2,
                                        rng.uniform(i, k, 2) * -30 + 3};
    tris.push_back(cam.to_clip(w));
  }
  std::vector<std::vector<index_t>> ref(64 * 48), got(64 * 48);
  for (std::size_t i = 0; i < tris.size(); ++i)
    (void)tessera::rasterize_clip_triangle(tris[i], cam.vp, {0, 0, 64, 48}, [&](const fragment& f) {
      ref[static_cast<std::size_t>(f.y * 64 + f.x)].push_back(static_cast<index_t>(i));
    });
  tessera::thread_pool_executor pool(2);
  REQUIRE(tessera::rasterize_clip_triangles(
      static_cast<index_t>(tris.size()), cam.vp, {0, 0, 64, 48},
      [&](index_t i, clip_triangle& out) {
        out = tris[static_cast<std::size_t>(i)];
        return true;
      },
      [&](index_t i, const fragment& f) { got[static_cast<std::size_t>(f.y * 64 + f.x)].push_back(i); },
      {.tile_size = 16}, pool));
  REQUIRE(got == ref);
}

TEST_CASE("depth_buffer: the nearest fragment wins whatever the drawing order", "[rasterizer]") {
  const tessera::counter_rng rng(9);
  std::vector<raster_triangle> tris;
  for (int i = 0; i < 50; ++i) {
    auto t = random_triangle(rng, i, -5, 45);
    for (auto& v : t) v.z = rng.uniform(i, 99) * 10 + (v.x * 1e-3);  // distinct, slightly tilted planes
    tris.push_back(t);
  }
  const pixel_rect clip{0, 0, 40, 40};
  // brute force: nearest covering triangle per pixel
  std::vector<index_t> expect(1600, -1);
  std::vector<double> best(1600, 1e300);
  for (std::size_t i = 0; i < tris.size(); ++i)
    (void)tessera::rasterize_triangle(tris[i], clip, [&](const fragment& f) {
      const auto p = static_cast<std::size_t>(f.y * 40 + f.x);
      if (static_cast<float>(f.depth) < best[p])
        best[p] = static_cast<float>(f.depth), expect[p] = static_cast<index_t>(i);
    });
  for (int order = 0; order < 2; ++order) {
    auto db = tessera::depth_buffer::create(40, 40);
    REQUIRE(db);
    std::vector<index_t> id(1600, -1);
    const index_t n = static_cast<index_t>(tris.size());
    tessera::thread_pool_executor pool(2);
    REQUIRE(tessera::rasterize_triangles(
        n, db->rect(),
        [&](index_t i, raster_triangle& out) {
          out = tris[static_cast<std::size_t>(order == 0 ? i : n - 1 - i)];
          return true;
        },
        [&](index_t i, const fragment& f) {
          if (db->test_and_set(f.x, f.y, f.depth))
            id[static_cast<std::size_t>(f.y * 40 + f.x)] = order == 0 ? i : n - 1 - i;
        },
        {.tile_size = 8}, pool));
    REQUIRE(id == expect);
  }
}
