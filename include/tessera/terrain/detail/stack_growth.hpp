// tessera/terrain/detail/stack_growth.hpp: the synthesis order of paper 003, §2.3 step (1), shared by
// the screen synthesis (synthesize_triangles.hpp) and the ground-anchored one
// (synthesize_anchored_region.hpp): a stack over face adjacency, plus a waiting list for faces that
// found no neighbour's coordinates to continue (defer_restarts).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "../../core/config.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

/// Grows one connected part from the faces on `stack` (§2.3 step (1) of paper 003): pops the last
/// pushed face and hands it to `visit(f, forced)`; when the stack is empty, takes up the faces
/// `visit` put on `deferred`, oldest first, with forced = true (they waited once and must now be
/// placed). `visit` places or defers f and pushes f's unplaced neighbours on `stack`; it returns
/// false to stop (an error or a cancellation), and then so does this. `deferred` is emptied first.
template <class Visit>
bool grow_by_stack(std::vector<std::int32_t>& stack, std::vector<std::int32_t>& deferred, Visit&& visit) {
  deferred.clear();
  std::size_t next_deferred = 0;
  while (!stack.empty() || next_deferred < deferred.size()) {
    bool forced = false;
    std::int32_t f;
    if (!stack.empty()) {
      f = stack.back();
      stack.pop_back();
    } else {
      f = deferred[next_deferred++];
      forced = true;
    }
    if (!visit(f, forced)) return false;
  }
  return true;
}

/// grow_by_stack with a queue instead of the stack: faces are taken up oldest first, so the part
/// grows breadth first, in rings round its start (the ground-anchored mode's default: its
/// unfolding closes each loop next to where it opened, see synthesize_anchored_region.hpp).
/// `queue` is emptied on return.
template <class Visit>
bool grow_by_queue(std::vector<std::int32_t>& queue, std::vector<std::int32_t>& deferred, Visit&& visit) {
  deferred.clear();
  std::size_t head = 0, next_deferred = 0;
  bool ok = true;
  while (ok && (head < queue.size() || next_deferred < deferred.size())) {
    if (head < queue.size())
      ok = visit(queue[head++], false);
    else
      ok = visit(deferred[next_deferred++], true);
  }
  queue.clear();
  return ok;
}

}  // namespace detail
TESSERA_NAMESPACE_END
