// 66_remesh: isotropic remeshing of CAD-style output before a polycube map and a shell
// (surface/remesh_isotropic.hpp). A plate with a hole triangulated the way CAD exporters do it (each flat face
// between its boundary loops only: long thin triangles, no vertex inside a face), or mesh files given
// after the output directory, remeshed into even triangles with its sharp rims kept; the polycube
// distortion and the shell at a height of a fifth of a tile compared before and after. Writes the
// remeshed meshes as OBJ and both versions drawn with their triangles as PNG.
// Usage: example_66_remesh [OUT_DIR [MESH...]].
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <tessera/io/mesh_file.hpp>
#include <tessera/io/mesh_preview.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/build_shell.hpp>
#include <tessera/surface/polycube_distortion.hpp>
#include <tessera/surface/remesh_isotropic.hpp>

using namespace tessera;

namespace {

// A square plate (20 x 20 x 3) with a round hole (radius 4, 48 segments) as a CAD exporter writes it:
// the top and bottom fanned from the four corners to the hole (triangles of 3 degrees), each side
// one quad, the hole's wall one quad per segment.
tri_mesh cad_plate() {
  const double pi = 3.14159265358979323846, r = 4, h = 3;
  const int n = 48;
  tri_mesh m;
  auto add = [&](int count, auto&& position) {
    const index_t first = m.num_vertices();
    for (int i = 0; i < count; ++i) m.add_vertex(position(i));
    return [first, count](int i) { return first + static_cast<index_t>(((i % count) + count) % count); };
  };
  auto hole = [&](double z) {
    return add(n, [&](int k) { return vec3{r * std::cos(2 * pi * k / n), r * std::sin(2 * pi * k / n), z}; });
  };
  auto corners = [&](double z) {  // corner q at 45 + 90 q degrees
    return add(4, [&](int q) { return vec3{q == 0 || q == 3 ? 10.0 : -10.0, q < 2 ? 10.0 : -10.0, z}; });
  };
  const auto ht = hole(h), hb = hole(0);
  const auto ct = corners(h), cb = corners(0);
  for (int k = 0; k < n; ++k) {  // each hole segment fanned to the corner of its quadrant
    const int q = 4 * k / n;
    m.add_face(ct(q), ht(k + 1), ht(k));
    m.add_face(cb(q), hb(k), hb(k + 1));
  }
  for (int q = 0; q < 4; ++q) {  // between two corners, the hole vertex on the axis between them
    m.add_face(ct(q), ct(q + 1), ht((q + 1) * n / 4));
    m.add_face(cb(q + 1), cb(q), hb((q + 1) * n / 4));
    m.add_face(cb(q), cb(q + 1), ct(q + 1));  // the side, facing out
    m.add_face(cb(q), ct(q + 1), ct(q));
  }
  for (int k = 0; k < n; ++k) {  // the hole's wall, facing its axis
    m.add_face(hb(k), ht(k + 1), hb(k + 1));
    m.add_face(hb(k), ht(k), ht(k + 1));
  }
  return m;
}

// "valid, area / angle distortion a / b" or the reason it failed
std::string polycube_summary(const tri_mesh& m) {
  polycube_options o;
  o.tiles_across = 8;
  const auto map = build_polycube_map(m, o);
  if (!map) return "no polycube map: " + map.error().message();
  const auto d = polycube_distortion(*map);
  char buf[96];
  std::snprintf(buf, sizeof buf, "valid, area / angle distortion %.2f / %.2f", d.area_distortion, d.angle_distortion);
  return buf;
}

std::string shell_summary(const tri_mesh& m, double height) {
  const auto s = build_shell(m, height);
  if (!s) return "no shell: " + s.error().message();
  return "built, " + std::to_string(s->repaired_vertices) + " vertices repaired";
}

bool picture(const tri_mesh& m, const std::string& path) {
  mesh_preview_options o;
  o.width = 480, o.height = 360, o.wireframe = true;
  const auto img = render_mesh_preview(m, o);
  return img && write_png(path, *img);
}

bool run(const tri_mesh& mesh, const std::string& name, const std::string& out) {
  // [snippet:remesh_use]
  remesh_options o;
  o.edges_across = 24;   // L = the bounding box's longest side / 24 (or o.edge_length = L)
  o.feature_angle = 40;  // edges whose faces meet at 40 degrees or more are creases, kept
  const auto r = remesh_isotropic(mesh, o);
  if (!r) {
    std::printf("%s: %s\n", name.c_str(), r.error().to_string().c_str());
    return false;
  }
  // r->mesh: closed, manifold, oriented like the input; r->stats: min_angle_input, min_angle, ...
  // [/snippet]
  const remesh_stats& st = r->stats;
  std::printf("%s: %td -> %td triangles (edge %.3g), smallest angle %.2f -> %.1f degrees, %td crease edges\n",
              name.c_str(), mesh.num_faces(), r->mesh.num_faces(), st.edge_length, st.min_angle_input, st.min_angle,
              st.feature_edges);
  const double tile = st.edge_length * o.edges_across / 8;
  std::printf("  polycube at 8 tiles across: before %s\n                              after  %s\n",
              polycube_summary(mesh).c_str(), polycube_summary(r->mesh).c_str());
  std::printf("  shell at a fifth of a tile: before %s\n                              after  %s\n",
              shell_summary(mesh, tile / 5).c_str(), shell_summary(r->mesh, tile / 5).c_str());
  return write_mesh(out + "/remesh_" + name + ".obj", r->mesh).ok() &&
         picture(mesh, out + "/remesh_" + name + "_before.png") &&
         picture(r->mesh, out + "/remesh_" + name + "_after.png");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  bool ok = true;
  if (argc > 2) {
    for (int i = 2; i < argc; ++i) {
      const auto m = read_mesh(argv[i]);
      if (!m) {
        std::printf("%s\n", m.error().to_string().c_str());
        ok = false;
        continue;
      }
      std::string name = argv[i];
      name = name.substr(name.find_last_of('/') + 1);
      ok = run(*m, name.substr(0, name.find_last_of('.')), out) && ok;
    }
  } else {
    ok = run(cad_plate(), "plate", out);
  }
  std::printf("wrote %s/remesh_*.obj and _before / _after.png\n", out.c_str());
  return ok ? 0 : 1;
}
