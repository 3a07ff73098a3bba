// tessera/core/compiled.hpp: the formats and executors that the optional tessera::compiled library
// instantiates once (docs/compile_once.md). A program that links tessera::compiled gets
// TESSERA_COMPILED defined, and then the heavy public function templates (patch synthesis, quilting,
// Wang tiles, terrain, geometric Wang tiles) are declared `extern template` for these formats and
// executors at the end of their headers (the `detail/compiled_*.hpp` files): its translation units
// call the library's copies instead of compiling their own. Other formats and executors are
// instantiated in the user's translation unit as in the header-only build; the results are the same.
#pragma once

#include <cstdint>

#include "config.hpp"
#include "executor.hpp"
#include "image_buffer.hpp"
#include "image_view.hpp"

/// `extern` in user translation units; empty in src/compiled/*.cpp, which define
/// TESSERA_COMPILED_INSTANTIATE so that the same lines are explicit instantiation definitions.
#ifdef TESSERA_COMPILED_INSTANTIATE
#define TESSERA_COMPILED_EXTERN
#else
#define TESSERA_COMPILED_EXTERN extern
#endif

/// Calls X(T, C, E) for every channel type (uint8, uint16, float), channel count (1-4) and executor
/// (serial_executor as passed by value or defaulted; thread_pool_executor passed as an lvalue).
// clang-format off
#define TESSERA_COMPILED_FORMATS_WITH(X, E)                                                \
  X(std::uint8_t, 1, E) X(std::uint8_t, 2, E) X(std::uint8_t, 3, E) X(std::uint8_t, 4, E)     \
  X(std::uint16_t, 1, E) X(std::uint16_t, 2, E) X(std::uint16_t, 3, E) X(std::uint16_t, 4, E) \
  X(float, 1, E) X(float, 2, E) X(float, 3, E) X(float, 4, E)
// clang-format on
#define TESSERA_COMPILED_FOR_EACH_FORMAT(X)                            \
  TESSERA_COMPILED_FORMATS_WITH(X, ::tessera::detail::compiled_serial) \
  TESSERA_COMPILED_FORMATS_WITH(X, ::tessera::detail::compiled_pool)
/// Calls X(E) for each executor.
#define TESSERA_COMPILED_FOR_EACH_EXECUTOR(X) X(::tessera::detail::compiled_serial) X(::tessera::detail::compiled_pool)

TESSERA_NAMESPACE_BEGIN
namespace detail {
/// The executor template arguments the compiled library covers: `f(..., serial_executor{})` or no
/// executor deduces serial_executor; `f(..., pool)` with an lvalue pool deduces thread_pool_executor&.
using compiled_serial = serial_executor;
using compiled_pool = thread_pool_executor&;
}  // namespace detail
TESSERA_NAMESPACE_END
