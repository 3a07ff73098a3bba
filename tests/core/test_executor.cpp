#include <tessera/core/executor.hpp>

#include <atomic>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

using tessera::index_t;

TEMPLATE_TEST_CASE("executors visit every index exactly once", "[executor]", tessera::serial_executor,
                   tessera::thread_pool_executor) {
  TestType exec;
  for (index_t n : {0, 1, 2, 7, 1000, 100003}) {
    std::vector<std::atomic<int>> hits(static_cast<std::size_t>(n));
    exec.parallel_for(0, n, [&](index_t i) { hits[static_cast<std::size_t>(i)].fetch_add(1); });
    for (auto& h : hits) REQUIRE(h.load() == 1);
  }
}

TEST_CASE("thread pool: explicit thread counts, offsets and nesting", "[executor]") {
  for (int threads : {1, 2, 3, 8}) {
    tessera::thread_pool_executor pool(threads);
    REQUIRE(pool.concurrency() == threads);
    std::vector<int> out(100, 0);
    pool.parallel_for(10, 60, [&](index_t i) {
      // a nested loop runs serially on the worker's thread
      int sum = 0;
      pool.parallel_for(0, 4, [&](index_t j) { sum += static_cast<int>(j); });
      out[static_cast<std::size_t>(i)] = sum + 1;
    });
    for (int i = 0; i < 100; ++i) REQUIRE(out[static_cast<std::size_t>(i)] == (i >= 10 && i < 60 ? 7 : 0));
  }
}

TEST_CASE("thread pool: an exception from the callback reaches the caller", "[executor]") {
  tessera::thread_pool_executor pool(2);
  REQUIRE_THROWS_AS(pool.parallel_for(0, 1000, [](index_t i) {
    if (i == 517) throw std::runtime_error("boom");
  }),
                    std::runtime_error);
  // the pool stays usable afterwards
  std::atomic<index_t> sum{0};
  pool.parallel_for(0, 100, [&](index_t i) { sum += i; });
  REQUIRE(sum.load() == 4950);
}

static_assert(tessera::Executor<tessera::serial_executor>);
static_assert(tessera::Executor<tessera::thread_pool_executor>);
