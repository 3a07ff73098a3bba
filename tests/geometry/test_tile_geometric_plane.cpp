// tile_geometric_plane / geometric_plane_layout::write into a mesh_sink (engine buffers) against
// the tri_mesh output: bit for bit in double / uint32, rounded once in float, uint16 refused with the
// count when it does not fit, interleaved strides, short buffers refused with nothing written.
#include <tessera/geometry/tile_geometric_plane.hpp>

#include <tessera/core/executor.hpp>
#include <tessera/core/mesh_sink.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/geometry/geometric_wang_tiles.hpp>
#include <tessera/geometry/mesh_exemplars.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace tessera;

namespace {
const geometric_tile_set& small_set() {
  static const geometric_tile_set set = [] {
    const quilt_exemplar ex = *prepare_quilt_exemplar(
        *make_ring_exemplar({.size = 8, .spacing = 2.0, .ring_segments = 8, .tube_segments = 4, .seed = 3}));
    geometric_wang_options o;
    o.tile_size = 4.0;
    o.quilt.seed = 11;
    auto r = build_geometric_wang_tiles(ex, o);
    REQUIRE(r.ok());
    return std::move(*r);
  }();
  return set;
}
}  // namespace

TEST_CASE("tile_geometric_plane into a sink: double/uint32 equals the tri_mesh bit for bit, float rounds once",
          "[geometric_wang][mesh_sink]") {
  const auto& set = small_set();
  thread_pool_executor pool(3);
  for (index_t cols : {1, 3, 5})
    for (index_t rows : {1, 4}) {
      auto coloring = scanline_coloring::create(2, 2, cols, rows, std::uint64_t(cols * 10 + rows));
      REQUIRE(coloring.ok());
      const auto plane = tile_geometric_plane(set, *coloring, cols, rows);
      REQUIRE(plane.ok());
      const std::size_t nv = plane->positions.size(), nf = plane->faces.size();
      // double / uint32, through a thread pool
      std::vector<double> vd(3 * nv);
      std::vector<std::uint32_t> id(3 * nf);
      auto sd = make_mesh_sink<double>(vd.data(), vd.size() * sizeof(double), id.data(), id.size());
      REQUIRE(tile_geometric_plane(set, *coloring, cols, rows, *sd, pool).ok());
      auto view = make_mesh_view(vd.data(), index_t(nv), id.data(), index_t(nf));
      REQUIRE(view.ok());
      tri_mesh back;
      for (index_t v = 0; v < view->num_vertices(); ++v) back.add_vertex(vertex_position(*view, v));
      for (index_t f = 0; f < view->num_faces(); ++f)
        back.add_face(view->face_vertex(f, 0), view->face_vertex(f, 1), view->face_vertex(f, 2));
      REQUIRE(back == *plane);
      // float / uint16 in an interleaved 32-byte record at offset 12 (normal before, uv after)
      std::vector<unsigned char> rec(32 * nv, 0x5A);
      std::vector<std::uint16_t> i16(3 * nf);
      auto sf = make_mesh_sink<float, std::uint16_t>(rec.data(), rec.size(), i16.data(), i16.size(), {12, 32});
      auto layout = plan_geometric_plane(set, *coloring, cols, rows);
      REQUIRE(layout.ok());
      REQUIRE(layout->write(*sf).ok());
      for (std::size_t v = 0; v < nv; ++v) {
        float p[3];
        std::memcpy(p, rec.data() + 32 * v + 12, sizeof p);
        REQUIRE(p[0] == float(plane->positions[v].x));
        REQUIRE(p[1] == float(plane->positions[v].y));
        REQUIRE(p[2] == float(plane->positions[v].z));
        for (std::size_t b = 0; b < 12; ++b) REQUIRE(rec[32 * v + b] == 0x5A);
        for (std::size_t b = 24; b < 32; ++b) REQUIRE(rec[32 * v + b] == 0x5A);
      }
      for (std::size_t f = 0; f < nf; ++f)
        for (std::size_t k = 0; k < 3; ++k) REQUIRE(index_t(i16[3 * f + k]) == plane->faces[f][k]);
    }
}

TEST_CASE("tile_geometric_plane into a sink: uint16 overflow and short buffers are statuses, nothing written",
          "[geometric_wang][mesh_sink]") {
  const auto& set = small_set();
  // a grid large enough for more than 65535 vertices
  index_t cols = 1;
  index_t nv = 0;
  auto one = tile_geometric_plane(set, *scanline_coloring::create(2, 2, 2, 2, 1), 2, 2);
  REQUIRE(one.ok());
  const double per_cell = double(one->num_vertices()) / 4.0;
  cols = index_t(std::sqrt(70000.0 / per_cell)) + 2;
  auto big = scanline_coloring::create(2, 2, cols, cols, 4);
  REQUIRE(big.ok());
  auto layout = plan_geometric_plane(set, *big, cols, cols);
  REQUIRE(layout.ok());
  nv = layout->num_vertices();
  REQUIRE(nv > 65535);
  std::vector<float> vb(3 * std::size_t(nv), -1.0f);
  std::vector<std::uint16_t> ib(3 * std::size_t(layout->num_faces()), 9);
  auto s16 = make_mesh_sink<float, std::uint16_t>(vb.data(), vb.size() * sizeof(float), ib.data(), ib.size());
  const status st = tile_geometric_plane(set, *big, cols, cols, *s16);
  REQUIRE(st.code() == status_code::size_overflow);
  REQUIRE(st.message().find(std::to_string(nv)) != std::string::npos);
  REQUIRE(st.message().find("65535") != std::string::npos);
  for (float x : vb) REQUIRE(x == -1.0f);
  // short buffers: one vertex, one index short
  std::vector<std::uint32_t> i32(3 * std::size_t(layout->num_faces()), 9);
  auto sv = make_mesh_sink<float>(vb.data(), vb.size() * sizeof(float) - 12, i32.data(), i32.size());
  REQUIRE(layout->write(*sv).code() == status_code::out_of_range);
  auto si = make_mesh_sink<float>(vb.data(), vb.size() * sizeof(float), i32.data(), i32.size() - 1);
  REQUIRE(layout->write(*si).code() == status_code::out_of_range);
  for (float x : vb) REQUIRE(x == -1.0f);
  for (auto i : i32) REQUIRE(i == 9);
  // exact buffers work
  auto ok = make_mesh_sink<float>(vb.data(), vb.size() * sizeof(float), i32.data(), i32.size());
  REQUIRE(layout->write(*ok).ok());
  REQUIRE(validate_mesh(*make_mesh_view(vb.data(), nv, i32.data(), layout->num_faces())).ok());
}
