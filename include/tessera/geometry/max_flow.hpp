// tessera/geometry/max_flow.hpp: maximum flow / minimum s-t cut by the Boykov-Kolmogorov algorithm
// (search trees grown from both terminals, reused between augmentations; "An experimental comparison
// of min-cut/max-flow algorithms", PAMI 2004). Mesh quilting uses it to cut elements on their
// triangle dual graph with the eq. 8 weights of paper 000 (§3.3.6); any graph cut problem fits.
#pragma once

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/status.hpp"

TESSERA_NAMESPACE_BEGIN

/// A directed graph with source/sink ("terminal") capacities per node and capacities per arc pair.
/// Capacities are non-negative doubles; +infinity is allowed and means "never cut". Build it with
/// add_terminal / add_edge, call solve() once, then ask which side each node is on.
///
///   max_flow_graph g(3);
///   g.add_terminal(0, 5, 0);          // node 0 tied to SOURCE with capacity 5
///   g.add_terminal(2, 0, 4);          // node 2 tied to SINK
///   g.add_edge(0, 1, 3, 0);  g.add_edge(1, 2, 6, 0);
///   double flow = *g.solve();         // 3; nodes 0 on the source side, 1 and 2 on the sink side
///
/// Complexity: O(V E^2 |C|) worst case, near linear on the grid- and mesh-like graphs of graph-cut
/// synthesis. Not thread safe for one object; separate objects are independent.
class max_flow_graph {
 public:
  /// A graph with `nodes` nodes and no edge.
  explicit max_flow_graph(index_t nodes = 0) { add_nodes(nodes); }

  /// Adds n nodes; returns the index of the first.
  index_t add_nodes(index_t n) {
    const auto first = static_cast<index_t>(nodes_.size());
    if (n > 0) nodes_.resize(nodes_.size() + detail::to_size(n));
    return first;
  }
  /// Number of nodes.
  [[nodiscard]] index_t num_nodes() const noexcept { return static_cast<index_t>(nodes_.size()); }

  /// Adds capacity from SOURCE to `node` and from `node` to SINK (accumulates over calls). Invalid
  /// input (node out of range, negative or NaN capacity) is remembered and reported by solve().
  void add_terminal(index_t node, double source_capacity, double sink_capacity) {
    if (!check_node(node, "add_terminal") || !check_cap(source_capacity, "source_capacity") ||
        !check_cap(sink_capacity, "sink_capacity"))
      return;
    nodes_[detail::to_size(node)].source_cap += source_capacity;
    nodes_[detail::to_size(node)].sink_cap += sink_capacity;
  }

  /// Adds an arc a -> b with capacity cap_ab and its reverse with cap_ba.
  void add_edge(index_t a, index_t b, double cap_ab, double cap_ba) {
    if (!check_node(a, "add_edge") || !check_node(b, "add_edge") || !check_cap(cap_ab, "cap_ab") ||
        !check_cap(cap_ba, "cap_ba"))
      return;
    if (a == b) return;  // a self loop never carries flow
    const auto ia = static_cast<index_t>(arcs_.size());
    arcs_.push_back({b, nodes_[detail::to_size(a)].first, ia + 1, cap_ab});
    nodes_[detail::to_size(a)].first = ia;
    arcs_.push_back({a, nodes_[detail::to_size(b)].first, ia, cap_ba});
    nodes_[detail::to_size(b)].first = ia + 1;
  }

  /// Computes the maximum flow (= minimum cut value). Returns +infinity when every cut has infinite
  /// capacity (a path of infinite arcs joins SOURCE and SINK), and the first invalid-input status
  /// recorded by the builders. Call once.
  [[nodiscard]] result<double> solve() {
    if (!error_.ok()) return error_;
    if (solved_) return status::invalid_argument("max_flow_graph::solve: already solved");
    solved_ = true;
    return run();
  }

  /// After solve(): true when `node` is on the SOURCE side of the minimum cut (reachable from
  /// SOURCE in the residual graph). Nodes on neither search tree are on the SINK side. False for a
  /// node out of range and before solve().
  [[nodiscard]] bool in_source_set(index_t node) const noexcept {
    if (!solved_ || node < 0 || node >= num_nodes()) return false;
    return nodes_[detail::to_size(node)].tree == tree_source;
  }

