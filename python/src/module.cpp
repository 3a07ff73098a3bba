// python/src/module.cpp: the extension module tessera._tessera (re-exported by tessera/__init__.py).
#include "bindings.hpp"

#ifndef TESSERA_PYTHON_VERSION
#define TESSERA_PYTHON_VERSION "unknown"
#endif

PYBIND11_MODULE(_tessera, m) {
  namespace tp = tessera::python;
  m.doc() = "tessera: texture synthesis over NumPy arrays (H x W x C, uint8 / uint16 / float32, C = 1-4)";
  m.attr("__version__") = TESSERA_PYTHON_VERSION;
  tp::bind_errors(m);  // first: the other parts raise these
  tp::bind_images(m);
  tp::bind_patch(m);
  tp::bind_quilting(m);
  tp::bind_wang(m);
  tp::bind_fabric(m);
  tp::bind_terrain(m);
  tp::bind_geometry(m);
  tp::bind_surface(m);
}
