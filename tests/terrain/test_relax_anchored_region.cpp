// The relaxation of grown ground-anchored regions (detail/relax_anchored_region.hpp, called by
// synthesize_anchored_region) and the settling of the faces it leaves stretched.
#include <tessera/core/executor.hpp>
#include <tessera/terrain/synthesize_anchored_region.hpp>
#include <tessera/terrain/texture_stretch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include <catch2/catch.hpp>

#include "terrain_test_scenes.hpp"

using tessera::index_t;

namespace {

struct grown {
  tessera::anchored_regions plan;
  tessera::anchored_atlas atlas;
  tessera::anchored_region_stats total;
};

// every region of `mesh` grown with `opts` (in parallel through `exec` when given)
template <class E = tessera::serial_executor>
grown grow(const tessera::terrain_mesh& mesh, const tessera::anchored_synthesis_options& opts, index_t W,
           E&& exec = {}) {
  grown g{tessera::plan_anchored_regions(mesh, W, W, opts).value(), {}, {}};
  tessera::reset_anchored_atlas(g.plan, mesh.num_faces(), g.atlas);
  std::vector<tessera::anchored_region_stats> st(static_cast<std::size_t>(g.plan.num_regions()));
  std::vector<int> ok(st.size(), 0);
  exec.parallel_for(0, g.plan.num_regions(), [&](index_t r) {
    ok[static_cast<std::size_t>(r)] =
        tessera::synthesize_anchored_region(mesh, g.plan, r, W, W, opts, g.atlas, &st[static_cast<std::size_t>(r)])
            .ok();
  });
  for (std::size_t r = 0; r < st.size(); ++r) {
    REQUIRE(ok[r]);
    g.total.hot += st[r].hot, g.total.relaxed += st[r].relaxed, g.total.settled += st[r].settled;
    g.total.patches += st[r].patches;
  }
  return g;
}

double max_stretch_of(const tessera::terrain_mesh& mesh, const grown& g) {
  double worst = 1;
  for (index_t f = 0; f < mesh.num_faces(); ++f)
    worst = std::max(worst,
                     tessera::face_stretch(mesh, f, g.atlas.uv[static_cast<std::size_t>(f)], g.plan.texels_per_unit));
  return worst;
}

// whether side k of face f is continuous: the same placement on both faces, and then (checked) the
// two shared corners bit for bit the same
bool continuous(const tessera::terrain_mesh& mesh, const grown& g, index_t f, std::size_t k) {
  const auto fi = static_cast<std::size_t>(f);
  const bool same = ((g.atlas.seam[fi] >> k) & 1) == 0;
  if (same) {
    const auto n = static_cast<std::size_t>(mesh.neighbors[fi][k]);
    for (std::size_t e = 0; e < 2; ++e) {
      const auto v = mesh.faces[fi][(k + e) % 3];
      for (std::size_t j = 0; j < 3; ++j)
        if (mesh.faces[n][j] == v) {
          CHECK(std::memcmp(&g.atlas.uv[n][2 * j], &g.atlas.uv[fi][2 * ((k + e) % 3)], 8) == 0);
        }
    }
  }
  return same;
}

}  // namespace

