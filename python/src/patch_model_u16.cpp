// python/src/patch_model_u16.cpp: PatchModel's kernels for std::uint16_t channels (see patch_model.hpp).
#include "patch_model_impl.hpp"

namespace tessera::python {
template any_patch_model build_model<std::uint16_t>(const py::array&, const patch_model_options&, int, call_progress&);
template py::array synthesize_model<std::uint16_t>(const any_patch_model&, const synthesis_request&, call_progress&);
template std::string save_model<std::uint16_t>(const any_patch_model&);
template any_patch_model load_model<std::uint16_t>(const std::string&, pixel_format, int);
}  // namespace tessera::python
