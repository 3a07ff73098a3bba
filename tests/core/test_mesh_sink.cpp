#include <tessera/core/mesh_sink.hpp>

#include <tessera/core/mesh_view.hpp>
#include <tessera/core/random.hpp>
#include <tessera/core/tri_mesh.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace tessera;

namespace {
// a strip of n quads (2n triangles) with distinct, non-representable-in-float positions
tri_mesh strip(index_t n) {
  tri_mesh m;
  for (index_t i = 0; i <= n; ++i) {
    m.add_vertex({0.1 * double(i), 0.0, 1.0 / 3.0});
    m.add_vertex({0.1 * double(i), 1.0, -2.0 / 7.0});
  }
  for (index_t i = 0; i < n; ++i) {
    m.add_face(2 * i, 2 * i + 2, 2 * i + 1);
    m.add_face(2 * i + 1, 2 * i + 2, 2 * i + 3);
  }
  return m;
}
}  // namespace

TEST_CASE("mesh_sink: packed float / uint32 buffers receive the mesh, readable as a mesh_view", "[mesh_sink]") {
  const tri_mesh m = strip(5);
  std::vector<float> vb(3 * std::size_t(m.num_vertices()));
  std::vector<std::uint32_t> ib(3 * std::size_t(m.num_faces()));
  auto sink = make_mesh_sink<float>(vb.data(), vb.size() * sizeof(float), ib.data(), ib.size());
  REQUIRE(sink.ok());
  REQUIRE(write_mesh(m, *sink).ok());
  REQUIRE(sink->num_vertices() == m.num_vertices());
  REQUIRE(sink->num_faces() == m.num_faces());
  auto view = make_mesh_view(vb.data(), m.num_vertices(), ib.data(), m.num_faces());
  REQUIRE(view.ok());
  REQUIRE(validate_mesh(*view).ok());
  for (index_t v = 0; v < m.num_vertices(); ++v) {
    const vec3 p = m.positions[std::size_t(v)];
    REQUIRE(view->position(v) == std::array<float, 3>{float(p.x), float(p.y), float(p.z)});
  }
  for (index_t f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) REQUIRE(view->face_vertex(f, k) == m.face_vertex(f, k));
}

TEST_CASE("mesh_sink: double positions are bit-identical, uint16 indices through mesh_view", "[mesh_sink]") {
  const tri_mesh m = strip(7);
  std::vector<double> vb(3 * std::size_t(m.num_vertices()));
  std::vector<std::uint16_t> ib(3 * std::size_t(m.num_faces()));
  auto sink = make_mesh_sink<double, std::uint16_t>(vb.data(), vb.size() * sizeof(double), ib.data(), ib.size());
  REQUIRE(sink.ok());
  REQUIRE(write_mesh(m, *sink).ok());
  auto view = make_mesh_view(vb.data(), m.num_vertices(), ib.data(), m.num_faces());
  REQUIRE(view.ok());
  tri_mesh back;
  for (index_t v = 0; v < view->num_vertices(); ++v) back.add_vertex(vertex_position(*view, v));
  for (index_t f = 0; f < view->num_faces(); ++f)
    back.add_face(view->face_vertex(f, 0), view->face_vertex(f, 1), view->face_vertex(f, 2));
  REQUIRE(back == m);  // bit for bit
}

TEST_CASE("mesh_sink: interleaved records at a byte offset and stride, bytes outside stay untouched", "[mesh_sink]") {
  // property-style: every offset / stride that fits, including unaligned ones
  const tri_mesh m = strip(3);
  const std::size_t nv = std::size_t(m.num_vertices());
  counter_rng rng(9);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t stride = 12 + std::size_t(rng.below(29, std::uint64_t(trial), 0));  // 12..40 bytes
    const std::size_t offset = std::size_t(rng.below(stride - 12 + 1, std::uint64_t(trial), 1));
    const std::size_t bytes = offset + (nv - 1) * stride + 12;  // exactly enough
    std::vector<unsigned char> vb(bytes + 16, 0xAB);            // 16 guard bytes
    std::vector<std::uint32_t> ib(3 * std::size_t(m.num_faces()) + 2, 0xDEADBEEF);
    auto sink = make_mesh_sink<float>(vb.data(), bytes, ib.data(), ib.size() - 2, {offset, stride});
    REQUIRE(sink.ok());
    REQUIRE(write_mesh(m, *sink).ok());
    for (std::size_t v = 0; v < nv; ++v) {
      float xyz[3];
      std::memcpy(xyz, vb.data() + offset + v * stride, sizeof xyz);
      REQUIRE(xyz[0] == float(m.positions[v].x));
      REQUIRE(xyz[2] == float(m.positions[v].z));
      // bytes of the record that are not the position are untouched
      for (std::size_t b = 0; b < stride; ++b)
        if ((b < offset || b >= offset + 12) && v * stride + b < bytes) REQUIRE(vb[v * stride + b] == 0xAB);
    }
    for (std::size_t b = bytes; b < vb.size(); ++b) REQUIRE(vb[b] == 0xAB);
    REQUIRE(ib[ib.size() - 1] == 0xDEADBEEF);
    REQUIRE(ib[ib.size() - 2] == 0xDEADBEEF);
  }
}

