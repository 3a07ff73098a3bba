// Tests for tessera/adapters/eigen.hpp: Eigen vectors as pixels and points, eigen_image_view over
// matrices / Maps / Blocks in both storage orders, eigen_mesh_view over V/F matrices, and bad input.
#include <tessera/adapters/eigen.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_checks.hpp>
#include <tessera/core/mesh_topology.hpp>
#include <tessera/core/tri_mesh.hpp>
#include <tessera/image/exemplars.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using tessera::index_t;

namespace {

using rgb8 = Eigen::Matrix<std::uint8_t, 3, 1>;

// A user image whose pixels are Eigen vectors (member style).
struct eigen_pixel_image {
  index_t w = 0, h = 0;
  std::vector<rgb8> pixels;
  eigen_pixel_image(index_t width, index_t height)
      : w(width), h(height), pixels(static_cast<std::size_t>(width * height), rgb8::Zero()) {}
  index_t width() const { return w; }
  index_t height() const { return h; }
  rgb8 read(index_t x, index_t y) const { return pixels[static_cast<std::size_t>(y * w + x)]; }
  void write(index_t x, index_t y, const rgb8& p) { pixels[static_cast<std::size_t>(y * w + x)] = p; }
};

// Two tetrahedra, the second shifted by +3 in x: 8 vertices, 8 faces, 2 components.
template <class V, class F>
void fill_two_tetrahedra(V& verts, F& faces) {
  const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int t[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  verts.resize(8, 3);
  faces.resize(8, 3);
  for (int c = 0; c < 2; ++c) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j)
        verts(4 * c + i, j) = static_cast<typename V::Scalar>(p[i][j] + (j == 0 ? 3.0 * c : 0.0));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) faces(4 * c + i, j) = static_cast<typename F::Scalar>(t[i][j] + 4 * c);
  }
}

template <class View>
void check_two_tetrahedra(const View& mesh) {
  REQUIRE(tessera::validate_mesh(mesh).ok());
  auto tm = tessera::to_tri_mesh(mesh);
  REQUIRE(tm.ok());
  CHECK(tm->num_vertices() == 8);
  CHECK(tm->num_faces() == 8);
  CHECK(tm->positions[5] == tessera::vec3{4, 0, 0});
  CHECK(tm->faces[6] == std::array<index_t, 3>{5, 6, 7});
  const auto comp = tessera::connected_components(mesh);
  CHECK(comp.count == 2);
  CHECK(comp.face_component[3] == 0);
  CHECK(comp.face_component[4] == 1);
  CHECK(tessera::face_adjacency(mesh).boundary_edges == 0);  // closed surfaces
  const auto box = tessera::bounding_box(mesh);
  CHECK(box.min == tessera::vec3{0, 0, 0});
  CHECK(box.max == tessera::vec3{4, 1, 1});
  // Face 0 = (0, 2, 1) lies in z = 0 and faces -z (outward for the tetrahedron).
  const auto n = tessera::face_normals(mesh);
  CHECK(n[0].z == Approx(-1.0));
  CHECK(tessera::face_area(mesh, 0) == Approx(0.5));
}

}  // namespace

