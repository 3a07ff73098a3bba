// tessera/geometry/tile_geometric_plane.hpp: lays out a geometric Wang tile set on a C x R grid by
// any TileColoring and welds it into one mesh: the border vertices of touching tiles (bit-identical
// in tile coordinates, paper 000 §3.2) become one vertex, so elements crossing tile edges come out
// closed. Also the border layout of a tile and the border-consistency count of a tile set. The
// plane comes out as a tri_mesh, or straight into an engine's vertex and index buffers through a
// mesh_sink (core/mesh_sink.hpp: float or double positions, uint16 or uint32 indices, any stride).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/mesh_sink.hpp"
#include "../core/mesh_topology.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/tri_mesh.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "geometric_wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN

/// The vertices of a tile lying on its sides, per side in a canonical order (along the side, then
/// by height), and for every vertex its side (-1 inside).
struct tile_border_layout {
  /// Per side: its vertices in canonical order.
  std::array<std::vector<index_t>, 4> side;
  /// Per vertex: its side, or -1 inside.
  std::vector<signed char> side_of;
};

/// Finds the border vertices of a tile covering [0, tile_size]^2 (exact coordinates 0 or tile_size).
/// Errors: a vertex outside the tile, or on two sides (at a corner: elements must not cross corners).
inline result<tile_border_layout> tile_border_vertices(const tri_mesh& tile, double tile_size) {
  tile_border_layout l;
  l.side_of.assign(tile.positions.size(), -1);
  for (std::size_t v = 0; v < tile.positions.size(); ++v) {
    const vec3 p = tile.positions[v];
    if (!(p.x >= 0 && p.x <= tile_size && p.y >= 0 && p.y <= tile_size))
      return status::invalid_argument(
          detail::cat("tile: vertex ", v, " (", p.x, ", ", p.y, ") lies outside [0, ", tile_size, "]^2"));
    const bool on[4] = {p.y == tile_size, p.x == tile_size, p.y == 0, p.x == 0};
    const int count = on[0] + on[1] + on[2] + on[3];
    if (count > 1) return status::invalid_argument(detail::cat("tile: vertex ", v, " lies on a tile corner"));
    for (int s = 0; s < 4; ++s)
      if (on[s]) {
        l.side_of[v] = static_cast<signed char>(s);
        l.side[detail::to_size(s)].push_back(static_cast<index_t>(v));
      }
  }
  for (int s = 0; s < 4; ++s) {
    const int a = is_horizontal_side(s) ? 0 : 1;
    std::sort(l.side[detail::to_size(s)].begin(), l.side[detail::to_size(s)].end(), [&](index_t x, index_t y) {
      const vec3 p = tile.positions[detail::to_size(x)], q = tile.positions[detail::to_size(y)];
      return p[a] != q[a] ? p[a] < q[a] : p.z != q.z ? p.z < q.z : x < y;
    });
  }
  return l;
}

/// Elements (connected components) of a tile that touch two adjacent sides of [0, tile_size]^2
/// (north and east, east and south, ...): elements crossing a tile corner, which §3.1 of paper 000
/// (after Cohen et al.) rules out. An element may touch two opposite sides (a thread across the
/// tile). A vertex counts as touching a side when its coordinate equals the side exactly (border
/// vertices are cut exactly on the line). O(V + F).
inline index_t tile_corner_crossings(const tri_mesh& tile, double tile_size) {
  const mesh_components comp = connected_components(tile);
  std::vector<unsigned> sides(detail::to_size(comp.count), 0);
  for (std::size_t f = 0; f < tile.faces.size(); ++f)
    for (index_t v : tile.faces[f]) {
      if (v < 0 || v >= tile.num_vertices()) continue;
      const vec3 p = tile.positions[detail::to_size(v)];
      auto& b = sides[detail::to_size(comp.face_component[f])];
      b |= (p.y == tile_size ? border_bit(side_north) : 0u) | (p.x == tile_size ? border_bit(side_east) : 0u) |
           (p.y == 0 ? border_bit(side_south) : 0u) | (p.x == 0 ? border_bit(side_west) : 0u);
    }
  index_t n = 0;
  for (unsigned b : sides) {
    const bool ns = b & (border_bit(side_north) | border_bit(side_south)),
               ew = b & (border_bit(side_east) | border_bit(side_west));
    n += ns && ew ? 1 : 0;
  }
  return n;
}

