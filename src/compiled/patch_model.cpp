// src/compiled/patch_model.cpp: patch models (their preprocessing) and the procedural exemplars.
// Part of tessera::compiled (docs/compile_once.md): the explicit instantiation definitions of the
// extern templates declared in the detail/compiled_*.hpp headers below. Compiled at -O2, apart from
// patch_synthesis.cpp, whose loops need -O3: at -O3 this file took 111 of the 180 CPU seconds the two
// took as one (27 Nov 2026).
#define TESSERA_COMPILED_INSTANTIATE 1

#include <tessera/image/detail/compiled_exemplars.hpp>
#include <tessera/image/detail/compiled_patch_model.hpp>
