// 04_raw_buffers: raw engine memory through views, the way Eigen::Map wraps a pointer.
//   * image_view over a region of a texture atlas: pointer, width, height and the atlas's row stride;
//   * mesh_view over an interleaved vertex buffer (position, normal, uv per vertex) and a uint32 index
//     buffer, without copying either.
// The make_* functions validate what the caller passes; the last part shows their messages.
// Usage: example_04_raw_buffers [OUTPUT_DIR]   (writes 04_raw_buffers_atlas.png and _mesh.obj)
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/mesh_file.hpp>
#include <tessera/io/png.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";

  // [snippet:raw-image]
  // A 192 x 64 RGBA8 atlas owned by the engine; tiles are 64 x 64 regions of it.
  const std::ptrdiff_t atlas_w = 192, atlas_h = 64, tile = 64, stride = atlas_w * 4;  // stride in channel values
  std::vector<std::uint8_t> atlas(std::size_t(stride * atlas_h), 0);
  const tessera::exemplar_kind kinds[] = {tessera::exemplar_kind::sand, tessera::exemplar_kind::rock,
                                          tessera::exemplar_kind::dots};
  for (int i = 0; i < 3; ++i) {
    auto region = tessera::make_image_view<4>(atlas.data() + i * tile * 4, tile, tile, stride);
    if (!region) return fail(region.error());
    auto tile_image = tessera::make_exemplar<std::uint8_t, 3>(kinds[i], {.width = tile, .height = tile});
    if (!tile_image) return fail(tile_image.error());
    if (auto s = tessera::copy_image(*tile_image, *region); !s) return fail(s);
  }
  // [/snippet]
  auto whole = tessera::make_image_view<4>(atlas.data(), atlas_w, atlas_h, stride);
  if (!whole) return fail(whole.error());
  const std::string atlas_path = dir + "/04_raw_buffers_atlas.png";
  if (auto s = tessera::write_png(atlas_path, *whole); !s) return fail(s);

  // [snippet:raw-mesh]
  // An interleaved vertex buffer as the engine uploads it: per vertex a position (x, y, z), a
  // normal (nx, ny, nz) and a uv (u, v), 8 floats. Two separate quads: a floor and a wall.
  const std::vector<float> vertices = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 1, 1, 0, 2, 2, 0, 0, 0, 1,
                                       1, 1, 0, 2, 0, 0, 0, 1, 0, 1, 4, 0, 0, 1, 0, 0, 0, 0, 4, 1, 0, 1,
                                       0, 0, 1, 0, 4, 1, 1, 1, 0, 0, 1, 1, 4, 0, 1, 1, 0, 0, 0, 1};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  auto mesh = tessera::make_mesh_view(vertices.data(), std::ptrdiff_t(vertices.size() / 8), indices.data(),
                                      std::ptrdiff_t(indices.size() / 3), nullptr, /*position_stride=*/8);
  if (!mesh) return fail(mesh.error());
  if (auto s = tessera::validate_mesh(*mesh, "level geometry"); !s) return fail(s);  // indices, NaN, degenerate

  const auto components = tessera::connected_components(*mesh);
  const auto normals = tessera::face_normals(*mesh);
  const auto box = tessera::bounding_box(*mesh);
  // [/snippet]
  std::printf("mesh: %td vertices, %td faces, %td components, %zu boundary edges\n", mesh->num_vertices(),
              mesh->num_faces(), components.count, tessera::boundary_edges(*mesh).size());
  for (std::ptrdiff_t f = 0; f < mesh->num_faces(); ++f) {
    const auto& n = normals[std::size_t(f)];
    std::printf("  face %td: component %td, normal (%g, %g, %g)\n", f, components.face_component[std::size_t(f)], n.x,
                n.y, n.z);
  }
  std::printf("  bounding box (%g, %g, %g) - (%g, %g, %g)\n", box.min.x, box.min.y, box.min.z, box.max.x, box.max.y,
              box.max.z);
  const std::string mesh_path = dir + "/04_raw_buffers_mesh.obj";
  if (auto s = tessera::write_mesh(mesh_path, *mesh); !s) return fail(s);  // straight from the engine's buffers

  // [snippet:raw-errors]
  // What the views say about bad buffers (nothing crashes, nothing is written).
  const auto narrow = tessera::make_image_view<4>(atlas.data(), 64, 64, /*stride=*/100);
  const auto null_data = tessera::make_image_view<3>(static_cast<std::uint8_t*>(nullptr), 8, 8);
  const auto huge = tessera::make_image_view<4>(atlas.data(), std::ptrdiff_t(1) << 40, 4);
  const std::vector<std::uint32_t> bad_indices = {0, 1, 9};
  const auto bad_mesh = tessera::make_mesh_view(vertices.data(), 8, bad_indices.data(), 1, nullptr, 8);
  if (!bad_mesh) return fail(bad_mesh.error());  // the pointers and counts are fine: the index is not
  std::printf("stride too small: %s\n", narrow.error().to_string().c_str());
  std::printf("null data:        %s\n", null_data.error().to_string().c_str());
  std::printf("overflowing size: %s\n", huge.error().to_string().c_str());
  std::printf("bad index:        %s\n", tessera::validate_mesh(*bad_mesh).to_string().c_str());
  // [/snippet]

  std::printf("wrote %s\nwrote %s\n", atlas_path.c_str(), mesh_path.c_str());
  return 0;
}
