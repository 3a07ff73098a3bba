// 07_eigen_mesh: libigl-style V / F matrices as a tessera Mesh. V holds one vertex per row (n x 3
// double), F one triangle per row (m x 3 int); any storage order, Maps and Refs work too. Here a
// terrain patch displaced by a procedural height field and a torus floating above it share one V/F
// pair; tessera finds the two parts, computes normals and the bounding box, and writes the V/F
// view as OBJ.
// Usage: example_07_eigen_mesh [OUTPUT_DIR]   (writes 07_eigen_mesh.obj)
#include <tessera/adapters/eigen.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/mesh_file.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

// Appends an n x n vertex grid over [0, 4]^2 displaced by `height`, and a torus above its centre.
void build(Eigen::MatrixXd& V, Eigen::MatrixXi& F, const tessera::image_buffer<float, 1>& height) {
  const int n = static_cast<int>(height.width()), ring = 32, tube = 12;
  V.resize(n * n + ring * tube, 3);
  F.resize(2 * (n - 1) * (n - 1) + 2 * ring * tube, 3);
  int f = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) V.row(y * n + x) << 4.0 * x / (n - 1), 4.0 * y / (n - 1), 0.4 * height.read(x, y)[0];
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      F.row(f++) << a, b, d;
      F.row(f++) << a, d, c;
    }
  const int base = n * n;
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * std::numbers::pi * i / ring, v = 2 * std::numbers::pi * j / tube;
      V.row(base + i * tube + j) << 2 + (1 + 0.3 * std::cos(v)) * std::cos(u),
          2 + (1 + 0.3 * std::cos(v)) * std::sin(u), 1.5 + 0.3 * std::sin(v);
      const int a = base + i * tube + j, b = base + ((i + 1) % ring) * tube + j;
      const int c = base + i * tube + (j + 1) % tube, d = base + ((i + 1) % ring) * tube + (j + 1) % tube;
      F.row(f++) << a, b, d;
      F.row(f++) << a, d, c;
    }
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  auto sand = tessera::make_exemplar<float, 1>(tessera::exemplar_kind::sand, {.width = 48, .height = 48, .seed = 3});
  if (!sand) return fail(sand.error());
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  build(V, F, *sand);

  // [snippet:eigen-mesh]
  auto mesh = tessera::make_eigen_mesh_view(V, F);  // checks the shapes (n x 3, m x 3); no copy
  if (!mesh) return fail(mesh.error());
  if (auto s = tessera::validate_mesh(*mesh, "V/F"); !s) return fail(s);  // index range, NaN, degenerate faces

  const auto parts = tessera::connected_components(*mesh);
  const auto normals = tessera::vertex_normals(*mesh);
  const auto box = tessera::bounding_box(*mesh);
  const auto adjacency = tessera::face_adjacency(*mesh);
  // [/snippet]
  std::printf("V %td x 3, F %td x 3: %td components, %td boundary edges, %td non-manifold edges\n",
              std::ptrdiff_t(V.rows()), std::ptrdiff_t(F.rows()), parts.count, adjacency.boundary_edges,
              adjacency.nonmanifold_edges);
  std::printf("bounding box (%.2f, %.2f, %.2f) - (%.2f, %.2f, %.2f); normal of vertex 0 (%.2f, %.2f, %.2f)\n",
              box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z, normals[0].x, normals[0].y,
              normals[0].z);

  // A transposed V (3 x n, a common slip) is named as such.
  const Eigen::MatrixXd Vt = V.transpose();
  std::printf("transposed V: %s\n", tessera::make_eigen_mesh_view(Vt, F).error().to_string().c_str());

  // Any Mesh can be written; the V/F view goes to OBJ as it is.
  const std::string path = dir + "/07_eigen_mesh.obj";
  if (auto s = tessera::write_mesh(path, *mesh); !s) return fail(s);
  std::printf("wrote %s\n", path.c_str());
  return 0;
}
