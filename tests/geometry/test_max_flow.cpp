#include <tessera/geometry/max_flow.hpp>

#include <tessera/core/random.hpp>

#include <catch2/catch.hpp>

#include <vector>

using namespace tessera;

namespace {
struct edge {
  index_t a, b;
  double ab, ba;
};
struct problem {
  int n;
  std::vector<double> src, snk;
  std::vector<edge> edges;
};
double cut_value(const problem& p, const std::vector<bool>& in_s) {
  double c = 0;
  for (int i = 0; i < p.n; ++i)
    c += in_s[static_cast<std::size_t>(i)] ? p.snk[static_cast<std::size_t>(i)] : p.src[static_cast<std::size_t>(i)];
  for (const edge& e : p.edges) {
    const bool sa = in_s[static_cast<std::size_t>(e.a)], sb = in_s[static_cast<std::size_t>(e.b)];
    if (sa && !sb) c += e.ab;
    if (sb && !sa) c += e.ba;
  }
  return c;
}
problem random_problem(std::uint64_t seed, bool with_infinite) {
  counter_rng rng(seed);
  problem p;
  p.n = 2 + static_cast<int>(rng.below(10, 0));
  const double inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < p.n; ++i) {
    const double r = rng.uniform(i, 1);
    p.src.push_back(r < 0.3 ? std::floor(rng.uniform(i, 2) * 10) : 0.0);
    p.snk.push_back(r > 0.7 ? std::floor(rng.uniform(i, 3) * 10) : 0.0);
    if (with_infinite && rng.uniform(i, 4) < 0.1) p.src.back() = inf;
    if (with_infinite && rng.uniform(i, 5) < 0.1) p.snk.back() = inf;
  }
  const int m = static_cast<int>(rng.below(static_cast<std::uint64_t>(3 * p.n), 6));
  for (int e = 0; e < m; ++e) {
    const auto a = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(p.n), e, 7));
    const auto b = static_cast<index_t>(rng.below(static_cast<std::uint64_t>(p.n), e, 8));
    double ab = std::floor(rng.uniform(e, 9) * 8),
           ba = rng.uniform(e, 10) < 0.5 ? 0.0 : std::floor(rng.uniform(e, 11) * 8);
    if (with_infinite && rng.uniform(e, 12) < 0.1) ab = inf;
    p.edges.push_back({a, b, ab, ba});
  }
  return p;
}
}  // namespace

TEST_CASE("max flow equals the brute-force minimum cut on small random graphs", "[max_flow]") {
  for (std::uint64_t seed = 0; seed < 600; ++seed) {
    const bool with_inf = seed % 3 == 0;
    const problem p = random_problem(seed, with_inf);
    max_flow_graph g(p.n);
    for (int i = 0; i < p.n; ++i)
      g.add_terminal(i, p.src[static_cast<std::size_t>(i)], p.snk[static_cast<std::size_t>(i)]);
    for (const edge& e : p.edges) g.add_edge(e.a, e.b, e.ab, e.ba);
    const auto flow = g.solve();
    REQUIRE(flow.ok());
    double best = std::numeric_limits<double>::infinity();
    for (unsigned mask = 0; mask < (1u << p.n); ++mask) {
      std::vector<bool> s(static_cast<std::size_t>(p.n));
      for (int i = 0; i < p.n; ++i) s[static_cast<std::size_t>(i)] = (mask >> i) & 1u;
      best = std::min(best, cut_value(p, s));
    }
    INFO("seed " << seed);
    if (std::isinf(best)) {
      REQUIRE(std::isinf(*flow));
      continue;
    }
    REQUIRE(*flow == Approx(best));
    std::vector<bool> s(static_cast<std::size_t>(p.n));
    for (int i = 0; i < p.n; ++i) s[static_cast<std::size_t>(i)] = g.in_source_set(i);
    REQUIRE(cut_value(p, s) == Approx(best));
  }
}

TEST_CASE("max flow on a grid separates two seeded regions along the cheap column", "[max_flow]") {
  const int w = 30, h = 20;
  max_flow_graph g(w * h);
  for (int y = 0; y < h; ++y) {
    g.add_terminal(y * w, std::numeric_limits<double>::infinity(), 0);
    g.add_terminal(y * w + w - 1, 0, std::numeric_limits<double>::infinity());
    for (int x = 0; x + 1 < w; ++x) {
      const double c = x == 17 ? 0.1 : 1.0;  // the cheap column boundary
      g.add_edge(y * w + x, y * w + x + 1, c, c);
    }
    if (y + 1 < h)
      for (int x = 0; x < w; ++x) g.add_edge(y * w + x, (y + 1) * w + x, 1, 1);
  }
  const auto flow = g.solve();
  REQUIRE(flow.ok());
  REQUIRE(*flow == Approx(0.1 * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) REQUIRE(g.in_source_set(y * w + x) == (x <= 17));
}

TEST_CASE("max flow reports bad input", "[max_flow]") {
  {
    max_flow_graph g(2);
    g.add_edge(0, 1, -1, 0);
    const auto r = g.solve();
    REQUIRE_FALSE(r.ok());
    REQUIRE(r.error().code() == status_code::invalid_argument);
    REQUIRE(r.error().message().find("cap_ab") != std::string::npos);
  }
  {
    max_flow_graph g(2);
    g.add_terminal(5, 1, 0);
    REQUIRE(g.solve().error().code() == status_code::out_of_range);
  }
  {
    max_flow_graph g(2);
    g.add_terminal(0, std::nan(""), 0);
    REQUIRE_FALSE(g.solve().ok());
  }
  {
    max_flow_graph g(1);
    g.add_terminal(0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
    const auto r = g.solve();
    REQUIRE(r.ok());
    REQUIRE(std::isinf(*r));
    REQUIRE_FALSE(g.solve().ok());  // solving twice is an error
  }
}
