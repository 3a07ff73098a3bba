// src/compiled/terrain.cpp: terrain meshes, exemplar pyramids, projection, scale fields, triangle synthesis, frames.
// Part of tessera::compiled (docs/compile_once.md): the explicit instantiation definitions of the
// extern templates declared in the detail/compiled_*.hpp headers below.
#define TESSERA_COMPILED_INSTANTIATE 1

#include <tessera/terrain/detail/compiled_assign_scale_field.hpp>
#include <tessera/terrain/detail/compiled_build_exemplar_pyramid.hpp>
#include <tessera/terrain/detail/compiled_make_terrain.hpp>
#include <tessera/terrain/detail/compiled_prepare_terrain_mesh.hpp>
#include <tessera/terrain/detail/compiled_project_mesh.hpp>
#include <tessera/terrain/detail/compiled_render_terrain_frame.hpp>
#include <tessera/terrain/detail/compiled_synthesize_triangles.hpp>
