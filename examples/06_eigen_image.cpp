// 06_eigen_image: an Eigen matrix as a one-channel image (x = column, y = row), without a copy. A
// height field lives in an Eigen::MatrixXf; tessera writes into it and reads from it through
// eigen_image_view, while the math stays Eigen's.
// Usage: example_06_eigen_image [OUTPUT_DIR]   (writes 06_eigen_height.png and 06_eigen_slope.png)
#include <tessera/adapters/eigen.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/exemplars.hpp>
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
  const Eigen::Index w = 160, h = 120;

  // [snippet:eigen-image]
  // A height field in an Eigen matrix: rows = image height, columns = image width.
  Eigen::MatrixXf height(h, w);
  tessera::eigen_image_view height_image(height);  // a WritableImage over the matrix, no copy

  // tessera fills it (the rock exemplar, converted to grey) ...
  auto rock = tessera::make_exemplar<float, 3>(tessera::exemplar_kind::rock, {.width = w, .height = h});
  if (!rock) return fail(rock.error());
  if (auto s = tessera::copy_image(*rock, height_image); !s) return fail(s);

  // ... Eigen does the math: slope magnitude by central differences ...
  Eigen::MatrixXf slope = Eigen::MatrixXf::Zero(h, w);
  const auto dx = (height.block(1, 2, h - 2, w - 2) - height.block(1, 0, h - 2, w - 2)) * 0.5f;
  const auto dy = (height.block(2, 1, h - 2, w - 2) - height.block(0, 1, h - 2, w - 2)) * 0.5f;
  slope.block(1, 1, h - 2, w - 2) = (dx.array().square() + dy.array().square()).sqrt().matrix();
  slope /= slope.maxCoeff();

  // ... and both matrices go to PNG as images (float -> 16-bit grey).
  if (auto s = tessera::write_png(dir + "/06_eigen_height.png", height_image); !s) return fail(s);
  if (auto s = tessera::write_png(dir + "/06_eigen_slope.png", tessera::eigen_image_view(slope)); !s) return fail(s);
  // [/snippet]

  // A raw row-major buffer seen through Eigen::Map is an image too (a temporary Map is fine).
  std::vector<std::uint8_t> engine_bytes(std::size_t(w * h));
  using row_major8 = Eigen::Matrix<std::uint8_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  tessera::eigen_image_view bytes_image(Eigen::Map<row_major8>(engine_bytes.data(), h, w));
  if (auto s = tessera::copy_image(height_image, bytes_image); !s) return fail(s);

  std::printf("height field %td x %td: min %.3f, max %.3f, mean %.3f; byte (10, 20) = %d\n", std::ptrdiff_t(w),
              std::ptrdiff_t(h), height.minCoeff(), height.maxCoeff(), height.mean(), int(engine_bytes[20 * w + 10]));
  std::printf("wrote %s/06_eigen_height.png\nwrote %s/06_eigen_slope.png\n", dir.c_str(), dir.c_str());
  return 0;
}
