// src/compiled/geometry.cpp: quilt exemplars, geometric Wang tiles and tiled planes.
// Part of tessera::compiled (docs/compile_once.md): the explicit instantiation definitions of the
// extern templates declared in the detail/compiled_*.hpp headers below.
#define TESSERA_COMPILED_INSTANTIATE 1

#include <tessera/geometry/detail/compiled_geometric_wang_tiles.hpp>
#include <tessera/geometry/detail/compiled_quilt_exemplar.hpp>
#include <tessera/geometry/detail/compiled_tile_geometric_plane.hpp>
