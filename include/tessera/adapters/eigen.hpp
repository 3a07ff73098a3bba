// tessera/adapters/eigen.hpp: Eigen types through tessera's concepts.
//
//   pixel_traits<Eigen::Matrix<T, C, 1>>   Eigen column vectors (and Eigen::Array) as pixels:
//                                          Eigen::Matrix<std::uint8_t, 4, 1>, Eigen::Vector3f, ...
//   point_traits<Eigen vectors>            Eigen vectors as positions and uvs (2D vectors read z = 0)
//   eigen_mesh_view<V, F>                  libigl-style V (n x 3 float/double) and F (m x 3 integer)
//                                          matrices as a Mesh, any storage order, Matrix/Map/Ref/Block
//   eigen_image_view<M>                    a matrix as a one-channel image, x = column, y = row
//
// Views never copy or own pixel and vertex data: a plain Eigen::Matrix is referenced (keep it alive
// while the view is used), expression types (Map, Ref, Block) are held by value since they are views
// themselves. Only <Eigen/Core> is included.
#pragma once

#include <Eigen/Core>

#include <array>
#include <concepts>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../core/config.hpp"
#include "../core/image.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"

TESSERA_NAMESPACE_BEGIN

// ---------------------------------------------------------------------------------------------
// Pixels and points

namespace detail {
/// Channel access shared by the Eigen::Matrix and Eigen::Array pixel specializations.
template <class V, class T, int C>
struct eigen_pixel_traits {
  using channel_type = T;
  static constexpr int channels = C;
  static T get(const V& p, int c) noexcept { return p[c]; }
  static void set(V& p, int c, T v) noexcept { p[c] = v; }
};
}  // namespace detail

/// Eigen column vectors as pixels: C channels of T. The Pixel concept accepts C in 1..4 and T in
/// uint8, uint16, float; other vectors (Eigen::Vector3d, 5 channels) are known but do not model
/// Pixel, so explain_image() names the problem.
template <class T, int C, int Options, int MaxRows, int MaxCols>
requires std::is_arithmetic_v<T> &&(C >= 1) struct pixel_traits<Eigen::Matrix<T, C, 1, Options, MaxRows, MaxCols>>
    : detail::eigen_pixel_traits<Eigen::Matrix<T, C, 1, Options, MaxRows, MaxCols>, T, C> {
};

/// Eigen::Array<T, C, 1> (C >= 1) is a C-channel pixel, like Eigen::Matrix above.
template <class T, int C, int Options, int MaxRows, int MaxCols>
requires std::is_arithmetic_v<T> &&(C >= 1) struct pixel_traits<Eigen::Array<T, C, 1, Options, MaxRows, MaxCols>>
    : detail::eigen_pixel_traits<Eigen::Array<T, C, 1, Options, MaxRows, MaxCols>, T, C> {
};

/// Eigen vectors (column or row, fixed or dynamic size) as points: coordinates past the vector's
/// size read as 0, so an Eigen::Vector2f position is (x, y, 0) rather than an out-of-bounds read.
template <class T, int R, int C, int Options, int MaxRows, int MaxCols>
requires std::is_arithmetic_v<T> &&
    (R == 1 || C == 1) struct point_traits<Eigen::Matrix<T, R, C, Options, MaxRows, MaxCols>> {
  static double get(const Eigen::Matrix<T, R, C, Options, MaxRows, MaxCols>& p, int i) noexcept {
    return i < p.size() ? static_cast<double>(p[i]) : 0.0;
  }
};

// ---------------------------------------------------------------------------------------------
// Holding Eigen objects without copying them

/// A dense Eigen object: Matrix, Array, or a view of one (Map, Ref, Block), any cv/ref qualification.
/// What eigen_mesh_view and eigen_image_view accept.
template <class X>
concept EigenDense = std::is_base_of_v<Eigen::DenseBase<std::remove_cvref_t<X>>, std::remove_cvref_t<X>>;

namespace detail {
/// True for Eigen::Matrix / Eigen::Array (objects that own their coefficients).
template <class X>
inline constexpr bool eigen_is_plain =
    std::is_base_of_v<Eigen::PlainObjectBase<std::remove_cvref_t<X>>, std::remove_cvref_t<X>>;

/// A plain matrix is referenced; an expression (Map, Ref, Block) is a view already and is copied.
template <class X>
class eigen_holder {
 public:
  explicit eigen_holder(X& x) noexcept requires eigen_is_plain<X> : ptr_(&x) {}
  explicit eigen_holder(const X& x) requires(!eigen_is_plain<X>) : value_(x) {}

