#include <tessera/core/mesh_view.hpp>
#include <tessera/core/tri_mesh.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::mesh_view;
using tessera::status_code;
using tessera::vec2;
using tessera::vec3;

static_assert(tessera::Mesh<mesh_view<float>> && tessera::UVMesh<mesh_view<float>>);
static_assert(tessera::UVMesh<mesh_view<double, std::int32_t>>);

TEST_CASE("mesh_view: raw and interleaved buffers", "[mesh_view]") {
  // interleaved vertex records: x y z nx ny nz (stride 6)
  const std::vector<float> vb = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1, 1, 1, 0, 0, 0, 1};
  const std::vector<std::uint32_t> ib = {0, 1, 2, 2, 1, 3};
  const std::vector<float> uv = {0, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 1};
  auto m = tessera::make_mesh_view(vb.data(), 4, ib.data(), 2, uv.data(), 6);
  REQUIRE(m.ok());
  REQUIRE(m->num_vertices() == 4);
  REQUIRE(m->num_faces() == 2);
  REQUIRE(m->position_stride() == 6);
  REQUIRE(tessera::vertex_position(*m, 3) == vec3{1, 1, 0});
  REQUIRE(tessera::face_vertex(*m, 1, 2) == 3);
  REQUIRE(tessera::has_uvs(*m));
  REQUIRE(tessera::corner_uv(*m, 1, 2) == vec2{1, 1});
  REQUIRE(tessera::validate_mesh(*m).ok());

  auto no_uv = tessera::make_mesh_view(vb.data(), 4, ib.data(), 2, nullptr, 6);
  REQUIRE_FALSE(no_uv->has_uvs());
  auto t = tessera::to_tri_mesh(*m);
  REQUIRE(t->uvs.size() == 2);
  REQUIRE(t->positions[1] == vec3{1, 0, 0});

  // an empty mesh is valid, with null pointers
  auto empty = tessera::make_mesh_view<double, std::uint32_t>(nullptr, 0, nullptr, 0);
  REQUIRE(empty.ok());
  REQUIRE(tessera::validate_mesh(*empty).ok());
}

TEST_CASE("mesh_view: bad buffers are rejected with a status", "[mesh_view]") {
  const std::vector<double> vb(9, 0.0);
  const std::vector<std::uint32_t> ib = {0, 1, 2};
  auto code = [](const auto& r) { return r.error().code(); };
  REQUIRE(code(tessera::make_mesh_view(vb.data(), -1, ib.data(), 1)) == status_code::invalid_argument);
  REQUIRE(code(tessera::make_mesh_view(vb.data(), 3, ib.data(), -1)) == status_code::invalid_argument);
  REQUIRE(code(tessera::make_mesh_view(vb.data(), 3, ib.data(), 1, nullptr, 2)) == status_code::invalid_argument);
  const double* no_positions = nullptr;
  const std::uint32_t* no_indices = nullptr;
  auto np = tessera::make_mesh_view(no_positions, 3, ib.data(), 1);
  REQUIRE(code(np) == status_code::invalid_argument);
  REQUIRE(np.error().message().find("positions is null") != std::string::npos);
  REQUIRE(code(tessera::make_mesh_view(vb.data(), 3, no_indices, 1)) == status_code::invalid_argument);
  // counts that 32-bit indices cannot address, or that overflow a buffer length
  const index_t too_many = index_t{std::numeric_limits<std::uint32_t>::max()} + 1;
  REQUIRE(code(tessera::make_mesh_view(vb.data(), too_many, ib.data(), 1)) == status_code::size_overflow);
  const std::vector<std::int32_t> sb = {0, 1, 2};
  REQUIRE(code(tessera::make_mesh_view(vb.data(), index_t{1} << 31, sb.data(), 1)) == status_code::size_overflow);
  REQUIRE(code(tessera::make_mesh_view(vb.data(), 3, ib.data(), std::numeric_limits<index_t>::max() / 2)) ==
          status_code::size_overflow);
  REQUIRE(code(tessera::make_mesh_view(vb.data(), index_t{1} << 31, ib.data(), 1, nullptr,
                                       std::numeric_limits<index_t>::max() / 4)) == status_code::size_overflow);
}

TEST_CASE("mesh_view: index, NaN and degenerate problems are found by validate_mesh", "[mesh_view]") {
  const std::vector<float> vb = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<std::int32_t> negative = {0, -1, 2};
  const std::vector<std::int32_t> too_big = {0, 1, 3};
  const std::vector<std::int32_t> degenerate = {0, 1, 1};
  auto check = [&](const std::vector<std::int32_t>& ib) {
    return tessera::validate_mesh(*tessera::make_mesh_view(vb.data(), 3, ib.data(), 1));
  };
  REQUIRE(check(negative).code() == status_code::out_of_range);
  REQUIRE(check(too_big).code() == status_code::out_of_range);
  REQUIRE(check(degenerate).code() == status_code::invalid_argument);
  std::vector<float> nan_vb = vb;
  nan_vb[4] = std::numeric_limits<float>::quiet_NaN();
  const std::vector<std::int32_t> ok = {0, 1, 2};
  const auto s = tessera::validate_mesh(*tessera::make_mesh_view(nan_vb.data(), 3, ok.data(), 1), "terrain");
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(s.message().find("terrain: vertex 1") == 0);
  const std::vector<float> bad_uv = {0, 0, 1, 0, 0, std::numeric_limits<float>::infinity()};
  REQUIRE(tessera::validate_mesh(*tessera::make_mesh_view(vb.data(), 3, ok.data(), 1, bad_uv.data())).code() ==
          status_code::invalid_argument);
}

TEST_CASE("mesh_view: 16-bit index buffers, and the 16-bit vertex limit", "[mesh_view]") {
  const std::vector<float> vb = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const std::vector<std::uint16_t> ib = {0, 1, 2, 2, 1, 3};
  auto v = tessera::make_mesh_view(vb.data(), 4, ib.data(), 2);
  REQUIRE(v.ok());
  STATIC_REQUIRE(tessera::Mesh<tessera::mesh_view<float, std::uint16_t>>);
  REQUIRE(tessera::validate_mesh(*v).ok());
  REQUIRE(v->face_vertex(1, 2) == 3);
  REQUIRE(tessera::vertex_position(*v, 3) == tessera::vec3{1, 1, 0});
  // 65535 vertices fit (0xFFFF stays free: the primitive-restart index); 65536 do not, and say why
  REQUIRE(tessera::make_mesh_view(vb.data(), 65535, ib.data(), 2).ok());
  auto over = tessera::make_mesh_view(vb.data(), 65536, ib.data(), 2);
  REQUIRE(over.error().code() == status_code::size_overflow);
  REQUIRE(over.error().message().find("16-bit indices") != std::string::npos);
  REQUIRE(over.error().message().find("65535") != std::string::npos);
  const std::vector<std::uint16_t> out_of_range = {0, 1, 4};
  REQUIRE(tessera::validate_mesh(*tessera::make_mesh_view(vb.data(), 4, out_of_range.data(), 1)).code() ==
          status_code::out_of_range);
}