/// tile_corner_crossings summed over the tiles of a set.
inline index_t tile_set_corner_crossings(const geometric_tile_set& set) {
  index_t n = 0;
  for (const auto& t : set.tiles) n += tile_corner_crossings(t, set.tile_size);
  return n;
}

/// Counts (tile, side) pairs whose border geometry differs from the reference of its colour (the
/// first side, in tile and side order, carrying that colour of that class: horizontal or vertical in a
/// planar set, the axis X, Y or Z the side runs along in a three-axis set, geometric_tile_set::
/// side_class): same number of vertices, positions within `tolerance` along the side (along +x or +y
/// of the tile, which is +axis in a three-axis set) and in height, and the same edges along the side.
/// 0 means any valid tiling is continuous, in the plane and, three-axis, around polycube edges.
/// Errors: those of tile_border_vertices, a set whose sizes disagree.
inline result<index_t> tile_set_border_mismatch(const geometric_tile_set& set, double tolerance = 1e-6) {
  if (set.tiles.size() != set.edges.size() || (set.three_axis() && set.faces.size() != set.tiles.size()))
    return status::invalid_argument("tile set: tiles, edges and faces differ in count");
  for (const int f : set.faces)
    if (f < 0 || f >= cube_faces) return status::out_of_range(detail::cat("tile set: face ", f, " outside [0, 6)"));
  const double w = set.tile_size;
  struct border {
    std::vector<vec3> pts;  // (along, height, 0) relative to the side line
    std::vector<std::pair<index_t, index_t>> edges;
  };
  auto border_of = [&](const tri_mesh& t, const tile_border_layout& l, int s) {
    border b;
    const int a = is_horizontal_side(s) ? 0 : 1;
    const auto& ids = l.side[detail::to_size(s)];
    std::map<index_t, index_t> rank;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const vec3 p = t.positions[detail::to_size(ids[i])];
      b.pts.push_back({p[a], p.z, 0});
      rank[ids[i]] = static_cast<index_t>(i);
    }
    for (const auto& f : t.faces)
      for (int k = 0; k < 3; ++k) {
        const auto x = rank.find(f[detail::to_size(k)]), y = rank.find(f[detail::to_size((k + 1) % 3)]);
        if (x != rank.end() && y != rank.end()) b.edges.push_back(std::minmax(x->second, y->second));
      }
    std::sort(b.edges.begin(), b.edges.end());
    b.edges.erase(std::unique(b.edges.begin(), b.edges.end()), b.edges.end());
    return b;
  };
  auto same = [&](const border& x, const border& y) {
    if (x.pts.size() != y.pts.size() || x.edges != y.edges) return false;
    for (std::size_t i = 0; i < x.pts.size(); ++i)
      if (norm(x.pts[i] - y.pts[i]) > tolerance) return false;
    return true;
  };
  std::map<int, border> refs[3];  // per colour class
  index_t mismatches = 0;
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    auto l = tile_border_vertices(set.tiles[t], w);
    if (!l) return l.error();
    const wang_edges& e = set.edges[t];
    for (int s = 0; s < 4; ++s) {
      const border b = border_of(set.tiles[t], *l, s);
      auto& ref = refs[set.side_class(static_cast<index_t>(t), s)];
      const int color = e[s];
      auto it = ref.find(color);
      if (it == ref.end())
        ref.emplace(color, b);
      else
        mismatches += same(it->second, b) ? 0 : 1;
    }
  }
  return mismatches;
}

namespace detail {
/// Outputs of geometric_plane_layout::write_cell: tessera's arrays, or an engine's mesh_sink.
struct plane_array_out {
  vec3* positions;
  std::array<index_t, 3>* faces;
  void position(index_t v, const vec3& p) const noexcept { positions[v] = p; }
  void face(index_t f, index_t a, index_t b, index_t c) const noexcept { faces[f] = {a, b, c}; }
};
template <class Scalar, class Index>
struct plane_sink_out {
  const mesh_sink<Scalar, Index>* sink;
  void position(index_t v, const vec3& p) const noexcept { sink->set_position(v, p); }
  void face(index_t f, index_t a, index_t b, index_t c) const noexcept { sink->set_face(f, a, b, c); }
};
}  // namespace detail

