// Shared by the mesh-format tests: small meshes with awkward coordinates, and the invariant every
// reader must keep on damaged input.
#pragma once

#include <cstdint>
#include <string>

#include <catch2/catch.hpp>

#include <tessera/core/random.hpp>
#include <tessera/core/status.hpp>
#include <tessera/core/tri_mesh.hpp>

namespace samples {

inline std::string out_path(const std::string& name) {
  std::string path = TESSERA_TEST_OUTPUT_DIR;
  path += '/';
  path += name;
  return path;
}

/// A (cols x rows)-quad grid with jittered double coordinates (values that need all 17 digits),
/// optionally with per-corner uvs that are exact in float.
inline tessera::tri_mesh grid(int cols, int rows, bool uvs, std::uint64_t seed = 1) {
  const tessera::counter_rng rng(seed);
  tessera::tri_mesh m;
  for (int y = 0; y <= rows; ++y)
    for (int x = 0; x <= cols; ++x)
      m.add_vertex({x + 0.3 * rng.uniform(x, y, 0), y - 1e-7 * rng.uniform(x, y, 1), 1e5 * rng.uniform(x, y, 2) - 5e4});
  auto id = [&](int x, int y) { return tessera::index_t{y * (cols + 1) + x}; };
  auto uv = [&](int x, int y) { return tessera::vec2{x / 64.0 + 0.25, y / 128.0 - 0.5}; };
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) {
      if (uvs) {
        m.add_face(id(x, y), id(x + 1, y), id(x + 1, y + 1), {uv(x, y), uv(x + 1, y), uv(x + 1, y + 1)});
        m.add_face(id(x, y), id(x + 1, y + 1), id(x, y + 1), {uv(x, y), uv(x + 1, y + 1), uv(x, y + 1)});
      } else {
        m.add_face(id(x, y), id(x + 1, y), id(x + 1, y + 1));
        m.add_face(id(x, y), id(x + 1, y + 1), id(x, y + 1));
      }
    }
  return m;
}

/// What a reader may return for damaged input: a mesh that passes validate_mesh, or a parse_error
/// whose message starts with the file name.
inline void require_valid_or_parse_error(const tessera::result<tessera::tri_mesh>& r, const std::string& name) {
  if (r.ok()) {
    REQUIRE(tessera::validate_mesh(*r).ok());
  } else {
    INFO(r.error().to_string());
    REQUIRE(r.error().code() == tessera::status_code::parse_error);
    REQUIRE(r.error().message().rfind(name, 0) == 0);
  }
}

/// Requires a parse_error whose message starts with "NAME, line LINE:" and contains `text`.
inline void require_error_at_line(const tessera::result<tessera::tri_mesh>& r, const std::string& name, int line,
                                  const std::string& text) {
  REQUIRE_FALSE(r.ok());
  INFO(r.error().to_string());
  REQUIRE(r.error().code() == tessera::status_code::parse_error);
  REQUIRE(r.error().message().rfind(name + ", line " + std::to_string(line) + ":", 0) == 0);
  REQUIRE(r.error().message().find(text) != std::string::npos);
}

}  // namespace samples
