// tessera/geometry/constrained_mesh_quilt.hpp: mesh quilting with boundary constraints, paper 000 §3.3:
// fills a rectangle around a given frame (the edge strips of a Wang tile) so that the frame's fixed
// vertices never move and nothing new reaches the rectangle's sides. Border vertices of frame
// elements (their triangles meeting the sides in the element's border set B(C), §3.3.5) are held
// fixed during deformation and kept by the cuts; merged elements carry B(C1) u B(C2).
#pragma once

#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"
#include "mesh_quilt.hpp"

TESSERA_NAMESPACE_BEGIN

/// The constraint of a constrained quilt: elements already in place (with fixed vertices and border
/// sets) and the regions they count as synthesized (grid cells whose centre lies in one of the
/// rectangles start occupied, §3.3.1).
struct quilt_frame {
  /// Elements already in place.
  std::vector<texture_element> elements;
  /// Rectangles counted as synthesized.
  std::vector<xy_rect> occupied;
};

/// Constrained mesh quilting of `domain` around `frame`. Every vertex of the output lies inside the
/// domain; only fixed frame vertices may lie on its sides; fixed vertices come out bit-identical;
/// every element is manifold and closed except along fixed vertices (cuts on the tile border), and
/// no two elements intersect. `stream` separates the random choices of several quilts made with one
/// seed (the tiles of a set).
/// Errors: a domain that is empty or not finite, frame elements with a `fixed` array of the wrong
/// size or vertices outside the domain, bad options, more than 2^26 grid cells; cancelled through
/// options.progress. Runs the translation search through `exec`; output identical for any executor.
template <Executor E = serial_executor>
result<mesh_quilt_result> constrained_mesh_quilt(const quilt_exemplar& exemplar, const xy_rect& domain,
                                                 quilt_frame frame, const mesh_quilt_options& options = {},
                                                 std::uint64_t stream = 0, E&& exec = {}) {
  if (!(domain.x1 > domain.x0) || !(domain.y1 > domain.y0) || !std::isfinite(domain.x0) || !std::isfinite(domain.x1) ||
      !std::isfinite(domain.y0) || !std::isfinite(domain.y1))
    return status::invalid_argument(detail::cat("constrained_mesh_quilt: domain [", domain.x0, ", ", domain.x1, "] x [",
                                                domain.y0, ", ", domain.y1, "] is empty or not finite"));
  if (exemplar.num_elements() == 0)
    return status::invalid_argument("constrained_mesh_quilt: the exemplar is empty (not prepared)");
  if (auto s = detail::check_quilt_options(options); !s) return s;
  const double cells = (domain.width() / exemplar.cell_size()) * (domain.height() / exemplar.cell_size());
  if (cells > double(1 << 26))
    return status::size_overflow(detail::cat("constrained_mesh_quilt: ", cells, " grid cells; at most 2^26"));
  for (std::size_t i = 0; i < frame.elements.size(); ++i) {
    const auto& e = frame.elements[i];
    if (auto s = validate_mesh(e.mesh, "constrained_mesh_quilt: frame element"); !s) return s;
    if (!e.fixed.empty() && e.fixed.size() != e.mesh.positions.size())
      return status::invalid_argument(detail::cat("constrained_mesh_quilt: frame element ", i, " has ", e.fixed.size(),
                                                  " fixed flags for ", e.mesh.positions.size(), " vertices"));
    for (const vec3& p : e.mesh.positions)
      if (!domain.contains(p))
        return status::invalid_argument(detail::cat("constrained_mesh_quilt: frame element ", i, " has a vertex (", p.x,
                                                    ", ", p.y, ") outside the domain"));
  }
  detail::quilt_engine engine(
      exemplar, domain, detail::to_params(options, true, stream),
      [&exec](index_t n, const std::function<void(index_t)>& fn) { exec.parallel_for(0, n, fn); });
  engine.add_frame(std::move(frame.elements), frame.occupied);
  if (auto s = engine.run(options.progress); !s) return s;
  if (auto s = engine.fill_holes(options.progress); !s) return s;
  return detail::finish_quilt(engine);
}

TESSERA_NAMESPACE_END