/// The welded layout of a tiled plane, prepared once by plan_geometric_plane: which tile fills each
/// cell, where each cell's vertices and faces land in the output, and per tile the precomputed
/// weld maps of its borders. Vertices on a tile's south and east sides belong to the cell below or
/// to the right (found through the k-th vertex of that tile's north or west side, the canonical
/// order of tile_border_vertices), so no vertex is hashed or searched. Writing is one pass over the
/// output, tile by tile in parallel. The layout refers to the tile set it was planned from, which
/// must outlive it and stay unchanged.
class geometric_plane_layout {
 public:
  /// Columns of the plane.
  [[nodiscard]] index_t cols() const noexcept { return cols_; }
  /// Rows of the plane.
  [[nodiscard]] index_t rows() const noexcept { return rows_; }
  /// Vertices of the output mesh.
  [[nodiscard]] index_t num_vertices() const noexcept { return vbase_.empty() ? 0 : vbase_.back(); }
  /// Faces of the output mesh.
  [[nodiscard]] index_t num_faces() const noexcept { return fbase_.empty() ? 0 : fbase_.back(); }
  /// Tile index used at cell `cell` (row * cols + col).
  [[nodiscard]] index_t tile_at(index_t cell) const noexcept { return type_[detail::to_size(cell)]; }

  /// Writes the welded plane into caller storage of exactly num_vertices() positions and
  /// num_faces() faces (any contents: every element is overwritten, nothing is read, so the storage
  /// need not be initialised). Cell (col, row) covers x in [col w, (col + 1) w], y in
  /// [(rows - 1 - row) w, (rows - row) w]; faces keep the tiles' orientation. Cells are written in
  /// parallel through `exec`, each to its own ranges: the output is identical for every executor.
  /// Errors: spans of the wrong size. O(output size); thread-safe (const).
  template <Executor E = serial_executor>
  status write(std::span<vec3> positions, std::span<std::array<index_t, 3>> faces, E&& exec = {}) const {
    if (static_cast<index_t>(positions.size()) != num_vertices() || static_cast<index_t>(faces.size()) != num_faces())
      return status::invalid_argument(detail::cat("geometric_plane_layout::write: storage for ", positions.size(),
                                                  " vertices and ", faces.size(), " faces, the plane has ",
                                                  num_vertices(), " and ", num_faces()));
    const detail::plane_array_out out{positions.data(), faces.data()};
    exec.parallel_for(0, cols_ * rows_, [&](index_t cell) { write_cell(cell, out); });
    return {};
  }

  /// Writes the welded plane into an engine's buffers through `sink` (core/mesh_sink.hpp), with
  /// no tri_mesh in between: sink.prepare(num_vertices(), num_faces()) (growing or refusing short
  /// buffers, refusing more vertices than 16-bit indices address), then every position (converted
  /// from the double computation, so a double sink holds exactly what write() stores) and face.
  /// Cells are written in parallel through `exec`; the output is identical for every executor.
  /// Errors: those of prepare(), with nothing written. O(output size); thread-safe (const).
  template <class Scalar, class Index, Executor E = serial_executor>
  status write(mesh_sink<Scalar, Index>& sink, E&& exec = {}) const {
    if (auto s = sink.prepare(num_vertices(), num_faces()); !s)
      return status(s.code(), detail::cat("geometric_plane_layout::write: ", s.message()));
    const detail::plane_sink_out<Scalar, Index> out{&sink};
    exec.parallel_for(0, cols_ * rows_, [&](index_t cell) { write_cell(cell, out); });
    return {};
  }

 private:
  template <TileColoring C>
  friend result<geometric_plane_layout> plan_geometric_plane(const geometric_tile_set&, const C&, index_t, index_t);

  struct tile_plan {
    std::vector<index_t> owned;        // tile vertices every cell writes, in output order (all but south/east sides)
    std::vector<index_t> south, east;  // tile vertices on the south / east side, canonical order
    std::vector<index_t> north_rank, west_rank;      // owned rank of the k-th north / west vertex
    std::vector<std::array<std::int32_t, 3>> faces;  // local ids: < owned.size() owned rank, then south k, then east k
  };

