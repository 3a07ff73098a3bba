#include <tessera/geometry/laplacian.hpp>

#include <tessera/core/mesh_view.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

namespace {
// n x n grid of squares in the XY plane with a bump in z.
tri_mesh grid(int n, double bump) {
  tri_mesh m;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) {
      const double u = double(x) / n, v = double(y) / n;
      m.add_vertex({u, v, bump * std::sin(3 * u) * std::cos(2 * v)});
    }
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const index_t a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      m.add_face(a, b, d);
      m.add_face(a, d, c);
    }
  return m;
}
}  // namespace

TEST_CASE("cotangent Laplacian: rows sum to zero, linear precision on a flat mesh", "[laplacian]") {
  const tri_mesh m = grid(6, 0.0);
  for (auto w : {laplacian_weighting::cotangent, laplacian_weighting::uniform}) {
    const auto L = laplacian_matrix(m, w);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m.num_vertices());
    REQUIRE((L * ones).cwiseAbs().maxCoeff() < 1e-12);
    REQUIRE((Eigen::MatrixXd(L) - Eigen::MatrixXd(L).transpose()).cwiseAbs().maxCoeff() < 1e-12);
  }
  const auto L = laplacian_matrix(m);
  Eigen::VectorXd f(m.num_vertices());
  for (index_t v = 0; v < m.num_vertices(); ++v)
    f(v) = 2 * m.positions[std::size_t(v)].x - 3 * m.positions[std::size_t(v)].y;
  const Eigen::VectorXd lf = L * f;
  for (int y = 1; y < 6; ++y)
    for (int x = 1; x < 6; ++x) REQUIRE(std::abs(lf(y * 7 + x)) < 1e-12);
}

TEST_CASE("Laplacian deformation: rest pose is a fixed point and fixed vertices are bit-identical", "[laplacian]") {
  const tri_mesh m = grid(8, 0.2);
  std::vector<unsigned char> fixed(m.positions.size(), 0);
  for (int x = 0; x <= 8; ++x) fixed[std::size_t(x)] = 1;
  const auto r = laplacian_deform(m, fixed, {});
  REQUIRE(r.ok());
  for (std::size_t v = 0; v < m.positions.size(); ++v) REQUIRE(norm((*r)[v] - m.positions[v]) < 1e-7);
  // pull one far vertex up with a soft constraint
  std::vector<laplacian_constraint> cs{{{80, -1, -1}, {1, 0, 0}, m.positions[80] + vec3{0, 0, 0.5}}};
  const auto d = laplacian_deform(m, fixed, cs, {.soft_weight = 10});
  REQUIRE(d.ok());
  for (int x = 0; x <= 8; ++x) REQUIRE((*d)[std::size_t(x)] == m.positions[std::size_t(x)]);  // bit-identical
  REQUIRE((*d)[80].z > m.positions[80].z + 0.3);
  REQUIRE((*d)[40].z > m.positions[40].z);  // smooth falloff
}

TEST_CASE("Laplacian deformation reproduces a translation exactly", "[laplacian]") {
  const tri_mesh m = grid(6, 0.3);
  const vec3 t{0.1, -0.2, 0.05};
  // pin a few vertices (softly) at their translated positions; the rest follow exactly
  std::vector<laplacian_constraint> cs;
  for (index_t v : {0, 6, 42, 48, 24}) cs.push_back({{v, -1, -1}, {1, 0, 0}, m.positions[std::size_t(v)] + t});
  const auto d = laplacian_deform(m, {}, cs, {.soft_weight = 1, .regularization = 0});
  REQUIRE(d.ok());
  for (std::size_t v = 0; v < m.positions.size(); ++v) REQUIRE(norm((*d)[v] - (m.positions[v] + t)) < 1e-8);
}

TEST_CASE("Laplacian deformation: barycentric soft constraints pull a point on a face", "[laplacian]") {
  const tri_mesh m = grid(6, 0.0);
  const index_t f = 30;
  laplacian_constraint c{{m.faces[f][0], m.faces[f][1], m.faces[f][2]}, {0.2, 0.3, 0.5}, {}};
  vec3 p;
  for (int k = 0; k < 3; ++k) p += m.positions[std::size_t(c.vertices[std::size_t(k)])] * c.weights[std::size_t(k)];
  c.target = p + vec3{0, 0, 0.2};
  std::vector<unsigned char> fixed(m.positions.size(), 0);
  fixed[0] = fixed[6] = fixed[42] = fixed[48] = 1;
  double prev = 1e9;
  for (double mu : {0.1, 1.0, 100.0}) {
    const auto d = laplacian_deform(m, fixed, std::span(&c, 1), {.soft_weight = mu});
    REQUIRE(d.ok());
    vec3 q;
    for (int k = 0; k < 3; ++k) q += (*d)[std::size_t(c.vertices[std::size_t(k)])] * c.weights[std::size_t(k)];
    const double err = norm(q - c.target);
    REQUIRE(err < prev);  // a larger mu fits the constraint more closely
    prev = err;
  }
  REQUIRE(prev < 0.01);
}

TEST_CASE("Laplacian deformation works on a float mesh_view", "[laplacian]") {
  const tri_mesh m = grid(4, 0.1);
  std::vector<float> pos;
  std::vector<std::uint32_t> idx;
  for (const vec3& p : m.positions) pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
  for (const auto& f : m.faces) idx.insert(idx.end(), {std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
  const auto view = make_mesh_view(pos.data(), m.num_vertices(), idx.data(), m.num_faces());
  REQUIRE(view.ok());
  std::vector<laplacian_constraint> cs{{{12, -1, -1}, {1, 0, 0}, {0.5, 0.5, 1}}};
  const auto d = laplacian_deform(*view, {}, cs);
  REQUIRE(d.ok());
  REQUIRE((*d)[12].z > 0.3);
}

TEST_CASE("Laplacian deformation rejects bad input", "[laplacian]") {
  const tri_mesh m = grid(3, 0.0);
  std::vector<unsigned char> wrong(3, 0);
  REQUIRE(laplacian_deform(m, wrong, {}).error().code() == status_code::invalid_argument);
  std::vector<laplacian_constraint> out{{{99, -1, -1}, {1, 0, 0}, {}}};
  REQUIRE(laplacian_deform(m, {}, out).error().code() == status_code::out_of_range);
  std::vector<laplacian_constraint> nan{{{1, -1, -1}, {1, 0, 0}, {std::nan(""), 0, 0}}};
  REQUIRE(laplacian_deform(m, {}, nan).error().message().find("non-finite") != std::string::npos);
  REQUIRE_FALSE(laplacian_deform(m, {}, {}, {.soft_weight = -1}).ok());
  tri_mesh bad = m;
  bad.positions[2].x = std::nan("");
  REQUIRE(laplacian_deform(bad, {}, {}).error().code() == status_code::invalid_argument);
}
