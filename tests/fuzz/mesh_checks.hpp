// What the mesh fuzz targets check beyond "no crash": a successful read passes validate_mesh, and
// writing it in every format reads back.
#pragma once

#include <tessera/core/mesh.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/io/obj.hpp>
#include <tessera/io/off.hpp>
#include <tessera/io/ply.hpp>

#include "fuzz_target.hpp"

namespace tessera_fuzz {
inline void check_mesh_round_trips(const tessera::tri_mesh& m) {
  FUZZ_CHECK(tessera::validate_mesh(m, "fuzz").ok());
  if (m.num_faces() == 0 && m.num_vertices() == 0) return;
  auto obj = tessera::parse_obj(tessera::format_obj(m), "roundtrip.obj");
  FUZZ_CHECK(obj.ok());
  FUZZ_CHECK(obj->positions == m.positions && obj->faces == m.faces && obj->has_uvs() == m.has_uvs());
  auto off = tessera::parse_off(tessera::format_off(m), "roundtrip.off");
  FUZZ_CHECK(off.ok());
  FUZZ_CHECK(off->positions == m.positions && off->faces == m.faces);
  for (bool binary : {false, true}) {
    auto ply = tessera::parse_ply(tessera::format_ply(m, {.binary = binary}), "roundtrip.ply");
    FUZZ_CHECK(ply.ok());
    FUZZ_CHECK(ply->positions == m.positions && ply->faces == m.faces && ply->has_uvs() == m.has_uvs());
  }
}
}  // namespace tessera_fuzz
