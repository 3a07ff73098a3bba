#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/core/random.hpp>
#include <tessera/core/tri_mesh.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::tri_mesh;

namespace {
// An n x n grid of quads split into triangles: (n+1)^2 vertices, 2 n^2 faces, 4 n boundary edges.
tri_mesh grid(index_t n, double x0 = 0) {
  tri_mesh m;
  for (index_t y = 0; y <= n; ++y)
    for (index_t x = 0; x <= n; ++x) m.add_vertex({x0 + double(x), double(y), 0});
  auto id = [&](index_t x, index_t y) { return y * (n + 1) + x; };
  for (index_t y = 0; y < n; ++y)
    for (index_t x = 0; x < n; ++x) {
      m.add_face(id(x, y), id(x + 1, y), id(x + 1, y + 1));
      m.add_face(id(x, y), id(x + 1, y + 1), id(x, y + 1));
    }
  return m;
}
tri_mesh tetrahedron() {
  tri_mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}
// Random soup over few vertices: produces shared, boundary and non-manifold edges and several components.
tri_mesh random_mesh(std::uint64_t seed, index_t nv, index_t nf) {
  tessera::counter_rng rng(seed);
  tri_mesh m;
  for (index_t v = 0; v < nv; ++v) m.add_vertex({double(v), 0, 0});
  for (index_t f = 0; f < nf; ++f) {
    index_t a, b, c;
    int tries = 0;
    do {
      a = static_cast<index_t>(rng.below(std::uint64_t(nv), f, tries, 0));
      b = static_cast<index_t>(rng.below(std::uint64_t(nv), f, tries, 1));
      c = static_cast<index_t>(rng.below(std::uint64_t(nv), f, tries, 2));
      ++tries;
    } while (a == b || b == c || a == c);
    m.add_face(a, b, c);
  }
  return m;
}
using edge_map = std::map<std::pair<index_t, index_t>, std::vector<std::array<index_t, 2>>>;
edge_map brute_edges(const tri_mesh& m) {
  edge_map e;
  for (index_t f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const index_t a = m.face_vertex(f, k), b = m.face_vertex(f, (k + 1) % 3);
      e[{std::min(a, b), std::max(a, b)}].push_back({f, k});
    }
  return e;
}
// Components by repeated relaxation (a slow but obviously correct oracle).
std::vector<index_t> brute_face_labels(const tri_mesh& m) {
  std::vector<index_t> label(static_cast<std::size_t>(m.num_faces()));
  for (std::size_t f = 0; f < label.size(); ++f) label[f] = static_cast<index_t>(f);
  for (bool changed = true; changed;) {
    changed = false;
    for (index_t f = 0; f < m.num_faces(); ++f)
      for (index_t g = 0; g < m.num_faces(); ++g) {
        bool share = false;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) share |= m.face_vertex(f, i) == m.face_vertex(g, j);
        auto& lf = label[static_cast<std::size_t>(f)];
        auto& lg = label[static_cast<std::size_t>(g)];
        if (share && lf != lg) {
          lf = lg = std::min(lf, lg);
          changed = true;
        }
      }
  }
  return label;
}
}  // namespace

TEST_CASE("mesh_topology: edges match a brute-force map", "[mesh_topology]") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const tri_mesh m = random_mesh(seed, 12, 30);
    REQUIRE(tessera::validate_mesh(m).ok());
    const auto edges = tessera::mesh_edges(m);
    const auto oracle = brute_edges(m);
    REQUIRE(edges.size() == oracle.size());
    std::size_t i = 0;
    index_t boundary = 0, nonmanifold = 0;
    for (const auto& [key, faces] : oracle) {  // std::map order = sorted by (v0, v1)
      REQUIRE(edges[i].v0 == key.first);
      REQUIRE(edges[i].v1 == key.second);
      REQUIRE(edges[i].faces == faces);
      REQUIRE(edges[i].is_boundary() == (faces.size() == 1));
      REQUIRE(edges[i].is_manifold() == (faces.size() <= 2));
      boundary += faces.size() == 1;
      nonmanifold += faces.size() > 2;
      ++i;
    }
    const auto adj = tessera::face_adjacency(m);
    REQUIRE(adj.boundary_edges == boundary);
    REQUIRE(adj.nonmanifold_edges == nonmanifold);
    REQUIRE(tessera::count_nonmanifold_edges(m) == nonmanifold);
    REQUIRE(static_cast<index_t>(tessera::boundary_edges(m).size()) == boundary);
    // neighbours: exactly the other face of a two-face edge, -1 otherwise
    for (index_t f = 0; f < m.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) {
        const index_t a = m.face_vertex(f, k), b = m.face_vertex(f, (k + 1) % 3);
        const auto& uses = oracle.at({std::min(a, b), std::max(a, b)});
        index_t expected = -1;
        if (uses.size() == 2) expected = uses[0][0] == f && uses[0][1] == k ? uses[1][0] : uses[0][0];
        REQUIRE(adj.neighbor[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)] == expected);
      }
  }
}

