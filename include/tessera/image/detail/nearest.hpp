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

#include "../../core/config.hpp"

#if TESSERA_HAS_EXCEPTIONS
#include <nanoflann.hpp>
#else
// nanoflann 1.4 throws std::runtime_error on a search before the index is built or an empty data
// set, and std::bad_alloc when malloc fails: under -fno-exceptions those `throw`s would not compile.
// Here each becomes std::abort(). lower_bound_knn never takes the runtime_error paths (it builds its
// index over n >= 1 points before any search; validated by its callers); malloc failing aborts, as a
// failed allocation does anywhere without exceptions (docs/no_exceptions.md).
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <unordered_set>
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wkeyword-macro"
#endif
#define throw ::std::abort(),
#include <nanoflann.hpp>
#undef throw
#if defined(__clang__)
#pragma clang diagnostic pop
#endif
#endif
#include "../../core/random.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// orthonormalize: a column whose norm after removing the kept directions is at or below this fraction
/// of its norm before is linearly dependent on them and is dropped.
inline constexpr double orthonormalize_drop_fraction = 1e-10;
/// pca_basis: eigenvalues at or below this fraction of the largest are rounding noise, not directions.
inline constexpr double pca_eigenvalue_cutoff = 1e-12;
/// lower_bound_knn: the absolute rounding margin of the pruning radius, as a fraction of the typical
/// squared vector length (floored by knn_scale_floor so a zero scale still gives a positive margin).
inline constexpr double knn_margin_fraction = 1e-12;
inline constexpr double knn_scale_floor = 1e-300;
/// lower_bound_knn: relative widening of the pruning radius, so rounding in the lower bounds cannot
/// prune a point that belongs in the top k.
inline constexpr double knn_prune_relative_margin = 1e-9;

/// One neighbour: exact squared distance and index; ordered by (distance, index).
struct neighbor {
  double dist = 0;
  std::uint32_t index = 0;
  friend bool operator<(const neighbor& a, const neighbor& b) noexcept {
    return a.dist < b.dist || (a.dist == b.dist && a.index < b.index);
  }
  friend bool operator==(const neighbor&, const neighbor&) = default;
};

/// The distance above which a candidate cannot enter a full top-k list (infinity while not full).
inline double bound_of(const std::vector<neighbor>& best, std::size_t k) noexcept {
  return best.size() < k ? std::numeric_limits<double>::infinity() : best.back().dist;
}

/// Inserts `n` into the ascending list `best` holding at most k entries.
inline void insert_top_k(std::vector<neighbor>& best, std::size_t k, const neighbor& n) {
  if (best.size() == k && !(n < best.back())) return;
  auto it = std::upper_bound(best.begin(), best.end(), n);
  best.insert(it, n);
  if (best.size() > k) best.pop_back();
}

/// Orthonormalizes the columns of `q` in place (modified Gram-Schmidt, twice); drops columns that
/// vanish. Returns the number of columns kept (moved to the front).
/// (This and `pca_basis` are templates only so that their Eigen code is instantiated by the
/// translation units that use them, not by every file that includes this header.)
template <class Matrix = Eigen::MatrixXd>
Eigen::Index orthonormalize(Matrix& q) {
  using column = Eigen::Matrix<typename Matrix::Scalar, Eigen::Dynamic, 1>;
  Eigen::Index kept = 0;
  for (Eigen::Index i = 0; i < q.cols(); ++i) {
    column v = q.col(i);
    const double before = v.norm();
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index j = 0; j < kept; ++j) v -= q.col(j).dot(v) * q.col(j);
    const double n = v.norm();
    if (!(n > orthonormalize_drop_fraction * before) || n == 0) continue;
    q.col(kept++) = v / n;
  }
  return kept;
}

/// Orthonormal basis (D x d, columns) of the top principal directions of the rows of `samples`
/// (m x D). Small problems use an exact eigen-decomposition (of the D x D covariance or the m x m Gram
/// matrix); larger ones a randomized range finder with two power iterations (Halko, Martinsson and
/// Tropp 2011) whose test matrix is hash-based, so the basis is deterministic. Any orthonormal basis
/// gives valid lower bounds; a good one only makes searches faster. The result has at least one column.
template <class Matrix = Eigen::MatrixXd>
Matrix pca_basis(Matrix samples, int dims) {
  using column = Eigen::Matrix<typename Matrix::Scalar, Eigen::Dynamic, 1>;
  using row = Eigen::Matrix<typename Matrix::Scalar, 1, Eigen::Dynamic>;
  const Eigen::Index m = samples.rows(), D = samples.cols();
  TESSERA_ASSERT(m >= 1 && D >= 1 && dims >= 1);
  const row mean = samples.colwise().mean();
  samples.rowwise() -= mean;
  const Eigen::Index want = std::min<Eigen::Index>({dims, D, m});
  Matrix basis(D, want);
  Eigen::Index got = 0;
  auto take_top = [&](const Eigen::SelfAdjointEigenSolver<Matrix>& es, auto&& direction) {
    const Eigen::Index n = es.eigenvalues().size();
    const double top = std::max(es.eigenvalues()(n - 1), 0.0);
    for (Eigen::Index i = n - 1; i >= 0 && got < want; --i) {
      if (!(es.eigenvalues()(i) > pca_eigenvalue_cutoff * top) || top == 0) break;
      basis.col(got++) = direction(i);
    }
  };
  if (std::min(m, D) <= 64) {
    if (D <= m) {
      Eigen::SelfAdjointEigenSolver<Matrix> es(samples.transpose() * samples);
      take_top(es, [&](Eigen::Index i) { return column(es.eigenvectors().col(i)); });
    } else {
      Eigen::SelfAdjointEigenSolver<Matrix> es(samples * samples.transpose());
      take_top(es, [&](Eigen::Index i) { return column(samples.transpose() * es.eigenvectors().col(i)); });
    }
  } else {
    const Eigen::Index l = std::min<Eigen::Index>({want + 8, D, m});
    Matrix omega(D, l);
    for (Eigen::Index j = 0; j < l; ++j)
      for (Eigen::Index i = 0; i < D; ++i)
        omega(i, j) =
            2.0 * bits_to_unit(hash_keys(0x70636131u, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j))) -
            1.0;
    Matrix q = samples * omega;  // m x l
    for (int power = 0; power < 2; ++power) {
      q.conservativeResize(Eigen::NoChange, orthonormalize(q));
      Matrix z = samples.transpose() * q;  // D x l
      z.conservativeResize(Eigen::NoChange, orthonormalize(z));
      q = samples * z;
    }
    q.conservativeResize(Eigen::NoChange, orthonormalize(q));
    if (q.cols() > 0) {  // rank-deficient samples (a flat exemplar) leave no column: no variance
      const Matrix b = q.transpose() * samples;  // l x D: the samples in the found subspace
      Eigen::SelfAdjointEigenSolver<Matrix> es(b * b.transpose());
      take_top(es, [&](Eigen::Index i) { return column(b.transpose() * es.eigenvectors().col(i)); });
    }
  }
  if (got == 0) {  // no variance at all: any unit direction is a valid (trivial) lower bound
    basis.col(0).setZero();
    basis(0, 0) = 1;
    got = 1;
  }
  basis.conservativeResize(D, got);
  basis.conservativeResize(D, std::max<Eigen::Index>(1, orthonormalize(basis)));
  return basis;
}

