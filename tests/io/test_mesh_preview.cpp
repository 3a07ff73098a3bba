#include <tessera/io/mesh_preview.hpp>

#include <tessera/geometry/mesh_exemplars.hpp>

#include <catch2/catch.hpp>

using namespace tessera;

// The renderer itself is tested in tests/render/test_render_mesh_preview.cpp.
TEST_CASE("mesh preview writes a PNG, and names the file it cannot write", "[mesh_preview]") {
  const auto m = make_ring_exemplar({.size = 4, .ring_segments = 12, .tube_segments = 6});
  REQUIRE(m.ok());
  REQUIRE(
      write_mesh_preview(std::string(TESSERA_TEST_OUTPUT_DIR) + "/preview_rings.png", *m, {.width = 64, .height = 48})
          .ok());
  REQUIRE(write_mesh_preview("/nonexistent-dir/x.png", *m, {.width = 8, .height = 8}).code() == status_code::io_error);
  REQUIRE_FALSE(write_mesh_preview(std::string(TESSERA_TEST_OUTPUT_DIR) + "/empty.png", tri_mesh{}).ok());
}
