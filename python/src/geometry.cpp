// python/src/geometry.cpp: tessera's geometric textures (paper 000): mesh exemplars, mesh quilting,
// geometric Wang tile sets (build, save, load) and tiling a plane, meshes as (V, F) NumPy arrays.
#include <cstdint>
#include <string>

#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/quilt_exemplar.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/io/geometric_tiles.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/render/render_mesh_preview.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include "bindings.hpp"
#include "common.hpp"
#include "mesh_arrays.hpp"

namespace tessera::python {
namespace {

quilt_exemplar prepared_exemplar(const py::array& vertices, const py::array& faces) {
  const tri_mesh mesh = mesh_from_arrays(vertices, faces, "exemplar");
  auto r = [&] {
    py::gil_scoped_release nogil;
    return prepare_quilt_exemplar(mesh);
  }();
  return value_or_raise(std::move(r));
}

}  // namespace

void bind_geometry(py::module_& m) {
  m.def(
      "read_mesh", [](const std::string& path) { return mesh_to_arrays(value_or_raise(read_mesh(path))); },
      py::arg("path"),
      "Reads an OBJ, OFF or PLY triangle mesh (chosen by extension) as (V float64 n x 3, F int64 m x 3); raises "
      "IOError / ParseError naming the file.");
  m.def(
      "write_mesh",
      [](const std::string& path, const py::array& vertices, const py::array& faces) {
        check(write_mesh(path, mesh_from_arrays(vertices, faces, "write_mesh")));
      },
      py::arg("path"), py::arg("vertices"), py::arg("faces"),
      "Writes (V, F) as an OBJ, OFF or PLY file chosen by the extension of `path`.");
  m.def(
      "render_mesh_preview",
      [](const py::array& vertices, const py::array& faces, std::int64_t width, std::int64_t height,
         double azimuth_degrees, double elevation_degrees, double grid_spacing, int threads) {
        const tri_mesh mesh = mesh_from_arrays(vertices, faces, "render_mesh_preview");
        mesh_preview_options o;
        o.width = width;
        o.height = height;
        o.azimuth_degrees = azimuth_degrees;
        o.elevation_degrees = elevation_degrees;
        o.grid_spacing = grid_spacing;
        auto img =
            value_or_raise(with_executor(threads, [&](auto& exec) { return render_mesh_preview(mesh, o, exec); }));
        return to_array(std::move(img));
      },
      py::arg("vertices"), py::arg("faces"), py::arg("width") = 800, py::arg("height") = 600,
      py::arg("azimuth_degrees") = -60.0, py::arg("elevation_degrees") = 45.0, py::arg("grid_spacing") = 0.0,
      py::arg("threads") = 0,
      R"doc(A shaded picture of a mesh (height x width x 3 uint8), elements tinted per connected component;
grid_spacing > 0 overlays tile borders x, y = k * grid_spacing. Sizes 1 to 8192. Releases the GIL.)doc");

  m.def(
      "mesh_exemplar",
      [](const std::string& kind, double size, std::uint64_t seed) {
        result<tri_mesh> r = status::invalid_argument(
            cat("mesh_exemplar: kind must be 'rings', 'chain_mail', 'stones' or 'weave', got '", kind, "'"));
        if (kind == "rings" || kind == "chain_mail")
          r = make_ring_exemplar(
              {.size = size,
               .minor_radius = kind == "chain_mail" ? 0.08 : 0.12,  // as `tessera exemplar --chain-mail`
               .chain_mail = kind == "chain_mail",
               .seed = seed});
        else if (kind == "stones")
          r = make_stone_exemplar({.size = size, .seed = seed});
        else if (kind == "weave")
          r = make_weave_exemplar({.size = size, .seed = seed});
        return mesh_to_arrays(value_or_raise(std::move(r)));
      },
      py::arg("kind") = "rings", py::arg("size") = 8.0, py::arg("seed") = 1,
      R"doc(A procedural geometric-texture exemplar covering [0, size]^2 in XY: 'rings' (loose tori),
'chain_mail' (interlocked 4-in-1 rings), 'stones' (pebbles) or 'weave' (over-under threads).
Returns (V, F): float64 (n x 3) and int64 (m x 3). Deterministic in (kind, size, seed).)doc");

  m.def(
      "mesh_quilt",
      [](const py::array& vertices, const py::array& faces, double width, double height, std::uint64_t seed,
         int threads, py::object progress_fn) {
        const quilt_exemplar ex = prepared_exemplar(vertices, faces);
        call_progress progress(std::move(progress_fn));
        mesh_quilt_options o;
        o.seed = seed;
        o.progress = progress.sink();
        auto r = progress.value_or_raise(
            with_executor(threads, [&](auto& exec) { return mesh_quilt(ex, width, height, o, exec); }));
        return mesh_to_arrays(r.mesh);
      },
      py::arg("vertices"), py::arg("faces"), py::arg("width"), py::arg("height"), py::arg("seed") = 0,
      py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(Mesh quilting (paper 000, section 3.3): a geometric texture of width x height (XY) synthesized from a
closed-element exemplar (V, F), elements matched on a grid, refined by ICP and merged at seams.
Returns (V, F). Deterministic for a seed, any thread count. Releases the GIL; progress may cancel.)doc");

  py::class_<geometric_tile_set>(m, "GeometricTileSet",
                                 R"doc(A complete set of geometric Wang tiles (paper 000, section 3): tile i covers
[0, tile_size]^2 in XY with edge colours edges[i] = (north, east, south, west). Build one with
GeometricTileSet.build, or load a saved one with GeometricTileSet.load.)doc")
      .def_static(
          "build",
          [](const py::array& vertices, const py::array& faces, double tile_size, int horizontal_colors,
             int vertical_colors, double edge_height, std::uint64_t seed, int threads, py::object progress_fn) {
            const quilt_exemplar ex = prepared_exemplar(vertices, faces);
            call_progress progress(std::move(progress_fn));
            geometric_wang_options o;
            o.horizontal_colors = horizontal_colors;
            o.vertical_colors = vertical_colors;
            o.tile_size = tile_size;
            o.edge_height = edge_height;
            o.quilt.seed = seed;
            o.progress = progress.sink();
            return progress.value_or_raise(
                with_executor(threads, [&](auto& exec) { return build_geometric_wang_tiles(ex, o, exec); }));
          },
          py::arg("vertices"), py::arg("faces"), py::arg("tile_size"), py::arg("horizontal_colors") = 2,
          py::arg("vertical_colors") = 2, py::arg("edge_height") = 0.0, py::arg("seed") = 0, py::arg("threads") = 0,
          py::arg("progress") = py::none(),
          R"doc(Builds the complete tile set of horizontal_colors x vertical_colors edge colours from an exemplar
(V, F): edge strips cut across each colour, tile interiors synthesized by mesh quilting (seeded by seed).
tile_size is required (> 0); edge_height 0 = 1.5 x the element size. Releases the GIL.)doc")
      .def_static(
          "load",
          [](const std::string& directory, double tolerance) {
            return value_or_raise(load_geometric_tile_set(directory, tolerance));
          },
          py::arg("directory"), py::arg("tolerance") = 1e-6,
          "Loads a tile set saved by save() (a directory of OBJ tiles and a manifest); raises IOError / ParseError.")
      .def(
          "save",
          [](const geometric_tile_set& s, const std::string& directory) {
            check(save_geometric_tile_set(directory, s));
          },
          py::arg("directory"), "Saves the set as a directory of OBJ tiles and a manifest.")
      .def_readonly("tile_size", &geometric_tile_set::tile_size, "Tile side in mesh units.")
      .def_readonly("edge_height", &geometric_tile_set::edge_height, "Height of the edge strips.")
      .def_readonly("horizontal_colors", &geometric_tile_set::horizontal_colors, "Colours of north/south edges.")
      .def_readonly("vertical_colors", &geometric_tile_set::vertical_colors, "Colours of east/west edges.")
      .def_property_readonly(
          "num_tiles", [](const geometric_tile_set& s) { return s.tiles.size(); }, "Number of tiles.")
      .def_property_readonly(
          "edges",
          [](const geometric_tile_set& s) {
            py::array_t<std::int32_t> e({static_cast<py::ssize_t>(s.edges.size()), py::ssize_t{4}});
            auto w = e.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < w.shape(0); ++i) {
              const wang_edges& x = s.edges[static_cast<std::size_t>(i)];
              w(i, 0) = x.north;
              w(i, 1) = x.east;
              w(i, 2) = x.south;
              w(i, 3) = x.west;
            }
            return e;
          },
          "Edge colours per tile: an int32 (tiles x 4) array of (north, east, south, west).")
      .def(
          "tile",
          [](const geometric_tile_set& s, std::int64_t i) {
            if (i < 0 || i >= static_cast<std::int64_t>(s.tiles.size()))
              throw py::index_error(cat("tile index ", i, " is outside [0, ", s.tiles.size(), ")"));
            return mesh_to_arrays(s.tiles[static_cast<std::size_t>(i)]);
          },
          py::arg("index"), "Tile `index` as (V, F).")
      .def(
          "tile_plane",
          [](const geometric_tile_set& s, std::int64_t cols, std::int64_t rows, std::uint64_t seed,
             std::int64_t origin_col, std::int64_t origin_row, int threads) {
            check(validate_geometric_plane_size(s, cols, rows));
            const hash_coloring hash =
                value_or_raise(hash_coloring::create(s.horizontal_colors, s.vertical_colors, seed));
            const auto coloring = value_or_raise(hash.window(origin_col, origin_row, cols, rows));
            auto mesh = value_or_raise(with_executor(
                threads, [&](auto& exec) { return tile_geometric_plane(s, coloring, cols, rows, exec); }));
            return mesh_to_arrays(mesh);
          },
          py::arg("cols"), py::arg("rows"), py::arg("seed") = 1, py::arg("origin_col") = 0, py::arg("origin_row") = 0,
          py::arg("threads") = 0,
          R"doc(Tiles a cols x rows plane by the hash colouring of `seed` (the window at (origin_col, origin_row) of
an unbounded plane) and welds the borders into one mesh (V, F). Cell (col, row) covers x in
[col w, (col + 1) w], y in [(rows - 1 - row) w, (rows - row) w]. Releases the GIL.)doc");
}

}  // namespace tessera::python
