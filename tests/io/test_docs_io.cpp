// The code blocks of docs/io.md, compiled and run (tests/structural/snippets.cmake keeps the page
// identical to the regions between the snippet markers).
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>

#include <tessera/core/image_buffer.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/png.hpp>

TEST_CASE("docs: io.md PNG and mesh files") {
  const auto dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "docs_io";
  std::filesystem::create_directories(dir);
  std::filesystem::current_path(dir);
  REQUIRE(tessera::write_png("exemplar.png", tessera::image_buffer<std::uint8_t, 3>(8, 4, {10, 20, 30})));
  tessera::tri_mesh crate;
  crate.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  crate.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  REQUIRE(tessera::write_mesh("crate.obj", crate));
  const tessera::status png = [] {
    // [snippet:io_png]
    auto img = tessera::read_png<float, 3>("exemplar.png");          // result<image_buffer<float, 3>>
    if (!img) return img.error();                                    // names the file, and the byte if corrupt
    if (auto s = tessera::write_png("out.png", *img); !s) return s;  // float -> 16-bit PNG
    auto info = tessera::read_png_info("exemplar.png");              // width, height, channels, bit_depth, palette
    // [/snippet]
    CHECK(info->width == 8);
    return tessera::status{};
  }();
  CHECK(png.ok());
  const tessera::status mesh = [] {
    // [snippet:io_mesh]
    auto mesh = tessera::read_mesh("crate.obj");  // result<tri_mesh>, uvs when the file has them
    if (!mesh) return mesh.error();
    if (auto s = tessera::write_mesh("crate.ply", *mesh, {.binary = true}); !s) return s;  // any Mesh type
    // [/snippet]
    CHECK(mesh->num_faces() == 4);
    return tessera::status{};
  }();
  CHECK(mesh.ok());
}
