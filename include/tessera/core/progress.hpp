// tessera/core/progress.hpp: progress reporting and cancellation for long work (preprocessing,
// tile-set synthesis, mesh quilting). Options structs of long algorithms carry a `progress` member:
//
//   tessera::cancellation_token stop;                  // another thread may call stop.cancel()
//   opts.progress = {.callback = [](double f, std::string_view stage) {
//                       std::printf("%s %.0f%%\n", std::string(stage).c_str(), 100 * f);
//                       return true; },                 // return false to cancel
//                    .token = &stop};
//
// Algorithms call report() from the calling thread only, so callbacks need no locking. When it
// returns false they stop and return status_code::cancelled; outputs are then unspecified but valid.
#pragma once

#include <atomic>
#include <functional>
#include <string_view>

#include "config.hpp"

TESSERA_NAMESPACE_BEGIN

/// A flag another thread can raise to stop an algorithm at its next progress report.
class cancellation_token {
 public:
  cancellation_token() = default;
  cancellation_token(const cancellation_token&) = delete;
  cancellation_token& operator=(const cancellation_token&) = delete;
  /// Raises the flag (any thread).
  void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  /// Lowers the flag, for reuse.
  void reset() noexcept { cancelled_.store(false, std::memory_order_relaxed); }
  /// True once cancel() was called (and not reset).
  [[nodiscard]] bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> cancelled_{false};
};

/// Optional progress callback (fraction in [0, 1], stage name; return false to cancel) and token.
struct progress {
  /// Called with the fraction done and the stage; return false to cancel. Optional.
  std::function<bool(double fraction, std::string_view stage)> callback;
  /// A token another thread may raise to cancel. Optional; not owned.
  const cancellation_token* token = nullptr;

  /// Reports progress; returns false when the work should stop (callback said so or token raised).
  /// The fraction is clamped to [0, 1] (NaN reports 0); the token is checked before the callback.
  bool report(double fraction, std::string_view stage = {}) const {
    if (token != nullptr && token->cancelled()) return false;
    const double f = fraction > 0 ? (fraction < 1 ? fraction : 1.0) : 0.0;  // NaN -> 0
    if (callback && !callback(f, stage)) return false;
    return true;
  }
  /// True when the token has been raised (cheap; no callback).
  [[nodiscard]] bool cancelled() const noexcept { return token != nullptr && token->cancelled(); }
};

TESSERA_NAMESPACE_END
