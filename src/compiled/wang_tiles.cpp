// src/compiled/wang_tiles.cpp: image quilting, Wang tile sets and their composition.
// Part of tessera::compiled (docs/compile_once.md): the explicit instantiation definitions of the
// extern templates declared in the detail/compiled_*.hpp headers below.
#define TESSERA_COMPILED_INSTANTIATE 1

#include <tessera/image/detail/compiled_compose_tiles.hpp>
#include <tessera/image/detail/compiled_quilt.hpp>
#include <tessera/image/detail/compiled_wang_tiles.hpp>
