// python/src/wang.cpp: Wang tile sets (image/wang_tiles.hpp), their directories (io/wang_tiles.hpp),
// composition through colourings (image/compose_tiles.hpp) and atlases (image/wang_atlas.hpp).
#include "bindings.hpp"
#include "common.hpp"

namespace tessera::python {

void bind_wang(py::module_& m) { (void)m; }

}  // namespace tessera::python
