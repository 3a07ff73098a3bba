// 60_polycube: polycube maps (surface/build_polycube_map.hpp, paper 000 §4) of procedural closed meshes
// (a sphere, a torus, a genus-2 block) or of mesh files given after the output directory, with
// pictures: the base mesh coloured by chart label, its polycube with the tile grid at two tile sizes,
// and an angle-distortion heat map. Usage: example_60_polycube [OUT_DIR [MESH...]].
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <tessera/core/image_buffer.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/png.hpp>
#include <tessera/render/triangle_rasterizer.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_distortion.hpp>
#include <tessera/surface/polycube_projection.hpp>

using namespace tessera;

namespace {

using rgb = std::array<float, 3>;

// Orthographic, Lambert-shaded picture of `m` with a colour per face; when grid > 0, pixels near the
// tile grid of each face's chart plane (every `grid` units) are drawn dark.
image_buffer<std::uint8_t, 3> picture(const tri_mesh& m, const std::vector<rgb>& color, const polycube_map* pc,
                                      double grid, index_t size = 480) {
  const double az = -0.9, el = 0.55;
  const vec3 f = normalized(vec3{std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), -std::sin(el)});
  const vec3 r = normalized(cross(f, vec3{0, 0, 1})), u = cross(r, f);
  aabb box;
  for (const vec3& p : m.positions) box.extend(vec3{dot(p, r), dot(p, u), dot(p, f)});
  const vec3 e = box.extent();
  const double s = 0.92 * static_cast<double>(size) / std::max(e.x, e.y);
  image_buffer<std::uint8_t, 3> img(size, size, {255, 255, 255});
  std::vector<double> depth(static_cast<std::size_t>(size * size), 1e300);
  const vec3 light = normalized(vec3{-0.3, -0.6, 1.0} - f);
  for (std::size_t fi = 0; fi < m.faces.size(); ++fi) {
    raster_triangle t;
    std::array<vec3, 3> p;
    for (int k = 0; k < 3; ++k) {
      p[static_cast<std::size_t>(k)] = m.position(m.faces[fi][static_cast<std::size_t>(k)]);
      const vec3& q = p[static_cast<std::size_t>(k)];
      t[static_cast<std::size_t>(k)] = {static_cast<double>(size) / 2 + (dot(q, r) - box.center().x) * s,
                                        static_cast<double>(size) / 2 - (dot(q, u) - box.center().y) * s, dot(q, f), 1};
    }
    const vec3 n = normalized(cross(p[1] - p[0], p[2] - p[0]));
    if (dot(n, f) > 0) continue;  // back face
    const float shade = static_cast<float>(0.35 + 0.65 * std::max(0.0, dot(n, light)));
    (void)rasterize_triangle(t, {0, 0, size, size}, [&](const fragment& fr) {
      auto& d = depth[static_cast<std::size_t>(fr.y * size + fr.x)];
      if (fr.depth >= d) return;
      d = fr.depth;
      rgb c = color[fi];
      if (pc != nullptr && grid > 0) {
        const vec3 q = fr.bary[0] * p[0] + fr.bary[1] * p[1] + fr.bary[2] * p[2];
        const int a = label_axis(pc->labels[fi]);
        for (int b = 0; b < 3; ++b) {
          if (b == a) continue;
          const double x = q[b] / grid, dist = std::abs(x - std::round(x)) * grid * s;
          if (dist < 0.9) c = {0.1f, 0.1f, 0.1f};
        }
      }
      std::uint8_t* px = img.pixel_ptr(fr.x, fr.y);
      for (int k = 0; k < 3; ++k)
        px[k] = static_cast<std::uint8_t>(std::clamp(c[static_cast<std::size_t>(k)] * shade, 0.0f, 1.0f) * 255);
    });
  }
  return img;
}

