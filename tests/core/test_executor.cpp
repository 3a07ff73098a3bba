#include <tessera/core/executor.hpp>

#include <atomic>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <algorithm>
#include <cstdint>
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
  REQUIRE_THROWS_AS(pool.parallel_for(0, 1000,
                                      [](index_t i) {
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

namespace {
struct not_an_executor {
  void run(index_t, index_t) {}
};
// An engine job system plugged in through the one member the concept asks for.
struct reversed_executor {
  template <class F>
  void parallel_for(index_t begin, index_t end, F&& fn) {
    for (index_t i = end; i-- > begin;) fn(i);
  }
};
}  // namespace
static_assert(!tessera::Executor<not_an_executor>);
static_assert(tessera::Executor<reversed_executor>);
static_assert(!tessera::Executor<const tessera::thread_pool_executor>);

TEST_CASE("thread pool: same output for every thread count and executor", "[executor]") {
  // a keyed per-index computation written into its own slot: the pattern every algorithm uses
  auto work = [](index_t i) {
    std::uint64_t h = static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ULL;
    for (int r = 0; r < 50; ++r) h = (h ^ (h >> 29)) * 0xbf58476d1ce4e5b9ULL;
    return h;
  };
  const index_t n = 20000;
  std::vector<std::uint64_t> expected(static_cast<std::size_t>(n));
  tessera::serial_executor{}.parallel_for(0, n, [&](index_t i) { expected[static_cast<std::size_t>(i)] = work(i); });
  for (int threads : {1, 2, 3, 4, 7, 16}) {
    tessera::thread_pool_executor pool(threads);
    std::vector<std::uint64_t> out(static_cast<std::size_t>(n));
    for (int rep = 0; rep < 3; ++rep) {  // the pool is reused across loops
      std::fill(out.begin(), out.end(), 0);
      pool.parallel_for(0, n, [&](index_t i) { out[static_cast<std::size_t>(i)] = work(i); });
      REQUIRE(out == expected);
    }
  }
  std::vector<std::uint64_t> out(static_cast<std::size_t>(n));
  reversed_executor{}.parallel_for(0, n, [&](index_t i) { out[static_cast<std::size_t>(i)] = work(i); });
  REQUIRE(out == expected);
}

TEST_CASE("thread pool: empty and reversed ranges, default thread count", "[executor]") {
  tessera::thread_pool_executor pool;  // hardware concurrency
  REQUIRE(pool.concurrency() >= 1);
  tessera::thread_pool_executor negative(-3);
  REQUIRE(negative.concurrency() >= 1);
  int calls = 0;
  pool.parallel_for(5, 5, [&](index_t) { ++calls; });
  pool.parallel_for(5, 2, [&](index_t) { ++calls; });
  pool.parallel_for(-10, -10, [&](index_t) { ++calls; });
  REQUIRE(calls == 0);
  std::atomic<index_t> sum{0};
  pool.parallel_for(-5, 5, [&](index_t i) { sum += i; });  // negative indices are fine
  REQUIRE(sum.load() == -5);
  const auto const_fn = [&](index_t i) { sum += i; };  // a const callable
  pool.parallel_for(0, 3, const_fn);
  REQUIRE(sum.load() == -2);
  REQUIRE(tessera::serial_executor{}.concurrency() == 1);
}

TEST_CASE("thread pool: loops submitted from several threads are serialized", "[executor]") {
  tessera::thread_pool_executor pool(3);
  std::vector<std::thread> callers;
  std::vector<index_t> sums(4, 0);
  for (int t = 0; t < 4; ++t)
    callers.emplace_back([&, t] {
      for (int rep = 0; rep < 20; ++rep) {
        std::atomic<index_t> s{0};
        pool.parallel_for(0, 500, [&](index_t i) { s += i; });
        if (rep == 19) sums[static_cast<std::size_t>(t)] = s.load();
      }
    });
  for (auto& c : callers) c.join();
  for (index_t s : sums) REQUIRE(s == 124750);
}

TEST_CASE("thread pool: a loop nested inside another pool's loop runs serially", "[executor]") {
  tessera::thread_pool_executor outer(2), inner(2);
  std::vector<int> out(64, 0);
  outer.parallel_for(0, 64, [&](index_t i) {
    int local = 0;
    inner.parallel_for(0, 10, [&](index_t j) { local += static_cast<int>(j); });  // no data race: serial
    out[static_cast<std::size_t>(i)] = local;
  });
  for (int v : out) REQUIRE(v == 45);
}

TEST_CASE("thread pool: absurd thread counts are clamped, not obeyed", "[executor][bad_input]") {
  tessera::thread_pool_executor huge(1 << 30);
  REQUIRE(huge.concurrency() >= 1);
  REQUIRE(huge.concurrency() <= tessera::thread_pool_executor::max_threads);
  std::atomic<index_t> sum{0};
  huge.parallel_for(0, 1000, [&](index_t i) { sum += i; });
  REQUIRE(sum.load() == 999 * 1000 / 2);
}

TEST_CASE("thread pool: polling and sleeping workers give the same loops, and a polling pool stops at once",
          "[executor]") {
  using std::chrono::microseconds;
  for (microseconds spin : {microseconds{0}, microseconds{-5}, microseconds{2000}, microseconds{3600000000LL}}) {
    // an hour of polling: the destructor must not wait for it (ctest's timeout fails a hang)
    tessera::thread_pool_executor pool(2, spin);
    for (int round = 0; round < 200; ++round) {
      const index_t n = 1 + round % 37;
      std::vector<std::atomic<int>> hits(static_cast<std::size_t>(n));
      pool.parallel_for(0, n, [&](index_t i) { hits[static_cast<std::size_t>(i)].fetch_add(1); });
      for (auto& h : hits) REQUIRE(h.load() == 1);
      // now and then let the polling run out, so that the next loop wakes sleeping workers
      if (round % 50 == 49) std::this_thread::sleep_for(std::chrono::milliseconds(3));
    }
  }
}
