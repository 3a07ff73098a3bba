// tessera/surface/detail/polycube_labeling.hpp: per-face polycube labelling by α-expansion graph cut
// (Boykov, Veksler & Zabih 2001) over the triangle dual graph, on geometry/max_flow.hpp. Energy: a
// fidelity term per face, area * (1 - exp(-((n·a_l - 1) / 0.2)² / 2)), and a compactness term per dual
// edge between different labels, compactness * length * exp(-((n_p·n_q - 1) / 0.25)² / 2) (times
// opposite_penalty between opposite labels): the weights of evocube (Dumery et al. 2022), described in
// ../shared/notes/surface.md. Areas and lengths are normalized by their means.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/executor.hpp"
#include "../../core/tri_mesh.hpp"
#include "../../core/vec.hpp"
#include "../../geometry/max_flow.hpp"
#include "../polycube_map.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Alpha-expansion stops when a sweep lowers the labeling energy by no more than this fraction of it.
inline constexpr double labeling_min_relative_gain = 1e-9;

/// Per-face fidelity costs (6 per face) and per-side compactness weights of a closed mesh.
struct polycube_energy {
  std::vector<std::array<double, 6>> data;
  std::vector<std::array<double, 3>> smooth;  ///< weight of side k of face f (0 where no neighbour)
  std::vector<std::array<index_t, 3>> neighbor;
  double opposite_penalty = 2;
};

template <Executor E>
polycube_energy make_polycube_energy(const tri_mesh& m, const std::vector<std::array<index_t, 3>>& neighbor,
                                     const polycube_options& o, E& exec) {
  const index_t nf = m.num_faces();
  polycube_energy en;
  en.neighbor = neighbor;
  en.opposite_penalty = o.opposite_penalty;
  en.data.resize(to_size(nf));
  en.smooth.resize(to_size(nf));
  std::vector<vec3> n(to_size(nf));
  std::vector<double> area(to_size(nf));
  exec.parallel_for(0, nf, [&](index_t f) {
    const vec3 an = face_area_normal(m, f);
    n[to_size(f)] = normalized(an);
    area[to_size(f)] = 0.5 * norm(an);
  });
  double total_area = 0, total_len = 0;
  index_t sides = 0;
  for (index_t f = 0; f < nf; ++f) {
    total_area += area[to_size(f)];
    for (int k = 0; k < 3; ++k) {
      total_len += distance(m.position(m.face_vertex(f, k)), m.position(m.face_vertex(f, (k + 1) % 3)));
      ++sides;
    }
  }
  const double mean_area = total_area / static_cast<double>(nf), mean_len = total_len / static_cast<double>(sides);
  exec.parallel_for(0, nf, [&](index_t f) {
    const auto fs = to_size(f);
    for (int l = 0; l < 6; ++l) {
      const double c = (dot(n[fs], label_direction(static_cast<polycube_label>(l))) - 1) / 0.2;
      en.data[fs][to_size(l)] = area[fs] / mean_area * (1 - std::exp(-0.5 * c * c));
    }
    for (int k = 0; k < 3; ++k) {
      const index_t g = neighbor[fs][to_size(k)];
      if (g < 0) continue;
      const double c = (dot(n[fs], n[to_size(g)]) - 1) / 0.25;
      const double len = distance(m.position(m.face_vertex(f, k)), m.position(m.face_vertex(f, (k + 1) % 3)));
      en.smooth[fs][to_size(k)] = o.compactness * len / mean_len * std::exp(-0.5 * c * c);
    }
  });
  return en;
}

/// Pairwise label cost factor: 0 equal, 1 different, opposite_penalty opposite.
inline double polycube_pair_cost(const polycube_energy& en, int a, int b) {
  return a == b ? 0.0 : (a ^ 1) == b ? en.opposite_penalty : 1.0;
}