  [[nodiscard]] X& get() noexcept {
    if constexpr (eigen_is_plain<X>)
      return *ptr_;
    else
      return value_;
  }
  [[nodiscard]] const X& get() const noexcept {
    if constexpr (eigen_is_plain<X>)
      return *ptr_;
    else
      return value_;
  }

 private:
  struct none {};
  [[no_unique_address]] std::conditional_t<eigen_is_plain<X>, X*, none> ptr_;
  [[no_unique_address]] std::conditional_t<eigen_is_plain<X>, none, std::remove_const_t<X>> value_;
};
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// V / F matrices as a Mesh

/// A triangle mesh over libigl-style matrices: V holds one vertex per row (n x 3, float or double),
/// F one triangle per row (m x 3, any integer type). Any storage order and any dense Eigen type
/// (Matrix, Map, Ref, Block) works; nothing is copied. Models Mesh.
///
/// The constructor does not check shapes: use make_eigen_mesh_view(). Index ranges, NaN positions
/// and degenerate faces are checked by validate_mesh() / to_tri_mesh() like for any Mesh.
template <class VMatrix, class FMatrix>
class eigen_mesh_view {
  using v_scalar = typename std::remove_const_t<VMatrix>::Scalar;
  using f_scalar = typename std::remove_const_t<FMatrix>::Scalar;
  static_assert(EigenDense<VMatrix> && EigenDense<FMatrix>,
                "eigen_mesh_view: V and F must be dense Eigen matrices (Matrix, Map, Ref or Block)");
  static_assert(std::is_same_v<v_scalar, float> || std::is_same_v<v_scalar, double>,
                "eigen_mesh_view: V (vertex positions) must hold float or double");
  static_assert(std::is_integral_v<f_scalar> && !std::is_same_v<f_scalar, bool>,
                "eigen_mesh_view: F (triangle indices) must hold an integer type");

 public:
  /// The vertex matrix type V.
  using vertex_matrix = VMatrix;
  /// The face matrix type F.
  using face_matrix = FMatrix;

  /// Views V (one vertex per row) and F (one triangle per row); both must outlive the view.
  eigen_mesh_view(VMatrix& V, FMatrix& F) : v_(V), f_(F) {}

  /// Rows of V.
  [[nodiscard]] index_t num_vertices() const noexcept { return static_cast<index_t>(v_.get().rows()); }
  /// Rows of F.
  [[nodiscard]] index_t num_faces() const noexcept { return static_cast<index_t>(f_.get().rows()); }
  /// F(f, k): vertex index of corner k of face f.
  [[nodiscard]] index_t face_vertex(index_t f, int k) const noexcept { return static_cast<index_t>(f_.get()(f, k)); }
  /// Row v of V.
  [[nodiscard]] std::array<v_scalar, 3> position(index_t v) const noexcept {
    const auto& V = v_.get();
    return {V(v, 0), V(v, 1), V(v, 2)};
  }
  /// The vertex matrix.
  [[nodiscard]] const VMatrix& vertices() const noexcept { return v_.get(); }
  /// The face matrix.
  [[nodiscard]] const FMatrix& faces() const noexcept { return f_.get(); }

 private:
  detail::eigen_holder<VMatrix> v_;
  detail::eigen_holder<FMatrix> f_;
};

/// Checks the shapes of V and F and returns a view over them: V must be n x 3 and F m x 3 (a 3 x n
/// matrix is reported as probably transposed). Plain matrices must be lvalues that outlive the view;
/// Maps and Refs may be temporaries. O(1): element checks are validate_mesh()'s job.
template <class VArg, class FArg>
requires EigenDense<VArg> && EigenDense<FArg>
    result<eigen_mesh_view<std::remove_reference_t<VArg>, std::remove_reference_t<FArg>>> make_eigen_mesh_view(
        VArg&& V, FArg&& F) {
  static_assert(std::is_lvalue_reference_v<VArg> || !detail::eigen_is_plain<VArg>,
                "make_eigen_mesh_view: V is a temporary matrix; the view would dangle. Pass a named matrix.");
  static_assert(std::is_lvalue_reference_v<FArg> || !detail::eigen_is_plain<FArg>,
                "make_eigen_mesh_view: F is a temporary matrix; the view would dangle. Pass a named matrix.");
  auto shape = [](const char* what, const char* layout, index_t rows, index_t cols) -> status {
    if (cols == 3) return {};
    return status::invalid_argument(detail::cat("eigen_mesh_view: ", what, " must be ", layout, ", got ", rows, " x ",
                                                cols, rows == 3 ? " (is it transposed?)" : ""));
  };
  if (auto s = shape("V", "n x 3 (one vertex position per row)", V.rows(), V.cols()); !s) return s;
  if (auto s = shape("F", "m x 3 (one triangle per row; triangulate polygons first)", F.rows(), F.cols()); !s) return s;
  return eigen_mesh_view<std::remove_reference_t<VArg>, std::remove_reference_t<FArg>>(V, F);
}

// ---------------------------------------------------------------------------------------------
// A matrix as a one-channel image

/// A one-channel image over an Eigen matrix (or Map, Ref, Block): width = cols, height = rows,
/// pixel (x, y) = coefficient (y, x), so a row-major buffer mapped with Eigen::Map reads in the usual
/// image order. Scalars uint8, uint16 and float are pixels as they are; double matrices (height
/// fields) read and write float pixels. Writable when the matrix is (not const, not a Map<const>).
/// Models Image, and WritableImage when writable. Nothing is copied; keep a plain matrix alive while
/// the view is used. Algorithms validate the size (an empty matrix is reported) at their entry.
template <class M>
class eigen_image_view {
  static_assert(EigenDense<M>, "eigen_image_view: M must be a dense Eigen matrix (Matrix, Map, Ref or Block)");