bool run(const tri_mesh& mesh, const std::string& name, const std::string& out) {
  std::vector<rgb> by_label, heat;
  bool ok = true, first = true;
  for (index_t n : {8, 16}) {
    // [snippet:polycube_use]
    polycube_options o;
    o.tiles_across = n;                      // or o.tile_size (mesh units)
    auto map = build_polycube_map(mesh, o);  // any Mesh; on failure a status naming the chart, face or corner
    if (!map) {
      std::printf("%s, %lld tiles across: %s\n", name.c_str(), static_cast<long long>(n),
                  map.error().to_string().c_str());
      ok = false;
      continue;
    }
    const polycube_projector pj(*map);
    auto fwd = pj.forward(0, {0.2, 0.3, 0.5});          // base point -> polycube position, quad, (u, v)
    auto back = pj.inverse(fwd->quad, fwd->u, fwd->v);  // quad point -> base face, barycentrics, position
    const auto d = polycube_distortion(*map);           // d.area_distortion, d.angle_distortion
    // [/snippet]
    if (!back || distance(back->position, map->base.position(map->base.faces[0][0]) * 0.2 +
                                              map->base.position(map->base.faces[0][1]) * 0.3 +
                                              map->base.position(map->base.faces[0][2]) * 0.5) > 1e-9)
      ok = false;
    by_label.clear();
    for (auto l : map->labels) by_label.push_back(polycube_label_color(l));
    std::printf("%s, %lld tiles across: %zu charts, %zu corners, %zu quads, area distortion %.3f, angle %.3f\n",
                name.c_str(), static_cast<long long>(n), map->charts.size(), map->corners.size(),
                map->layout.quads.size(), d.area_distortion, d.angle_distortion);
    ok = write_png(out + "/" + name + "_polycube_" + std::to_string(n) + ".png",
                   picture(map->deformed_mesh(), by_label, &*map, map->tile_size))
             .ok() &&
         ok;
    if (first) {
      first = false;
      ok = write_png(out + "/" + name + "_charts.png", picture(map->base, by_label, nullptr, 0)).ok() && ok;
      heat.clear();
      for (double a : d.angle) {
        const auto k = static_cast<float>(std::clamp((a - 1) / 1.5, 0.0, 1.0));
        heat.push_back({0.95f, 0.95f - 0.75f * k, 0.95f - 0.85f * k});
      }
      ok = write_png(out + "/" + name + "_angle_distortion.png", picture(map->base, heat, nullptr, 0)).ok() && ok;
    }
  }
  return ok;
}

tri_mesh sphere(int n) {  // a cube's faces cut into n x n squares, pushed onto the unit sphere
  tri_mesh m;
  for (int a = 0; a < 3; ++a)
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      const int u = sgn > 0 ? (a + 1) % 3 : (a + 2) % 3, w = sgn > 0 ? (a + 2) % 3 : (a + 1) % 3;
      const index_t base = m.num_vertices();
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          vec3 p;
          p[a] = sgn, p[u] = -1 + 2.0 * i / n, p[w] = -1 + 2.0 * j / n;
          m.add_vertex(normalized(p));
        }
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const index_t v = base + j * (n + 1) + i;
          m.add_face(v, v + 1, v + n + 2);
          m.add_face(v, v + n + 2, v + n + 1);
        }
    }
  // weld the duplicated cube-edge vertices
  std::vector<index_t> id(m.positions.size());
  tri_mesh w;
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    id[v] = -1;
    for (index_t k = 0; k < w.num_vertices(); ++k)
      if (distance(w.position(k), m.positions[v]) < 1e-9) id[v] = k;
    if (id[v] < 0) id[v] = w.add_vertex(m.positions[v]);
  }
  for (const auto& f : m.faces)
    w.add_face(id[static_cast<std::size_t>(f[0])], id[static_cast<std::size_t>(f[1])],
               id[static_cast<std::size_t>(f[2])]);
  return w;
}

tri_mesh torus(double R, double r, int nu, int nv) {
  tri_mesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double a = 2 * pi * i / nu, b = 2 * pi * j / nv;
      m.add_vertex({(R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b)});
    }
  auto at = [&](int i, int j) { return static_cast<index_t>(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  bool ok = true;
  if (argc > 2) {
    for (int i = 2; i < argc; ++i) {
      auto m = read_mesh(argv[i]);
      if (!m) {
        std::printf("%s\n", m.error().to_string().c_str());
        continue;
      }
      std::string name = argv[i];
      name = name.substr(name.find_last_of('/') + 1);
      name = name.substr(0, name.find('.'));
      run(*m, name, out);  // a mesh the construction cannot handle is reported, not fatal
    }
    return 0;
  }
  ok = run(sphere(10), "sphere", out) && ok;
  ok = run(torus(2, 0.8, 48, 16), "torus", out) && ok;
  return ok ? 0 : 1;
}
