// tessera/geometry/tile_geometric_plane.hpp: lays out a geometric Wang tile set on a C x R grid by
// any TileColoring and welds it into one mesh: the border vertices of touching tiles (bit-identical
// in tile coordinates, paper 000 §3.2) become one vertex, so elements crossing tile edges come out
// closed. Also the border layout of a tile and the border-consistency count of a tile set.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/status.hpp"
#include "../core/tile_coloring.hpp"
#include "../core/tri_mesh.hpp"
#include "../tiling/complete_tile_set.hpp"
#include "geometric_wang_tiles.hpp"

TESSERA_NAMESPACE_BEGIN

/// The vertices of a tile lying on its sides, per side in a canonical order (along the side, then
/// by height), and for every vertex its side (-1 inside).
struct tile_border_layout {
  std::array<std::vector<index_t>, 4> side;
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
      return status::invalid_argument(detail::cat("tile: vertex ", v, " (", p.x, ", ", p.y, ") lies outside [0, ", tile_size, "]^2"));
    const bool on[4] = {p.y == tile_size, p.x == tile_size, p.y == 0, p.x == 0};
    const int count = on[0] + on[1] + on[2] + on[3];
    if (count > 1) return status::invalid_argument(detail::cat("tile: vertex ", v, " lies on a tile corner"));
    for (int s = 0; s < 4; ++s)
      if (on[s]) l.side_of[v] = static_cast<signed char>(s), l.side[static_cast<std::size_t>(s)].push_back(static_cast<index_t>(v));
  }
  for (int s = 0; s < 4; ++s) {
    const int a = is_horizontal_side(s) ? 0 : 1;
    std::sort(l.side[static_cast<std::size_t>(s)].begin(), l.side[static_cast<std::size_t>(s)].end(), [&](index_t x, index_t y) {
      const vec3 p = tile.positions[static_cast<std::size_t>(x)], q = tile.positions[static_cast<std::size_t>(y)];
      return p[a] != q[a] ? p[a] < q[a] : p.z != q.z ? p.z < q.z : x < y;
    });
  }
  return l;
}

/// Counts (tile, side) pairs whose border geometry differs from the reference of its colour (the
/// north side of the first tile with that north colour, or the west side of the first with that west
/// colour): same number of vertices, positions within `tolerance` along the side and in height, and
/// the same edges along the side. 0 means any valid tiling is continuous. Errors: those of
/// tile_border_vertices, a set whose sizes disagree.
inline result<index_t> tile_set_border_mismatch(const geometric_tile_set& set, double tolerance = 1e-6) {
  if (set.tiles.size() != set.edges.size()) return status::invalid_argument("tile set: tiles and edges differ in count");
  const double w = set.tile_size;
  struct border {
    std::vector<vec3> pts;  // (along, height, 0) relative to the side line
    std::vector<std::pair<index_t, index_t>> edges;
  };
  auto border_of = [&](const tri_mesh& t, const tile_border_layout& l, int s) {
    border b;
    const int a = is_horizontal_side(s) ? 0 : 1;
    const auto& ids = l.side[static_cast<std::size_t>(s)];
    std::map<index_t, index_t> rank;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const vec3 p = t.positions[static_cast<std::size_t>(ids[i])];
      b.pts.push_back({p[a], p.z, 0});
      rank[ids[i]] = static_cast<index_t>(i);
    }
    for (const auto& f : t.faces)
      for (int k = 0; k < 3; ++k) {
        const auto x = rank.find(f[static_cast<std::size_t>(k)]), y = rank.find(f[static_cast<std::size_t>((k + 1) % 3)]);
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
  std::map<int, border> ref_h, ref_v;
  index_t mismatches = 0;
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    auto l = tile_border_vertices(set.tiles[t], w);
    if (!l) return l.error();
    const wang_edges& e = set.edges[t];
    for (int s = 0; s < 4; ++s) {
      const border b = border_of(set.tiles[t], *l, s);
      auto& refs = is_horizontal_side(s) ? ref_h : ref_v;
      const int color = s == side_north ? e.north : s == side_east ? e.east : s == side_south ? e.south : e.west;
      auto it = refs.find(color);
      if (it == refs.end()) refs.emplace(color, b);
      else mismatches += same(it->second, b) ? 0 : 1;
    }
  }
  return mismatches;
}