TEST_CASE(
    "relaxation: lower stretch on curved ground, every face within max_stretch, inside the exemplar, "
    "no edge's continuity changed",
    "[terrain][anchored][relax]") {
  const auto mesh = terrain_test::prepared_terrain(64, 1, 14);
  const index_t W = 128;
  // the growth joins faces up to 2 in all three (as the relaxation's does by default)
  const tessera::anchored_synthesis_options off{.seed = 3, .max_stretch = 2, .relax_iterations = 0};
  tessera::anchored_synthesis_options relax_only = off, relax = off;
  relax_only.relax_iterations = relax.relax_iterations = 3;
  relax_only.relaxed_max_stretch = 2;  // no settling: the relaxation alone
  const grown a = grow(mesh, off, W), b = grow(mesh, relax_only, W), c = grow(mesh, relax, W);
  REQUIRE(a.total.hot == 0);
  REQUIRE(b.total.hot > 0);
  REQUIRE(b.total.relaxed > 0);
  REQUIRE(b.total.settled == 0);
  REQUIRE(c.total.settled > 0);
  const double worst_a = max_stretch_of(mesh, a), worst_b = max_stretch_of(mesh, b), worst_c = max_stretch_of(mesh, c);
  INFO("max stretch: grown " << worst_a << ", relaxed " << worst_b << ", settled " << worst_c);
  REQUIRE(worst_a > 1.5);  // the curved relief closes loops stretched
  REQUIRE(worst_b < worst_a);
  REQUIRE(worst_c <= relax.relaxed_max_stretch * (1 + 1e-6));
  REQUIRE(relax.relaxed_max_stretch == 1.3);  // the default
  // the 95th percentile falls too
  auto p95 = [&](const grown& g) {
    std::vector<double> s;
    for (index_t f = 0; f < mesh.num_faces(); ++f)
      s.push_back(tessera::face_stretch(mesh, f, g.atlas.uv[static_cast<std::size_t>(f)], g.plan.texels_per_unit));
    return tessera::summarize_stretch(s).p95;
  };
  REQUIRE(p95(b) < p95(a));
  const double half = 0.5 * static_cast<double>(W) - off.margin;
  index_t shared = 0, cont_a = 0, cont_c = 0, moved = 0;
  for (index_t f = 0; f < mesh.num_faces(); ++f) {
    const auto fi = static_cast<std::size_t>(f);
    for (const grown* g : {&b, &c}) {
      const auto& t = g->atlas.uv[fi];
      // never beyond max_stretch nor mirrored, never outside the exemplar less the margin
      REQUIRE(tessera::face_stretch(mesh, f, t, g->plan.texels_per_unit) <= off.max_stretch * (1 + 1e-6));
      for (const float x : t) REQUIRE(std::abs(static_cast<double>(x)) <= half);
    }
    moved += a.atlas.uv[fi] != b.atlas.uv[fi] ? 1 : 0;
    // the relaxation alone keeps the placements and seams exactly
    REQUIRE(b.atlas.patch[fi] == a.atlas.patch[fi]);
    REQUIRE(b.atlas.seam[fi] == a.atlas.seam[fi]);
    for (std::size_t k = 0; k < 3; ++k) {
      if (mesh.neighbors[fi][k] < 0) continue;
      ++shared;
      const bool ca = continuous(mesh, a, f, k), cb = continuous(mesh, b, f, k), cc = continuous(mesh, c, f, k);
      REQUIRE(ca == cb);
      REQUIRE((!cc || ca));  // settling only cuts edges
      cont_a += ca ? 1 : 0;
      cont_c += cc ? 1 : 0;
    }
  }
  REQUIRE(moved > 0);
  // only round the stretched faces (on this relief, curved at the scale of a face, about half)
  REQUIRE(moved < mesh.num_faces() * 6 / 10);
  // settling costs a few edges
  const double fa = static_cast<double>(cont_a) / static_cast<double>(shared),
               fc = static_cast<double>(cont_c) / static_cast<double>(shared);
  INFO("continuous: grown " << fa << ", settled " << fc);
  REQUIRE(fc < fa);
  REQUIRE(fc > fa - 0.02);
}

TEST_CASE("relaxation: nothing moves on developable ground", "[terrain][anchored][relax]") {
  // flat, tilted by 50 degrees, bent round a cylinder: the unfolding is congruent (to 0.5 % on the
  // cylinder), no face is stretched beyond relax_above, and the result is bit for bit the growth's
  for (const auto& mesh : terrain_test::developable_reliefs()) {
    const grown a = grow(mesh, {.seed = 3, .relax_iterations = 0}, 128),
                b = grow(mesh, {.seed = 3, .relax_above = 1.01, .relaxed_max_stretch = 1.01}, 128);
    REQUIRE(b.total.hot == 0);
    REQUIRE(b.total.settled == 0);
    REQUIRE(a.atlas.uv == b.atlas.uv);
    REQUIRE(a.atlas.patch == b.atlas.patch);
  }
}

