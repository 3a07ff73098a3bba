// python/src/surface.cpp: tessera's surface family: isotropic remeshing of a closed mesh, and the
// polycube map of a closed triangle mesh (its charts, polycube positions and quad layout as NumPy
// arrays), saved and loaded as a file.
#include <cstdint>
#include <string>
#include <vector>

#include <tessera/io/polycube_file.hpp>
#include <tessera/surface/build_polycube_map.hpp>
#include <tessera/surface/polycube_map.hpp>
#include <tessera/surface/remesh_isotropic.hpp>

#include "bindings.hpp"
#include "common.hpp"
#include "mesh_arrays.hpp"

namespace tessera::python {
namespace {
/// A copy of a vector of indices as an int64 NumPy array.
py::array_t<std::int64_t> index_array(const std::vector<index_t>& v) {
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(v.size()));
  auto w = a.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < w.shape(0); ++i) w(i) = v[static_cast<std::size_t>(i)];
  return a;
}
}  // namespace

void bind_surface(py::module_& m) {
  m.def(
      "remesh",
      [](const py::array& vertices, const py::array& faces, double edge_length, int edges_across, double feature_angle,
         int iterations) {
        const tri_mesh mesh = mesh_from_arrays(vertices, faces, "mesh");
        remesh_options o;
        o.edge_length = edge_length, o.edges_across = edges_across, o.feature_angle = feature_angle;
        o.iterations = iterations;
        auto r = [&] {
          py::gil_scoped_release nogil;
          return remesh_isotropic(mesh, o);
        }();
        const remesh_result out = value_or_raise(std::move(r));
        py::dict stats;
        stats["edge_length"] = out.stats.edge_length;
        stats["feature_edges"] = out.stats.feature_edges;
        stats["splits"] = out.stats.splits;
        stats["collapses"] = out.stats.collapses;
        stats["flips"] = out.stats.flips;
        stats["min_angle_input"] = out.stats.min_angle_input;
        stats["min_angle"] = out.stats.min_angle;
        stats["edge_length_rms"] = out.stats.edge_length_rms;
        stats["max_deviation"] = out.stats.max_deviation;
        return py::make_tuple(positions_array(out.mesh.positions), faces_array(out.mesh.faces), stats);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("edge_length") = 0.0, py::arg("edges_across") = 64,
      py::arg("feature_angle") = 40.0, py::arg("iterations") = 10,
      R"doc(Isotropic remeshing of a closed, manifold, oriented triangle mesh (V float64 n x 3, F int m x 3) into
even triangles of edge length about edge_length (0: the bounding box's longest side / edges_across),
keeping edges whose faces meet at feature_angle degrees or more (180: none, for scans). Returns
(V, F, stats) with stats min_angle_input, min_angle, edge_length_rms, max_deviation, ... CAD output
(long faces beside slivers) remeshed this way gets better polycube maps and shells. Releases the GIL.
Raises InvalidArgument for a refused mesh or option, naming it.)doc");
  py::class_<polycube_map>(
      m, "PolycubeMap",
      R"doc(A polycube map of a closed triangle mesh: every face labelled with one of the six axis directions
(+x, -x, +y, -y, +z, -z = 0..5), grouped into planar charts, every vertex given a polycube position,
and the polycube surface cut into tile_size squares (the quad layout) for surface tiling. Build one with
PolycubeMap.build(V, F) or load a saved one with PolycubeMap.load(path).)doc")
      .def_static(
          "build",
          [](const py::array& vertices, const py::array& faces, double tile_size, std::int64_t tiles_across,
             double compactness, int distortion_retries, int threads) {
            const tri_mesh mesh = mesh_from_arrays(vertices, faces, "mesh");
            polycube_options o;
            o.tile_size = tile_size;
            o.tiles_across = tiles_across;
            o.compactness = compactness;
            o.distortion_retries = distortion_retries;
            return value_or_raise(
                with_executor(threads, [&](auto& exec) { return build_polycube_map(mesh, o, exec); }));
          },
          py::arg("vertices"), py::arg("faces"), py::arg("tile_size") = 0.0, py::arg("tiles_across") = 8,
          py::arg("compactness") = 1.0, py::arg("distortion_retries") = 0, py::arg("threads") = 0,
          R"doc(Builds the polycube map of a closed, manifold triangle mesh (V float64 n x 3, F int32/int64 m x 3).
tile_size in mesh units, or 0 to put tiles_across tiles across the largest bounding-box extent.
distortion_retries > 0 tries that many more labellings after the first valid map and keeps the least
distorted (slower).
Deterministic for any thread count. Releases the GIL. Raises InvalidArgument for an open or
degenerate mesh, naming the problem.)doc")
      .def_static(
          "load", [](const std::string& path) { return value_or_raise(load_polycube_map(path)); }, py::arg("path"),
          "Loads a map written by save(); raises IOError / ParseError naming the file.")
      .def(
          "save", [](const polycube_map& p, const std::string& path) { check(save_polycube_map(path, p)); },
          py::arg("path"), "Writes the map to `path` (a text format whose numbers round-trip exactly).")
      .def_readonly("tile_size", &polycube_map::tile_size, "Tile side in mesh units.")
      .def_property_readonly(
          "vertices", [](const polycube_map& p) { return positions_array(p.base.positions); },
          "The base mesh's vertices (float64 n x 3).")
      .def_property_readonly(
          "faces", [](const polycube_map& p) { return faces_array(p.base.faces); },
          "The base mesh's faces (int64 m x 3).")
      .def_property_readonly(
          "polycube_positions", [](const polycube_map& p) { return positions_array(p.polycube); },
          "The polycube position of every base vertex (float64 n x 3): V with these positions is the "
          "polycube-deformed mesh.")
      .def_property_readonly(
          "labels",
          [](const polycube_map& p) {
            py::array_t<std::uint8_t> a(static_cast<py::ssize_t>(p.labels.size()));
            auto w = a.mutable_unchecked<1>();
            for (py::ssize_t i = 0; i < w.shape(0); ++i)
              w(i) = static_cast<std::uint8_t>(p.labels[static_cast<std::size_t>(i)]);
            return a;
          },
          "The label of every face (uint8: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z).")
      .def_property_readonly(
          "face_origin", [](const polycube_map& p) { return index_array(p.face_origin); },
          "When the construction refined the input (split edges that would collapse): the input face of "
          "every base face (int64); empty when the base mesh is the input.")
      .def_property_readonly(
          "face_chart", [](const polycube_map& p) { return index_array(p.face_chart); },
          "The chart of every face (int64).")
      .def_property_readonly(
          "charts",
          [](const polycube_map& p) {
            py::list out;
            for (const polycube_chart& c : p.charts) {
              py::dict d;
              d["label"] = static_cast<int>(c.label);
              d["plane"] = c.plane;
              d["faces"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(c.faces.size()),
                                                     reinterpret_cast<const std::int64_t*>(c.faces.data()));
              out.append(d);
            }
            return out;
          },
          "The charts: a list of dicts with label (0-5), plane (grid coordinate along the label's axis) and faces.")
      .def_property_readonly(
          "num_quads", [](const polycube_map& p) { return p.layout.quads.size(); },
          "Number of tile-size squares on the polycube surface.")
      .def_property_readonly(
          "quad_corners",
          [](const polycube_map& p) {
            const auto& q = p.layout.quads;
            py::array_t<std::int64_t> a({static_cast<py::ssize_t>(q.size()), py::ssize_t{4}, py::ssize_t{3}});
            auto w = a.mutable_unchecked<3>();
            for (py::ssize_t i = 0; i < w.shape(0); ++i)
              for (py::ssize_t k = 0; k < 4; ++k)
                for (py::ssize_t j = 0; j < 3; ++j)
                  w(i, k, j) =
                      q[static_cast<std::size_t>(i)].corners[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)];
            return a;
          },
          "Grid corners of every quad (int64 quads x 4 x 3, counter-clockwise seen from outside; multiply by "
          "tile_size for mesh units).")
      .def_property_readonly(
          "quad_neighbors",
          [](const polycube_map& p) {
            const auto& q = p.layout.quads;
            py::array_t<std::int64_t> a({static_cast<py::ssize_t>(q.size()), py::ssize_t{4}});
            auto w = a.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < w.shape(0); ++i)
              for (py::ssize_t k = 0; k < 4; ++k)
                w(i, k) = q[static_cast<std::size_t>(i)].neighbors[static_cast<std::size_t>(k)];
            return a;
          },
          "The quad across each side of every quad (int64 quads x 4), also around polycube edges.")
      .def_property_readonly(
          "quad_chart",
          [](const polycube_map& p) {
            const auto& q = p.layout.quads;
            py::array_t<std::int64_t> a(static_cast<py::ssize_t>(q.size()));
            auto w = a.mutable_unchecked<1>();
            for (py::ssize_t i = 0; i < w.shape(0); ++i) w(i) = q[static_cast<std::size_t>(i)].chart;
            return a;
          },
          "The chart of every quad (int64).")
      .def_property_readonly(
          "num_corners", [](const polycube_map& p) { return p.corners.size(); }, "Polycube corners.")
      .def_property_readonly(
          "num_edges", [](const polycube_map& p) { return p.edges.size(); }, "Polycube edges.");
}

}  // namespace tessera::python
