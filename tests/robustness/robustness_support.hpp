// Shared inputs of the robustness tests: degenerate images and meshes, and the check every entry
// point must pass on them (a valid output, or a status with a message; never a crash or a hang).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/random.hpp>
#include <tessera/core/status.hpp>
#include <tessera/core/tri_mesh.hpp>

namespace robust {

/// How many times more random cases each property runs in an optimized build than under the
/// sanitizers, which run about five times slower (CI budget).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr std::uint64_t property_scale = 1;
#else
inline constexpr std::uint64_t property_scale = 3;
#endif

using tessera::index_t;

/// A named degenerate input.
template <class T>
struct named {
  std::string name;
  T value;
};

/// A failure must say what went wrong: a code other than ok and a non-empty message.
inline void check_refusal(const tessera::status& s) {
  INFO(s.to_string());
  CHECK_FALSE(s.ok());
  CHECK_FALSE(s.message().empty());
}

/// Records a status: either success, or a refusal with a message. Returns s.ok().
inline bool ok_or_refused(const tessera::status& s) {
  if (!s.ok()) check_refusal(s);
  return s.ok();
}
template <class R>
bool ok_or_refused_result(const R& r) {
  if (!r) check_refusal(r.error());
  return static_cast<bool>(r);
}

/// Every channel value of an image is finite (outputs of finite inputs).
template <class T, int C>
bool all_finite(const tessera::image_buffer<T, C>& img) {
  if constexpr (std::is_floating_point_v<T>) {
    const T* d = img.data();
    for (index_t i = 0; i < img.width() * img.height() * C; ++i)
      if (!std::isfinite(d[i])) return false;
  }
  return true;
}

/// A random image (counter_rng keyed by seed), values over the whole channel range ([0, 1] for float).
template <class T, int C>
tessera::image_buffer<T, C> noise(index_t w, index_t h, std::uint64_t seed) {
  const tessera::counter_rng rng(seed);
  tessera::image_buffer<T, C> img(w, h);
  for (index_t y = 0; y < h; ++y)
    for (index_t x = 0; x < w; ++x) {
      tessera::pixel<T, C> p{};
      for (int c = 0; c < C; ++c)
        p[static_cast<std::size_t>(c)] = tessera::unit_to_channel<T>(static_cast<float>(
            rng.uniform(static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(c))));
      img.write(x, y, p);
    }
  return img;
}

/// The degenerate images of the matrix for one pixel type: flat, all black, zero alpha, two-valued,
/// 1 x 1, one row, one column, smaller than a patch, a normal small noise image, and for float images
/// one NaN, all NaN and one infinity.
template <class T, int C>
std::vector<named<tessera::image_buffer<T, C>>> degenerate_images() {
  using img = tessera::image_buffer<T, C>;
  using px = tessera::pixel<T, C>;
  px grey{}, black{}, white{};
  for (int c = 0; c < C; ++c) {
    grey[static_cast<std::size_t>(c)] = tessera::unit_to_channel<T>(0.5f);
    white[static_cast<std::size_t>(c)] = tessera::unit_to_channel<T>(1.0f);
  }
  std::vector<named<img>> out;
  out.push_back({"flat grey 40x40", img(40, 40, grey)});
  out.push_back({"all black 40x40", img(40, 40, black)});
  if constexpr (C == 2 || C == 4) {
    px clear = grey;
    clear[static_cast<std::size_t>(C - 1)] = T{0};
    out.push_back({"zero alpha 40x40", img(40, 40, clear)});
  }
  img two(40, 40, black);
  for (index_t y = 0; y < 40; ++y)
    for (index_t x = 0; x < 40; ++x)
      if ((x / 5 + y / 5) % 2) two.write(x, y, white);
  out.push_back({"two-valued checker 40x40", two});
  img stripe(40, 40, black);
  for (index_t x = 0; x < 40; ++x) stripe.write(x, 17, white);
  out.push_back({"one bright row 40x40", stripe});
  out.push_back({"1x1", img(1, 1, grey)});
  out.push_back({"one row 40x1", noise<T, C>(40, 1, 2)});
  out.push_back({"one column 1x40", noise<T, C>(1, 40, 3)});
  out.push_back({"smaller than a patch 5x5", noise<T, C>(5, 5, 4)});
  out.push_back({"noise 24x24", noise<T, C>(24, 24, 5)});
  if constexpr (std::is_floating_point_v<T>) {
    img one_nan = noise<T, C>(24, 24, 6);
    auto p = one_nan.read(3, 4);
    p[0] = std::numeric_limits<T>::quiet_NaN();
    one_nan.write(3, 4, p);
    out.push_back({"one NaN", one_nan});
    px nan{};
    for (int c = 0; c < C; ++c) nan[static_cast<std::size_t>(c)] = std::numeric_limits<T>::quiet_NaN();
    out.push_back({"all NaN", img(24, 24, nan)});
    img inf = noise<T, C>(24, 24, 7);
    auto q = inf.read(20, 1);
    q[static_cast<std::size_t>(C - 1)] = -std::numeric_limits<T>::infinity();
    inf.write(20, 1, q);
    out.push_back({"one -infinity", inf});
  }
  return out;
}

/// True for the inputs with a NaN or an infinity (which every entry point doing maths must refuse).
inline bool non_finite_case(const std::string& name) {
  return name.find("NaN") != std::string::npos || name.find("infinity") != std::string::npos;
}

/// A closed tetrahedron of edge ~1 at (x, y).
inline void add_tetrahedron(tessera::tri_mesh& m, double x, double y, double s = 0.4) {
  const index_t a = m.add_vertex({x, y, 0}), b = m.add_vertex({x + s, y, 0}), c = m.add_vertex({x, y + s, 0}),
                d = m.add_vertex({x + s / 3, y + s / 3, s});
  m.add_face(a, c, b);
  m.add_face(a, b, d);
  m.add_face(b, c, d);
  m.add_face(c, a, d);
}

/// The degenerate meshes of the matrix.
inline std::vector<named<tessera::tri_mesh>> degenerate_meshes() {
  using tessera::tri_mesh;
  std::vector<named<tri_mesh>> out;
  out.push_back({"empty", tri_mesh{}});
  tri_mesh vertices_only;
  vertices_only.add_vertex({0, 0, 0});
  vertices_only.add_vertex({1, 0, 0});
  out.push_back({"vertices without faces", vertices_only});
  tri_mesh one;
  one.add_face(one.add_vertex({0, 0, 0}), one.add_vertex({1, 0, 0}), one.add_vertex({0, 1, 0}));
  out.push_back({"one triangle", one});
  tri_mesh zero_area = one;
  zero_area.add_face(zero_area.add_vertex({2, 0, 0}), zero_area.add_vertex({3, 0, 0}), zero_area.add_vertex({4, 0, 0}));
  out.push_back({"zero-area face", zero_area});
  tri_mesh dup = one;
  dup.positions.push_back(dup.positions[0]);
  dup.add_face(3, 1, 2);
  out.push_back({"duplicated vertex", dup});
  tri_mesh coincident;
  add_tetrahedron(coincident, 0, 0);
  add_tetrahedron(coincident, 0, 0);
  out.push_back({"coincident elements", coincident});
  tri_mesh open;
  add_tetrahedron(open, 0, 0);
  open.faces.pop_back();
  out.push_back({"open border", open});
  tri_mesh fan = one;
  const index_t c = fan.add_vertex({0, -1, 0}), d = fan.add_vertex({0, 0, 1});
  fan.add_face(0, c, 1);
  fan.add_face(0, 1, d);  // edge (0, 1) shared by three faces
  out.push_back({"non-manifold fan", fan});
  tri_mesh many;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) add_tetrahedron(many, 1.0 * i, 1.0 * j);
  out.push_back({"36 tetrahedra", many});
  tri_mesh nan = many;
  nan.positions[5].y = std::numeric_limits<double>::quiet_NaN();
  out.push_back({"NaN coordinate", nan});
  tri_mesh huge = many;
  huge.positions[7].x = 1e300;
  out.push_back({"coordinate at 1e300", huge});
  tri_mesh far = many;
  for (auto& p : far.positions) p.x += 1e300;
  out.push_back({"all coordinates near 1e300", far});
  tri_mesh bad_index = one;
  bad_index.faces.push_back({0, 1, 99});
  out.push_back({"index out of range", bad_index});
  return out;
}

}  // namespace robust
