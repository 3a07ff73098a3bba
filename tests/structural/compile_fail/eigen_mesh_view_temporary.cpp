// expect: V is a temporary matrix; the view would dangle
#include <tessera/adapters/eigen.hpp>
int main() {
  Eigen::MatrixXi F(1, 3);
  auto view = tessera::make_eigen_mesh_view(Eigen::MatrixXd(3, 3), F);
  return view.ok() ? 0 : 1;
}
