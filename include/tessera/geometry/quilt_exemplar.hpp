// tessera/geometry/quilt_exemplar.hpp: the prepared exemplar of mesh quilting (paper 000 §3.3, after
// Zhou et al. 2006): the exemplar's elements, a triangle BVH with face normals for the matching cost
// of eq. 1-4, the XY grid cell size and which elements are "long" (threads that run across a patch
// and are clipped and capped at patch borders instead of being taken whole). Build it once and reuse
// it for every quilt and every tile of a tile set.
#pragma once

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"
#include "bvh.hpp"
#include "mesh_elements.hpp"

TESSERA_NAMESPACE_BEGIN

/// Options of prepare_quilt_exemplar.
struct quilt_exemplar_options {
  /// Side of the XY grid cells of §3.3.1 (occupancy, translations on grid multiples). 0 = automatic:
  /// half the median element size (smaller XY extent: a ring's diameter, a thread's width).
  double cell_size = 0;
  /// An element is "long" when its XY extent exceeds this fraction of the exemplar's smaller side.
  double long_element_fraction = 0.45;
};

class quilt_exemplar;
/// Prepares an exemplar for quilting (defined below).
template <Mesh M>
result<quilt_exemplar> prepare_quilt_exemplar(const M& exemplar, const quilt_exemplar_options& options = {});

/// A geometric-texture exemplar prepared for quilting. Immutable after preparation; share it freely
/// between threads.
class quilt_exemplar {
 public:
  quilt_exemplar() = default;

  /// The exemplar mesh, its elements stored contiguously.
  [[nodiscard]] const tri_mesh& mesh() const noexcept { return mesh_; }
  /// The elements.
  [[nodiscard]] const std::vector<texture_element>& elements() const noexcept { return elements_; }
  /// A BVH over mesh().
  [[nodiscard]] const triangle_bvh& bvh() const noexcept { return bvh_; }
  /// Unit normal of every face of mesh().
  [[nodiscard]] const std::vector<vec3>& face_normals() const noexcept { return normals_; }
  /// Element of each face of mesh() (elements are stored contiguously, in element order).
  [[nodiscard]] index_t element_of_face(index_t f) const noexcept { return face_element_[detail::to_size(f)]; }
  /// First face of element e in mesh(); faces of e are [first_face(e), first_face(e + 1)).
  [[nodiscard]] index_t first_face(index_t e) const noexcept { return face_offset_[detail::to_size(e)]; }
  /// True when element e is long (see quilt_exemplar_options).
  [[nodiscard]] bool is_long(index_t e) const noexcept { return long_[detail::to_size(e)] != 0; }
  /// Bounds of mesh().
  [[nodiscard]] const aabb& bounds() const noexcept { return bounds_; }
  /// Side of the XY grid cells.
  [[nodiscard]] double cell_size() const noexcept { return cell_; }
  /// Median of the elements' smaller XY extent (a ring's or pebble's diameter, a thread's width).
  [[nodiscard]] double element_diameter() const noexcept { return diameter_; }
  /// Number of elements.
  [[nodiscard]] index_t num_elements() const noexcept { return static_cast<index_t>(elements_.size()); }

  /// Builds it (see the declaration above).
  template <Mesh M>
  friend result<quilt_exemplar> prepare_quilt_exemplar(const M& exemplar, const quilt_exemplar_options& options);

 private:
  tri_mesh mesh_;
  std::vector<texture_element> elements_;
  triangle_bvh bvh_;
  std::vector<vec3> normals_;
  std::vector<index_t> face_element_, face_offset_;
  std::vector<unsigned char> long_;
  aabb bounds_;
  double cell_ = 0, diameter_ = 0;
};

/// Largest grid of a quilting exemplar, in cells of cell_size (2^22): every grid translation of the
/// exemplar is a candidate, so a larger grid only means a hang.
inline constexpr index_t max_quilt_exemplar_cells = index_t{1} << 22;

