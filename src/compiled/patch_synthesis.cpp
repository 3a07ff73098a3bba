// src/compiled/patch_synthesis.cpp: patch models, patch synthesis and the procedural exemplars.
// Part of tessera::compiled (docs/compile_once.md): the explicit instantiation definitions of the
// extern templates declared in the detail/compiled_*.hpp headers below.
#define TESSERA_COMPILED_INSTANTIATE 1

#include <tessera/image/detail/compiled_exemplars.hpp>
#include <tessera/image/detail/compiled_patch_model.hpp>
#include <tessera/image/detail/compiled_patch_synthesis.hpp>