 private:
  static constexpr index_t no_arc = -1, terminal = -2, orphan = -3;
  static constexpr int tree_free = 0, tree_source = 1, tree_sink = 2;
  static constexpr double inf = std::numeric_limits<double>::infinity();

  struct node {
    index_t first = no_arc;   // first outgoing arc
    index_t parent = no_arc;  // arc to the parent in its tree, or terminal / orphan
    double source_cap = 0, sink_cap = 0;
    double tr_cap = 0;  // residual terminal capacity: > 0 to SOURCE side, < 0 to SINK side
    int tree = tree_free;
    bool active = false;
    long long ts = 0;    // timestamp of the distance mark
    long long dist = 0;  // distance to the terminal (valid when ts is current)
  };
  struct arc {
    index_t head;
    index_t next;
    index_t sister;
    double cap;  // residual capacity
  };

  bool check_node(index_t n, const char* where) {
    if (n >= 0 && n < num_nodes()) return true;
    if (error_.ok())
      error_ =
          status::out_of_range(detail::cat("max_flow_graph::", where, ": node ", n, " outside [0, ", num_nodes(), ")"));
    return false;
  }
  bool check_cap(double c, const char* name) {
    if (c >= 0) return true;  // false for NaN too
    if (error_.ok()) error_ = status::invalid_argument(detail::cat("max_flow_graph: ", name, " must be >= 0, got ", c));
    return false;
  }

  node& N(index_t i) { return nodes_[detail::to_size(i)]; }
  arc& A(index_t a) { return arcs_[detail::to_size(a)]; }

  void activate(index_t i) {
    if (!N(i).active) {
      N(i).active = true;
      active_.push_back(i);
    }
  }

  double run() {
    double flow = 0;
    for (index_t i = 0; i < num_nodes(); ++i) {
      node& n = N(i);
      if (n.source_cap == inf && n.sink_cap == inf) return inf;
      flow += std::min(n.source_cap, n.sink_cap);
      n.tr_cap = n.source_cap == inf ? inf : n.sink_cap == inf ? -inf : n.source_cap - n.sink_cap;
      if (n.tr_cap > 0) {
        n.tree = tree_source;
        n.parent = terminal;
        n.ts = 0;
        n.dist = 1;
        activate(i);
      } else if (n.tr_cap < 0) {
        n.tree = tree_sink;
        n.parent = terminal;
        n.ts = 0;
        n.dist = 1;
        activate(i);
      }
    }
    index_t current = no_arc;  // node being grown, kept across augmentations
    while (true) {
      // --- growth: find an arc joining the two trees
      index_t joint = no_arc;  // arc from the source tree to the sink tree
      while (joint == no_arc) {
        if (current == no_arc || N(current).tree == tree_free) {
          current = no_arc;
          while (!active_.empty()) {
            const index_t i = active_.front();
            active_.pop_front();
            N(i).active = false;
            if (N(i).tree != tree_free) {
              current = i;
              break;
            }
          }
          if (current == no_arc) return flow;
        }
        const index_t i = current;
        const bool src = N(i).tree == tree_source;
        for (index_t a = N(i).first; a != no_arc; a = A(a).next) {
          const double cap = src ? A(a).cap : A(A(a).sister).cap;
          if (!(cap > 0)) continue;
          const index_t j = A(a).head;
          if (N(j).tree == tree_free) {
            N(j).tree = N(i).tree;
            N(j).parent = A(a).sister;
            N(j).ts = N(i).ts;
            N(j).dist = N(i).dist + 1;
            activate(j);
          } else if (N(j).tree != N(i).tree) {
            joint = src ? a : A(a).sister;
            break;
          } else if (N(j).ts <= N(i).ts && N(j).dist > N(i).dist) {
            // shorten the tree (heuristic of the BK paper)
            N(j).parent = A(a).sister;
            N(j).ts = N(i).ts;
            N(j).dist = N(i).dist + 1;
          }
        }
        if (joint == no_arc) current = no_arc;
      }
      // --- augmentation along SOURCE -> ... -> tail(joint) -> head(joint) -> ... -> SINK
      ++time_;
      const index_t u = A(A(joint).sister).head, v = A(joint).head;
      double b = A(joint).cap;
      for (index_t x = u; N(x).parent != terminal; x = A(N(x).parent).head)
        b = std::min(b, A(A(N(x).parent).sister).cap);
      index_t root_s = u;
      while (N(root_s).parent != terminal) root_s = A(N(root_s).parent).head;
      b = std::min(b, N(root_s).tr_cap);
      for (index_t x = v; N(x).parent != terminal; x = A(N(x).parent).head) b = std::min(b, A(N(x).parent).cap);
      index_t root_t = v;
      while (N(root_t).parent != terminal) root_t = A(N(root_t).parent).head;
      b = std::min(b, -N(root_t).tr_cap);
      if (b == inf) return inf;
      A(joint).cap -= b;
      A(A(joint).sister).cap += b;
      for (index_t x = u; N(x).parent != terminal;) {
        const index_t pa = N(x).parent, down = A(pa).sister;  // down: parent -> x
        A(down).cap -= b;
        A(pa).cap += b;
        const index_t next = A(pa).head;
        if (!(A(down).cap > 0)) {
          N(x).parent = orphan;
          orphans_.push_back(x);
        }
        x = next;
        if (N(x).parent == terminal) break;
      }
      N(root_s).tr_cap -= b;
      if (!(N(root_s).tr_cap > 0)) {
        N(root_s).parent = orphan;
        orphans_.push_back(root_s);
      }
      for (index_t x = v; N(x).parent != terminal;) {
        const index_t pa = N(x).parent;  // x -> parent
        A(pa).cap -= b;
        A(A(pa).sister).cap += b;
        const index_t next = A(pa).head;
        if (!(A(pa).cap > 0)) {
          N(x).parent = orphan;
          orphans_.push_back(x);
        }
        x = next;
        if (N(x).parent == terminal) break;
      }
      N(root_t).tr_cap += b;
      if (!(N(root_t).tr_cap < 0)) {
        N(root_t).parent = orphan;
        orphans_.push_back(root_t);
      }
      flow += b;
      // --- adoption
      while (!orphans_.empty()) {
        const index_t i = orphans_.front();
        orphans_.pop_front();
        adopt(i);
      }
    }
  }

