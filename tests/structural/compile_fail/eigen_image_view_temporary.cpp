// expect: use of deleted function
#include <tessera/adapters/eigen.hpp>
int main() {
  tessera::eigen_image_view view(Eigen::MatrixXf(4, 4));  // would dangle
  return static_cast<int>(view.width());
}
