// explain_* helpers: positive cases are called (they must compile to nothing); negative cases would
// stop compilation by design, so they are checked through the constexpr diagnosis the static_asserts
// are built on.
#include <tessera/core/explain.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/core/mesh_view.hpp>
#include <tessera/core/tri_mesh.hpp>

#include <array>
#include <cstdint>
#include <string>

#include <catch2/catch.hpp>

using tessera::index_t;
using tessera::detail::image_problem;
using tessera::detail::mesh_problem;

namespace {
struct no_size {
  float read(index_t, index_t) const { return 0; }
};
struct no_read {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
};
struct unknown_pixel {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  std::string read(index_t, index_t) const { return {}; }
};
struct double_pixels {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  std::array<double, 3> read(index_t, index_t) const { return {}; }
};
struct six_channels {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  std::array<float, 6> read(index_t, index_t) const { return {}; }
};
struct half_traits_pixel {
  std::uint8_t v;
};
struct half_traits_image {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  half_traits_pixel read(index_t, index_t) const { return {}; }
};
struct read_only {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  float read(index_t, index_t) const { return 0; }
};

struct mesh_no_counts {
  index_t face_vertex(index_t, int) const { return 0; }
};
struct mesh_no_face_vertex {
  index_t num_vertices() const { return 0; }
  index_t num_faces() const { return 0; }
};
struct mesh_no_position : mesh_no_face_vertex {
  index_t face_vertex(index_t, int) const { return 0; }
};
struct opaque_point {
  int secret;
};
struct mesh_bad_point : mesh_no_position {
  opaque_point position(index_t) const { return {}; }
};
struct mesh_string_counts {
  std::string num_vertices() const { return {}; }
  std::string num_faces() const { return {}; }
  index_t face_vertex(index_t, int) const { return 0; }
  std::array<float, 3> position(index_t) const { return {}; }
};
struct good_mesh : mesh_no_position {
  std::array<float, 3> position(index_t) const { return {}; }
};
struct mesh_bad_uv : good_mesh {
  bool has_uvs() const { return true; }
  opaque_point corner_uv(index_t, int) const { return {}; }
};
struct coloring_missing_colors {
  index_t num_faces() const { return 0; }
  int edge_color(index_t, int) const { return 0; }
};
}  // namespace

template <>
struct tessera::pixel_traits<half_traits_pixel> {  // no get/set
  using channel_type = std::uint8_t;
  static constexpr int channels = 1;
};

TEST_CASE("explain: fitting types compile to nothing", "[explain]") {
  tessera::explain_image<tessera::image_view<const std::uint8_t, 4>>();
  tessera::explain_writable_image<tessera::image_buffer<float, 3>>();
  tessera::explain_image<read_only>();
  tessera::explain_mesh<tessera::tri_mesh>();
  tessera::explain_mesh<good_mesh>();
  tessera::explain_uv_mesh<tessera::mesh_view<double>>();
  tessera::explain_tile_coloring<tessera::stored_tile_coloring>();
  tessera::explain_executor<tessera::serial_executor>();
  tessera::explain_executor<tessera::thread_pool_executor>();
  SUCCEED();
}

TEST_CASE("explain: each image problem is diagnosed", "[explain]") {
  using tessera::detail::image_problem_of;
  using tessera::detail::writable_image_problem_of;
  STATIC_REQUIRE(image_problem_of<tessera::image_buffer<std::uint16_t, 2>>() == image_problem::none);
  STATIC_REQUIRE(image_problem_of<no_size>() == image_problem::no_size);
  STATIC_REQUIRE(image_problem_of<int>() == image_problem::no_size);
  STATIC_REQUIRE(image_problem_of<no_read>() == image_problem::no_read);
  STATIC_REQUIRE(image_problem_of<unknown_pixel>() == image_problem::unknown_pixel);
  STATIC_REQUIRE(image_problem_of<double_pixels>() == image_problem::bad_channel_type);
  STATIC_REQUIRE(image_problem_of<six_channels>() == image_problem::bad_channel_count);
  STATIC_REQUIRE(image_problem_of<half_traits_image>() == image_problem::incomplete_pixel_traits);
  STATIC_REQUIRE(writable_image_problem_of<read_only>() == image_problem::not_writable);
  STATIC_REQUIRE(writable_image_problem_of<tessera::image_view<const float, 1>>() == image_problem::not_writable);
  STATIC_REQUIRE(writable_image_problem_of<tessera::image_view<float, 1>>() == image_problem::none);
  STATIC_REQUIRE(writable_image_problem_of<no_read>() == image_problem::no_read);  // first problem wins
}

TEST_CASE("explain: each mesh problem is diagnosed", "[explain]") {
  using tessera::detail::mesh_problem_of;
  using tessera::detail::uv_mesh_problem_of;
  STATIC_REQUIRE(mesh_problem_of<tessera::tri_mesh>() == mesh_problem::none);
  STATIC_REQUIRE(mesh_problem_of<mesh_no_counts>() == mesh_problem::no_counts);
  STATIC_REQUIRE(mesh_problem_of<mesh_no_face_vertex>() == mesh_problem::no_face_vertex);
  STATIC_REQUIRE(mesh_problem_of<mesh_no_position>() == mesh_problem::no_position);
  STATIC_REQUIRE(mesh_problem_of<mesh_bad_point>() == mesh_problem::bad_point);
  STATIC_REQUIRE(mesh_problem_of<mesh_string_counts>() == mesh_problem::incomplete);
  STATIC_REQUIRE(uv_mesh_problem_of<good_mesh>() == mesh_problem::no_uvs);
  STATIC_REQUIRE(uv_mesh_problem_of<mesh_bad_uv>() == mesh_problem::bad_uv_point);
  STATIC_REQUIRE(uv_mesh_problem_of<tessera::tri_mesh>() == mesh_problem::none);
  STATIC_REQUIRE(uv_mesh_problem_of<mesh_no_counts>() == mesh_problem::no_counts);
}

TEST_CASE("explain: tile colouring and executor concepts", "[explain]") {
  STATIC_REQUIRE_FALSE(tessera::TileColoring<coloring_missing_colors>);
  STATIC_REQUIRE_FALSE(tessera::Executor<int>);
  STATIC_REQUIRE(tessera::TileColoring<tessera::stored_tile_coloring>);
}
