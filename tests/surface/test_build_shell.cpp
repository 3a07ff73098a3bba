#include <catch2/catch.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/surface/build_shell.hpp>

#include "shapes.hpp"

using namespace tessera;

namespace {
double min_quality(const shell& s) {
  double q = 1e300;
  for (index_t f = 0; f < s.base.num_faces(); ++f) q = std::min(q, shell_prism_quality(s, f));
  return q;
}
}  // namespace

TEST_CASE("shell: the sorted prism split is shared by neighbouring prisms and covers the prism") {
  // on a side (one β = 0) the top weights depend on that side's two vertices only
  for (double t : {0.0, 0.2, 0.5, 0.9, 1.0})
    for (double b : {0.0, 0.3, 0.7, 1.0}) {
      // side (1, 2) seen from a prism where they are sorted positions 1, 2 and from one where they are 0, 1
      const vec3 g1 = detail::prism_top_weights({0, b, 1 - b}, t);
      const vec3 g2 = detail::prism_top_weights({b, 1 - b, 0}, t);
      CHECK(g1[1] == Approx(g2[0]).margin(1e-15));
      CHECK(g1[2] == Approx(g2[1]).margin(1e-15));
      CHECK(g1[1] + g1[2] == Approx(t));
    }
  // the weights are barycentric in the tetrahedron: 0 <= γ <= β
  for (double t = 0; t <= 1; t += 0.125)
    for (const vec3 beta : {vec3{0.2, 0.3, 0.5}, vec3{0.6, 0.3, 0.1}, vec3{1, 0, 0}}) {
      const vec3 g = detail::prism_top_weights(beta, t);
      for (int k = 0; k < 3; ++k) {
        CHECK(g[k] >= 0);
        CHECK(g[k] <= beta[k] + 1e-15);
      }
      CHECK(g[0] + g[1] + g[2] == Approx(t));
    }
}

TEST_CASE("shell: a sphere's shell needs no repair, the shell map is exact at the corners") {
  const auto m = shapes::sphere(8);
  auto s = build_shell(m, 0.3);
  REQUIRE(s);
  CHECK(s->repaired_vertices == 0);
  CHECK(s->repair_rounds == 0);
  CHECK(min_quality(*s) > 0.5);
  for (index_t v = 0; v < m.num_vertices(); ++v) {
    CHECK(norm(s->directions[static_cast<std::size_t>(v)]) == Approx(1));
    CHECK(dot(s->directions[static_cast<std::size_t>(v)], normalized(m.position(v))) > 0.99);
  }
  const auto& f = m.faces[5];
  CHECK(distance(shell_position(*s, 5, {1, 0, 0}, 1), s->top(f[0])) < 1e-15);
  CHECK(distance(shell_position(*s, 5, {0, 0, 1}, 0.5),
                 m.position(f[2]) + 0.15 * s->directions[static_cast<std::size_t>(f[2])]) < 1e-15);
  const vec3 c = (m.position(f[0]) + m.position(f[1]) + m.position(f[2])) / 3;
  CHECK(distance(shell_position(*s, 5, {1.0 / 3, 1.0 / 3, 1.0 / 3}, 0), c) < 1e-15);
}

TEST_CASE("shell: folds in concave regions are repaired by smoothing and lowering the height") {
  // the inner side of a thin torus (tube radius 0.3) and an L-shaped voxel solid with a concave edge
  const auto torus = shapes::torus(1.0, 0.3, 48, 16);
  auto plain = build_shell(torus, 0.1);
  REQUIRE(plain);
  CHECK(plain->repaired_vertices == 0);
  // the inner side is concave around the axis (radius 0.7): offset by 0.75 the plain normals cross
  shell_options no_repair;
  no_repair.max_rounds = 0;
  CHECK(build_shell(torus, 0.75, no_repair).error().code() == status_code::not_converged);
  auto deep = build_shell(torus, 0.75);
  REQUIRE(deep);
  CHECK(deep->repaired_vertices > 0);
  CHECK(deep->repaired_vertices < torus.num_vertices());
  CHECK(min_quality(*deep) >= shell_options{}.min_quality);
  double lowest = 1;
  for (double h : deep->heights) lowest = std::min(lowest, h / 0.75);
  CHECK(lowest < 1);
  CHECK(lowest >= shell_options{}.min_height_ratio);

  const auto l = shapes::voxel_surface(shapes::l_shape(), 3);
  auto ls = build_shell(l, 0.5);
  REQUIRE(ls);
  CHECK(ls->repaired_vertices > 0);
  CHECK(min_quality(*ls) >= shell_options{}.min_quality);
  INFO("L-shape: repaired " << ls->repaired_vertices << " of " << l.num_vertices() << " in " << ls->repair_rounds
                            << " rounds");
}

TEST_CASE("shell: the same shell on any number of threads") {
  const auto l = shapes::voxel_surface(shapes::l_shape(), 3);
  auto a = build_shell(l, 0.5);
  thread_pool_executor pool(3);
  auto b = build_shell(l, 0.5, {}, pool);
  CHECK(a->repaired_vertices > 0);
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->directions == b->directions);
  CHECK(a->heights == b->heights);
  CHECK(a->repaired_vertices == b->repaired_vertices);
}

TEST_CASE("shell: bad input returns a clear status") {
  const auto m = shapes::sphere(4);
  CHECK(build_shell(m, 0).error().code() == status_code::invalid_argument);
  CHECK(build_shell(m, -1).error().code() == status_code::invalid_argument);
  CHECK(build_shell(m, std::nan("")).error().code() == status_code::invalid_argument);
  CHECK(build_shell(m, 1.0 / 0.0).error().code() == status_code::invalid_argument);
  // open base
  auto open = m;
  open.faces.pop_back();
  auto e = build_shell(open, 0.1);
  REQUIRE(!e);
  CHECK(e.error().message().find("not closed") != std::string::npos);
  // non-manifold: a second sphere sharing an edge's vertices... simplest: a face repeated with another apex
  auto nm = m;
  const auto f0 = nm.faces[0];
  const index_t apex = nm.add_vertex({5, 5, 5});
  nm.add_face(f0[1], f0[0], apex);
  CHECK(build_shell(nm, 0.1).error().code() == status_code::invalid_argument);
  // a height the torus's hole cannot hold anywhere near its inner side
  auto big = build_shell(shapes::torus(1.0, 0.3, 48, 16), 5.0);
  REQUIRE(!big);
  CHECK(big.error().code() == status_code::invalid_argument);
  CHECK(big.error().message().find("too large") != std::string::npos);
  shell_options bad;
  bad.height_step = 1;
  CHECK(build_shell(m, 0.1, bad).error().code() == status_code::invalid_argument);
}