TEST_CASE("mesh_topology: closed, open and non-manifold surfaces", "[mesh_topology]") {
  const tri_mesh t = tetrahedron();
  auto adj = tessera::face_adjacency(t);
  REQUIRE(adj.boundary_edges == 0);
  REQUIRE(adj.nonmanifold_edges == 0);
  REQUIRE(tessera::mesh_edges(t).size() == 6);
  for (const auto& n : adj.neighbor)
    for (index_t g : n) REQUIRE(g >= 0);

  const tri_mesh g = grid(4);
  adj = tessera::face_adjacency(g);
  REQUIRE(adj.boundary_edges == 16);
  const auto b = tessera::boundary_edges(g);
  REQUIRE(b.size() == 16);
  // boundary edges keep their face's orientation: a counter-clockwise grid walks its border counter-clockwise
  for (const auto& e : b) {
    const auto p = g.positions[static_cast<std::size_t>(e[0])], q = g.positions[static_cast<std::size_t>(e[1])];
    const tessera::vec3 mid = (p + q) * 0.5, dir = q - p, centre{2, 2, 0};
    REQUIRE(tessera::cross(dir, centre - mid).z > 0);  // interior lies to the left
  }

  // three triangles around one edge (0, 1)
  tri_mesh fin;
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  REQUIRE(tessera::count_nonmanifold_edges(fin) == 1);
  adj = tessera::face_adjacency(fin);
  REQUIRE(adj.nonmanifold_edges == 1);
  REQUIRE(adj.neighbor[0][0] == -1);  // no single neighbour across a non-manifold edge
  REQUIRE(adj.boundary_edges == 6);
}

TEST_CASE("mesh_topology: connected components", "[mesh_topology]") {
  tri_mesh m = grid(2);
  m.append(tetrahedron(), {10, 0, 0});
  m.add_vertex({50, 50, 50});  // isolated vertex
  m.append(grid(1), {20, 0, 0});
  const auto c = tessera::connected_components(m);
  REQUIRE(c.count == 3);
  REQUIRE(c.face_component[0] == 0);
  REQUIRE(c.face_component[8] == 1);   // first tetrahedron face
  REQUIRE(c.face_component[12] == 2);  // the last grid
  REQUIRE(c.vertex_component[9 + 4] == -1);
  REQUIRE(c.vertex_component[0] == 0);

  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const tri_mesh r = random_mesh(seed, 40, 15);
    const auto cc = tessera::connected_components(r);
    const auto oracle = brute_face_labels(r);
    // same partition, and ids numbered by first face
    std::map<index_t, index_t> to_id;
    for (std::size_t f = 0; f < oracle.size(); ++f) {
      auto [it, fresh] = to_id.emplace(oracle[f], static_cast<index_t>(to_id.size()));
      REQUIRE(cc.face_component[f] == it->second);
    }
    REQUIRE(cc.count == static_cast<index_t>(to_id.size()));
    for (index_t f = 0; f < r.num_faces(); ++f)
      for (int k = 0; k < 3; ++k)
        REQUIRE(cc.vertex_component[static_cast<std::size_t>(r.face_vertex(f, k))] ==
                cc.face_component[static_cast<std::size_t>(f)]);
  }
}

TEST_CASE("mesh_topology: works on any Mesh type", "[mesh_topology]") {
  const std::vector<float> vb = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const std::vector<std::uint32_t> ib = {0, 1, 2, 2, 1, 3};
  const auto v = *tessera::make_mesh_view(vb.data(), 4, ib.data(), 2);
  const auto adj = tessera::face_adjacency(v);
  REQUIRE(adj.neighbor[0][1] == 1);
  REQUIRE(adj.neighbor[1][0] == 0);
  REQUIRE(adj.boundary_edges == 4);
  REQUIRE(tessera::connected_components(v).count == 1);
  const tri_mesh empty;
  REQUIRE(tessera::mesh_edges(empty).empty());
  REQUIRE(tessera::connected_components(empty).count == 0);
}

TEST_CASE("mesh_topology: faces naming vertices out of range are ignored, never indexed",
          "[mesh_topology][bad_input]") {
  // The tetrahedron plus three bad faces: a negative index, one past the end, a huge one. Under
  // ASan any read or write through those indices would fail this test.
  tri_mesh m = tetrahedron();
  m.faces.push_back({0, 1, -1});
  m.faces.push_back({4, 1, 2});
  m.faces.push_back({0, 1000000, 2});
  REQUIRE_FALSE(tessera::validate_mesh(m).ok());

  const auto adj = tessera::face_adjacency(m);
  REQUIRE(adj.neighbor.size() == 7);
  CHECK(adj.boundary_edges == 0);  // the four good faces still close up
  CHECK(adj.nonmanifold_edges == 0);
  for (std::size_t f = 4; f < 7; ++f) CHECK(adj.neighbor[f] == std::array<index_t, 3>{-1, -1, -1});
  CHECK(tessera::mesh_edges(m).size() == 6);
  CHECK(tessera::boundary_edges(m).empty());
  CHECK(tessera::count_nonmanifold_edges(m) == 0);
  const auto c = tessera::connected_components(m);
  CHECK(c.count == 1);
  CHECK(c.face_component == std::vector<index_t>{0, 0, 0, 0, -1, -1, -1});
  CHECK(tessera::face_normals(m)[5] == tessera::vec3{});
  CHECK(tessera::vertex_normals(m).size() == 4);
}
