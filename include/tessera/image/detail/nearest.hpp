// tessera/image/detail/nearest.hpp: exact k-nearest-neighbour search over long vectors (image windows,
// overlap strips) accelerated by PCA and nanoflann. Internal; no stability promise.
//
// The vectors are projected on an orthonormal PCA basis of a few dimensions (Eigen). A projection on
// orthonormal directions never lengthens a vector, so the projected squared distance is a lower bound
// of the exact one. A kd-tree (nanoflann 1.4.3, KDTreeSingleIndexAdaptor) over the projections is
// searched with a result set that evaluates the exact distance of every point the tree cannot rule
// out and prunes with the k-th best exact distance so far: the answer is the exact top k, ties broken
// by the smaller index, whatever the number of PCA dimensions (which only changes the speed).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <nanoflann.hpp>

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// One neighbour: exact squared distance and index; ordered by (distance, index).
struct neighbor {
  double dist = 0;
  std::uint32_t index = 0;
  friend bool operator<(const neighbor& a, const neighbor& b) noexcept {
    return a.dist < b.dist || (a.dist == b.dist && a.index < b.index);
  }
  friend bool operator==(const neighbor&, const neighbor&) = default;
};

/// Inserts `n` into the ascending list `best` holding at most k entries.
inline void insert_top_k(std::vector<neighbor>& best, std::size_t k, const neighbor& n) {
  if (best.size() == k && !(n < best.back())) return;
  auto it = std::upper_bound(best.begin(), best.end(), n);
  best.insert(it, n);
  if (best.size() > k) best.pop_back();
}

/// Orthonormal basis (D x d, columns) of the top principal directions of the rows of `samples`
/// (m x D). Uses the D x D covariance when D <= m, else the m x m Gram matrix. Directions with no
/// variance are dropped; the result has at least one column. Columns are re-orthonormalized (twice
/// modified Gram-Schmidt) so projections are exact lower bounds up to rounding.
inline Eigen::MatrixXd pca_basis(Eigen::MatrixXd samples, int dims) {
  const Eigen::Index m = samples.rows(), D = samples.cols();
  TESSERA_ASSERT(m >= 1 && D >= 1 && dims >= 1);
  const Eigen::RowVectorXd mean = samples.colwise().mean();
  samples.rowwise() -= mean;
  const Eigen::Index want = std::min<Eigen::Index>({dims, D, m});
  Eigen::MatrixXd basis(D, want);
  Eigen::Index got = 0;
  if (D <= m) {
    const Eigen::MatrixXd cov = samples.transpose() * samples;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(cov);
    const double top = std::max(es.eigenvalues().maxCoeff(), 0.0);
    for (Eigen::Index i = D - 1; i >= 0 && got < want; --i) {
      if (!(es.eigenvalues()(i) > 1e-12 * top) || top == 0) break;
      basis.col(got++) = es.eigenvectors().col(i);
    }
  } else {
    const Eigen::MatrixXd gram = samples * samples.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(gram);
    const double top = std::max(es.eigenvalues().maxCoeff(), 0.0);
    for (Eigen::Index i = m - 1; i >= 0 && got < want; --i) {
      if (!(es.eigenvalues()(i) > 1e-12 * top) || top == 0) break;
      basis.col(got++) = samples.transpose() * es.eigenvectors().col(i);
    }
  }
  if (got == 0) {  // no variance at all: any unit direction is a valid (trivial) lower bound
    basis.col(0).setZero();
    basis(0, 0) = 1;
    got = 1;
  }
  basis.conservativeResize(D, got);
  for (int pass = 0; pass < 2; ++pass)
    for (Eigen::Index i = 0; i < got; ++i) {
      for (Eigen::Index j = 0; j < i; ++j) basis.col(i) -= basis.col(j).dot(basis.col(i)) * basis.col(j);
      const double n = basis.col(i).norm();
      TESSERA_ASSERT(n > 0);
      basis.col(i) /= n;
    }
  return basis;
}

/// Exact k-nearest-neighbour index over points known through their projections (n x d, row-major,
/// owned) and an exact squared distance supplied at query time.
class lower_bound_knn {
 public:
  lower_bound_knn() = default;
  /// `projected`: n rows of d coordinates. `scale`: a typical squared vector length, for the
  /// absolute rounding margin of the pruning radius.
  lower_bound_knn(std::vector<double> projected, index_t n, int d, double scale)
      : data_(std::make_unique<dataset>(dataset{std::move(projected), n, d})), margin_(1e-12 * std::max(scale, 1e-300)) {
    TESSERA_ASSERT(n >= 1 && d >= 1 && static_cast<index_t>(data_->points.size()) == n * d);
    tree_ = std::make_unique<tree>(d, *data_, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  }

  [[nodiscard]] index_t size() const noexcept { return data_ ? data_->n : 0; }
  [[nodiscard]] int dims() const noexcept { return data_ ? data_->d : 0; }

  /// The exact top k (by `exact(i)`, ties by index) for a query with projection `q` (d values).
  /// `exact(i)` must return the squared distance whose lower bound the projections give.
  template <class Exact>
  void search(const double* q, std::size_t k, Exact&& exact, std::vector<neighbor>& out) const {
    out.clear();
    if (!tree_ || k == 0) return;
    result_set<std::remove_reference_t<Exact>> rs{exact, out, k, margin_};
    tree_->findNeighbors(rs, q, nanoflann::SearchParams(32, 0.0f, false));
  }

 private:
  struct dataset {
    std::vector<double> points;
    index_t n = 0;
    int d = 0;
    [[nodiscard]] std::size_t kdtree_get_point_count() const { return static_cast<std::size_t>(n); }
    [[nodiscard]] double kdtree_get_pt(std::uint32_t i, std::size_t dim) const {
      return points[static_cast<std::size_t>(i) * static_cast<std::size_t>(d) + dim];
    }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const {
      return false;
    }
  };
  using tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, dataset>, dataset, -1, std::uint32_t>;

  /// nanoflann result set: exact distances for every point the tree offers, pruning radius = the
  /// k-th best exact distance plus a rounding margin (so equal distances with smaller indices are
  /// never pruned).
  template <class Exact>
  struct result_set {
    Exact& exact;
    std::vector<neighbor>& best;
    std::size_t k;
    double margin;
    [[nodiscard]] std::size_t size() const { return best.size(); }
    [[nodiscard]] bool full() const { return best.size() == k; }
    bool addPoint(double lower, std::uint32_t index) {
      if (full() && lower > worstDist()) return true;
      insert_top_k(best, k, neighbor{exact(index), index});
      return true;
    }
    [[nodiscard]] double worstDist() const {
      if (!full()) return std::numeric_limits<double>::max();
      return best.back().dist * (1 + 1e-9) + margin;
    }
  };

  std::unique_ptr<dataset> data_;
  std::unique_ptr<tree> tree_;
  double margin_ = 0;
};

}  // namespace detail
TESSERA_NAMESPACE_END
