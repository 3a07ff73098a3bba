// tessera/surface/detail/polycube_chart_cuts.hpp: the boundary polygons of the charts once their planes
// are on the tile grid, the check that each is a polycube face (one outer loop turning by +360 degrees,
// holes by -360, no edge turning back), and the cut of every non-convex chart into rectangles: from each
// reflex corner the chart's edge along its first in-plane axis is extended across the chart (the
// horizontal decomposition of a rectilinear polygon) by a shortest path of interior base-mesh vertices,
// which are then held on that segment. Tutte's embedding (polycube_embed.hpp) is injective inside
// convex pieces; on an L-shaped chart it folds faces around the reflex corner.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../../core/tri_mesh.hpp"
#include "../quad_layout.hpp"
#include "polycube_charts.hpp"
#include "polycube_deform.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// One side of a chart's boundary loop: a polycube edge path, forward when the chart is the path's c
/// (the path then runs in the chart's orientation, interior on its left).
struct chart_loop_side {
  index_t path = -1;
  bool forward = true;
};

inline index_t side_start(const std::vector<polycube_edge_path>& paths, chart_loop_side s) {
  const auto& v = paths[to_size(s.path)].vertices;
  return s.forward ? v.front() : v.back();
}
inline index_t side_end(const std::vector<polycube_edge_path>& paths, chart_loop_side s) {
  const auto& v = paths[to_size(s.path)].vertices;
  return s.forward ? v.back() : v.front();
}

/// The boundary loops of every chart as sequences of sides, each loop continuing at the corner where
/// the previous side ends (the first unused side starting there). Deterministic: sides in path order.
inline std::vector<std::vector<std::vector<chart_loop_side>>> chart_boundary_loops(
    std::size_t chart_count, const std::vector<polycube_edge_path>& paths) {
  std::vector<std::vector<chart_loop_side>> sides(chart_count);
  for (std::size_t i = 0; i < paths.size(); ++i) {
    sides[to_size(paths[i].c)].push_back({static_cast<index_t>(i), true});
    sides[to_size(paths[i].d)].push_back({static_cast<index_t>(i), false});
  }
  std::vector<std::vector<std::vector<chart_loop_side>>> loops(chart_count);
  for (std::size_t c = 0; c < chart_count; ++c) {
    const auto& sc = sides[c];
    std::vector<std::uint8_t> used(sc.size(), 0);
    for (std::size_t i0 = 0; i0 < sc.size(); ++i0) {
      if (used[i0]) continue;
      used[i0] = 1;
      std::vector<chart_loop_side> loop{sc[i0]};
      const index_t start = side_start(paths, sc[i0]);
      for (std::size_t guard = 0; guard < sc.size() && side_end(paths, loop.back()) != start; ++guard) {
        const index_t at = side_end(paths, loop.back());
        std::size_t next = sc.size();
        for (std::size_t j = 0; j < sc.size() && next == sc.size(); ++j)
          if (!used[j] && side_start(paths, sc[j]) == at) next = j;
        if (next == sc.size()) break;
        used[next] = 1;
        loop.push_back(sc[next]);
      }
      loops[c].push_back(std::move(loop));
    }
  }
  return loops;
}

/// A corner's position in its chart's plane (the chart's in-plane axes, counter-clockwise seen from
/// the label direction).
inline vec2 chart_point(const vec3& p, polycube_label l) {
  const auto ax = quad_plane_axes(l);
  return {p[ax[0]], p[ax[1]]};
}

