// Tests of core/compiled.hpp: the format and executor lists tessera::compiled instantiates.
#include <tessera/core/compiled.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <set>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#define TESSERA_TEST_STRINGIFY2(x) #x
#define TESSERA_TEST_STRINGIFY(x) TESSERA_TEST_STRINGIFY2(x)

namespace {

// The executor type a call deduces for an argument expression, as `X&& exec` parameters do.
template <class X>
constexpr bool deduces_as_pool(X&&) {
  return std::is_same_v<X, tessera::detail::compiled_pool>;
}
template <class X>
constexpr bool deduces_as_serial(X&&) {
  return std::is_same_v<X, tessera::detail::compiled_serial>;
}

}  // namespace

TEST_CASE("compiled: the format list covers uint8, uint16, float x 1-4 channels for both executors, once each",
          "[compiled]") {
  std::set<std::tuple<int, int, bool>> seen;  // (channel size, channels, pool executor)
  int count = 0;
#define TESSERA_TEST_X(T, C, E)                                                                     \
  ++count;                                                                                          \
  seen.insert({static_cast<int>(sizeof(T)), C, std::is_same_v<E, tessera::detail::compiled_pool>}); \
  static_assert(tessera::Channel<T>);
  TESSERA_COMPILED_FOR_EACH_FORMAT(TESSERA_TEST_X)
#undef TESSERA_TEST_X
  CHECK(count == 24);
  CHECK(seen.size() == 24);
  for (int size : {1, 2, 4})
    for (int c = 1; c <= 4; ++c)
      for (bool pool : {false, true}) CHECK(seen.count({size, c, pool}) == 1);
}

TEST_CASE("compiled: the executor types are those a call deduces (no executor or a pool lvalue)", "[compiled]") {
  tessera::thread_pool_executor pool(1);
  CHECK(deduces_as_pool(pool));
  CHECK(deduces_as_serial(tessera::serial_executor{}));
  CHECK_FALSE(deduces_as_pool(tessera::thread_pool_executor(1)));  // a temporary pool is not covered
  int executors = 0;
#define TESSERA_TEST_E(E) ++executors;
  TESSERA_COMPILED_FOR_EACH_EXECUTOR(TESSERA_TEST_E)
#undef TESSERA_TEST_E
  CHECK(executors == 2);
}

TEST_CASE("compiled: TESSERA_COMPILED_EXTERN is extern outside the library's own sources", "[compiled]") {
#ifdef TESSERA_COMPILED_INSTANTIATE
  FAIL("tests are user translation units");
#else
  constexpr std::string_view spelled = TESSERA_TEST_STRINGIFY(TESSERA_COMPILED_EXTERN);
  CHECK(spelled == "extern");
#endif
}
