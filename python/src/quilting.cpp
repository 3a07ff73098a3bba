// python/src/quilting.cpp: image quilting (image/quilt.hpp) and constrained quilting with masks
// (image/constrained_quilt.hpp).
#include "bindings.hpp"
#include "common.hpp"

namespace tessera::python {

void bind_quilting(py::module_& m) { (void)m; }

}  // namespace tessera::python
