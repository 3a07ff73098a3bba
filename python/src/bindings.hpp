// python/src/bindings.hpp: the parts of the tessera Python module; module.cpp calls each.
#pragma once

#include <pybind11/pybind11.h>

namespace tessera::python {
namespace py = pybind11;

void bind_errors(py::module_& m);    ///< tessera.Error and one subclass per status code (errors.cpp)
void bind_images(py::module_& m);    ///< read_png, write_png, exemplars (images.cpp)
void bind_patch(py::module_& m);     ///< PatchModel (patch.cpp, patch_model_*.cpp)
void bind_quilting(py::module_& m);  ///< quilt, constrained_quilt (quilting.cpp)
void bind_wang(py::module_& m);      ///< WangTileSet, colourings, atlas (wang.cpp)
void bind_fabric(py::module_& m);    ///< fabric (py-families)
void bind_terrain(py::module_& m);   ///< terrain (py-families)
void bind_geometry(py::module_& m);  ///< geometric tiles (py-families)
void bind_surface(py::module_& m);   ///< polycube / surface tiling (py-families)

}  // namespace tessera::python
