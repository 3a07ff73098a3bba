#include <tessera/core/format.hpp>

#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <type_traits>
#include <utility>

#include <catch2/catch.hpp>

using tessera::channel_type;
using tessera::pixel_format;
using tessera::status_code;

static_assert(tessera::channel_type_of<std::uint8_t> == channel_type::uint8);
static_assert(tessera::channel_type_of<std::uint16_t> == channel_type::uint16);
static_assert(tessera::channel_type_of<float> == channel_type::float32);
static_assert(tessera::pixel_format_of<std::array<std::uint16_t, 3>> == pixel_format{channel_type::uint16, 3});
static_assert(tessera::pixel_format_of<float> == pixel_format{channel_type::float32, 1});
static_assert(tessera::pixel_size({channel_type::float32, 4}) == 16);
static_assert(tessera::channel_size(channel_type::uint16) == 2);

TEST_CASE("format: dispatch reaches the matching compile-time pair", "[format]") {
  std::set<std::pair<int, int>> seen;
  for (channel_type t : {channel_type::uint8, channel_type::uint16, channel_type::float32})
    for (int c = 1; c <= 4; ++c) {
      int calls = 0;
      const auto s = tessera::dispatch_format({t, c}, [&]<class T, int C>(tessera::format_tag<T, C>) {
        ++calls;
        REQUIRE(tessera::channel_type_of<T> == t);
        REQUIRE(C == c);
        REQUIRE(static_cast<int>(sizeof(T)) == tessera::channel_size(t));
        seen.insert({static_cast<int>(t), C});
      });
      REQUIRE(s.ok());
      REQUIRE(calls == 1);
    }
  REQUIRE(seen.size() == 12);
}

TEST_CASE("format: a status returned by the callback is passed on", "[format]") {
  const auto s = tessera::dispatch_format({channel_type::uint16, 2}, []<class T, int C>(tessera::format_tag<T, C>) {
    return C == 2 ? tessera::status::unsupported("two channels") : tessera::status{};
  });
  REQUIRE(s.code() == status_code::unsupported);
  REQUIRE(s.message() == "two channels");
  REQUIRE(tessera::dispatch_channels<float>(3, []<class T, int C>(tessera::format_tag<T, C>) {
            static_assert(std::is_same_v<T, float>);
            return tessera::status{};
          }).ok());
}

TEST_CASE("format: bad runtime formats are rejected without calling back", "[format]") {
  int calls = 0;
  auto count = [&]<class T, int C>(tessera::format_tag<T, C>) { ++calls; };
  for (int c : {0, -1, 5, 1000}) {
    const auto s = tessera::dispatch_format({channel_type::uint8, c}, count);
    REQUIRE(s.code() == status_code::invalid_argument);
    REQUIRE(s.message().find("got " + std::to_string(c)) != std::string::npos);
    REQUIRE(tessera::dispatch_channels<std::uint16_t>(c, count).code() == status_code::invalid_argument);
  }
  const auto s = tessera::dispatch_format({static_cast<channel_type>(7), 3}, count);
  REQUIRE(s.code() == status_code::invalid_argument);
  REQUIRE(s.message().find("7") != std::string::npos);
  REQUIRE(calls == 0);
  REQUIRE(tessera::to_string(channel_type::float32) == "float32");
  REQUIRE(tessera::to_string(static_cast<channel_type>(7)) == "unknown");
}