TEST_CASE("eigen: vectors are pixels and convert like std::array pixels") {
  STATIC_REQUIRE(tessera::Pixel<rgb8>);
  STATIC_REQUIRE(tessera::Pixel<Eigen::Vector4f>);
  STATIC_REQUIRE(tessera::Pixel<Eigen::Matrix<std::uint16_t, 1, 1>>);
  STATIC_REQUIRE(tessera::Pixel<Eigen::Array<std::uint8_t, 4, 1>>);
  STATIC_REQUIRE_FALSE(tessera::Pixel<Eigen::Vector3d>);             // double channels
  STATIC_REQUIRE_FALSE(tessera::Pixel<Eigen::Matrix<float, 5, 1>>);  // 5 channels
  STATIC_REQUIRE_FALSE(tessera::Pixel<Eigen::VectorXf>);             // size unknown at compile time

  const rgb8 p(200, 0, 255);
  const auto f = tessera::convert_pixel<Eigen::Vector3f>(p);
  CHECK(f[0] == Approx(200.0f / 255.0f));
  CHECK(f[2] == 1.0f);
  const auto rgba = tessera::convert_pixel<tessera::pixel<std::uint16_t, 4>>(p);
  CHECK(rgba == tessera::pixel<std::uint16_t, 4>{51400, 0, 65535, 65535});
  const auto grey = tessera::convert_pixel<Eigen::Matrix<std::uint8_t, 1, 1>>(rgb8(255, 255, 255));
  CHECK(grey[0] == 255);
  const auto back = tessera::convert_pixel<rgb8>(tessera::pixel<float, 3>{200.0f / 255.0f, 0.0f, 1.0f});
  CHECK(back == p);
}

TEST_CASE("eigen: an image of Eigen pixels goes through to_buffer and copy_image") {
  auto ex = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::bricks, {.width = 24, .height = 16});
  REQUIRE(ex.ok());
  eigen_pixel_image img(24, 16);
  REQUIRE(tessera::copy_image(*ex, img).ok());
  CHECK(img.read(5, 7)[1] == ex->read(5, 7)[1]);
  auto buf = tessera::to_buffer(img);
  REQUIRE(buf.ok());
  CHECK(*buf == *ex);
  auto grey = tessera::to_buffer<float, 1>(img);
  REQUIRE(grey.ok());
  eigen_pixel_image wrong(23, 16);
  CHECK(tessera::copy_image(*ex, wrong).code() == tessera::status_code::invalid_argument);
  eigen_pixel_image empty(0, 16);
  CHECK(tessera::to_buffer(empty).error().code() == tessera::status_code::invalid_argument);
}

TEST_CASE("eigen: vectors are points, 2D vectors read z = 0") {
  CHECK(tessera::to_vec3(Eigen::Vector3d(1, 2, 3)) == tessera::vec3{1, 2, 3});
  CHECK(tessera::to_vec3(Eigen::Vector2f(1, 2)) == tessera::vec3{1, 2, 0});
  CHECK(tessera::to_vec3(Eigen::RowVector3f(4, 5, 6)) == tessera::vec3{4, 5, 6});
  Eigen::VectorXd dyn(2);
  dyn << 7, 8;
  CHECK(tessera::to_vec3(dyn) == tessera::vec3{7, 8, 0});
}

TEST_CASE("eigen: a matrix is a one-channel image with x = column and y = row") {
  Eigen::MatrixXf m(3, 5);  // 3 rows (height), 5 columns (width), column-major
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 5; ++c) m(r, c) = static_cast<float>(10 * r + c) / 100.0f;
  tessera::eigen_image_view view(m);
  STATIC_REQUIRE(tessera::WritableImage<decltype(view)>);
  CHECK(tessera::width_of(view) == 5);
  CHECK(tessera::height_of(view) == 3);
  CHECK(view.read(4, 2) == m(2, 4));
  view.write(1, 2, 0.5f);
  CHECK(m(2, 1) == 0.5f);

  // Runs core functions through the view: to_buffer, copy_image (with conversion to uint8).
  auto buf = tessera::to_buffer(view);
  REQUIRE(buf.ok());
  CHECK(buf->read(3, 1)[0] == m(1, 3));
  Eigen::Matrix<std::uint8_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> bytes(3, 5);
  tessera::eigen_image_view out(bytes);
  REQUIRE(tessera::copy_image(view, out).ok());
  CHECK(bytes(1, 3) == tessera::unit_to_channel<std::uint8_t>(m(1, 3)));

  const Eigen::MatrixXf& cm = m;
  tessera::eigen_image_view ro(cm);
  STATIC_REQUIRE(tessera::Image<decltype(ro)>);
  STATIC_REQUIRE_FALSE(tessera::WritableImage<decltype(ro)>);
}

