// tessera/adapters/cgal_boolean.hpp: Boolean union, difference and intersection of two closed
// triangle meshes through CGAL's corefinement (Polygon Mesh Processing, CGAL 5.5; Debian libcgal-dev),
// with exact constructions (Epeck). Paper 000 §5, Fig. 7: a geometric texture mapped onto a base mesh
// (map_geometric_tiles) joined with the base into one solid (e.g. for 3D printing), or engraved into it.
//
// Link tessera::cgal (CMake option TESSERA_WITH_CGAL; built when CGAL is found). Licence: CGAL's
// Polygon Mesh Processing package is GPL-3.0-or-later, so a program that includes this header is
// bound by the GPL; the rest of tessera does not include it and stays under its own licence.
// Needs exceptions (CGAL reports failures by throwing); they are caught here and come back as statuses.
//
//   mesh_boolean(a, b, boolean_op::unite | subtract | intersect, options) -> result<tri_mesh>
//
// Inputs: any two Meshes, each closed, manifold, free of self-intersections and bounding a volume
// (outward-facing, counter-clockwise seen from outside); several components per mesh are fine (the
// texture elements of a surface are thousands of closed components) as long as none crosses another.
// Every one of these is checked first and reported with the face or count that fails it.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <exception>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/progress.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "../core/vec.hpp"

TESSERA_NAMESPACE_BEGIN

/// Which Boolean mesh_boolean computes, of the solids A and B the two meshes bound.
enum class boolean_op {
  unite,     ///< A ∪ B (CLI: union): one solid, e.g. a base mesh and the texture elements on it
  subtract,  ///< A \ B (CLI: difference): B engraved into A
  intersect  ///< A ∩ B (CLI: intersection)
};

/// Options of mesh_boolean.
struct mesh_boolean_options {
  /// Test each input for self-intersections first (O(F log F)); corefinement assumes there are none,
  /// so turn it off only for meshes known to be clean.
  bool check_self_intersections = true;
  /// Progress (stages "checking", "intersecting", "triangulating", "building") and cancellation,
  /// reported from inside CGAL's corefinement.
  tessera::progress progress = {};
};

namespace detail {
using cgal_kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using cgal_mesh = CGAL::Surface_mesh<cgal_kernel::Point_3>;

/// Thrown by the visitor to stop CGAL when the progress asks to cancel; caught in mesh_boolean.
struct cgal_boolean_cancelled {};

/// Corefinement visitor that forwards CGAL's progress hooks to a tessera::progress.
struct cgal_progress_visitor : CGAL::Polygon_mesh_processing::Corefinement::Default_visitor<cgal_mesh> {
  const tessera::progress* progress = nullptr;
  mutable std::size_t total = 0, done = 0;
  void report(double f, std::string_view stage) const {
    if (progress != nullptr && !progress->report(f, stage)) throw cgal_boolean_cancelled{};
  }
  void start_filtering_intersections() const { report(0, "intersecting"); }
  void progress_filtering_intersections(double d) const { report(d, "intersecting"); }
  void start_triangulating_faces(std::size_t n) const {
    total = n;
    done = 0;
    report(0, "triangulating");
  }
  void triangulating_faces_step() const {
    if (++done % 1024 == 0) report(static_cast<double>(done) / static_cast<double>(total), "triangulating");
  }
  void start_building_output() const { report(0, "building"); }
  void end_building_output() const { report(1, "building"); }
};

/// Copies a validated Mesh into a CGAL Surface_mesh. Errors (invalid_argument): a face CGAL's halfedge
/// structure refuses (an edge used twice in one direction: non-manifold or inconsistently oriented).
template <Mesh M>
status to_cgal_mesh(const M& m, std::string_view what, cgal_mesh& out) {
  const index_t nv = tessera::num_vertices(m), nf = tessera::num_faces(m);
  out.reserve(static_cast<cgal_mesh::size_type>(nv), static_cast<cgal_mesh::size_type>(3 * nf / 2),
              static_cast<cgal_mesh::size_type>(nf));
  std::vector<cgal_mesh::Vertex_index> vid(to_size(nv));
  for (index_t v = 0; v < nv; ++v) {
    const vec3 p = tessera::vertex_position(m, v);
    vid[to_size(v)] = out.add_vertex(cgal_kernel::Point_3(p.x, p.y, p.z));
  }
  for (index_t f = 0; f < nf; ++f) {
    const auto a = vid[to_size(tessera::face_vertex(m, f, 0))], b = vid[to_size(tessera::face_vertex(m, f, 1))],
               c = vid[to_size(tessera::face_vertex(m, f, 2))];
    if (out.add_face(a, b, c) == cgal_mesh::null_face())
      return status::invalid_argument(cat(what, ": face ", f,
                                          " shares an edge in the same direction with another face, or a third face "
                                          "on an edge (non-manifold or inconsistently oriented)"));
  }
  return {};
}

/// The checks corefinement relies on: closed, no self-intersection, bounds a volume.
inline status check_boolean_input(const cgal_mesh& m, std::string_view what, const mesh_boolean_options& o) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::size_t border = 0;
  for (auto h : m.halfedges())
    if (m.is_border(h)) ++border;
  if (border > 0)
    return status::invalid_argument(
        cat(what, " is not closed: ", border, " edges have a face on one side only; a Boolean needs closed meshes"));
  if (o.check_self_intersections) {
    std::vector<std::pair<cgal_mesh::Face_index, cgal_mesh::Face_index>> pairs;
    PMP::self_intersections(m, std::back_inserter(pairs));
    // CGAL reports a degenerate face (zero area) as a pair of the face with itself
    for (const auto& [f, g] : pairs)
      if (f == g)
        return status::invalid_argument(cat(what, ": face ", static_cast<std::size_t>(f),
                                            " is degenerate (zero area); a Boolean needs proper triangles"));
    if (!pairs.empty())
      return status::invalid_argument(
          cat(what, " intersects itself: ", pairs.size(), " pairs of faces cross (first: faces ",
              static_cast<std::size_t>(pairs.front().first), " and ", static_cast<std::size_t>(pairs.front().second),
              "); a Boolean needs meshes without self-intersections"));
  }
  // does_bound_a_volume checks the nesting of the components against their orientations; an
  // inside-out mesh as a whole passes it, and has a negative volume
  if (!PMP::does_bound_a_volume(m) || !(CGAL::to_double(PMP::volume(m)) > 0))
    return status::invalid_argument(
        cat(what,
            " does not bound a volume: it faces inwards (its faces must be counter-clockwise "
            "seen from outside), or components are nested the wrong way round"));
  return {};
}

