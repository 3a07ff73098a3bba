// tessera/geometry/laplacian.hpp: the cotangent Laplacian of a triangle mesh and Laplacian mesh
// editing (Sorkine et al. 2004) with hard (fixed) and soft constraints, solved with Eigen's sparse
// Cholesky (SimplicialLDLT). Mesh quilting deforms corresponding elements towards each other with it
// (eq. 6-7 of paper 000, §3.3.5): soft constraints are points given by barycentric weights on a face,
// hard constraints are the border vertices that must not move.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN

namespace detail {
/// Floor of the mean diagonal of L^T L that the regularization is relative to, so a system with a
/// zero diagonal (no free vertex moves anything) still gets a positive regularization.
inline constexpr double laplacian_min_mean_diagonal = 1e-12;
}  // namespace detail

/// How edges are weighted in the Laplacian.
enum class laplacian_weighting {
  cotangent,  ///< w_ij = (cot a_ij + cot b_ij) / 2, clamped to [-1e4, 1e4] for degenerate faces
  uniform     ///< w_ij = 1 (graph Laplacian)
};

/// The Laplacian matrix L (V x V) with (L x)_i = sum_j w_ij (x_i - x_j), so rows sum to zero.
/// Input must be valid (validate_mesh); O(F) time.
template <Mesh M>
Eigen::SparseMatrix<double> laplacian_matrix(const M& m,
                                             laplacian_weighting weighting = laplacian_weighting::cotangent) {
  using sparse = Eigen::SparseMatrix<detail::dependent_t<double, M>>;  // see laplacian_deform
  const index_t nv = num_vertices(m);
  std::vector<Eigen::Triplet<typename sparse::Scalar>> t;
  t.reserve(detail::to_size(num_faces(m)) * 12);
  for (index_t f = 0; f < num_faces(m); ++f) {
    index_t v[3];
    vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = face_vertex(m, f, k);
      p[k] = vertex_position(m, v[k]);
    }
    for (int k = 0; k < 3; ++k) {
      // the edge opposite corner k joins i and j; corner k's angle gives half its weight
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      double w = 0.5;
      if (weighting == laplacian_weighting::cotangent) {
        const vec3 a = p[i] - p[k], b = p[j] - p[k];
        const double s = norm(cross(a, b));
        const double cot = s > 0 ? dot(a, b) / s : 1e4;
        w = 0.5 * std::clamp(cot, -1e4, 1e4);
      } else {
        w = 0.5;  // each interior edge is seen by two faces
      }
      t.emplace_back(static_cast<int>(v[i]), static_cast<int>(v[j]), -w);
      t.emplace_back(static_cast<int>(v[j]), static_cast<int>(v[i]), -w);
      t.emplace_back(static_cast<int>(v[i]), static_cast<int>(v[i]), w);
      t.emplace_back(static_cast<int>(v[j]), static_cast<int>(v[j]), w);
    }
  }
  sparse L(static_cast<int>(nv), static_cast<int>(nv));
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

/// A soft constraint: sum_k weights[k] * position(vertices[k]) should be close to `target`. With one
/// vertex and weight 1 it pins a vertex; with a face's corners and barycentric weights it pins a
/// point on a face (eq. 7 of paper 000).
struct laplacian_constraint {
  std::array<index_t, 3> vertices{-1, -1, -1};  ///< unused slots are -1
  /// Weights of the vertices (unused slots 0).
  std::array<double, 3> weights{0, 0, 0};
  /// Where the weighted point must go.
  vec3 target;
};

/// Options of the Laplacian deformation.
struct laplacian_deform_options {
  double soft_weight = 1.0;  ///< mu of eq. 6-7: weight of the soft constraints against detail preservation
  /// Weights of the Laplacian: cotangent or uniform.
  laplacian_weighting weighting = laplacian_weighting::cotangent;
  /// Tiny pull of every free vertex towards its rest position, so parts with no constraint stay in
  /// place and the system is always positive definite. Relative to the mean diagonal of L^T L.
  double regularization = 1e-9;
};

