// python/src/mesh_arrays.hpp: triangle meshes <-> NumPy arrays for the geometry, terrain and
// surface parts of the module: V float64 (n x 3), F int32 or int64 (m x 3), validated with a clear
// exception naming the argument (dtype, shape, NaN, index out of range, size limit).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include <tessera/core/tri_mesh.hpp>

#include "common.hpp"

namespace tessera::python {

/// Largest vertex or face count accepted from Python (tessera's meshes index with 32-bit limits).
inline constexpr py::ssize_t max_mesh_elements = py::ssize_t{1} << 30;

namespace detail_py {
inline std::string shape_string(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + ")";
}
inline void check_rows_of_three(const py::array& a, const char* what, const char* letter) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(cat(what, ": expected an ", letter, " x 3 array, got shape ", shape_string(a)));
  if (a.shape(0) > max_mesh_elements)
    throw py::value_error(cat(what, ": ", static_cast<long long>(a.shape(0)), " rows exceed the limit of ",
                              static_cast<long long>(max_mesh_elements)));
}
template <class T>
T element(const py::array& a, py::ssize_t i, py::ssize_t j) {
  const char* p = static_cast<const char*>(a.data()) + i * a.strides(0) + j * a.strides(1);
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}
}  // namespace detail_py

/// A tri_mesh from V (float64, n x 3, finite) and F (int32 or int64, m x 3, indices in [0, n)).
/// Any strides are accepted (the arrays are copied). Raises TypeError for another dtype, ValueError
/// for a wrong shape, a non-finite coordinate or an index out of range (naming the row).
inline tri_mesh mesh_from_arrays(const py::array& vertices, const py::array& faces, const char* what = "mesh") {
  const std::string vname = cat(what, " vertices"), fname = cat(what, " faces");
  if (!vertices.dtype().is(py::dtype::of<double>()))
    throw py::type_error(cat(vname, ": expected a float64 array, got ", dtype_name(vertices),
                             "; convert with numpy.asarray(V, dtype=numpy.float64)"));
  const bool f32 = faces.dtype().is(py::dtype::of<std::int32_t>()),
             f64 = faces.dtype().is(py::dtype::of<std::int64_t>());
  if (!f32 && !f64)
    throw py::type_error(cat(fname, ": expected an int32 or int64 array, got ", dtype_name(faces),
                             "; convert with numpy.asarray(F, dtype=numpy.int64)"));
  detail_py::check_rows_of_three(vertices, vname.c_str(), "n");
  detail_py::check_rows_of_three(faces, fname.c_str(), "m");
  tri_mesh m;
  const py::ssize_t nv = vertices.shape(0), nf = faces.shape(0);
  m.positions.resize(static_cast<std::size_t>(nv));
  for (py::ssize_t i = 0; i < nv; ++i) {
    vec3 p{detail_py::element<double>(vertices, i, 0), detail_py::element<double>(vertices, i, 1),
           detail_py::element<double>(vertices, i, 2)};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw py::value_error(
          cat(vname, ": row ", static_cast<long long>(i), " is not finite (", p.x, ", ", p.y, ", ", p.z, ")"));
    m.positions[static_cast<std::size_t>(i)] = p;
  }
  m.faces.resize(static_cast<std::size_t>(nf));
  for (py::ssize_t i = 0; i < nf; ++i)
    for (py::ssize_t k = 0; k < 3; ++k) {
      const long long v =
          f32 ? detail_py::element<std::int32_t>(faces, i, k) : detail_py::element<std::int64_t>(faces, i, k);
      if (v < 0 || v >= nv)
        throw py::value_error(cat(fname, ": row ", static_cast<long long>(i), " refers to vertex ", v, ", outside [0, ",
                                  static_cast<long long>(nv), ")"));
      m.faces[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = static_cast<index_t>(v);
    }
  return m;
}

/// V (float64 n x 3) of a list of positions.
inline py::array_t<double> positions_array(const std::vector<vec3>& positions) {
  py::array_t<double> v({static_cast<py::ssize_t>(positions.size()), py::ssize_t{3}});
  auto w = v.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < w.shape(0); ++i) {
    const vec3& p = positions[static_cast<std::size_t>(i)];
    w(i, 0) = p.x;
    w(i, 1) = p.y;
    w(i, 2) = p.z;
  }
  return v;
}
/// F (int64 m x 3) of a list of faces.
inline py::array_t<std::int64_t> faces_array(const std::vector<std::array<index_t, 3>>& faces) {
  py::array_t<std::int64_t> f({static_cast<py::ssize_t>(faces.size()), py::ssize_t{3}});
  auto w = f.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < w.shape(0); ++i)
    for (py::ssize_t k = 0; k < 3; ++k) w(i, k) = faces[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
  return f;
}
/// (V, F) of a tri_mesh: float64 n x 3 and int64 m x 3.
inline py::tuple mesh_to_arrays(const tri_mesh& m) {
  return py::make_tuple(positions_array(m.positions), faces_array(m.faces));
}

}  // namespace tessera::python
