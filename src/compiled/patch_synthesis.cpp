// src/compiled/patch_synthesis.cpp: patch synthesis into image_buffer and image_view.
// Part of tessera::compiled (docs/compile_once.md): the explicit instantiation definitions of the
// extern templates declared in the detail/compiled_*.hpp header below. The one file compiled at -O3
// (CMakeLists.txt: its overlap-error and blending loops need the vectorizer).
#define TESSERA_COMPILED_INSTANTIATE 1

#include <tessera/image/detail/compiled_patch_synthesis.hpp>