 public:
  /// The viewed matrix type M.
  using matrix_type = M;
  /// M's scalar type.
  using scalar_type = typename std::remove_const_t<M>::Scalar;
  static_assert(Channel<scalar_type> || std::is_same_v<scalar_type, double>,
                "eigen_image_view: the matrix must hold std::uint8_t, std::uint16_t, float or double");
  /// The pixel type: the scalar, with double read as float.
  using pixel_type = std::conditional_t<std::is_same_v<scalar_type, double>, float, scalar_type>;
  /// True when M's coefficients can be assigned (not a const matrix or view).
  static constexpr bool writable = std::is_assignable_v<decltype(std::declval<M&>()(0, 0)), scalar_type>;

  /// Views a named matrix (referenced) or a Map / Ref / Block (copied: it is a view itself).
  explicit eigen_image_view(M& m) : m_(m) {}
  /// Views a Map / Ref / Block temporary (copied: it is a view itself).
  explicit eigen_image_view(M&& m) requires(!detail::eigen_is_plain<M>) : m_(m) {}
  eigen_image_view(M&& m) requires detail::eigen_is_plain<M>
  = delete;  // would dangle: name the matrix

  /// cols() of the matrix.
  [[nodiscard]] index_t width() const noexcept { return static_cast<index_t>(m_.get().cols()); }
  /// rows() of the matrix.
  [[nodiscard]] index_t height() const noexcept { return static_cast<index_t>(m_.get().rows()); }
  /// Coefficient (row y, column x).
  [[nodiscard]] pixel_type read(index_t x, index_t y) const noexcept {
    TESSERA_ASSERT(x >= 0 && x < width() && y >= 0 && y < height());
    return static_cast<pixel_type>(m_.get()(y, x));
  }
  /// Sets coefficient (row y, column x); writable matrices only.
  void write(index_t x, index_t y, const pixel_type& v) noexcept requires writable {
    TESSERA_ASSERT(x >= 0 && x < width() && y >= 0 && y < height());
    m_.get()(y, x) = static_cast<scalar_type>(v);
  }
  /// The matrix.
  [[nodiscard]] M& matrix() noexcept { return m_.get(); }
  /// The matrix (read-only).
  [[nodiscard]] const M& matrix() const noexcept { return m_.get(); }

  /// The image_traits validate hook (run by validate_image): a Map over null data that claims a
  /// non-empty size, or a negative size, is refused.
  [[nodiscard]] status validate(std::string_view what) const {
    const auto& m = m_.get();
    if (m.rows() < 0 || m.cols() < 0)
      return status::invalid_argument(
          detail::cat(what, ": Eigen matrix has a negative size ", m.rows(), " x ", m.cols()));
    if constexpr (requires { m.data(); }) {
      if (m.size() > 0 && m.data() == nullptr)
        return status::invalid_argument(
            detail::cat(what, ": Eigen matrix data is null for a ", m.rows(), " x ", m.cols(), " matrix"));
    }
    return {};
  }

 private:
  detail::eigen_holder<M> m_;
};

// Deduction guides: a named matrix is referenced, an expression (Map, Ref, Block) is held by value.
// Spelled out because Clang 14 finds the two constrained rvalue constructors ambiguous.
template <class M>
eigen_image_view(M&) -> eigen_image_view<M>;
template <class M>
eigen_image_view(M&&) -> eigen_image_view<std::remove_cvref_t<M>>;

TESSERA_NAMESPACE_END
