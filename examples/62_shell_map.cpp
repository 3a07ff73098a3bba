// 62_shell_map: geometric tiles on a surface (surface/map_tiles_to_shell.hpp, paper 000 §4): a procedural
// ring per quad of a sphere's polycube map, and rings centred on every quad side of a torus's map (each
// cut into two halves that the mapping welds back together, also around polycube edges). Writes the
// meshes as OBJ and shaded pictures as PNG. Usage: example_62_shell_map [OUT_DIR].
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/build_shell.hpp>
#include <tessera/surface/map_tiles_to_shell.hpp>

using namespace tessera;

namespace {

const double pi = 3.14159265358979323846;

// A ring swept over the angles [t0, t1] (a closed ring when the range is 2π): `place(angle, radius)`
// gives the quad-local (u, v) of a point at that angle and distance from the ring's centre; the tube's
// cross-section is a circle of radius r in the plane and rh in height around height hc.
template <class Place>
void add_ring(tri_mesh& m, double t0, double t1, bool closed, double R, double r, double hc, double rh, Place place,
              int nt = 24, int np = 8) {
  if (!closed) nt /= 2;
  const int cols = closed ? nt : nt + 1;
  const index_t base = m.num_vertices();
  for (int i = 0; i < cols; ++i)
    for (int j = 0; j < np; ++j) {
      const double phi = 2 * pi * j / np;
      const double angle = i == cols - 1 && !closed ? t1 : t0 + (t1 - t0) * i / nt;
      const auto uv = place(angle, R + r * std::cos(phi), i == 0 || (!closed && i == cols - 1));
      m.add_vertex({uv[0], uv[1], hc + rh * std::sin(phi)});
    }
  auto at = [&](int i, int j) { return base + static_cast<index_t>((i % cols) * np + (j % np)); };
  for (int i = 0; i < (closed ? cols : cols - 1); ++i)
    for (int j = 0; j < np; ++j) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

// (u, v) of the point at parameter p along side k of a quad (corner k to k + 1), d inwards
std::array<double, 2> on_side(int k, double p, double d) {
  const double cu[5] = {0, 1, 1, 0, 0}, cv[5] = {0, 0, 1, 1, 0};
  const double dx = cu[k + 1] - cu[k], dy = cv[k + 1] - cv[k];
  return {cu[k] + p * dx - d * dy, cv[k] + p * dy + d * dx};
}

bool run(const tri_mesh& base, index_t tiles_across, bool across_sides, const std::string& name,
         const std::string& out) {
  polycube_options po;
  po.tiles_across = tiles_across;
  auto map = build_polycube_map(base, po);
  if (!map) {
    std::printf("%s: %s\n", name.c_str(), map.error().to_string().c_str());
    return false;
  }
  const double T = map->tile_size, H = 0.25 * T;
  auto sh = build_shell(map->base, H);
  if (!sh) {
    std::printf("%s: %s\n", name.c_str(), sh.error().to_string().c_str());
    return false;
  }
  const auto& quads = map->layout.quads;
  std::vector<tri_mesh> tiles(quads.size());
  for (std::size_t q = 0; q < quads.size(); ++q) {
    if (!across_sides) {
      add_ring(tiles[q], 0, 2 * pi, true, 0.28, 0.08, 0.1 * T, 0.07 * T, [](double a, double rho, bool) {
        return std::array<double, 2>{0.5 + rho * std::cos(a), 0.5 + rho * std::sin(a)};
      });
      continue;
    }
    // a ring on every quad side, owned by the lower quad id: its half inside q, and the other half in
    // the neighbour's own frame (p -> 1 - p, d -> -d across the shared side)
    for (int k = 0; k < 4; ++k) {
      const index_t n = quads[q].neighbors[static_cast<std::size_t>(k)];
      if (n < static_cast<index_t>(q)) continue;
      const int k2 = quads[q].neighbor_side[static_cast<std::size_t>(k)];
      for (int half = 0; half < 2; ++half)
        add_ring(tiles[half == 0 ? q : static_cast<std::size_t>(n)], half * pi, (half + 1) * pi, false, 0.2, 0.06,
                 0.1 * T, 0.06 * T, [&](double a, double rho, bool cut) {
                   const double p = 0.5 + rho * std::cos(a), d = cut ? 0.0 : rho * std::sin(a);
                   return half == 0 ? on_side(k, p, d) : on_side(k2, 1 - p, -d);
                 });
    }
  }
  // [snippet:shell_map_use]
  const polycube_projector pj(*map);
  thread_pool_executor pool;
  shell_map_options o;
  o.with_base = true;  // the base mesh after the elements
  auto r = map_tiles_to_shell(
      *map, pj, *sh, [&](index_t q) { return &tiles[static_cast<std::size_t>(q)]; }, o, pool);
  // [/snippet]
  if (!r) {
    std::printf("%s: %s\n", name.c_str(), r.error().to_string().c_str());
    return false;
  }
  const tri_mesh elements = r->elements();
  std::printf(
      "%s: %zu quads, H = %.3g, %lld shell repairs, %lld element vertices, %lld faces, %lld welded, "
      "%lld split edges, %lld elements, %zu open edges\n",
      name.c_str(), quads.size(), H, static_cast<long long>(sh->repaired_vertices),
      static_cast<long long>(r->element_vertices), static_cast<long long>(r->element_faces),
      static_cast<long long>(r->welded_vertices), static_cast<long long>(r->split_edges),
      static_cast<long long>(connected_components(elements).count), boundary_edges(elements).size());
  mesh_preview_options view;
  view.width = view.height = 520;
  view.azimuth_degrees = -50;
  view.elevation_degrees = 35;
  view.color = {0.85f, 0.68f, 0.35f};
  bool ok = write_obj(out + "/" + name + ".obj", r->mesh).ok();
  ok = write_mesh_preview(out + "/" + name + ".png", r->mesh, view, pool).ok() && ok;
  view.width = view.height = 420;
  ok = write_mesh_preview(out + "/" + name + "_elements.png", elements, view, pool).ok() && ok;
  return ok;
}

// unit sphere from a cube with n x n squares per face
tri_mesh sphere(int n) {
  tri_mesh m;
  std::map<std::array<int, 3>, index_t> id;
  auto vert = [&](std::array<int, 3> g) {
    auto [it, fresh] = id.emplace(g, m.num_vertices());
    if (fresh) m.add_vertex(normalized(vec3{g[0] * 1.0 / n - 0.5, g[1] * 1.0 / n - 0.5, g[2] * 1.0 / n - 0.5}));
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s) {
      const int u = s == 1 ? (a + 1) % 3 : (a + 2) % 3, w = s == 1 ? (a + 2) % 3 : (a + 1) % 3;
      auto at = [&](int i, int j) {
        std::array<int, 3> g{};
        g[static_cast<std::size_t>(a)] = s == 1 ? n : 0;
        g[static_cast<std::size_t>(u)] = i;
        g[static_cast<std::size_t>(w)] = j;
        return vert(g);
      };
      for (int c = 0; c < n * n; ++c) {  // square (i, j) = (c / n, c % n) as two triangles
        const std::array<index_t, 4> q{at(c / n, c % n), at(c / n + 1, c % n), at(c / n + 1, c % n + 1),
                                       at(c / n, c % n + 1)};
        m.add_face(q[0], q[1], q[2]);
        m.add_face(q[0], q[2], q[3]);
      }
    }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  bool ok = run(sphere(24), 8, false, "shell_sphere_rings", out);
  tri_mesh torus;  // a ring swept in 3D is a torus: radii 2 and 0.8, 96 x 32 vertices
  add_ring(
      torus, 0, 2 * pi, true, 2, 0.8, 0, 0.8,
      [](double a, double rho, bool) {
        return std::array<double, 2>{rho * std::cos(a), rho * std::sin(a)};
      },
      96, 32);
  ok = run(torus, 10, true, "shell_torus_rings_across", out) && ok;
  std::printf("wrote %s/shell_*.obj and .png\n", out.c_str());
  return ok ? 0 : 1;
}