/// Checks that every chart's boundary, with the corners at `pos` (planes on the tile grid), is the
/// boundary of a polycube face: every side of positive length, no side turning back onto the previous
/// one, exactly one loop turning by +4 right angles and every other by -4. Returns the first chart
/// (smallest index) that fails, or -1; `why` receives the reason.
inline index_t find_unturnable_chart(const polycube_chart_set& cs, const std::vector<polycube_edge_path>& paths,
                                     const std::vector<std::vector<std::vector<chart_loop_side>>>& loops,
                                     const std::vector<vec3>& pos, double t, std::string& why) {
  if (cs.chart_label.size() < 2) return -1;
  const double eps = 1e-6 * t;
  for (std::size_t c = 0; c < loops.size(); ++c) {
    const auto l = static_cast<polycube_label>(cs.chart_label[c]);
    index_t outer = 0;
    for (const auto& loop : loops[c]) {
      const std::size_t n = loop.size();
      std::int64_t turn = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto& sp = loop[(i + n - 1) % n];
        const auto& sn = loop[i];
        const vec2 a = chart_point(pos[to_size(side_start(paths, sp))], l);
        const vec2 b = chart_point(pos[to_size(side_start(paths, sn))], l);
        const vec2 d = chart_point(pos[to_size(side_end(paths, sn))], l);
        const vec2 din = b - a, dout = d - b;
        if (!(norm(dout) > eps)) {
          why = cat("its side from the corner at vertex ", side_start(paths, sn), " has length zero");
          return static_cast<index_t>(c);
        }
        const double cr = cross(din, dout);
        if (cr > eps * eps)
          ++turn;
        else if (cr < -eps * eps)
          --turn;
        else if (dot(din, dout) < 0) {
          why = cat("its boundary turns back at the corner at vertex ", side_start(paths, sn));
          return static_cast<index_t>(c);
        }
      }
      if (turn == 4)
        ++outer;
      else if (turn != -4) {
        why = cat("a boundary loop turns by ", turn, " right angles (a polycube face needs +4, holes -4)");
        return static_cast<index_t>(c);
      }
    }
    if (!loops[c].empty() && outer != 1) {
      why = cat("it has ", outer, " outer boundary loops (a polycube face needs 1)");
      return static_cast<index_t>(c);
    }
  }
  return -1;
}

/// Order constraints that keep every chart's interior open: two parallel sides of a chart that face
/// each other across it (overlapping in the continuous solution `cont`, the first with the interior
/// above it, the second below, in that order along the axis across them) keep their order with at
/// least one tile between them; so a hole cannot touch its chart's outer boundary. Per axis, in chart
/// and side order.
inline std::vector<polycube_plane_order> chart_facing_orders(
    const polycube_chart_set& cs, const std::vector<polycube_edge_path>& paths,
    const std::vector<std::vector<std::vector<chart_loop_side>>>& loops, const std::vector<vec3>& cont, int axis) {
  std::vector<polycube_plane_order> out;
  struct side2 {
    index_t other;
    double lo, hi, at;
    bool up;  // interior on the + side of the axis
  };
  for (std::size_t c = 0; c < loops.size(); ++c) {
    const auto l = static_cast<polycube_label>(cs.chart_label[c]);
    const auto ax = quad_plane_axes(l);
    if (ax[0] != axis && ax[1] != axis) continue;
    const int k = ax[0] == axis ? 1 : 0;  // sides along ax[k] lie on planes of `axis`
    std::vector<side2> sides;
    for (const auto& loop : loops[c])
      for (const auto& sd : loop) {
        const auto& p = paths[to_size(sd.path)];
        const index_t other = p.c == static_cast<index_t>(c) ? p.d : p.c;
        if (cs.chart_label[to_size(other)] / 2 != axis) continue;
        const vec3 a = cont[to_size(side_start(paths, sd))], b = cont[to_size(side_end(paths, sd))];
        const double da = b[ax[to_size(k)]] - a[ax[to_size(k)]];
        // left of the direction in the chart's counter-clockwise frame: +ax[1] for +ax[0], -ax[0] for +ax[1]
        const bool up = k == 0 ? da > 0 : da < 0;
        sides.push_back({other, std::min(a[ax[to_size(k)]], b[ax[to_size(k)]]),
                         std::max(a[ax[to_size(k)]], b[ax[to_size(k)]]), 0.5 * (a[axis] + b[axis]), up});
      }
    for (const auto& s1 : sides)
      for (const auto& s2 : sides)
        if (s1.up && !s2.up && s1.other != s2.other && s1.at < s2.at && std::min(s1.hi, s2.hi) > std::max(s1.lo, s2.lo))
          out.push_back({s1.other, s2.other});
  }
  return out;
}