/// Lays out `set` on a cols x rows grid by `coloring` (face = row * cols + col, row 0 at the top:
/// cell (col, row) covers x in [col w, (col + 1) w], y in [(rows - 1 - row) w, (rows - row) w]) and
/// welds touching borders into one mesh. Each cell uses the tile whose four edge colours match.
/// Errors: a colouring that is not a valid cols x rows colouring, colour counts that differ from the
/// set's, a cell whose edges no tile has, tiles whose matching borders have different vertex counts
/// (an inconsistent set), more than 2^31 output vertices. Cells are filled in parallel through
/// `exec`; the mesh is identical for every executor. O(output size).
template <TileColoring C, Executor E = serial_executor>
result<tri_mesh> tile_geometric_plane(const geometric_tile_set& set, const C& coloring, index_t cols, index_t rows, E&& exec = {}) {
  if (auto s = check_grid_coloring(coloring, cols, rows); !s) return s;
  if (coloring.num_colors(side_north) != set.horizontal_colors || coloring.num_colors(side_east) != set.vertical_colors)
    return status::invalid_argument(detail::cat("tile_geometric_plane: the colouring has ", coloring.num_colors(side_north), " x ",
                                                coloring.num_colors(side_east), " colours, the tile set ", set.horizontal_colors, " x ",
                                                set.vertical_colors));
  if (set.tiles.empty() || set.tiles.size() != set.edges.size()) return status::invalid_argument("tile_geometric_plane: empty tile set");
  std::map<std::array<int, 4>, index_t> by_edges;
  for (std::size_t t = 0; t < set.edges.size(); ++t) {
    const auto& e = set.edges[t];
    by_edges.emplace(std::array<int, 4>{e.north, e.east, e.south, e.west}, static_cast<index_t>(t));
  }
  const std::size_t ncells = static_cast<std::size_t>(cols * rows);
  std::vector<index_t> type(ncells);
  std::vector<unsigned char> used(set.tiles.size(), 0);
  for (index_t f = 0; f < cols * rows; ++f) {
    const std::array<int, 4> key{coloring.edge_color(f, 0), coloring.edge_color(f, 1), coloring.edge_color(f, 2), coloring.edge_color(f, 3)};
    const auto it = by_edges.find(key);
    if (it == by_edges.end())
      return status::invalid_argument(detail::cat("tile_geometric_plane: cell ", f, " needs edges [", key[0], ", ", key[1], ", ", key[2], ", ",
                                                  key[3], "] which no tile has"));
    type[static_cast<std::size_t>(f)] = it->second;
    used[static_cast<std::size_t>(it->second)] = 1;
  }
  // per tile type: border layout and the order of the vertices every cell owns (all but south/east)
  struct layout {
    tile_border_layout border;
    std::vector<index_t> rank;  // owned rank, or -1 for south/east vertices
    index_t owned = 0;
  };
  std::vector<layout> lay(set.tiles.size());
  for (std::size_t t = 0; t < set.tiles.size(); ++t) {
    if (!used[t]) continue;
    auto b = tile_border_vertices(set.tiles[t], set.tile_size);
    if (!b) return b.error();
    lay[t].border = std::move(*b);
    lay[t].rank.assign(set.tiles[t].positions.size(), -1);
    for (std::size_t v = 0; v < set.tiles[t].positions.size(); ++v) {
      const int s = lay[t].border.side_of[v];
      if (s != side_south && s != side_east) lay[t].rank[v] = lay[t].owned++;
    }
  }
  // neighbours must agree on their shared border's vertex count
  for (index_t r = 0; r < rows; ++r)
    for (index_t c = 0; c < cols; ++c) {
      const auto& a = lay[static_cast<std::size_t>(type[static_cast<std::size_t>(r * cols + c)])].border;
      if (r + 1 < rows && a.side[side_south].size() != lay[static_cast<std::size_t>(type[static_cast<std::size_t>((r + 1) * cols + c)])].border.side[side_north].size())
        return status::invalid_argument(detail::cat("tile_geometric_plane: tiles at cells ", r * cols + c, " and ", (r + 1) * cols + c,
                                                    " have different border vertex counts (inconsistent tile set)"));
      if (c + 1 < cols && a.side[side_east].size() != lay[static_cast<std::size_t>(type[static_cast<std::size_t>(r * cols + c + 1)])].border.side[side_west].size())
        return status::invalid_argument(detail::cat("tile_geometric_plane: tiles at cells ", r * cols + c, " and ", r * cols + c + 1,
                                                    " have different border vertex counts (inconsistent tile set)"));
    }
  // vertex and face offsets per cell
  std::vector<index_t> vbase(ncells + 1, 0), fbase(ncells + 1, 0);
  for (index_t r = 0; r < rows; ++r)
    for (index_t c = 0; c < cols; ++c) {
      const std::size_t cell = static_cast<std::size_t>(r * cols + c);
      const auto& L = lay[static_cast<std::size_t>(type[cell])];
      index_t n = L.owned;
      if (r == rows - 1) n += static_cast<index_t>(L.border.side[side_south].size());
      if (c == cols - 1) n += static_cast<index_t>(L.border.side[side_east].size());
      vbase[cell + 1] = vbase[cell] + n;
      fbase[cell + 1] = fbase[cell] + set.tiles[static_cast<std::size_t>(type[cell])].num_faces();
    }
  if (vbase.back() > (index_t{1} << 31))
    return status::size_overflow(detail::cat("tile_geometric_plane: ", vbase.back(), " vertices exceed 2^31"));
  tri_mesh out;
  out.positions.resize(static_cast<std::size_t>(vbase.back()));
  out.faces.resize(static_cast<std::size_t>(fbase.back()));
  const double w = set.tile_size;
  exec.parallel_for(0, static_cast<index_t>(ncells), [&](index_t cell) {
    const index_t r = cell / cols, c = cell % cols;
    const std::size_t t = static_cast<std::size_t>(type[static_cast<std::size_t>(cell)]);
    const tri_mesh& tile = set.tiles[t];
    const layout& L = lay[t];
    const vec3 off{static_cast<double>(c) * w, static_cast<double>(rows - 1 - r) * w, 0};
    const index_t base = vbase[static_cast<std::size_t>(cell)];
    const index_t extra_s = L.owned, extra_e = L.owned + (r == rows - 1 ? static_cast<index_t>(L.border.side[side_south].size()) : 0);
    std::vector<index_t> gid(tile.positions.size());
    std::vector<index_t> kth(tile.positions.size(), -1);
    for (int s : {side_south, side_east})
      for (std::size_t k = 0; k < L.border.side[static_cast<std::size_t>(s)].size(); ++k)
        kth[static_cast<std::size_t>(L.border.side[static_cast<std::size_t>(s)][k])] = static_cast<index_t>(k);
    for (std::size_t v = 0; v < tile.positions.size(); ++v) {
      const int s = L.border.side_of[v];
      if (L.rank[v] >= 0) {
        gid[v] = base + L.rank[v];
        out.positions[static_cast<std::size_t>(gid[v])] = tile.positions[v] + off;
      } else if (s == side_south) {
        if (r == rows - 1) {
          gid[v] = base + extra_s + kth[v];
          out.positions[static_cast<std::size_t>(gid[v])] = tile.positions[v] + off;
        } else {
          const std::size_t below = static_cast<std::size_t>((r + 1) * cols + c);
          const layout& B = lay[static_cast<std::size_t>(type[below])];
          gid[v] = vbase[below] + B.rank[static_cast<std::size_t>(B.border.side[side_north][static_cast<std::size_t>(kth[v])])];
        }
      } else {  // east
        if (c == cols - 1) {
          gid[v] = base + extra_e + kth[v];
          out.positions[static_cast<std::size_t>(gid[v])] = tile.positions[v] + off;
        } else {
          const std::size_t right = static_cast<std::size_t>(r * cols + c + 1);
          const layout& B = lay[static_cast<std::size_t>(type[right])];
          gid[v] = vbase[right] + B.rank[static_cast<std::size_t>(B.border.side[side_west][static_cast<std::size_t>(kth[v])])];
        }
      }
    }
    const index_t fb = fbase[static_cast<std::size_t>(cell)];
    for (std::size_t f = 0; f < tile.faces.size(); ++f)
      out.faces[static_cast<std::size_t>(fb) + f] = {gid[static_cast<std::size_t>(tile.faces[f][0])], gid[static_cast<std::size_t>(tile.faces[f][1])],
                                                     gid[static_cast<std::size_t>(tile.faces[f][2])]};
  });
  return out;
}

TESSERA_NAMESPACE_END