TEST_CASE("relaxation: on flat ground a displaced vertex returns to the congruent map", "[terrain][anchored][relax]") {
  // the oracle: on a plane the as-rigid-as-possible minimum is the congruent unfolding itself, so a
  // vertex moved off it and relaxed with its neighbours held comes back (its faces to stretch 1)
  const auto mesh =
      tessera::prepare_terrain_mesh(tessera::make_terrain({.cells_x = 24, .cells_y = 24, .height = 0}).value()).value();
  const index_t W = 256;
  const tessera::anchored_synthesis_options opts{.seed = 1, .relax_iterations = 0};
  const auto plan = tessera::plan_anchored_regions(mesh, W, W, opts).value();
  REQUIRE(plan.num_regions() == 1);
  tessera::anchored_atlas atlas;
  tessera::reset_anchored_atlas(plan, mesh.num_faces(), atlas);
  REQUIRE(tessera::synthesize_anchored_region(mesh, plan, 0, W, W, opts, atlas));
  // the growth's scratch still holds the region: its table, corners and placements
  auto& scr = tessera::detail::anchored_thread_scratch();
  const auto i = static_cast<std::size_t>(plan.seed[0]);  // region index = face id (one region)
  const std::int32_t e = scr.corners[i][0];
  const tessera::vec2 home = scr.table.coord(e);
  scr.table.move(e, home + tessera::vec2{0.6, -0.4});
  const tessera::detail::anchored_relax_region reg{scr.geometry.data(), scr.patch.data(), scr.corners.data(),
                                                   static_cast<std::size_t>(mesh.num_faces()),
                                                   static_cast<std::size_t>(mesh.num_vertices())};
  const tessera::detail::anchored_relax_settings set{.iterations = 60,
                                                     .rings = 2,
                                                     .passes = 1,
                                                     .above = 1.0001,
                                                     .max_stretch = 1.55,
                                                     .half_w = 126,
                                                     .half_h = 126,
                                                     .texels_per_unit = plan.texels_per_unit};
  scr.relax.hot.assign(1, static_cast<std::int32_t>(i));
  REQUIRE(tessera::detail::relax_anchored_region(reg, scr.table, set, scr.relax) > 3);
  const tessera::vec2 back = scr.table.coord(e);
  INFO("moved back to " << back.x - home.x << ", " << back.y - home.y);
  REQUIRE(tessera::distance(back, home) < 0.02);
  for (const std::int32_t f : scr.relax.changed) {
    const auto& ce = scr.corners[static_cast<std::size_t>(f)];
    std::array<float, 6> t;
    for (std::size_t k = 0; k < 3; ++k) {
      t[2 * k] = static_cast<float>(scr.table.coord(ce[k]).x);
      t[2 * k + 1] = static_cast<float>(scr.table.coord(ce[k]).y);
    }
    REQUIRE(tessera::face_stretch(mesh, f, t, plan.texels_per_unit) < 1.01);
  }
}

TEST_CASE("relaxation: the same for any thread count and region order", "[terrain][anchored][relax]") {
  const auto mesh = terrain_test::prepared_terrain(48, 4, 10);
  const tessera::anchored_synthesis_options opts{.seed = 2, .region_size = 0.4};
  const grown serial = grow(mesh, opts, 96);
  REQUIRE(serial.total.hot > 0);
  REQUIRE(serial.total.relaxed > 0);
  tessera::thread_pool_executor p2(2), p3(3);
  for (const grown& g : {grow(mesh, opts, 96, p2), grow(mesh, opts, 96, p3)}) {
    REQUIRE(g.atlas.uv == serial.atlas.uv);
    REQUIRE(g.atlas.patch == serial.atlas.patch);
    REQUIRE(g.atlas.seam == serial.atlas.seam);
  }
}