/// What the cuts into rectangles could not do, for the refinement of the next try
/// (polycube_refine.hpp): charts where a cut found no path of free interior vertices at all (their
/// boundary-spanning edges are split), and edges whose split frees a path that the line-face rule
/// blocked (an interior vertex and a vertex of the cut's line, smaller index first).
struct polycube_uncut {
  std::vector<index_t> charts;
  std::vector<std::array<index_t, 2>> edges;
  [[nodiscard]] bool empty() const { return charts.empty() && edges.empty(); }
};

/// Placement of the vertices of the polycube edge paths: each path's vertices spread by the base
/// mesh's arc length between pins (its corners, and the ends of the cuts that reach it).
struct polycube_path_pins {
  std::vector<std::vector<double>> arc;                         ///< per path, per vertex, in [0, 1]
  std::vector<std::vector<std::pair<std::size_t, vec3>>> pins;  ///< per path, (vertex slot, point)
};

template <class Free>
void spread_path(const polycube_edge_path& p, const polycube_path_pins& pp, std::size_t i, std::vector<vec3>& pos,
                 Free&& is_free) {
  auto pins = pp.pins[i];
  pins.push_back({0, pos[to_size(p.vertices.front())]});
  pins.push_back({p.vertices.size() - 1, pos[to_size(p.vertices.back())]});
  std::sort(pins.begin(), pins.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  const auto& s = pp.arc[i];
  for (std::size_t k = 0; k + 1 < pins.size(); ++k) {
    const auto [k0, p0] = pins[k];
    const auto [k1, p1] = pins[k + 1];
    for (std::size_t j = k0; j <= k1; ++j) {
      const auto v = to_size(p.vertices[j]);
      const double f = s[k1] > s[k0] ? (s[j] - s[k0]) / (s[k1] - s[k0]) : 0.0;
      for (int a = 0; a < 3; ++a)
        if (is_free(v, a)) pos[v][a] = p0[a] + (p1[a] - p0[a]) * f;
    }
  }
}

/// Cuts every non-convex chart into rectangles (see the file comment). `ring` holds each vertex's
/// neighbours; `fixed` marks the vertices whose position is final (corners and path vertices on entry;
/// cut vertices are added). A cut that finds no path of free interior vertices is left out (Tutte may
/// then fold faces near that corner, and the verification names them); `uncut`, when given, receives
/// what would let it through (polycube_uncut). Returns the number of cuts.
template <class Free>
index_t cut_charts_into_rectangles(const tri_mesh& m, const polycube_chart_set& cs,
                                   const std::vector<polycube_edge_path>& paths,
                                   const std::vector<std::vector<std::vector<chart_loop_side>>>& loops,
                                   const std::vector<std::vector<index_t>>& ring, double t, polycube_path_pins& pp,
                                   std::vector<vec3>& pos, std::vector<std::uint8_t>& fixed, Free&& is_free,
                                   polycube_uncut* uncut = nullptr) {
  const double eps = 1e-6 * t;
  const auto nv = to_size(m.num_vertices());
  index_t cuts = 0;
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::vector<index_t> from(nv, -1);
  std::vector<std::uint8_t> on_line(nv, 0);
  std::vector<std::pair<index_t, index_t>> done;
  for (std::size_t c = 0; c < loops.size(); ++c) {
    const auto l = static_cast<polycube_label>(cs.chart_label[c]);
    // the chart's sides in its plane
    struct side2 {
      chart_loop_side s;
      vec2 a, b;
    };
    std::vector<side2> sides;
    for (const auto& loop : loops[c])
      for (const auto& s : loop)
        sides.push_back(
            {s, chart_point(pos[to_size(side_start(paths, s))], l), chart_point(pos[to_size(side_end(paths, s))], l)});
    for (const auto& loop : loops[c]) {
      const std::size_t n = loop.size();
      for (std::size_t i = 0; i < n; ++i) {
        const auto sp = loop[(i + n - 1) % n], sn = loop[i];
        const index_t r = side_start(paths, sn);
        const vec2 a = chart_point(pos[to_size(side_start(paths, sp))], l), b = chart_point(pos[to_size(r)], l),
                   d = chart_point(pos[to_size(side_end(paths, sn))], l);
        const vec2 din = b - a, dout = d - b;
        if (!(cross(din, dout) < -eps * eps)) continue;  // not a reflex corner
        // extend the side along the first in-plane axis: the incoming one forward, else the outgoing back
        double dir = 0;
        if (std::abs(din.y) <= eps && std::abs(din.x) > eps) {
          dir = din.x > 0 ? 1 : -1;
        } else if (std::abs(dout.y) <= eps && std::abs(dout.x) > eps) {
          dir = dout.x > 0 ? -1 : 1;
        } else {
          continue;
        }
        // nearest side crossing the ray {b + s (dir, 0), s > 0}
        double best = std::numeric_limits<double>::infinity(), hit_frac = 0;
        std::size_t hit = sides.size();
        for (std::size_t k = 0; k < sides.size(); ++k) {
          const auto& sd = sides[k];
          if (std::abs(sd.a.x - sd.b.x) > eps) continue;  // not across the ray
          const double lo = std::min(sd.a.y, sd.b.y), hi = std::max(sd.a.y, sd.b.y);
          if (b.y < lo - eps || b.y > hi + eps) continue;
          const double s = (sd.a.x - b.x) * dir;
          if (!(s > eps) || !(s < best)) continue;
          best = s;
          hit = k;
          hit_frac = std::clamp((b.y - sd.a.y) / (sd.b.y - sd.a.y), 0.0, 1.0);
        }
        if (hit == sides.size()) continue;
        const auto& hs = sides[hit];
        const auto pi = to_size(hs.s.path);
        const auto& pv = paths[pi].vertices;
        // the hit in the path's own order
        const double frac = hs.s.forward ? hit_frac : 1 - hit_frac;
        std::size_t slot = pv.size();
        vec3 hit_point = pos[to_size(r)];
        hit_point[quad_plane_axes(l)[0]] = hs.a.x;
        if (frac <= eps / std::max(t, norm(hs.b - hs.a))) {
          slot = 0;
        } else if (frac >= 1 - eps / std::max(t, norm(hs.b - hs.a))) {
          slot = pv.size() - 1;
        } else {
          // the interior vertex closest to the hit (vertices sit in order along the path), strictly
          // between the pins around it
          const int w = quad_plane_axes(l)[1];
          const double y0 = pos[to_size(pv.front())][w], y1 = pos[to_size(pv.back())][w];
          auto at = [&](std::size_t k) { return (pos[to_size(pv[k])][w] - y0) / (y1 - y0); };
          std::size_t lo = 0, hi = pv.size() - 1;
          for (const auto& pin : pp.pins[pi]) {
            if (at(pin.first) <= frac && pin.first > lo) lo = pin.first;
            if (at(pin.first) >= frac && pin.first < hi) hi = pin.first;
          }
          for (std::size_t k = lo + 1; k < hi; ++k)
            if (slot == pv.size() || std::abs(at(k) - frac) < std::abs(at(slot) - frac)) slot = k;
        }
        if (slot == pv.size()) continue;
        const index_t target = pv[slot];
        if (std::find(done.begin(), done.end(), std::pair{std::min(r, target), std::max(r, target)}) != done.end())
          continue;
        // vertices already on the cut's line: a cut vertex must not close a face with two of them (or
        // with its predecessor and one of them): that face would collapse onto the line
        for (const auto& sd : sides) {
          if (std::abs(sd.a.y - b.y) > eps || std::abs(sd.b.y - b.y) > eps) continue;
          for (index_t v : paths[to_size(sd.s.path)].vertices) on_line[to_size(v)] = 1;
        }
        on_line[to_size(r)] = on_line[to_size(target)] = 1;
        auto adjacent = [&](index_t x, index_t y) {
          const auto& rx = ring[to_size(x)];
          return std::find(rx.begin(), rx.end(), y) != rx.end();
        };
        // the vertices x of the line with which a cut step v -> w would close a face onto the line,
        // (v, w, x) or (w, x, y) with y on the line too (not at the target), each passed to `visit`
        // until it returns true
        auto line_partners = [&](index_t v, index_t w, auto&& visit) {
          for (index_t x : ring[to_size(w)]) {
            if (!on_line[to_size(x)] || x == v) continue;
            bool closes = adjacent(x, v);
            if (w != target)
              for (index_t y : ring[to_size(w)]) closes = closes || (y != x && on_line[to_size(y)] && adjacent(x, y));
            if (closes && visit(x)) return true;
          }
          return false;
        };
        auto closes_line_face = [&](index_t v, index_t w) { return line_partners(v, w, [](index_t) { return true; }); };
        // Dijkstra over free interior vertices of chart c, from r to target (the cut, r last), with or
        // without the line-face rule
        auto shortest = [&](bool line_rule) {
          auto usable = [&](index_t v, index_t w) {
            if (line_rule && closes_line_face(v, w)) return false;
            if (w == target) return true;
            const auto& vc = cs.vertex_charts[to_size(w)];
            return vc.size() == 1 && vc[0] == static_cast<index_t>(c) && !fixed[to_size(w)];
          };
          std::vector<index_t> touched;
          using item = std::pair<double, index_t>;
          std::priority_queue<item, std::vector<item>, std::greater<>> queue;
          dist[to_size(r)] = 0;
          touched.push_back(r);
          queue.push({0.0, r});
          while (!queue.empty()) {
            const auto [dv, v] = queue.top();
            queue.pop();
            if (dv > dist[to_size(v)] || v == target) continue;
            for (index_t w : ring[to_size(v)]) {
              if (!usable(v, w)) continue;
              const double nd = dv + distance(m.position(v), m.position(w));
              if (nd < dist[to_size(w)]) {
                if (std::isinf(dist[to_size(w)])) touched.push_back(w);
                dist[to_size(w)] = nd;
                from[to_size(w)] = v;
                queue.push({nd, w});
              }
            }
          }
          std::vector<index_t> path;
          if (!std::isinf(dist[to_size(target)]))
            for (index_t v = target; v >= 0; v = v == r ? -1 : from[to_size(v)]) path.push_back(v);
          for (index_t v : touched) {
            dist[to_size(v)] = std::numeric_limits<double>::infinity();
            from[to_size(v)] = -1;
          }
          return path;
        };
        std::vector<index_t> cut = shortest(true);
        if (cut.size() < 2 && uncut) {
          // blocked by the line-face rule: the edges from a cut vertex to the line's vertices of the
          // faces it would collapse are split for the next try; with no path at all, the chart's
          // boundary-spanning edges
          const auto free_path = shortest(false);
          const std::size_t before = uncut->edges.size();
          for (std::size_t k = 0; k + 1 < free_path.size(); ++k) {
            const index_t w = free_path[k], v = free_path[k + 1];  // v precedes w on the way from r
            const index_t inner = w == target ? v : w;             // the end that is not on a chart side
            if (inner == r) continue;
            line_partners(v, w, [&](index_t x) {
              uncut->edges.push_back({std::min(inner, x), std::max(inner, x)});
              return false;
            });
          }
          if (uncut->edges.size() == before &&
              (uncut->charts.empty() || uncut->charts.back() != static_cast<index_t>(c)))
            uncut->charts.push_back(static_cast<index_t>(c));
        }
        std::fill(on_line.begin(), on_line.end(), std::uint8_t{0});
        if (cut.size() < 2) continue;
        std::reverse(cut.begin(), cut.end());  // r ... target
        // pin the target on its path, then spread the cut from r to the hit point by arc length
        if (slot != 0 && slot != pv.size() - 1) {
          pp.pins[pi].push_back({slot, hit_point});
          pos[to_size(target)] = hit_point;
          spread_path(paths[pi], pp, pi, pos, is_free);
          pos[to_size(target)] = hit_point;
        }
        std::vector<double> s(cut.size(), 0.0);
        for (std::size_t k = 1; k < cut.size(); ++k)
          s[k] = s[k - 1] + distance(m.position(cut[k - 1]), m.position(cut[k]));
        const vec3 p0 = pos[to_size(r)], p1 = pos[to_size(target)];
        for (std::size_t k = 1; k + 1 < cut.size(); ++k) {
          const auto v = to_size(cut[k]);
          for (int ax = 0; ax < 3; ++ax)
            if (is_free(v, ax)) pos[v][ax] = p0[ax] + (p1[ax] - p0[ax]) * (s[k] / s.back());
          fixed[v] = 1;
        }
        done.push_back({std::min(r, target), std::max(r, target)});
        ++cuts;
      }
    }
  }
  return cuts;
}

}  // namespace detail
TESSERA_NAMESPACE_END
