// Concept checks, positive and negative: which types model Image, WritableImage, Pixel, Mesh,
// UVMesh, Point, TileColoring and Executor. Mostly static_asserts (a failure breaks the build); the
// test cases also call explain_*() on every positive type, which must compile to nothing.
#include <tessera/tessera.hpp>
#include <tessera/adapters/eigen.hpp>
#include <tessera/adapters/glm.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/gtc/type_precision.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

using namespace tessera;  // NOLINT: a test file, not a header

namespace {

// --- user types that must model the concepts --------------------------------------------------

// Member style: the members are there, nothing to specialize.
struct member_image {
  index_t width() const { return 4; }
  index_t height() const { return 4; }
  pixel<std::uint8_t, 3> read(index_t, index_t) const { return {}; }
  void write(index_t, index_t, const pixel<std::uint8_t, 3>&) {}
};
struct member_readonly_image {
  int width() const { return 4; }  // any integer type converts
  int height() const { return 4; }
  float read(index_t, index_t) const { return 0; }
};

// Traits style: an engine texture with its own names, adapted by specializing image_traits.
namespace engine {
struct Texture {
  int GetWidth() const { return 2; }
  int GetHeight() const { return 2; }
  std::uint32_t Fetch(int, int) const { return 0; }  // packed RGBA8
  void Store(int, int, std::uint32_t) {}
};
}  // namespace engine

struct member_mesh {
  std::vector<std::array<float, 3>> p;
  std::vector<std::uint32_t> idx;
  std::size_t num_vertices() const { return p.size(); }
  std::size_t num_faces() const { return idx.size() / 3; }
  std::uint32_t face_vertex(index_t f, int k) const { return idx[static_cast<std::size_t>(3 * f + k)]; }
  const std::array<float, 3>& position(index_t v) const { return p[static_cast<std::size_t>(v)]; }
};
struct xyz {
  double x, y, z;
};
struct member_xyz_mesh : member_mesh {
  xyz position(index_t) const { return {}; }
};
struct member_uv_mesh : member_mesh {
  bool has_uvs() const { return false; }
  glm::vec2 corner_uv(index_t, int) const { return {}; }
};

struct job_system {
  template <class F>
  void parallel_for(index_t b, index_t e, F&& f) {
    for (index_t i = b; i < e; ++i) f(i);
  }
};

// --- types that must NOT model them -----------------------------------------------------------
struct no_read {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
};
struct double_pixels {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  double read(index_t, index_t) const { return 0; }
};
struct five_channels {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  std::array<float, 5> read(index_t, index_t) const { return {}; }
};
struct string_pixels {
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  std::string read(index_t, index_t) const { return {}; }
};
struct write_wrong_pixel {  // read gives RGB8, write takes a float: not writable with its own pixels
  index_t width() const { return 1; }
  index_t height() const { return 1; }
  pixel<std::uint8_t, 3> read(index_t, index_t) const { return {}; }
  void write(index_t, index_t, float) {}
};
struct mesh_without_positions {
  index_t num_vertices() const { return 0; }
  index_t num_faces() const { return 0; }
  index_t face_vertex(index_t, int) const { return 0; }
};
struct opaque_point {  // no p[i], no x/y/z
  float data[3];
};
struct mesh_with_opaque_positions : mesh_without_positions {
  opaque_point position(index_t) const { return {}; }
};
struct mesh_uvs_without_flag : member_mesh {
  glm::vec2 corner_uv(index_t, int) const { return {}; }
};

}  // namespace

template <>
struct tessera::image_traits<engine::Texture> {
  static index_t width(const engine::Texture& t) { return t.GetWidth(); }
  static index_t height(const engine::Texture& t) { return t.GetHeight(); }
  static pixel<std::uint8_t, 4> read(const engine::Texture& t, index_t x, index_t y) {
    const std::uint32_t v = t.Fetch(static_cast<int>(x), static_cast<int>(y));
    return {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(v >> 24)};
  }
  static void write(engine::Texture& t, index_t x, index_t y, const pixel<std::uint8_t, 4>& p) {
    t.Store(static_cast<int>(x), static_cast<int>(y), p[0] | p[1] << 8 | p[2] << 16 | std::uint32_t(p[3]) << 24);
  }
};

// --- Image / WritableImage ----------------------------------------------------------------------
static_assert(WritableImage<image_view<std::uint8_t, 4>>);
static_assert(WritableImage<image_view<float, 1>>);
static_assert(Image<image_view<const std::uint16_t, 2>>);
static_assert(!WritableImage<image_view<const std::uint16_t, 2>>);
static_assert(WritableImage<image_buffer<float, 3>>);
static_assert(WritableImage<image_buffer<std::uint16_t, 1>>);
static_assert(WritableImage<member_image>);
static_assert(Image<member_readonly_image> && !WritableImage<member_readonly_image>);
static_assert(WritableImage<engine::Texture>);
static_assert(std::is_same_v<pixel_t<engine::Texture>, pixel<std::uint8_t, 4>>);
static_assert(channels_v<engine::Texture> == 4);
static_assert(WritableImage<eigen_image_view<Eigen::MatrixXf>>);
static_assert(WritableImage<eigen_image_view<Eigen::Matrix<std::uint8_t, -1, -1, Eigen::RowMajor>>>);
static_assert(WritableImage<eigen_image_view<Eigen::Map<Eigen::MatrixXf>>>);
static_assert(Image<eigen_image_view<const Eigen::MatrixXf>> &&
              !WritableImage<eigen_image_view<const Eigen::MatrixXf>>);
