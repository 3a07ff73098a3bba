// tessera/core/executor.hpp: where parallel loops run. An Executor has
// `parallel_for(begin, end, fn)` calling fn(i) once for every i in [begin, end), in any order and on
// any thread. tessera's algorithms only hand it work whose result does not depend on that order, so
// output is bit-identical for every executor and thread count. Plug an engine's job system in by
// writing a type with that one member.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <concepts>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "config.hpp"

TESSERA_NAMESPACE_BEGIN

/// Where tessera runs its parallel loops: any type with `parallel_for(begin, end, fn)` that calls
/// fn(i) exactly once for each i in [begin, end), in any order, on any threads, and returns when all
/// calls have returned. Algorithms take one as their last argument (default serial_executor).
template <class E>
concept Executor = requires(E& e, index_t n, void (*fn)(index_t)) {
  e.parallel_for(index_t{0}, n, fn);
};

/// Runs every loop on the calling thread, in index order.
struct serial_executor {
  /// Calls fn(i) for i = begin, ..., end - 1 in order, on the calling thread.
  template <class F>
  void parallel_for(index_t begin, index_t end, F&& fn) const {
    for (index_t i = begin; i < end; ++i) fn(i);
  }
  /// Threads a loop may use: 1.
  [[nodiscard]] int concurrency() const noexcept { return 1; }
};

namespace detail {
inline thread_local bool inside_parallel_for = false;
}  // namespace detail

/// A fixed pool of std::threads. parallel_for splits the range into chunks taken dynamically by the
/// workers and the calling thread; it returns when all are done. A parallel_for issued from inside a
/// running one runs serially on its thread (no deadlock). If fn throws, the first exception is
/// rethrown on the calling thread after the loop stops. Calls from several threads are serialized.
///
/// After a loop the workers poll for the next one for a short while (`spin`, default
/// default_spin) before they sleep, as OpenMP runtimes do: back-to-back loops of a frame or of a
/// sub-millisecond synthesis then find every worker awake on its own core instead of paying a wake-up
/// and, on a small machine, the scheduler's choice of placing the woken worker on the caller's core.
/// Polling yields the core to any other runnable thread. A pool with more threads than the machine
/// has cores does not poll.
class thread_pool_executor {
 public:
  /// Most threads a pool starts; larger requests are clamped (a typo must not start 10^9 threads).
  static constexpr int max_threads = 256;
  /// How long idle workers poll for the next loop before sleeping.
  static constexpr std::chrono::microseconds default_spin{2000};

  /// `threads` workers in total including the caller; 0 (or negative) means
  /// std::thread::hardware_concurrency(); clamped to max_threads. If the system refuses to start a
  /// thread (std::system_error), the pool runs with those it has: concurrency() tells how many.
  /// `spin`: how long idle workers poll before sleeping (0: sleep at once).
  explicit thread_pool_executor(int threads = 0, std::chrono::microseconds spin = default_spin) {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (threads <= 0) threads = cores;
    threads = std::min(threads, max_threads);
    spin_ = threads <= cores ? std::max(spin, std::chrono::microseconds{0}) : std::chrono::microseconds{0};
    workers_.reserve(detail::to_size(threads - 1));
#if TESSERA_HAS_EXCEPTIONS
    try {
      for (int t = 1; t < threads; ++t) workers_.emplace_back([this] { worker_loop(); });
    } catch (const std::system_error&) {
      // keep the workers already running; parallel_for counts workers_, not the request
    }
#else
    for (int t = 1; t < threads; ++t) workers_.emplace_back([this] { worker_loop(); });
#endif
    threads_ = static_cast<int>(workers_.size()) + 1;
  }
  thread_pool_executor(const thread_pool_executor&) = delete;
  thread_pool_executor& operator=(const thread_pool_executor&) = delete;
  /// Stops and joins the worker threads.
  ~thread_pool_executor() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
  }

  /// Threads that run a parallel_for: the workers plus the calling thread.
  [[nodiscard]] int concurrency() const noexcept { return threads_; }

  /// Calls fn(i) for every i in [begin, end) on the pool and the calling thread; returns when done.
  template <class F>
  void parallel_for(index_t begin, index_t end, F&& fn) {
    if (end <= begin) return;
    if (threads_ == 1 || end - begin == 1 || detail::inside_parallel_for) {
      for (index_t i = begin; i < end; ++i) fn(i);
      return;
    }
    std::lock_guard<std::mutex> one_loop_at_a_time(submit_);
    using Fn = std::remove_reference_t<F>;
    job j;
    j.invoke = [](void* ctx, index_t i) { (*static_cast<Fn*>(ctx))(i); };
    j.ctx = const_cast<void*>(static_cast<const void*>(std::addressof(fn)));
    j.begin = begin;
    j.end = end;
    j.chunk = std::max<index_t>(1, (end - begin) / (static_cast<index_t>(threads_) * 8));
    j.next.store(begin, std::memory_order_relaxed);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      current_ = &j;
      busy_ = static_cast<int>(workers_.size());
      ++generation_;
    }
    wake_.notify_all();
    run_chunks(j);
    poll([&] { return busy_.load(std::memory_order_acquire) == 0; });
    {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [&] { return busy_ == 0; });
      current_ = nullptr;
    }
#if TESSERA_HAS_EXCEPTIONS
    if (j.error) std::rethrow_exception(j.error);
#endif
  }

 private:
  struct job {
    void (*invoke)(void*, index_t) = nullptr;
    void* ctx = nullptr;
    index_t begin = 0, end = 0, chunk = 1;
    std::atomic<index_t> next{0};
#if TESSERA_HAS_EXCEPTIONS
    std::mutex error_mutex;
    std::exception_ptr error;
#endif
  };

  static void run_chunks(job& j) {
    detail::inside_parallel_for = true;
    for (;;) {
      const index_t s = j.next.fetch_add(j.chunk, std::memory_order_relaxed);
      if (s >= j.end) break;
      const index_t e = std::min(j.end, s + j.chunk);
#if TESSERA_HAS_EXCEPTIONS
      try {
        for (index_t i = s; i < e; ++i) j.invoke(j.ctx, i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(j.error_mutex);
        if (!j.error) j.error = std::current_exception();
        j.next.store(j.end, std::memory_order_relaxed);
      }
#else
      for (index_t i = s; i < e; ++i) j.invoke(j.ctx, i);
#endif
    }
    detail::inside_parallel_for = false;
  }

  // Polls (yielding the core) until done() holds or spin_ has passed; the condition-variable wait
  // that follows is then free when it already holds.
  template <class Done>
  void poll(Done done) const {
    if (spin_.count() == 0) return;
    const auto until = std::chrono::steady_clock::now() + spin_;
    for (int i = 1; !done(); ++i) {
      if (i % 16 == 0 && std::chrono::steady_clock::now() >= until) return;
      std::this_thread::yield();
    }
  }

  void worker_loop() {
    std::uint64_t seen = 0;
    for (;;) {
      poll(
          [&] { return generation_.load(std::memory_order_acquire) != seen || stop_.load(std::memory_order_acquire); });
      job* j = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
        j = current_;
      }
      run_chunks(*j);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (--busy_ == 0) done_.notify_one();
      }
    }
  }

  int threads_ = 1;
  std::vector<std::thread> workers_;
  std::mutex submit_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  job* current_ = nullptr;
  // written under mutex_; atomic so that polling workers may read them without it
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<bool> stop_{false};
  std::atomic<int> busy_{0};
  std::chrono::microseconds spin_{0};
};

TESSERA_NAMESPACE_END
