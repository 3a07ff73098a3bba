// tessera/core/config.hpp: namespace macros, index type, TESSERA_ASSERT, exception detection.
//
// TESSERA_ASSERT checks tessera's own invariants, never caller input (caller input is validated and
// reported through `status`). Define TESSERA_ASSERT before including tessera to route it to an
// engine's own assertion handler. By default it is active unless NDEBUG is defined; define
// TESSERA_ENABLE_ASSERTS to keep it in release builds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <type_traits>

#define TESSERA_NAMESPACE_BEGIN \
  namespace tessera {           \
  inline namespace v0 {
#define TESSERA_NAMESPACE_END \
  }                           \
  }

#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
#define TESSERA_HAS_EXCEPTIONS 1
#else
#define TESSERA_HAS_EXCEPTIONS 0
#endif

TESSERA_NAMESPACE_BEGIN

/// Signed index and size type used throughout tessera (pixels, vertices, faces, cells).
using index_t = std::ptrdiff_t;

namespace detail {
[[noreturn]] inline void assertion_failed(const char* expr, const char* file, int line) noexcept {
  std::fprintf(stderr, "tessera: internal assertion failed: %s (%s:%d)\n", expr, file, line);
  std::abort();
}

/// `T`, spelled so that it depends on `Dependent`. Heavy library code (Eigen, glm) written with
/// `dependent_t<double, X>` inside a template over X is compiled only when the template is
/// instantiated; with plain `double` compilers analyse and instantiate it in every translation unit
/// that includes the header (the umbrella header's compile-time goal).
template <class T, class Dependent>
using dependent_t = std::conditional_t<sizeof(Dependent*) != 0, T, T>;

/// `v` as a std::size_t, the index and size type of std::vector, std::array and std::span: tessera
/// counts with the signed index_t and converts only where it touches a standard container.
template <class T>
[[nodiscard]] constexpr std::size_t to_size(T v) noexcept {
  return static_cast<std::size_t>(v);
}
}  // namespace detail

TESSERA_NAMESPACE_END

#ifndef TESSERA_ASSERT
#if !defined(NDEBUG) || defined(TESSERA_ENABLE_ASSERTS)
#define TESSERA_ASSERT(cond) \
  ((cond) ? static_cast<void>(0) : ::tessera::detail::assertion_failed(#cond, __FILE__, __LINE__))
#else
#define TESSERA_ASSERT(cond) static_cast<void>(0)
#endif
#endif
