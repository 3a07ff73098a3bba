// tessera/core/status.hpp: the error model. Every public entry point that can fail on caller input
// returns a `status` (or a `result<T>`) whose message names the parameter and the offending value.
// tessera itself never throws; exceptions raised by user callbacks pass through unchanged.
#pragma once

#include <charconv>
#include <concepts>
#include <cstdio>
#include <initializer_list>
#include <new>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "config.hpp"

TESSERA_NAMESPACE_BEGIN

/// What kind of failure a `status` reports.
enum class status_code {
  ok = 0,
  invalid_argument,  ///< a parameter is outside its documented domain
  out_of_range,      ///< an index or window lies outside the valid range
  size_overflow,     ///< sizes whose product or byte count does not fit the index type
  io_error,          ///< a file could not be opened, read or written
  parse_error,       ///< a file is malformed or truncated
  unsupported,       ///< a valid request that this build or format cannot serve
  cancelled,         ///< the progress callback or cancellation token asked to stop
  not_converged,     ///< an iterative solver did not reach its tolerance
  internal_error     ///< a failure that is not the caller's fault (for example a singular solve)
};

/// Human-readable name of a status code ("invalid_argument", ...).
constexpr std::string_view to_string(status_code c) noexcept {
  switch (c) {
    case status_code::ok: return "ok";
    case status_code::invalid_argument: return "invalid_argument";
    case status_code::out_of_range: return "out_of_range";
    case status_code::size_overflow: return "size_overflow";
    case status_code::io_error: return "io_error";
    case status_code::parse_error: return "parse_error";
    case status_code::unsupported: return "unsupported";
    case status_code::cancelled: return "cancelled";
    case status_code::not_converged: return "not_converged";
    case status_code::internal_error: return "internal_error";
  }
  return "unknown";
}

/// Success, or a failure code with a message. Default-constructed means success.
/// Test with `if (!s) ...` or `s.ok()`.
class [[nodiscard]] status {
 public:
  status() = default;
  /// A status with this code and message.
  status(status_code code, std::string message) : code_(code), message_(std::move(message)) {}

  /// True when the code is ok.
  [[nodiscard]] bool ok() const noexcept { return code_ == status_code::ok; }
  /// True when ok().
  explicit operator bool() const noexcept { return ok(); }
  /// The code.
  [[nodiscard]] status_code code() const noexcept { return code_; }
  /// The message (empty when ok).
  [[nodiscard]] const std::string& message() const noexcept { return message_; }
  /// "ok" or "<code>: <message>".
  [[nodiscard]] std::string to_string() const {
    if (ok()) return "ok";
    std::string s(tessera::to_string(code_));
    s += ": ";
    s += message_;
    return s;
  }

  /// Bad input: a parameter's value is not accepted (the message names it).
  static status invalid_argument(std::string m) { return {status_code::invalid_argument, std::move(m)}; }
  /// A coordinate or window outside what is supported.
  static status out_of_range(std::string m) { return {status_code::out_of_range, std::move(m)}; }
  /// A size whose element or byte count would overflow.
  static status size_overflow(std::string m) { return {status_code::size_overflow, std::move(m)}; }
  /// A file could not be read or written.
  static status io_error(std::string m) { return {status_code::io_error, std::move(m)}; }
  /// A file's content is malformed (the message says where).
  static status parse_error(std::string m) { return {status_code::parse_error, std::move(m)}; }
  /// A valid input this code cannot handle.
  static status unsupported(std::string m) { return {status_code::unsupported, std::move(m)}; }
  /// The caller cancelled (progress callback or token).
  static status cancelled(std::string m = "cancelled by the caller") { return {status_code::cancelled, std::move(m)}; }
  /// An iteration did not converge.
  static status not_converged(std::string m) { return {status_code::not_converged, std::move(m)}; }
  /// A broken internal invariant (a bug: please report it).
  static status internal_error(std::string m) { return {status_code::internal_error, std::move(m)}; }

 private:
  status_code code_ = status_code::ok;
  std::string message_;
};