  template <class Out>
  void write_cell(index_t cell, const Out& out) const {
    const index_t r = cell / cols_, c = cell % cols_;
    const std::size_t t = detail::to_size(type_[detail::to_size(cell)]);
    const tile_plan& P = plan_[t];
    const std::vector<vec3>& src = set_->tiles[t].positions;
    const vec3 off{static_cast<double>(c) * w_, static_cast<double>(rows_ - 1 - r) * w_, 0};
    const index_t base = vbase_[detail::to_size(cell)];
    const std::size_t no = P.owned.size(), ns = P.south.size(), ne = P.east.size();
    for (std::size_t i = 0; i < no; ++i)
      out.position(base + static_cast<index_t>(i), src[detail::to_size(P.owned[i])] + off);
    // global ids of the south and east vertices: new ones on the plane border, else the neighbour's
    thread_local std::vector<index_t> border;
    border.resize(ns + ne);
    index_t extra = base + static_cast<index_t>(no);
    if (r == rows_ - 1) {
      for (std::size_t k = 0; k < ns; ++k) {
        out.position(base + static_cast<index_t>(no + k), src[detail::to_size(P.south[k])] + off);
        border[k] = extra + static_cast<index_t>(k);
      }
      extra += static_cast<index_t>(ns);
    } else {
      const std::size_t below = detail::to_size(cell + cols_);
      const tile_plan& B = plan_[detail::to_size(type_[below])];
      for (std::size_t k = 0; k < ns; ++k) border[k] = vbase_[below] + B.north_rank[k];
    }
    if (c == cols_ - 1) {
      for (std::size_t k = 0; k < ne; ++k) {
        out.position(extra + static_cast<index_t>(k), src[detail::to_size(P.east[k])] + off);
        border[ns + k] = extra + static_cast<index_t>(k);
      }
    } else {
      const std::size_t right = detail::to_size(cell + 1);
      const tile_plan& B = plan_[detail::to_size(type_[right])];
      for (std::size_t k = 0; k < ne; ++k) border[ns + k] = vbase_[right] + B.west_rank[k];
    }
    const std::int32_t owned = static_cast<std::int32_t>(no);
    const index_t* bd = border.data();
    const index_t fb = fbase_[detail::to_size(cell)];
    for (std::size_t f = 0; f < P.faces.size(); ++f) {
      const auto& l = P.faces[f];
      out.face(fb + static_cast<index_t>(f), l[0] < owned ? base + l[0] : bd[l[0] - owned],
               l[1] < owned ? base + l[1] : bd[l[1] - owned], l[2] < owned ? base + l[2] : bd[l[2] - owned]);
    }
  }

  const geometric_tile_set* set_ = nullptr;
  index_t cols_ = 0, rows_ = 0;
  double w_ = 0;
  std::vector<index_t> type_;           // tile per cell
  std::vector<tile_plan> plan_;         // per tile (empty when unused)
  std::vector<index_t> vbase_, fbase_;  // output offsets per cell (+ total)
};

/// Checks, from the sizes alone, that tiling `set` on a cols x rows grid can fit tessera's output
/// limit (2^31 faces and vertices): every cell holds one tile, so the output has at least cols · rows ·
/// (fewest faces of a tile) faces. Run it before building a colouring of that grid (a stored colouring
/// of 65536 x 4096 cells is itself 4 GB); plan_geometric_plane runs it before allocating anything.
/// Errors: invalid_argument for a non-positive grid or an empty set, size_overflow beyond the limit. O(tiles).
inline status validate_geometric_plane_size(const geometric_tile_set& set, index_t cols, index_t rows) {
  if (cols <= 0 || rows <= 0)
    return status::invalid_argument(
        detail::cat("tile_geometric_plane: grid must be at least 1 x 1, got ", cols, " x ", rows));
  if (set.tiles.empty()) return status::invalid_argument("tile_geometric_plane: empty tile set");
  std::size_t fewest = set.tiles.front().faces.size();
  for (const auto& t : set.tiles) fewest = std::min(fewest, t.faces.size());
  constexpr index_t limit = index_t{1} << 31;
  if (cols > limit / rows ||
      static_cast<double>(cols) * static_cast<double>(rows) * static_cast<double>(fewest) > static_cast<double>(limit))
    return status::size_overflow(detail::cat("tile_geometric_plane: a ", cols, " x ", rows,
                                             " grid of tiles with at least ", fewest,
                                             " faces each exceeds the output limit of 2^31 faces"));
  return {};
}