TEST_CASE("eigen: Maps over raw row-major buffers, Blocks and double matrices") {
  // A row-major 4 x 6 uint16 buffer, as an engine keeps a height map.
  std::vector<std::uint16_t> raw(24);
  for (std::size_t i = 0; i < raw.size(); ++i) raw[i] = static_cast<std::uint16_t>(i * 1000);
  using row_major16 = Eigen::Matrix<std::uint16_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  tessera::eigen_image_view map(Eigen::Map<row_major16>(raw.data(), 4, 6));  // a temporary Map is fine
  CHECK(tessera::width_of(map) == 6);
  CHECK(map.read(2, 1) == raw[8]);  // x = 2, y = 1 -> index 1 * 6 + 2
  auto buf = tessera::to_buffer<float, 1>(map);
  REQUIRE(buf.ok());
  CHECK(buf->read(5, 3)[0] == Approx(23000.0f / 65535.0f));
  map.write(0, 0, 7);
  CHECK(raw[0] == 7);

  // A read-only Map over const data.
  const std::vector<std::uint16_t>& craw = raw;
  tessera::eigen_image_view cmap(Eigen::Map<const row_major16>(craw.data(), 4, 6));
  STATIC_REQUIRE_FALSE(tessera::WritableImage<decltype(cmap)>);
  CHECK(cmap.read(2, 1) == 8000);

  // A block of a larger matrix: a 2 x 3 window starting at row 1, column 2.
  Eigen::MatrixXf big = Eigen::MatrixXf::Zero(5, 6);
  tessera::eigen_image_view block(big.block(1, 2, 2, 3));
  tessera::image_buffer<float, 1> ones(3, 2, {1.0f});
  REQUIRE(tessera::copy_image(ones, block).ok());
  CHECK(big.sum() == 6.0f);
  CHECK(big(2, 4) == 1.0f);
  CHECK(big(0, 2) == 0.0f);

  // A double height field reads and writes float pixels.
  Eigen::MatrixXd height = Eigen::MatrixXd::Constant(2, 2, 0.25);
  tessera::eigen_image_view hv(height);
  STATIC_REQUIRE(std::is_same_v<tessera::pixel_t<decltype(hv)>, float>);
  hv.write(1, 0, 0.75f);
  CHECK(height(0, 1) == 0.75);
  CHECK(tessera::to_buffer(hv)->read(0, 1)[0] == 0.25f);
}

TEST_CASE("eigen: an empty matrix is reported by the image checks") {
  Eigen::MatrixXf empty(0, 4);
  tessera::eigen_image_view view(empty);
  const auto s = tessera::validate_image(view, "height map");
  CHECK(s.code() == tessera::status_code::invalid_argument);
  CHECK(s.message().find("height map") != std::string::npos);
  CHECK_FALSE(tessera::to_buffer(view).ok());
}