/// Laplacian editing: returns new positions w minimising
///   sum_i |L(w)_i - L(v)_i|^2 + mu * sum_c |sum_k b_ck w_k - c_c|^2      (eq. 6 and 7 of paper 000)
/// where v are the current positions, with `fixed[i] != 0` vertices held exactly at v_i (bit-identical
/// in the output). `fixed` is empty (nothing fixed) or has one entry per vertex.
/// Errors: invalid mesh, `fixed` of the wrong size, a constraint naming a vertex out of range, a
/// non-finite target or weight, soft_weight < 0 or NaN, a failed factorisation (internal_error).
/// O(V) memory; the sparse Cholesky dominates time (near linear for mesh-like graphs).
template <Mesh M>
result<std::vector<vec3>> laplacian_deform(const M& mesh, std::span<const unsigned char> fixed,
                                           std::span<const laplacian_constraint> constraints,
                                           const laplacian_deform_options& options = {}) {
  if (auto s = validate_mesh(mesh, "laplacian_deform: mesh"); !s) return s;
  if (auto s = validate_enum(options.weighting, {"cotangent", "uniform"}, "laplacian_deform: options.weighting"); !s)
    return s;
  const index_t nv = num_vertices(mesh);
  if (!fixed.empty() && static_cast<index_t>(fixed.size()) != nv)
    return status::invalid_argument(
        detail::cat("laplacian_deform: fixed has ", fixed.size(), " entries, the mesh has ", nv, " vertices"));
  if (!(options.soft_weight >= 0) || !std::isfinite(options.soft_weight))
    return status::invalid_argument(
        detail::cat("laplacian_deform: soft_weight must be finite and >= 0, got ", options.soft_weight));
  if (!(options.regularization >= 0) || !std::isfinite(options.regularization))
    return status::invalid_argument(
        detail::cat("laplacian_deform: regularization must be finite and >= 0, got ", options.regularization));
  for (std::size_t c = 0; c < constraints.size(); ++c) {
    const auto& k = constraints[c];
    if (!is_finite(k.target))
      return status::invalid_argument(detail::cat("laplacian_deform: constraint ", c, " has a non-finite target"));
    for (int j = 0; j < 3; ++j) {
      if (k.vertices[detail::to_size(j)] < -1 || k.vertices[detail::to_size(j)] >= nv)
        return status::out_of_range(detail::cat("laplacian_deform: constraint ", c, " names vertex ",
                                                k.vertices[detail::to_size(j)], " of a mesh with ", nv, " vertices"));
      if (!std::isfinite(k.weights[detail::to_size(j)]))
        return status::invalid_argument(detail::cat("laplacian_deform: constraint ", c, " has a non-finite weight"));
    }
  }
  // Eigen types through dependent_t: this solve is compiled only by the code that calls it.
  using real = detail::dependent_t<double, M>;
  using sparse = Eigen::SparseMatrix<real>;
  using dense3 = Eigen::Matrix<real, Eigen::Dynamic, 3>;
  using row3 = Eigen::Matrix<real, 1, 3>;
  using triplet = Eigen::Triplet<real>;
  std::vector<vec3> x(detail::to_size(nv));
  for (index_t v = 0; v < nv; ++v) x[detail::to_size(v)] = vertex_position(mesh, v);
  // free-variable numbering
  std::vector<int> col(detail::to_size(nv), -1);
  int nfree = 0;
  for (index_t v = 0; v < nv; ++v)
    if (fixed.empty() || !fixed[detail::to_size(v)]) col[detail::to_size(v)] = nfree++;
  if (nfree == 0) return x;

  const sparse L = laplacian_matrix(mesh, options.weighting);
  dense3 X(static_cast<int>(nv), 3);
  for (index_t v = 0; v < nv; ++v)
    for (int d = 0; d < 3; ++d) X(static_cast<int>(v), d) = x[detail::to_size(v)][d];
  const dense3 delta = L * X;  // L(v): the rest Laplacian coordinates

  // Split L = [L_f | L_c]; move the fixed part to the right-hand side.
  std::vector<triplet> lf;
  dense3 rhs_l = delta;
  for (int k = 0; k < L.outerSize(); ++k)
    for (typename sparse::InnerIterator it(L, k); it; ++it) {
      const int c = col[detail::to_size(it.col())];
      if (c >= 0)
        lf.emplace_back(static_cast<int>(it.row()), c, it.value());
      else
        rhs_l.row(static_cast<int>(it.row())) -= it.value() * X.row(static_cast<int>(it.col()));
    }
  sparse Lf(static_cast<int>(nv), nfree);
  Lf.setFromTriplets(lf.begin(), lf.end());

  std::vector<triplet> cf;
  dense3 rhs_c(static_cast<int>(constraints.size()), 3);
  for (std::size_t c = 0; c < constraints.size(); ++c) {
    const auto& k = constraints[c];
    row3 r(k.target.x, k.target.y, k.target.z);
    for (int j = 0; j < 3; ++j) {
      const index_t v = k.vertices[detail::to_size(j)];
      if (v < 0) continue;
      const double w = k.weights[detail::to_size(j)];
      const int cc = col[detail::to_size(v)];
      if (cc >= 0)
        cf.emplace_back(static_cast<int>(c), cc, w);
      else
        r -= w * X.row(static_cast<int>(v));
    }
    rhs_c.row(static_cast<int>(c)) = r;
  }
  sparse Cf(static_cast<int>(constraints.size()), nfree);
  Cf.setFromTriplets(cf.begin(), cf.end());

  sparse A = sparse(Lf.transpose()) * Lf;
  if (!constraints.empty()) A += options.soft_weight * (sparse(Cf.transpose()) * Cf);
  double mean_diag = 0;
  for (int i = 0; i < nfree; ++i) mean_diag += A.coeff(i, i);
  mean_diag = nfree > 0 ? mean_diag / nfree : 1.0;
  const double eps = options.regularization * std::max(mean_diag, detail::laplacian_min_mean_diagonal);
  dense3 x0(nfree, 3);
  for (index_t v = 0; v < nv; ++v)
    if (col[detail::to_size(v)] >= 0) x0.row(col[detail::to_size(v)]) = X.row(static_cast<int>(v));
  {
    sparse I(nfree, nfree);
    I.setIdentity();
    A += eps * I;
  }
  dense3 rhs = Lf.transpose() * rhs_l + eps * x0;
  if (!constraints.empty()) rhs += options.soft_weight * (Cf.transpose() * rhs_c);

  Eigen::SimplicialLDLT<sparse> solver(A);
  if (solver.info() != Eigen::Success)
    return status::internal_error("laplacian_deform: sparse Cholesky factorisation failed");
  const dense3 sol = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !sol.allFinite())
    return status::internal_error("laplacian_deform: sparse solve failed");
  for (index_t v = 0; v < nv; ++v) {
    const int c = col[detail::to_size(v)];
    if (c >= 0) x[detail::to_size(v)] = {sol(c, 0), sol(c, 1), sol(c, 2)};
  }
  return x;
}

TESSERA_NAMESPACE_END