TEST_CASE("mesh_sink: short buffers, bad layouts and uint16 overflow are statuses, nothing is written", "[mesh_sink]") {
  const tri_mesh m = strip(4);
  const std::size_t nv = std::size_t(m.num_vertices()), nf = std::size_t(m.num_faces());
  std::vector<float> vb(3 * nv, -1.0f);
  std::vector<std::uint32_t> ib(3 * nf, 7);
  // one byte short of vertex buffer
  auto a = make_mesh_sink<float>(vb.data(), vb.size() * sizeof(float) - 1, ib.data(), ib.size());
  REQUIRE(a.ok());
  const status sa = write_mesh(m, *a);
  REQUIRE(sa.code() == status_code::out_of_range);
  REQUIRE(sa.message().find("bytes of vertex buffer") != std::string::npos);
  // one index short
  auto b = make_mesh_sink<float>(vb.data(), vb.size() * sizeof(float), ib.data(), ib.size() - 1);
  const status sb = write_mesh(m, *b);
  REQUIRE(sb.code() == status_code::out_of_range);
  REQUIRE(sb.message().find(std::to_string(3 * nf) + " indices") != std::string::npos);
  // null buffers for a non-empty mesh
  auto c = make_mesh_sink<float, std::uint32_t>(nullptr, 1 << 20, nullptr, 1 << 20);
  REQUIRE(write_mesh(m, *c).code() == status_code::out_of_range);
  for (float x : vb) REQUIRE(x == -1.0f);
  for (auto i : ib) REQUIRE(i == 7);
  // an empty mesh needs no buffers
  REQUIRE(write_mesh(tri_mesh{}, *c).ok());
  // layouts whose positions do not fit the stride
  REQUIRE(make_mesh_sink<float>(vb.data(), 64, ib.data(), 3, {8, 16}).error().code() == status_code::invalid_argument);
  REQUIRE(make_mesh_sink<double>(vb.data(), 64, ib.data(), 3, {0, 20}).error().message().find("stride of 20") !=
          std::string::npos);
  REQUIRE(make_mesh_sink<float>(vb.data(), 64, ib.data(), 3, {0, std::size_t{1} << 40}).error().code() ==
          status_code::invalid_argument);
  // 16-bit indices: the vertex count and the limit are named
  std::vector<std::uint16_t> small(30);
  auto d = make_mesh_sink<float, std::uint16_t>(vb.data(), vb.size() * sizeof(float), small.data(), small.size());
  const status sd = d->prepare(70000, 10);
  REQUIRE(sd.code() == status_code::size_overflow);
  REQUIRE(sd.message().find("70000") != std::string::npos);
  REQUIRE(sd.message().find("65535") != std::string::npos);
  REQUIRE(d->prepare(-1, 0).code() == status_code::invalid_argument);
  // bad meshes: an index out of range, a position float cannot hold
  tri_mesh bad = m;
  bad.faces[1][2] = 99;
  REQUIRE(write_mesh(bad, *a).code() == status_code::out_of_range);
  tri_mesh huge = m;
  huge.positions[0].x = 1e300;
  auto e = make_mesh_sink<float>(vb.data(), vb.size() * sizeof(float), ib.data(), ib.size());
  REQUIRE(write_mesh(huge, *e).code() == status_code::invalid_argument);
  for (float x : vb) REQUIRE(x == -1.0f);
}

TEST_CASE("mesh_sink: a growing sink asks its callback for exactly the room it needs", "[mesh_sink]") {
  const tri_mesh m = strip(6);
  std::vector<std::byte> vertices;
  std::vector<std::uint16_t> indices;
  int calls = 0;
  auto sink = make_growing_mesh_sink<float, std::uint16_t>(
      [&](std::size_t bytes, std::size_t count, mesh_buffers<std::uint16_t>& b) {
        ++calls;
        vertices.resize(bytes);
        indices.resize(count);
        b = {vertices.data(), vertices.size(), indices.data(), indices.size()};
        return status{};
      },
      {4, 20});  // 20-byte records (e.g. a uv pair before the position), position at byte 4
  REQUIRE(sink.ok());
  REQUIRE(write_mesh(m, *sink).ok());
  REQUIRE(calls == 1);
  REQUIRE(vertices.size() == 4 + std::size_t(m.num_vertices() - 1) * 20 + 12);
  REQUIRE(indices.size() == 3 * std::size_t(m.num_faces()));
  REQUIRE(sink->position(3) ==
          std::array<float, 3>{float(m.positions[3].x), float(m.positions[3].y), float(m.positions[3].z)});
  REQUIRE(write_mesh(strip(2), *sink).ok());  // smaller: no new call
  REQUIRE(calls == 1);
  // a refusing callback's message is passed on
  auto refusing = make_growing_mesh_sink<float>(
      [](std::size_t, std::size_t, mesh_buffers<std::uint32_t>&) { return status::size_overflow("GPU heap full"); });
  const status s = write_mesh(m, *refusing);
  REQUIRE(s.code() == status_code::size_overflow);
  REQUIRE(s.message().find("GPU heap full") != std::string::npos);
  // a callback that returns short buffers is caught
  std::vector<float> tiny(3);
  auto liar = make_growing_mesh_sink<float>([&](std::size_t, std::size_t, mesh_buffers<std::uint32_t>& b) {
    b = {tiny.data(), tiny.size() * sizeof(float), nullptr, 0};
    return status{};
  });
  REQUIRE(write_mesh(m, *liar).code() == status_code::out_of_range);
  REQUIRE(make_growing_mesh_sink<float>(nullptr).error().code() == status_code::invalid_argument);
}