inline double polycube_labeling_energy(const polycube_energy& en, const std::vector<std::uint8_t>& lab) {
  double e = 0;
  for (std::size_t f = 0; f < lab.size(); ++f) {
    e += en.data[f][lab[f]];
    for (int k = 0; k < 3; ++k) {
      const index_t g = en.neighbor[f][to_size(k)];
      if (g > static_cast<index_t>(f)) e += en.smooth[f][to_size(k)] * polycube_pair_cost(en, lab[f], lab[to_size(g)]);
    }
  }
  return e;
}

/// α-expansion: starts from the best fidelity label of each face (ties: smallest label), then sweeps
/// α = 0..5 until a sweep lowers the energy by less than 1e-9 relative or `cycles` sweeps ran. Each move
/// is kept only when it lowers the energy. Deterministic. O(cycles * 6 * maxflow(F)).
inline result<std::vector<std::uint8_t>> alpha_expansion_labels(const polycube_energy& en, int cycles) {
  const auto nf = static_cast<index_t>(en.data.size());
  std::vector<std::uint8_t> lab(to_size(nf));
  for (std::size_t f = 0; f < lab.size(); ++f) {
    int best = 0;
    for (int l = 1; l < 6; ++l)
      if (en.data[f][to_size(l)] < en.data[f][to_size(best)]) best = l;
    lab[f] = static_cast<std::uint8_t>(best);
  }
  double energy = polycube_labeling_energy(en, lab);
  for (int cycle = 0; cycle < cycles; ++cycle) {
    const double start = energy;
    for (int alpha = 0; alpha < 6; ++alpha) {
      // binary variable x_f: 0 keeps lab[f], 1 takes alpha (x = 1 <=> sink side)
      max_flow_graph g(nf);
      for (index_t f = 0; f < nf; ++f) {
        const auto fs = to_size(f);
        if (lab[fs] == alpha) {
          g.add_terminal(f, 0, std::numeric_limits<double>::infinity());  // fixed at alpha (x = 1)
          continue;
        }
        double e0 = en.data[fs][lab[fs]], e1 = en.data[fs][to_size(alpha)];
        for (int k = 0; k < 3; ++k) {
          const index_t q = en.neighbor[fs][to_size(k)];
          if (q < 0) continue;
          const auto qs = to_size(q);
          const double w = en.smooth[fs][to_size(k)];
          if (lab[qs] == alpha) {  // q is fixed at alpha: a unary term on f
            e0 += w * polycube_pair_cost(en, lab[fs], alpha);
            continue;
          }
          if (q < f) continue;  // each free pair once
          const double A = w * polycube_pair_cost(en, lab[fs], lab[qs]), B = w * polycube_pair_cost(en, lab[fs], alpha),
                       C = w * polycube_pair_cost(en, alpha, lab[qs]), D = 0;
          // E = A + (C - A) x_f + (D - C) x_q + (B + C - A - D) (1 - x_f) x_q
          e1 += C - A;
          const double dq = D - C;
          if (dq > 0)
            g.add_terminal(q, dq, 0);
          else
            g.add_terminal(q, 0, -dq);
          g.add_edge(f, q, std::max(0.0, B + C - A - D), 0);
        }
        const double d = e1 - e0;
        if (d > 0)
          g.add_terminal(f, d, 0);
        else
          g.add_terminal(f, 0, -d);
      }
      auto flow = g.solve();
      if (!flow) return flow.error();
      std::vector<std::uint8_t> next = lab;
      for (index_t f = 0; f < nf; ++f)
        if (!g.in_source_set(f)) next[to_size(f)] = static_cast<std::uint8_t>(alpha);
      const double e = polycube_labeling_energy(en, next);
      if (e < energy) {
        energy = e;
        lab.swap(next);
      }
    }
    if (!(start - energy > labeling_min_relative_gain * std::abs(start))) break;
  }
  return lab;
}

}  // namespace detail
TESSERA_NAMESPACE_END
