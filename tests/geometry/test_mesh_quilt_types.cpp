#include <tessera/geometry/mesh_quilt_types.hpp>

#include <catch2/catch.hpp>

#include <tessera/geometry/mesh_quilt.hpp>

using tessera::index_t;

namespace {
// every counter a distinct value: k, k+1, ... in declaration order
tessera::mesh_quilt_stats numbered(index_t k) {
  tessera::mesh_quilt_stats s;
  for (index_t* f : {&s.patches,           &s.elements_added,   &s.elements_merged,
                     &s.elements_dropped,  &s.merges_attempted, &s.merges_succeeded,
                     &s.icp_iterations,    &s.icp_discarded,    &s.merge_fail_correspondence,
                     &s.merge_fail_deform, &s.merge_fail_cut,   &s.merge_fail_loops,
                     &s.merge_fail_check,  &s.merges_plane_cut, &s.elements_skipped,
                     &s.cells_retried,     &s.elements_nudged,  &s.elements_filled,
                     &s.elements_relaxed,  &s.elements_replaced})
    *f = k++;
  return s;
}
}  // namespace

TEST_CASE("mesh_quilt_types: stats += sums every counter and nothing else", "[mesh_quilt_types]") {
  static_assert(sizeof(tessera::mesh_quilt_stats) == 20 * sizeof(index_t), "a new counter must be summed too");
  auto a = numbered(1);
  const auto b = numbered(100);
  a += b;
  // (1 + 100), (2 + 101), ...: every field summed with its own partner
  CHECK(a.patches == 101);
  CHECK(a.elements_added == 103);
  CHECK(a.elements_merged == 105);
  CHECK(a.elements_dropped == 107);
  CHECK(a.merges_attempted == 109);
  CHECK(a.merges_succeeded == 111);
  CHECK(a.icp_iterations == 113);
  CHECK(a.icp_discarded == 115);
  CHECK(a.merge_fail_correspondence == 117);
  CHECK(a.merge_fail_deform == 119);
  CHECK(a.merge_fail_cut == 121);
  CHECK(a.merge_fail_loops == 123);
  CHECK(a.merge_fail_check == 125);
  CHECK(a.merges_plane_cut == 127);
  CHECK(a.elements_skipped == 129);
  CHECK(a.cells_retried == 131);
  CHECK(a.elements_nudged == 133);
  CHECK(a.elements_filled == 135);
  CHECK(a.elements_relaxed == 137);
  CHECK(a.elements_replaced == 139);
  const tessera::mesh_quilt_stats zero;
  a += zero;
  CHECK(a.merge_fail_check == 125);
}

TEST_CASE("mesh_quilt_types: the options default to tessera's cut rules", "[mesh_quilt_types]") {
  CHECK(tessera::mesh_quilt_options{}.rules == tessera::merge_rules::tessera);
  CHECK(tessera::merge_rules::tessera != tessera::merge_rules::paper);
}
