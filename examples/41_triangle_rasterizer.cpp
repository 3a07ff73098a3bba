// Example 41: the exact triangle rasterizer (render/triangle_rasterizer.hpp) on its own: a torus
// cutting through a checkered ground plane, projected with GLM, clipped against the near plane,
// depth-tested and shaded from perspective-correct barycentrics; plus an overdraw map proving that
// the triangulation covers every pixel exactly once.
//
// usage: example_41_triangle_rasterizer [output directory, default "."]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/io/png.hpp>
#include <tessera/render/triangle_rasterizer.hpp>

namespace {

using tessera::index_t;

struct vertex {
  glm::dvec3 p, n;
  double u = 0, v = 0;
};
struct mesh {
  std::vector<vertex> v;
  std::vector<std::array<std::int32_t, 3>> f;
};

mesh torus_and_ground() {
  mesh m;
  const int rings = 48, sides = 24;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      constexpr double pi = 3.14159265358979323846;
      const double a = 2 * pi * i / rings, b = 2 * pi * j / sides;
      const glm::dvec3 c(std::cos(a), std::sin(a), 0.0), n = std::cos(b) * c + glm::dvec3(0, 0, std::sin(b));
      m.v.push_back({1.2 * c + 0.45 * n + glm::dvec3(0, 0, 0.25), n, 0, 0});
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const int a = i * sides + j, b = ((i + 1) % rings) * sides + j, c = ((i + 1) % rings) * sides + (j + 1) % sides,
                d = i * sides + (j + 1) % sides;
      m.f.push_back({a, b, c});
      m.f.push_back({a, c, d});
    }
  const auto base = static_cast<std::int32_t>(m.v.size());
  for (double y : {-8.0, 8.0})
    for (double x : {-8.0, 8.0}) m.v.push_back({glm::dvec3(x, y, 0), glm::dvec3(0, 0, 1), x, y});
  m.f.push_back({base, base + 1, base + 3});
  m.f.push_back({base, base + 3, base + 2});
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  const mesh m = torus_and_ground();
  constexpr index_t w = 480, h = 320;
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0.5, -3.6, 1.6), glm::dvec3(0, 0, 0.1), glm::dvec3(0, 0, 1));
  const glm::dmat4 proj = glm::perspective(glm::radians(60.0), double(w) / h, 0.1, 50.0);
  const glm::dmat4 mvp = proj * view;
  const glm::dvec3 light = glm::normalize(glm::dvec3(0.3, -0.5, 1.0));
  tessera::thread_pool_executor pool;

  // [snippet:rasterizer_depth]
  auto buffer = tessera::depth_buffer::create(w, h);
  if (!buffer) return std::fprintf(stderr, "example 41: %s\n", buffer.error().to_string().c_str()), 1;
  auto& depth = *buffer;
  std::vector<std::int32_t> id(w * h, -1);
  std::vector<std::array<double, 3>> bary(w * h);
  auto s = tessera::rasterize_clip_triangles(
      static_cast<index_t>(m.f.size()), {0, 0, double(w), double(h)}, depth.rect(),
      [&](index_t f, tessera::clip_triangle& t) {  // a pure read: called once to bin, once per tile
        for (int k = 0; k < 3; ++k) {
          const glm::dvec4 c = mvp * glm::dvec4(m.v[m.f[f][k]].p, 1.0);
          t[k] = {c.x, c.y, c.z, c.w};
        }
        return true;  // false would skip the triangle
      },
      [&](index_t f, const tessera::fragment& frag) {      // each pixel on one thread, f ascending
        if (depth.test_and_set(frag.x, frag.y, frag.w)) {  // w: view depth, even precision
          id[frag.y * w + frag.x] = static_cast<std::int32_t>(f);
          bary[frag.y * w + frag.x] = frag.bary;  // perspective-correct corner weights
        }
      },
      {.tile_size = 32}, pool);
  // [/snippet]
  if (!s) {
    std::fprintf(stderr, "example 41: %s\n", s.to_string().c_str());
    return 1;
  }

  tessera::image_buffer<std::uint8_t, 3> image(w, h), overdraw(w, h);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      const std::int32_t f = id[y * w + x];
      std::array<double, 3> c = {0.75, 0.82, 0.92};
      if (f >= 0) {
        const auto& b = bary[y * w + x];
        glm::dvec3 n(0.0);
        double u = 0, v = 0;
        for (int k = 0; k < 3; ++k) {
          const vertex& vx = m.v[m.f[f][k]];
          n += b[k] * vx.n, u += b[k] * vx.u, v += b[k] * vx.v;
        }
        const double lambert = 0.3 + 0.7 * std::max(0.0, glm::dot(glm::normalize(n), light));
        const bool ground = f >= static_cast<std::int32_t>(m.f.size()) - 2;
        const bool dark = ground && ((static_cast<int>(std::floor(u * 2)) + static_cast<int>(std::floor(v * 2))) & 1);
        const std::array<double, 3> albedo =
            ground ? (dark ? std::array<double, 3>{0.35, 0.38, 0.4} : std::array<double, 3>{0.85, 0.85, 0.8})
                   : std::array<double, 3>{0.85, 0.45, 0.2};
        for (int k = 0; k < 3; ++k) c[k] = albedo[k] * lambert;
      }
      image.write(x, y,
                  {static_cast<std::uint8_t>(255 * c[0]), static_cast<std::uint8_t>(255 * c[1]),
                   static_cast<std::uint8_t>(255 * c[2])});
    }

  // overdraw of the torus alone seen from above: a closed surface covers each pixel exactly twice
  // (front and back), never a gap or a third time along shared edges
  const glm::dmat4 top = glm::perspective(glm::radians(50.0), double(w) / h, 0.1, 50.0) *
                         glm::lookAt(glm::dvec3(0, 0, 5), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
  std::vector<int> hits(w * h, 0);
  s = tessera::rasterize_clip_triangles(
      static_cast<index_t>(m.f.size()) - 2, {0, 0, double(w), double(h)}, {0, 0, w, h},
      [&](index_t f, tessera::clip_triangle& t) {
        for (int k = 0; k < 3; ++k) {
          const glm::dvec4 c = top * glm::dvec4(m.v[m.f[f][k]].p, 1.0);
          t[k] = {c.x, c.y, c.z, c.w};
        }
        return true;
      },
      [&](index_t, const tessera::fragment& frag) { ++hits[frag.y * w + frag.x]; }, {}, pool);
  int histogram[4] = {0, 0, 0, 0};
  for (index_t i = 0; i < w * h; ++i) {
    ++histogram[std::min(hits[i], 3)];
    const std::uint8_t g = hits[i] == 0 ? 255 : hits[i] == 2 ? 90 : 0;
    overdraw.write(i % w, i / w, {static_cast<std::uint8_t>(hits[i] == 1 || hits[i] >= 3 ? 220 : g), g, g});
  }
  const std::string a = dir + "/rasterizer_depth.png", b = dir + "/rasterizer_overdraw.png";
  if (!s || !tessera::write_png(a, image) || !tessera::write_png(b, overdraw)) {
    std::fprintf(stderr, "example 41: failed to render or write\n");
    return 1;
  }
  std::printf("wrote %s\nwrote %s\n", a.c_str(), b.c_str());
  std::printf(
      "torus from above: %d pixels covered twice, %d once (silhouette rims: none expected), %d three times or more\n",
      histogram[2], histogram[1], histogram[3]);
  return histogram[3] == 0 ? 0 : 1;
}
