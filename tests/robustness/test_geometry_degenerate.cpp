// Degenerate-content matrix of the geometry family: every entry point on empty meshes, one
// triangle, zero-area faces, duplicated vertices, coincident elements, open borders, non-manifold
// fans, NaN and 1e300 coordinates, and absurd options. Each call gives a valid output or a status.
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <catch2/catch.hpp>
#include <tessera/geometry/bvh.hpp>
#include <tessera/geometry/check_geometric_texture.hpp>
#include <tessera/geometry/constrained_mesh_quilt.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/icp.hpp>
#include <tessera/geometry/laplacian.hpp>
#include <tessera/geometry/mesh_elements.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/geometry/mesh_quilt.hpp>
#include <tessera/geometry/quilt_exemplar.hpp>
#include <tessera/geometry/tile_geometric_plane.hpp>
#include <tessera/tiling/complete_tile_set.hpp>
#include <tessera/tiling/hash_coloring.hpp>

#include "robustness_support.hpp"

using robust::index_t;

namespace {
tessera::mesh_quilt_options quick_quilt() {
  tessera::mesh_quilt_options o;
  o.max_samples = 24;
  o.icp_iterations = 4;
  o.seed = 5;
  return o;
}
}  // namespace

TEST_CASE("robustness: geometry entry points on degenerate meshes") {
  for (const auto& [name, mesh] : robust::degenerate_meshes()) {
    INFO("mesh: " << name);
    const tessera::tri_mesh copy = mesh;
    robust::ok_or_refused_result(tessera::extract_elements(mesh));
    robust::ok_or_refused_result(tessera::extract_elements(mesh, {.require_closed = false, .require_manifold = false}));
    robust::ok_or_refused_result(tessera::check_geometric_texture(mesh, {0, 0, 6, 6}));
    robust::ok_or_refused_result(tessera::laplacian_deform(mesh, {}, {}));
    auto ex = tessera::prepare_quilt_exemplar(mesh, {});
    if (robust::ok_or_refused_result(ex)) {
      auto q = tessera::mesh_quilt(*ex, 2.5, 2.0, quick_quilt());
      if (robust::ok_or_refused_result(q)) {
        auto report = tessera::check_geometric_texture(q->mesh);
        REQUIRE(report);
        CHECK(report->intersecting_pairs == 0);
      }
      auto c = tessera::constrained_mesh_quilt(*ex, {0, 0, 2, 2}, {}, quick_quilt());
      robust::ok_or_refused_result(c);
    }
    CHECK(mesh.positions.size() == copy.positions.size());
    CHECK(mesh.faces == copy.faces);
  }
}

TEST_CASE("robustness: geometry options out of range are refused") {
  tessera::tri_mesh many;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) robust::add_tetrahedron(many, 1.0 * i, 1.0 * j);
  auto ex = tessera::prepare_quilt_exemplar(many, {}).value();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double size : {0.0, -1.0, nan, inf, 1e300}) {
    INFO("size " << size);
    robust::check_refusal(tessera::mesh_quilt(ex, size, 2.0, quick_quilt()).error());
    robust::check_refusal(tessera::constrained_mesh_quilt(ex, {0, 0, size, 2}, {}, quick_quilt()).error());
    tessera::geometric_wang_options wo;
    wo.tile_size = size;
    robust::check_refusal(tessera::build_geometric_wang_tiles(ex, wo).error());
  }
  auto o = quick_quilt();
  o.lambda = nan;
  robust::check_refusal(tessera::mesh_quilt(ex, 2, 2, o).error());
  o = quick_quilt();
  o.rules = static_cast<tessera::merge_rules>(2);
  robust::check_refusal(tessera::mesh_quilt(ex, 2, 2, o).error());
  for (double cell : {-1.0, nan, 1e-300}) {
    INFO("cell " << cell);
    robust::check_refusal(tessera::prepare_quilt_exemplar(many, {.cell_size = cell}).error());
  }
  tessera::laplacian_deform_options lo;
  lo.weighting = static_cast<tessera::laplacian_weighting>(3);
  robust::check_refusal(tessera::laplacian_deform(many, {}, {}, lo).error());
  tessera::geometric_wang_options wo;
  wo.tile_size = 3;
  wo.horizontal_colors = 1 << 16;
  robust::check_refusal(tessera::build_geometric_wang_tiles(ex, wo).error());
  // procedural exemplars refuse sizes they cannot build in reasonable memory
  tessera::ring_exemplar_options ro;
  ro.ring_segments = 1 << 30;
  robust::check_refusal(tessera::make_ring_exemplar(ro).error());
  tessera::weave_exemplar_options weo;
  weo.around = 1 << 20;
  robust::check_refusal(tessera::make_weave_exemplar(weo).error());
}

TEST_CASE("robustness: tile_geometric_plane on degenerate tile sets and grids") {
  tessera::geometric_tile_set set;
  set.tile_size = 1;
  set.horizontal_colors = set.vertical_colors = 2;
  for (index_t t = 0; t < tessera::complete_tile_count(2, 2); ++t) {
    set.edges.push_back(tessera::complete_tile_edges(t, 2, 2));
    tessera::tri_mesh m;
    robust::add_tetrahedron(m, 0.3, 0.3, 0.3);
    set.tiles.push_back(m);
  }
  auto plane = tessera::hash_coloring::create(2, 2, 1).value();
  auto small = plane.window(0, 0, 3, 2).value();
  auto ok = tessera::tile_geometric_plane(set, small, 3, 2);
  REQUIRE(ok);
  CHECK(ok->num_faces() == 6 * 4);
  robust::check_refusal(tessera::tile_geometric_plane(set, small, 4, 2).error());  // wrong grid
  auto bad = set;
  for (auto& t : bad.tiles) t.positions[0].x = 1e300;
  robust::check_refusal(tessera::tile_geometric_plane(bad, small, 3, 2).error());
  bad = set;
  for (auto& t : bad.tiles) t.positions[1].y = std::numeric_limits<double>::quiet_NaN();
  robust::ok_or_refused_result(tessera::tile_geometric_plane(bad, small, 3, 2));
  bad = set;
  bad.tiles.pop_back();
  robust::check_refusal(tessera::tile_geometric_plane(bad, small, 3, 2).error());
  bad = set;
  for (auto& t : bad.tiles) t = {};
  robust::ok_or_refused_result(tessera::tile_geometric_plane(bad, small, 3, 2));
  auto huge = plane.window(0, 0, index_t{1} << 20, index_t{1} << 11).value();
  robust::check_refusal(tessera::tile_geometric_plane(set, huge, index_t{1} << 20, index_t{1} << 11).error());
  robust::check_refusal(tessera::validate_geometric_plane_size(set, -1, 4));
}