  void adopt(index_t i) {
    const int tree = N(i).tree;
    const bool src = tree == tree_source;
    index_t best_arc = no_arc;
    long long best_d = std::numeric_limits<long long>::max();
    for (index_t a = N(i).first; a != no_arc; a = A(a).next) {
      const index_t j = A(a).head;
      if (N(j).tree != tree) continue;
      const double cap = src ? A(A(a).sister).cap : A(a).cap;  // j -> i (source tree) or i -> j (sink tree)
      if (!(cap > 0)) continue;
      // is j rooted at a terminal? walk up
      long long d = 0;
      index_t x = j;
      bool ok = true;
      while (true) {
        if (N(x).ts == time_) {
          d += N(x).dist;
          break;
        }
        const index_t p = N(x).parent;
        ++d;
        if (p == terminal) {
          N(x).ts = time_;
          N(x).dist = 1;
          break;
        }
        if (p == orphan || p == no_arc) {
          ok = false;
          break;
        }
        x = A(p).head;
      }
      if (!ok) continue;
      if (d < best_d) {
        best_d = d;
        best_arc = a;
      }
      // mark the walked path with distances
      for (index_t y = j; N(y).ts != time_; y = A(N(y).parent).head) {
        N(y).ts = time_;
        N(y).dist = d--;
      }
    }
    if (best_arc != no_arc) {
      N(i).parent = best_arc;
      N(i).ts = time_;
      N(i).dist = best_d + 1;
      return;
    }
    // no parent: free the node, re-activate neighbours that could reach it, orphan its children
    for (index_t a = N(i).first; a != no_arc; a = A(a).next) {
      const index_t j = A(a).head;
      if (N(j).tree != tree) continue;
      const double cap = src ? A(A(a).sister).cap : A(a).cap;
      if (cap > 0) activate(j);
      const index_t p = N(j).parent;
      if (p != terminal && p != orphan && p != no_arc && A(p).head == i) {
        N(j).parent = orphan;
        orphans_.push_back(j);
      }
    }
    N(i).tree = tree_free;
    N(i).parent = no_arc;
  }

  std::vector<node> nodes_;
  std::vector<arc> arcs_;
  std::deque<index_t> active_;
  std::deque<index_t> orphans_;
  long long time_ = 0;
  status error_;
  bool solved_ = false;
};

TESSERA_NAMESPACE_END