/// The faces of a CGAL Surface_mesh as a tri_mesh, coordinates rounded to double.
inline tri_mesh from_cgal_mesh(const cgal_mesh& m) {
  tri_mesh out;
  out.positions.reserve(m.number_of_vertices());
  std::vector<index_t> id(m.num_vertices(), -1);
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    id[static_cast<std::size_t>(v)] =
        out.add_vertex({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  out.faces.reserve(m.number_of_faces());
  for (auto f : m.faces()) {
    std::array<index_t, 3> c{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      if (k < 3) c[to_size(k++)] = id[static_cast<std::size_t>(v)];
    out.add_face(c[0], c[1], c[2]);
  }
  return out;
}
}  // namespace detail

/// The Boolean `op` of the solids bounded by `a` and `b` (see the file comment), computed by CGAL's
/// corefinement with exact constructions and rounded to double at the end. Neither input is modified.
/// Errors (invalid_argument, naming "A" or "B"): a mesh validate_mesh refuses, an empty one, one that is
/// not manifold or not consistently oriented (the face), not closed (the open edges), with a zero-area
/// face (the face), crossing itself
/// (the pairs of faces), not bounding a volume; when the result is not a manifold surface (the inputs
/// touch along an edge or at a vertex without overlapping: sink elements into the base,
/// shell_options::sink); cancelled by the progress; internal_error when CGAL throws
/// (the message it gave). O((F_a + F_b) log(F_a + F_b) + intersections).
template <Mesh A, Mesh B>
result<tri_mesh> mesh_boolean(const A& a, const B& b, boolean_op op, const mesh_boolean_options& o = {}) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  if (op != boolean_op::unite && op != boolean_op::subtract && op != boolean_op::intersect)
    return status::invalid_argument("mesh_boolean: op must be unite, subtract or intersect");
  if (auto s = validate_mesh(a, "A"); !s) return s;
  if (auto s = validate_mesh(b, "B"); !s) return s;
  if (tessera::num_faces(a) == 0 || tessera::num_faces(b) == 0)
    return status::invalid_argument("mesh_boolean: A and B need faces (an empty mesh bounds no solid)");
  try {
    detail::cgal_mesh ma, mb, out;
    if (auto s = detail::to_cgal_mesh(a, "A", ma); !s) return s;
    if (auto s = detail::to_cgal_mesh(b, "B", mb); !s) return s;
    if (!o.progress.report(0, "checking")) return status::cancelled();
    if (auto s = detail::check_boolean_input(ma, "A", o); !s) return s;
    if (!o.progress.report(0.5, "checking")) return status::cancelled();
    if (auto s = detail::check_boolean_input(mb, "B", o); !s) return s;
    detail::cgal_progress_visitor visitor;
    visitor.progress = &o.progress;
    const auto np = CGAL::parameters::visitor(visitor);
    bool ok = false;
    switch (op) {
      case boolean_op::unite: ok = PMP::corefine_and_compute_union(ma, mb, out, np); break;
      case boolean_op::subtract: ok = PMP::corefine_and_compute_difference(ma, mb, out, np); break;
      case boolean_op::intersect: ok = PMP::corefine_and_compute_intersection(ma, mb, out, np); break;
    }
    if (!ok)
      return status::invalid_argument(
          "mesh_boolean: the result would not be a manifold surface (A and B touch along an edge or at a vertex "
          "without overlapping there); move one of them so that they overlap or stay apart (for texture elements: "
          "sink them into the base, shell_options::sink / geo-wang map --sink)");
    return detail::from_cgal_mesh(out);
  } catch (const detail::cgal_boolean_cancelled&) { return status::cancelled(); } catch (const std::exception& e) {
    return status::internal_error(detail::cat("mesh_boolean: CGAL failed: ", e.what()));
  }
}

TESSERA_NAMESPACE_END