static_assert(Image<eigen_image_view<Eigen::Map<const Eigen::MatrixXf>>> &&
              !WritableImage<eigen_image_view<Eigen::Map<const Eigen::MatrixXf>>>);
static_assert(std::is_same_v<pixel_t<eigen_image_view<Eigen::MatrixXd>>, float>);

static_assert(!Image<int>);
static_assert(!Image<std::vector<float>>);
static_assert(!Image<Eigen::MatrixXf>);  // a bare matrix: wrap it in eigen_image_view
static_assert(!Image<no_read>);
static_assert(!Image<double_pixels>);
static_assert(!Image<five_channels>);
static_assert(!Image<string_pixels>);
static_assert(Image<write_wrong_pixel> && !WritableImage<write_wrong_pixel>);
static_assert(!Image<tri_mesh>);

// --- Pixel ---------------------------------------------------------------------------------------
static_assert(Pixel<std::uint8_t> && Pixel<std::uint16_t> && Pixel<float>);
static_assert(Pixel<pixel<std::uint8_t, 1>> && Pixel<pixel<float, 4>>);
static_assert(Pixel<Eigen::Matrix<std::uint8_t, 4, 1>> && Pixel<Eigen::Vector3f> &&
              Pixel<Eigen::Array<std::uint16_t, 2, 1>>);
static_assert(Pixel<glm::u8vec4> && Pixel<glm::vec3> && Pixel<glm::u16vec1>);
static_assert(!Pixel<double> && !Pixel<int> && !Pixel<bool>);
static_assert(!Pixel<std::array<std::uint8_t, 5>> && !Pixel<std::array<double, 3>>);
static_assert(!Pixel<Eigen::Vector3d> && !Pixel<Eigen::VectorXf> && !Pixel<Eigen::Matrix<float, 5, 1>>);
static_assert(!Pixel<glm::dvec3> && !Pixel<glm::ivec4>);
static_assert(!Pixel<std::string>);

// --- Mesh / UVMesh / Point -----------------------------------------------------------------------
static_assert(UVMesh<tri_mesh>);
static_assert(UVMesh<mesh_view<float>> && UVMesh<mesh_view<double, std::int32_t>>);
static_assert(Mesh<member_mesh> && !UVMesh<member_mesh>);
static_assert(Mesh<member_xyz_mesh>);
static_assert(UVMesh<member_uv_mesh>);
static_assert(Mesh<eigen_mesh_view<Eigen::MatrixXd, Eigen::MatrixXi>>);
static_assert(Mesh<eigen_mesh_view<const Eigen::Matrix<float, -1, 3, Eigen::RowMajor>,
                                   Eigen::Map<const Eigen::Matrix<std::uint32_t, -1, 3, Eigen::RowMajor>>>>);

static_assert(!Mesh<int>);
static_assert(!Mesh<Eigen::MatrixXd>);  // bare V: use make_eigen_mesh_view(V, F)
static_assert(!Mesh<image_buffer<float, 3>>);
static_assert(!Mesh<mesh_without_positions>);
static_assert(!Mesh<mesh_with_opaque_positions>);
static_assert(Mesh<mesh_uvs_without_flag> && !UVMesh<mesh_uvs_without_flag>);

static_assert(Point<vec3> && Point<vec2> && Point<std::array<float, 3>> && Point<xyz>);
static_assert(Point<Eigen::Vector3d> && Point<Eigen::Vector2f> && Point<glm::vec3> && Point<glm::dvec2>);
static_assert(!Point<opaque_point> && !Point<int> && !Point<tri_mesh>);

// --- TileColoring / Executor ---------------------------------------------------------------------
static_assert(TileColoring<stored_tile_coloring>);
static_assert(!TileColoring<tri_mesh> && !TileColoring<int>);
static_assert(Executor<serial_executor> && Executor<thread_pool_executor> && Executor<job_system>);
static_assert(!Executor<int> && !Executor<member_image>);

TEST_CASE("explain_* compiles to nothing for every type that models the concepts") {
  explain_writable_image<image_view<std::uint8_t, 4>>();
  explain_writable_image<image_buffer<float, 3>>();
  explain_writable_image<member_image>();
  explain_image<member_readonly_image>();
  explain_writable_image<engine::Texture>();
  explain_writable_image<eigen_image_view<Eigen::MatrixXf>>();
  explain_image<eigen_image_view<const Eigen::MatrixXd>>();
  explain_mesh<tri_mesh>();
  explain_mesh<mesh_view<float>>();
  explain_mesh<member_mesh>();
  explain_mesh<member_xyz_mesh>();
  explain_mesh<eigen_mesh_view<Eigen::MatrixXd, Eigen::MatrixXi>>();
  SUCCEED("all explain_* calls compiled");
}

TEST_CASE("a traits-specialized engine texture runs through the core image functions") {
  engine::Texture t;
  const auto buf = to_buffer<float, 3>(t);
  REQUIRE(buf.ok());
  CHECK(buf->width() == 2);
  image_buffer<std::uint8_t, 4> src(2, 2, {1, 2, 3, 4});
  CHECK(copy_image(src, t).ok());
}
