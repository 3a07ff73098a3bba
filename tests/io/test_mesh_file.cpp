#include <tessera/io/mesh_file.hpp>

#include <string>

#include <catch2/catch.hpp>

#include "mesh_samples.hpp"

using tessera::mesh_format;
using tessera::status_code;
using tessera::tri_mesh;

TEST_CASE("mesh_file: the format comes from the extension, in any case", "[mesh_file]") {
  REQUIRE(*tessera::mesh_format_of("a/b/mesh.obj") == mesh_format::obj);
  REQUIRE(*tessera::mesh_format_of("MESH.OFF") == mesh_format::off);
  REQUIRE(*tessera::mesh_format_of("x.y.Ply") == mesh_format::ply);
  REQUIRE(tessera::is_mesh_path("m.obj"));
  REQUIRE_FALSE(tessera::is_mesh_path("m.png"));
  for (const char* bad : {"mesh.stl", "mesh", "dir.obj/mesh", "mesh.", ".obj/x"}) {
    const auto r = tessera::mesh_format_of(bad);
    INFO(bad);
    REQUIRE(r.error().code() == status_code::unsupported);
    REQUIRE(r.error().message().rfind(bad, 0) == 0);
  }
  REQUIRE(tessera::mesh_format_of("mesh.stl").error().message().find("'stl'") != std::string::npos);
  REQUIRE(tessera::to_string(mesh_format::ply) == "ply");
}

TEST_CASE("mesh_file: a mesh survives OBJ -> PLY -> OFF -> OBJ", "[mesh_file]") {
  const tri_mesh m = samples::grid(3, 3, true);
  REQUIRE(tessera::write_mesh(samples::out_path("chain.obj"), m).ok());
  auto a = tessera::read_mesh(samples::out_path("chain.obj"));
  REQUIRE(*a == m);
  REQUIRE(tessera::write_mesh(samples::out_path("chain.PLY"), *a, {.binary = true}).ok());
  auto b = tessera::read_mesh(samples::out_path("chain.PLY"));
  REQUIRE(*b == m);
  REQUIRE(tessera::write_mesh(samples::out_path("chain.off"), *b).ok());
  auto c = tessera::read_mesh(samples::out_path("chain.off"));
  REQUIRE(c->positions == m.positions);
  REQUIRE(c->faces == m.faces);
  REQUIRE_FALSE(c->has_uvs());  // OFF holds no uvs
  // --binary selects binary PLY
  const auto bytes = tessera::detail::read_file(samples::out_path("chain.PLY"));
  REQUIRE(bytes->find("format binary_little_endian 1.0") != std::string::npos);
}

namespace graphlib {  // a mesh type whose namespace has same-named free functions (see test_tri_mesh.cpp)
struct surface {};
inline int num_vertices(const surface&) { return -99; }
inline bool has_uvs(const surface&) { return true; }
}  // namespace graphlib
template <>
struct tessera::mesh_traits<graphlib::surface> {
  static index_t num_vertices(const graphlib::surface&) { return 3; }
  static index_t num_faces(const graphlib::surface&) { return 1; }
  static index_t face_vertex(const graphlib::surface&, index_t, int k) { return k; }
  static tessera::vec3 position(const graphlib::surface&, index_t v) { return {double(v == 1), double(v == 2), 0}; }
};

TEST_CASE("mesh_file: writers reach foreign meshes only through mesh_traits", "[mesh_file]") {
  for (const char* name : {"foreign.obj", "foreign.off", "foreign.ply"}) {
    REQUIRE(tessera::write_mesh(samples::out_path(name), graphlib::surface{}).ok());
    const auto back = tessera::read_mesh(samples::out_path(name));
    REQUIRE(back->num_vertices() == 3);
    REQUIRE_FALSE(back->has_uvs());
  }
}

TEST_CASE("mesh_file: errors name the file", "[mesh_file]") {
  const tri_mesh m = samples::grid(1, 1, false);
  REQUIRE(tessera::write_mesh(samples::out_path("x.stl"), m).code() == status_code::unsupported);
  REQUIRE(tessera::read_mesh(samples::out_path("x.stl")).error().code() == status_code::unsupported);
  const auto missing = tessera::read_mesh(samples::out_path("missing.ply"));
  REQUIRE(missing.error().code() == status_code::io_error);
  REQUIRE(missing.error().message().find("missing.ply") != std::string::npos);
  REQUIRE(tessera::detail::write_file(samples::out_path("garbage.obj"), std::string("\x7f"
                                                                                    "ELF\0\0\0",
                                                                                    7))
              .ok());
  const auto g = tessera::read_mesh(samples::out_path("garbage.obj"));
  REQUIRE(g.error().code() == status_code::parse_error);
  REQUIRE(g.error().message().find("garbage.obj, line 1") != std::string::npos);
}
