#include <tessera/core/config.hpp>

#include <cstdint>
#include <type_traits>

#include <catch2/catch.hpp>

TESSERA_NAMESPACE_BEGIN
inline int config_test_marker() { return 42; }
TESSERA_NAMESPACE_END

TEST_CASE("config: index type, namespace macros and exception detection", "[config]") {
  static_assert(std::is_signed_v<tessera::index_t>);
  static_assert(sizeof(tessera::index_t) == sizeof(void*));
  // TESSERA_NAMESPACE_BEGIN opens tessera::v0 inline, so both spellings reach the same function
  REQUIRE(tessera::config_test_marker() == 42);
  REQUIRE(tessera::v0::config_test_marker() == 42);
  REQUIRE(TESSERA_HAS_EXCEPTIONS == 1);  // the tests build with exceptions
  // assertions are active in the sanitizer build (TESSERA_ENABLE_ASSERTS) and without NDEBUG: there a
  // true assertion evaluates its condition once and does nothing else; in Release it is not evaluated
  int evaluated = 0;
  TESSERA_ASSERT(++evaluated == 1);
#if !defined(NDEBUG) || defined(TESSERA_ENABLE_ASSERTS)
  REQUIRE(evaluated == 1);
#else
  REQUIRE(evaluated == 0);
#endif
}

TEST_CASE("config: the library tests are instrumented when the build says so", "[config]") {
  // TESSERA_TESTS_SANITIZE (scripts/test.sh) and TESSERA_SANITIZE define TESSERA_TESTS_SANITIZED for the
  // test executables: then AddressSanitizer must really be compiled in, and the kernels' assertions on
#if defined(TESSERA_TESTS_SANITIZED)
#if defined(__SANITIZE_ADDRESS__)
  constexpr bool address_sanitizer = true;
#elif defined(__has_feature)
  constexpr bool address_sanitizer = __has_feature(address_sanitizer);
#else
  constexpr bool address_sanitizer = false;
#endif
  REQUIRE(address_sanitizer);
#if !defined(TESSERA_ENABLE_ASSERTS)
  FAIL("an instrumented test build runs with TESSERA_ENABLE_ASSERTS");
#endif
#else
  SUCCEED("the test executables are built like the library (TESSERA_TESTS_SANITIZE=OFF)");
#endif
}