/// Prepares any Mesh as a quilting exemplar. Open and non-manifold exemplars are rejected (closed
/// elements are what keeps every synthesized element closed); so are invalid meshes (NaN positions,
/// bad indices, degenerate faces), meshes without faces, a flat XY extent, a bad cell size, and (size_overflow)
/// an extent of more than max_quilt_exemplar_cells grid cells or a non-finite one.
/// O(F log F).
template <Mesh M>
result<quilt_exemplar> prepare_quilt_exemplar(const M& exemplar, const quilt_exemplar_options& options) {
  if (!(options.cell_size >= 0) || !std::isfinite(options.cell_size))
    return status::invalid_argument(
        detail::cat("quilt exemplar: cell_size must be finite and >= 0, got ", options.cell_size));
  if (!(options.long_element_fraction > 0))
    return status::invalid_argument(
        detail::cat("quilt exemplar: long_element_fraction must be > 0, got ", options.long_element_fraction));
  auto elems = extract_elements(exemplar, {}, "exemplar");
  if (!elems) return elems.error();
  quilt_exemplar q;
  q.elements_ = std::move(*elems);
  q.mesh_ = combine_elements(q.elements_);
  q.bounds_ = bounding_box(q.mesh_);
  const vec3 ext = q.bounds_.extent();
  if (!(ext.x > 0) || !(ext.y > 0))
    return status::invalid_argument(
        detail::cat("exemplar: XY extent is ", ext.x, " x ", ext.y, "; a geometric texture needs area"));
  std::vector<double> diam;
  for (const auto& e : q.elements_) {
    const vec3 x = e.box.extent();
    diam.push_back(std::min(x.x, x.y));  // across a thread, not along it
  }
  std::nth_element(diam.begin(), diam.begin() + static_cast<std::ptrdiff_t>(diam.size() / 2), diam.end());
  q.diameter_ = diam[diam.size() / 2];
  q.cell_ = options.cell_size > 0 ? options.cell_size : 0.5 * q.diameter_;
  if (!(q.cell_ > 0)) return status::invalid_argument("exemplar: elements have no XY extent");
  if (q.cell_ * 2 > std::min(ext.x, ext.y))
    return status::invalid_argument(
        detail::cat("exemplar: ", ext.x, " x ", ext.y, " is smaller than two grid cells of ", q.cell_));
  // Quilting tries every grid translation of the exemplar: its grid must stay small (a stray vertex
  // at 1e300 would otherwise ask for astronomically many candidates and cells).
  if (!std::isfinite(ext.x) || !std::isfinite(ext.y) || !std::isfinite(ext.z) ||
      (ext.x / q.cell_) * (ext.y / q.cell_) > static_cast<double>(max_quilt_exemplar_cells))
    return status::size_overflow(detail::cat("exemplar: ", ext.x, " x ", ext.y, " is ",
                                             (ext.x / q.cell_) * (ext.y / q.cell_), " grid cells of ", q.cell_,
                                             "; at most max_quilt_exemplar_cells = ", max_quilt_exemplar_cells,
                                             " (a stray vertex far away, or a tiny cell_size?)"));
  q.bvh_ = triangle_bvh(q.mesh_);
  q.normals_ = tessera::face_normals(q.mesh_);
  index_t f = 0;
  for (std::size_t e = 0; e < q.elements_.size(); ++e) {
    q.face_offset_.push_back(f);
    f += q.elements_[e].mesh.num_faces();
    q.face_element_.insert(q.face_element_.end(), detail::to_size(q.elements_[e].mesh.num_faces()),
                           static_cast<index_t>(e));
    const vec3 x = q.elements_[e].box.extent();
    q.long_.push_back(std::max(x.x, x.y) > options.long_element_fraction * std::min(ext.x, ext.y) ? 1 : 0);
  }
  q.face_offset_.push_back(f);
  return q;
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_quilt_exemplar.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