/// Exact k-nearest-neighbour index over points known through their projections (n x d, row-major,
/// owned) and an exact squared distance supplied at query time. `DIM` fixes d at compile time (faster
/// distance loops) or is -1 for a run-time d.
template <int DIM = -1>
class lower_bound_knn {
 public:
  lower_bound_knn() = default;
  /// `projected`: n rows of d coordinates. `scale`: a typical squared vector length, for the
  /// absolute rounding margin of the pruning radius.
  lower_bound_knn(std::vector<double> projected, index_t n, int d, double scale)
      : data_(std::make_unique<dataset>(dataset{std::move(projected), n, d})),
        margin_(knn_margin_fraction * std::max(scale, knn_scale_floor)) {
    TESSERA_ASSERT(n >= 1 && d >= 1 && static_cast<index_t>(data_->points.size()) == n * d && (DIM < 0 || DIM == d));
    tree_ = std::make_unique<tree>(d, *data_, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  }

  [[nodiscard]] index_t size() const noexcept { return data_ ? data_->n : 0; }
  [[nodiscard]] int dims() const noexcept { return data_ ? data_->d : 0; }

  /// `exact(i, bound)` returns the exact squared distance of point i, or any value above `bound` when
  /// the distance exceeds it (so callers may stop summing early).
  /// The top k by `exact` (ties by index) among the `pool` points nearest to `q` in the projected
  /// space (eps-approximate kd-tree search: neighbours within (1 + eps) of the true ones): the
  /// approximate search, where the exact distance re-ranks the projected candidates.
  template <class Exact>
  void search_approximate(const double* q, std::size_t k, std::size_t pool, float eps, Exact&& exact,
                          std::vector<neighbor>& out, std::vector<std::uint32_t>& ids,
                          std::vector<double>& dists) const {
    out.clear();
    if (!tree_ || k == 0) return;
    pool = std::min(std::max(pool, k), to_size(data_->n));
    ids.resize(pool);
    dists.resize(pool);
    nanoflann::KNNResultSet<double, std::uint32_t> rs(pool);
    rs.init(ids.data(), dists.data());
    tree_->findNeighbors(rs, q, nanoflann::SearchParams(32, eps, true));
    const std::size_t found = rs.size();
    for (std::size_t i = 0; i < found; ++i) insert_top_k(out, k, neighbor{exact(ids[i], bound_of(out, k)), ids[i]});
  }

  /// The exact top k (by `exact`, ties by index) for a query with projection `q` (d values). `exact`
  /// must measure the squared distance whose lower bound the projections give.
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
    [[nodiscard]] std::size_t kdtree_get_point_count() const { return to_size(n); }
    [[nodiscard]] double kdtree_get_pt(std::uint32_t i, std::size_t dim) const {
      return points[to_size(i) * to_size(d) + dim];
    }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const {
      return false;
    }
  };
  using tree =
      nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, dataset>, dataset, DIM, std::uint32_t>;

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
      insert_top_k(best, k, neighbor{exact(index, bound_of(best, k)), index});
      return true;
    }
    [[nodiscard]] double worstDist() const {
      if (!full()) return std::numeric_limits<double>::max();
      return best.back().dist * (1 + knn_prune_relative_margin) + margin;
    }
  };

  std::unique_ptr<dataset> data_;
  std::unique_ptr<tree> tree_;
  double margin_ = 0;
};

/// lower_bound_knn<DIM>, spelled so that it depends on `Dependent` (see dependent_t): the kd-tree
/// code is then compiled only by the translation units that build one.
template <int DIM, class Dependent>
using dependent_knn = lower_bound_knn<(sizeof(Dependent*) != 0 ? DIM : DIM)>;

}  // namespace detail
TESSERA_NAMESPACE_END
