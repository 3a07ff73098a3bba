// tessera/tessera.hpp: umbrella header. Includes the core vocabulary and every algorithm; optional
// parts (io/, adapters/) are included separately since they need extra libraries or touch files.
// A structural test checks that every other public header is listed here.
// Docs and examples include the specific header instead, which compiles faster.
#pragma once

#include "version.hpp"
#include "core/compiled.hpp"
#include "core/config.hpp"
#include "core/executor.hpp"
#include "core/explain.hpp"
#include "core/format.hpp"
#include "core/image.hpp"
#include "core/image_buffer.hpp"
#include "core/image_checks.hpp"
#include "core/image_rows.hpp"
#include "core/image_view.hpp"
#include "core/mesh.hpp"
#include "core/mesh_sink.hpp"
#include "core/mesh_topology.hpp"
#include "core/mesh_view.hpp"
#include "core/progress.hpp"
#include "core/random.hpp"
#include "core/status.hpp"
#include "core/tile_coloring.hpp"
#include "core/tri_mesh.hpp"
#include "core/vec.hpp"

// images: exemplars, metrics, patch synthesis (paper 002), quilting, Wang tiles
#include "image/compose_tiles.hpp"
#include "image/constrained_quilt.hpp"
#include "image/exemplars.hpp"
#include "image/metrics.hpp"
#include "image/patch_model.hpp"
#include "image/patch_size.hpp"
#include "image/patch_synthesis.hpp"
#include "image/quilt.hpp"
#include "image/wang_atlas.hpp"
#include "image/wang_seam_quality.hpp"
#include "image/wang_tiles.hpp"

// tile colourings and tile sets
#include "tiling/complete_tile_set.hpp"
#include "tiling/hash_coloring.hpp"
#include "tiling/periodic_coloring.hpp"
#include "tiling/scanline_coloring.hpp"
#include "tiling/tile_lookup.hpp"
#include "tiling/tile_set_edges.hpp"

// fabric (paper 001)
#include "fabric/cat_map.hpp"
#include "fabric/cat_map_period.hpp"
#include "fabric/hls.hpp"
#include "fabric/life_perturbation.hpp"
#include "fabric/make_fabric.hpp"
#include "fabric/source_image.hpp"
#include "fabric/tone_proportions.hpp"

// rendering
#include "render/triangle_rasterizer.hpp"
#include "render/render_mesh_preview.hpp"

// surface (paper 000 §4: polycube maps, shell mapping)
#include "surface/build_polycube_map.hpp"
#include "surface/build_shell.hpp"
#include "surface/map_tiles_to_shell.hpp"
#include "surface/polycube_distortion.hpp"
#include "surface/polycube_map.hpp"
#include "surface/polycube_projection.hpp"
#include "surface/quad_layout.hpp"

// terrain (paper 003)
#include "terrain/assign_scale_field.hpp"
#include "terrain/build_exemplar_pyramid.hpp"
#include "terrain/export_corner_uvs.hpp"
#include "terrain/export_session_uvs.hpp"
#include "terrain/make_terrain.hpp"
#include "terrain/plan_anchored_regions.hpp"
#include "terrain/prepare_terrain_mesh.hpp"
#include "terrain/project_mesh.hpp"
#include "terrain/render_anchored_frame.hpp"
#include "terrain/render_terrain_frame.hpp"
#include "terrain/render_tiled_frame.hpp"
#include "terrain/synthesize_anchored_region.hpp"
#include "terrain/synthesize_triangles.hpp"
#include "terrain/terrain_camera.hpp"
#include "terrain/terrain_session.hpp"
#include "terrain/texture_stretch.hpp"

// geometric textures (paper 000 §2-3); tile-set files are in io/geometric_tiles.hpp
#include "geometry/bvh.hpp"
#include "geometry/check_geometric_texture.hpp"
#include "geometry/constrained_mesh_quilt.hpp"
#include "geometry/geometric_wang_tiles.hpp"
#include "geometry/icp.hpp"
#include "geometry/laplacian.hpp"
#include "geometry/max_flow.hpp"
#include "geometry/mesh_elements.hpp"
#include "geometry/mesh_exemplars.hpp"
#include "geometry/mesh_quilt.hpp"
#include "geometry/mesh_quilt_types.hpp"
#include "geometry/quilt_exemplar.hpp"
#include "geometry/texture_quality.hpp"
#include "geometry/tile_geometric_plane.hpp"