/// Plans the welded layout of `set` on a cols x rows grid by `coloring` (face = row * cols + col, row
/// 0 at the top). Each cell uses the tile whose four edge colours match; touching borders are welded
/// by the canonical vertex order of their sides, which is identical for every tile carrying a colour
/// (paper 000 §3.2). Errors: a colouring that is not a valid cols x rows colouring, colour counts
/// that differ from the set's, a cell whose edges no tile has, a tile with a vertex outside the tile
/// or on a corner, neighbours whose shared borders have different vertex counts (an inconsistent
/// set), more than 2^31 output vertices (size_overflow, checked first from the grid size as far as
/// validate_geometric_plane_size can). O(cells + size of the tiles used); not thread-safe only in
/// the sense that `set` must not change while the layout is used.
template <TileColoring C>
result<geometric_plane_layout> plan_geometric_plane(const geometric_tile_set& set, const C& coloring, index_t cols,
                                                    index_t rows) {
  if (set.three_axis())
    return status::invalid_argument(
        "tile_geometric_plane: a three-axis tile set covers polycube quads (surface/polycube_tiling.hpp); tile a "
        "plane with the planar set of one of its faces, face_tile_set(set, face)");
  if (auto s = validate_geometric_plane_size(set, cols, rows); !s) return s;
  if (auto s = check_grid_coloring(coloring, cols, rows); !s) return s;
  if (coloring.num_colors(side_north) != set.horizontal_colors || coloring.num_colors(side_east) != set.vertical_colors)
    return status::invalid_argument(detail::cat(
        "tile_geometric_plane: the colouring has ", coloring.num_colors(side_north), " x ",
        coloring.num_colors(side_east), " colours, the tile set ", set.horizontal_colors, " x ", set.vertical_colors));
  if (set.tiles.empty() || set.tiles.size() != set.edges.size())
    return status::invalid_argument("tile_geometric_plane: empty tile set");
  std::map<std::array<int, 4>, index_t> by_edges;
  for (std::size_t t = 0; t < set.edges.size(); ++t) {
    const auto& e = set.edges[t];
    by_edges.emplace(std::array<int, 4>{e.north, e.east, e.south, e.west}, static_cast<index_t>(t));
  }
  geometric_plane_layout L;
  L.set_ = &set;
  L.cols_ = cols;
  L.rows_ = rows;
  L.w_ = set.tile_size;
  const std::size_t ncells = detail::to_size(cols * rows);
  L.type_.resize(ncells);
  std::vector<unsigned char> used(set.tiles.size(), 0);
  for (index_t f = 0; f < cols * rows; ++f) {
    const std::array<int, 4> key{coloring.edge_color(f, 0), coloring.edge_color(f, 1), coloring.edge_color(f, 2),
                                 coloring.edge_color(f, 3)};
    const auto it = by_edges.find(key);
    if (it == by_edges.end())
      return status::invalid_argument(detail::cat("tile_geometric_plane: cell ", f, " needs edges [", key[0], ", ",
                                                  key[1], ", ", key[2], ", ", key[3], "] which no tile has"));
    L.type_[detail::to_size(f)] = it->second;
    used[detail::to_size(it->second)] = 1;
  }
  // per tile: owned vertices, south/east sides, weld maps of the north/west sides, local faces
  L.plan_.resize(set.tiles.size());
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    if (!used[t]) continue;
    const tri_mesh& tile = set.tiles[t];
    if (tile.positions.size() > std::size_t{1} << 30)
      return status::size_overflow(
          detail::cat("tile_geometric_plane: tile ", t, " has ", tile.positions.size(), " vertices"));
    auto b = tile_border_vertices(tile, set.tile_size);
    if (!b) return b.error();
    auto& P = L.plan_[t];
    std::vector<std::int32_t> local(tile.positions.size(), -1);
    for (std::size_t v = 0; v < tile.positions.size(); ++v) {
      const int s = b->side_of[v];
      if (s != side_south && s != side_east) {
        local[v] = static_cast<std::int32_t>(P.owned.size());
        P.owned.push_back(static_cast<index_t>(v));
      }
    }
    P.south = std::move(b->side[side_south]);
    P.east = std::move(b->side[side_east]);
    for (std::size_t k = 0; k < P.south.size(); ++k)
      local[detail::to_size(P.south[k])] = static_cast<std::int32_t>(P.owned.size() + k);
    for (std::size_t k = 0; k < P.east.size(); ++k)
      local[detail::to_size(P.east[k])] = static_cast<std::int32_t>(P.owned.size() + P.south.size() + k);
    for (index_t v : b->side[side_north]) P.north_rank.push_back(local[detail::to_size(v)]);
    for (index_t v : b->side[side_west]) P.west_rank.push_back(local[detail::to_size(v)]);
    P.faces.resize(tile.faces.size());
    for (std::size_t f = 0; f < tile.faces.size(); ++f)
      for (std::size_t k = 0; k < 3; ++k) {
        const index_t v = tile.faces[f][k];
        if (v < 0 || v >= tile.num_vertices())
          return status::invalid_argument(
              detail::cat("tile_geometric_plane: tile ", t, " face ", f, " has vertex ", v, " out of range"));
        P.faces[f][k] = local[detail::to_size(v)];
      }
  }
  // neighbours must agree on their shared border's vertex count
  const auto plan_at = [&](index_t cell) -> const auto& {
    return L.plan_[detail::to_size(L.type_[detail::to_size(cell)])];
  };
  for (index_t r = 0; r < rows; ++r)
    for (index_t c = 0; c < cols; ++c) {
      const auto& a = plan_at(r * cols + c);
      if (r + 1 < rows && a.south.size() != plan_at((r + 1) * cols + c).north_rank.size())
        return status::invalid_argument(detail::cat("tile_geometric_plane: tiles at cells ", r * cols + c, " and ",
                                                    (r + 1) * cols + c,
                                                    " have different border vertex counts (inconsistent tile set)"));
      if (c + 1 < cols && a.east.size() != plan_at(r * cols + c + 1).west_rank.size())
        return status::invalid_argument(detail::cat("tile_geometric_plane: tiles at cells ", r * cols + c, " and ",
                                                    r * cols + c + 1,
                                                    " have different border vertex counts (inconsistent tile set)"));
    }
  // vertex and face offsets per cell
  L.vbase_.assign(ncells + 1, 0);
  L.fbase_.assign(ncells + 1, 0);
  for (index_t r = 0; r < rows; ++r)
    for (index_t c = 0; c < cols; ++c) {
      const std::size_t cell = detail::to_size(r * cols + c);
      const auto& P = plan_at(static_cast<index_t>(cell));
      index_t n = static_cast<index_t>(P.owned.size());
      if (r == rows - 1) n += static_cast<index_t>(P.south.size());
      if (c == cols - 1) n += static_cast<index_t>(P.east.size());
      L.vbase_[cell + 1] = L.vbase_[cell] + n;
      L.fbase_[cell + 1] = L.fbase_[cell] + static_cast<index_t>(P.faces.size());
    }
  if (L.vbase_.back() > (index_t{1} << 31))
    return status::size_overflow(detail::cat("tile_geometric_plane: ", L.vbase_.back(), " vertices exceed 2^31"));
  return L;
}