TEST_CASE("eigen: V/F matrices are a mesh in any storage order and scalar type") {
  SECTION("column-major double V, int F (libigl's MatrixXd / MatrixXi)") {
    Eigen::MatrixXd V;
    Eigen::MatrixXi F;
    fill_two_tetrahedra(V, F);
    auto mesh = tessera::make_eigen_mesh_view(V, F);
    REQUIRE(mesh.ok());
    STATIC_REQUIRE(tessera::Mesh<std::remove_cvref_t<decltype(*mesh)>>);
    check_two_tetrahedra(*mesh);
  }
  SECTION("row-major float V, uint32 F") {
    Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> V;
    Eigen::Matrix<std::uint32_t, Eigen::Dynamic, 3, Eigen::RowMajor> F;
    fill_two_tetrahedra(V, F);
    auto mesh = tessera::make_eigen_mesh_view(V, F);
    REQUIRE(mesh.ok());
    check_two_tetrahedra(*mesh);
  }
  SECTION("Maps over raw engine buffers, and const matrices") {
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> V0;
    Eigen::Matrix<std::int64_t, Eigen::Dynamic, 3, Eigen::RowMajor> F0;
    fill_two_tetrahedra(V0, F0);
    std::vector<double> positions(V0.data(), V0.data() + V0.size());
    std::vector<std::int64_t> indices(F0.data(), F0.data() + F0.size());
    using VMap = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>;
    using FMap = Eigen::Map<const Eigen::Matrix<std::int64_t, Eigen::Dynamic, 3, Eigen::RowMajor>>;
    auto mesh = tessera::make_eigen_mesh_view(VMap(positions.data(), 8, 3), FMap(indices.data(), 8, 3));
    REQUIRE(mesh.ok());
    check_two_tetrahedra(*mesh);
    const auto& cV = V0;
    const auto& cF = F0;
    auto cmesh = tessera::make_eigen_mesh_view(cV, cF);
    REQUIRE(cmesh.ok());
    check_two_tetrahedra(*cmesh);
  }
}

TEST_CASE("eigen: wrong shapes, NaN positions and bad indices are reported") {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  fill_two_tetrahedra(V, F);

  Eigen::MatrixXd Vt = V.transpose();
  auto transposed = tessera::make_eigen_mesh_view(Vt, F);
  REQUIRE_FALSE(transposed.ok());
  CHECK(transposed.error().code() == tessera::status_code::invalid_argument);
  CHECK(transposed.error().message().find("transposed") != std::string::npos);
  CHECK(transposed.error().message().find("3 x 8") != std::string::npos);

  Eigen::MatrixXi quads = Eigen::MatrixXi::Zero(2, 4);
  auto q = tessera::make_eigen_mesh_view(V, quads);
  REQUIRE_FALSE(q.ok());
  CHECK(q.error().message().find("F must be m x 3") != std::string::npos);
  CHECK(q.error().message().find("2 x 4") != std::string::npos);

  Eigen::MatrixXd V2 = Eigen::MatrixXd::Zero(4, 2);
  CHECK_FALSE(tessera::make_eigen_mesh_view(V2, F).ok());

  // Element checks run through validate_mesh / to_tri_mesh like for any Mesh.
  V(5, 1) = std::numeric_limits<double>::quiet_NaN();
  auto nan_mesh = tessera::make_eigen_mesh_view(V, F);
  REQUIRE(nan_mesh.ok());
  auto s = tessera::validate_mesh(*nan_mesh, "V/F");
  CHECK(s.code() == tessera::status_code::invalid_argument);
  CHECK(s.message().find("vertex 5") != std::string::npos);
  CHECK_FALSE(tessera::to_tri_mesh(*nan_mesh).ok());
  V(5, 1) = 0.0;

  F(3, 2) = 8;  // one past the last vertex
  s = tessera::validate_mesh(*tessera::make_eigen_mesh_view(V, F));
  CHECK(s.code() == tessera::status_code::out_of_range);
  CHECK(s.message().find("face 3") != std::string::npos);
  F(3, 2) = -1;
  CHECK(tessera::validate_mesh(*tessera::make_eigen_mesh_view(V, F)).code() == tessera::status_code::out_of_range);
  F(3, 2) = F(3, 0);
  CHECK(tessera::validate_mesh(*tessera::make_eigen_mesh_view(V, F)).message().find("degenerate") != std::string::npos);

  // An empty mesh (0 x 3 matrices) is valid and has no components.
  Eigen::MatrixXd V0(0, 3);
  Eigen::MatrixXi F0(0, 3);
  auto empty = tessera::make_eigen_mesh_view(V0, F0);
  REQUIRE(empty.ok());
  CHECK(tessera::validate_mesh(*empty).ok());
  CHECK(tessera::connected_components(*empty).count == 0);
}