/// A value or the `status` explaining why there is none (like std::expected<T, status>).
template <class T>
class [[nodiscard]] result {
 public:
  /// The value type T.
  using value_type = T;
  /// A result holding a value.
  result(T value) : has_value_(true) {
    ::new (static_cast<void*>(&value_)) T(std::move(value));
  }  // NOLINT(google-explicit-constructor)
  /// Holds a failure. An ok status carries no value, so it is turned into an internal_error rather
  /// than producing a result that is neither a value nor an error.
  result(status error) : error_(std::move(error)) {  // NOLINT(google-explicit-constructor)
    if (error_.ok()) error_ = status::internal_error("result<T> was constructed from an ok status without a value");
  }
  // (a union rather than std::optional: result<T> is instantiated for many T, and this keeps the
  // umbrella header's compile time down)
  /// Copies the value or the error.
  result(const result& o) requires std::copy_constructible<T> : has_value_(o.has_value_), error_(o.error_) {
    if (has_value_) ::new (static_cast<void*>(&value_)) T(o.value_);
  }
  /// Moves the value or the error.
  result(result&& o) noexcept(std::is_nothrow_move_constructible_v<T>)
      : has_value_(o.has_value_), error_(std::move(o.error_)) {
    if (has_value_) ::new (static_cast<void*>(&value_)) T(std::move(o.value_));
  }
  /// Copies the value or the error.
  result& operator=(const result& o) requires std::copy_constructible<T> {
    if (this != &o) *this = result(o);
    return *this;
  }
  /// Moves the value or the error.
  result& operator=(result&& o) noexcept(std::is_nothrow_move_constructible_v<T>) {
    if (this == &o) return *this;
    reset();
    if (o.has_value_) ::new (static_cast<void*>(&value_)) T(std::move(o.value_));
    has_value_ = o.has_value_;
    error_ = std::move(o.error_);
    return *this;
  }
  /// Destroys the value, if any.
  ~result() { reset(); }

  /// True when it holds a value.
  [[nodiscard]] bool ok() const noexcept { return has_value_; }
  /// True when ok().
  explicit operator bool() const noexcept { return ok(); }
  /// The failure; an ok status when a value is held.
  [[nodiscard]] const status& error() const noexcept { return error_; }

  /// The value. Precondition: ok() (checked by TESSERA_ASSERT; test first, or use value_or).
  [[nodiscard]] T& value() & {
    TESSERA_ASSERT(ok());
    return value_;
  }
  /// The value; asserts ok().
  [[nodiscard]] const T& value() const& {
    TESSERA_ASSERT(ok());
    return value_;
  }
  /// The value, moved out; asserts ok().
  [[nodiscard]] T&& value() && {
    TESSERA_ASSERT(ok());
    return std::move(value_);
  }
  /// The value; asserts ok().
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  /// The value, moved out; asserts ok().
  T&& operator*() && { return std::move(*this).value(); }
  /// Pointer to the value; asserts ok().
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  /// The value, or `fallback` when there is none.
  template <class U>
  [[nodiscard]] T value_or(U&& fallback) const& {
    return ok() ? value_ : static_cast<T>(std::forward<U>(fallback));
  }
  /// The value moved out, or `fallback` when there is none.
  template <class U>
  [[nodiscard]] T value_or(U&& fallback) && {
    return ok() ? std::move(value_) : static_cast<T>(std::forward<U>(fallback));
  }

 private:
  void reset() noexcept {
    if (has_value_) value_.~T();
    has_value_ = false;
  }
  union {
    T value_;
  };
  bool has_value_ = false;
  status error_;
};

namespace detail {
inline void append_to(std::string& out, std::string_view s) { out += s; }
inline void append_to(std::string& out, const char* s) { out += s != nullptr ? s : "(null)"; }
inline void append_to(std::string& out, const std::string& s) { out += s; }
inline void append_to(std::string& out, char c) { out += c; }
inline void append_to(std::string& out, bool b) { out += b ? "true" : "false"; }
template <class T>
requires std::integral<T> &&(!std::same_as<T, bool>)&&(!std::same_as<T, char>)void append_to(std::string& out, T v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}
template <std::floating_point T>
void append_to(std::string& out, T v) {
  char buf[48];
  int n = std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  out.append(buf, to_size(n > 0 ? n : 0));
}
template <class T>
requires std::is_enum_v<T>
void append_to(std::string& out, T v) { append_to(out, static_cast<std::underlying_type_t<T>>(v)); }

}  // namespace detail

/// Concatenates strings, characters, booleans, integers, floating-point values (9 significant
/// digits) and enums (their underlying value) into one message:
/// `cat("width must be > 0, got ", w)`. What the library's error messages are built with; public so
/// that tools built on tessera word their own messages the same way.
template <class... Args>
std::string cat(const Args&... args) {
  std::string out;
  (detail::append_to(out, args), ...);
  return out;
}
namespace detail {
using tessera::cat;  // the library's own spelling, detail::cat, stays valid
}  // namespace detail

/// Checks that an enum option holds one of its enumerators, numbered 0 to names.size() - 1 in
/// declaration order (a value cast from an integer, `seam_mode(42)`, is refused). `what` names the
/// option ("synthesize: options.seams"); the message lists the valid names.
template <class E>
requires std::is_enum_v<E> status validate_enum(E value, std::initializer_list<std::string_view> names,
                                                std::string_view what) {
  const auto v = static_cast<long long>(static_cast<std::underlying_type_t<E>>(value));
  if (v >= 0 && v < static_cast<long long>(names.size())) return {};
  std::string list;
  for (std::string_view n : names) {
    if (!list.empty()) list += ", ";
    list += n;
  }
  return status(status_code::invalid_argument,
                detail::cat(what, " has the unknown value ", v, " (valid: ", list.c_str(), ")"));
}

TESSERA_NAMESPACE_END