/// Lays out `set` on a cols x rows grid by `coloring` and welds touching borders into one mesh
/// (plan_geometric_plane, then geometric_plane_layout::write into a tri_mesh sized once). Callers
/// that own their vertex storage, or tile the same grid repeatedly, use the two steps directly.
/// Errors: those of plan_geometric_plane. Cells are filled in parallel through `exec`; the mesh is
/// identical for every executor. O(output size).
template <TileColoring C, Executor E = serial_executor>
result<tri_mesh> tile_geometric_plane(const geometric_tile_set& set, const C& coloring, index_t cols, index_t rows,
                                      E&& exec = {}) {
  auto plan = plan_geometric_plane(set, coloring, cols, rows);
  if (!plan) return plan.error();
  tri_mesh out;
  out.positions.resize(detail::to_size(plan->num_vertices()));
  out.faces.resize(detail::to_size(plan->num_faces()));
  if (auto s = plan->write(out.positions, out.faces, exec); !s) return s;
  return out;
}

/// tile_geometric_plane written straight into an engine's buffers through `sink`
/// (core/mesh_sink.hpp): float or double positions at any offset and stride, uint16 or uint32
/// indices, no double/int64 tri_mesh in between. A double/uint32 sink receives exactly the
/// positions and indices of the tri_mesh overload. Errors: those of plan_geometric_plane and of
/// mesh_sink::prepare (too many vertices for 16-bit indices, short buffers), with nothing written.
template <TileColoring C, class Scalar, class Index, Executor E = serial_executor>
status tile_geometric_plane(const geometric_tile_set& set, const C& coloring, index_t cols, index_t rows,
                            mesh_sink<Scalar, Index>& sink, E&& exec = {}) {
  auto plan = plan_geometric_plane(set, coloring, cols, rows);
  if (!plan) return plan.error();
  return plan->write(sink, exec);
}

TESSERA_NAMESPACE_END

#ifdef TESSERA_COMPILED
#include "detail/compiled_tile_geometric_plane.hpp"  // extern templates: tessera::compiled (core/compiled.hpp)
#endif
