#include <tessera/core/status.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <set>
#include <string>

#include <catch2/catch.hpp>

using tessera::result;
using tessera::status;
using tessera::status_code;

TEST_CASE("status: default is ok, factories carry code and message", "[status]") {
  const status ok;
  REQUIRE(ok.ok());
  REQUIRE(static_cast<bool>(ok));
  REQUIRE(ok.code() == status_code::ok);
  REQUIRE(ok.to_string() == "ok");

  const status e = status::invalid_argument("width must be > 0, got -3");
  REQUIRE_FALSE(e.ok());
  REQUIRE_FALSE(static_cast<bool>(e));
  REQUIRE(e.code() == status_code::invalid_argument);
  REQUIRE(e.message() == "width must be > 0, got -3");
  REQUIRE(e.to_string() == "invalid_argument: width must be > 0, got -3");

  REQUIRE(status::out_of_range("x").code() == status_code::out_of_range);
  REQUIRE(status::size_overflow("x").code() == status_code::size_overflow);
  REQUIRE(status::io_error("x").code() == status_code::io_error);
  REQUIRE(status::parse_error("x").code() == status_code::parse_error);
  REQUIRE(status::unsupported("x").code() == status_code::unsupported);
  REQUIRE(status::cancelled().code() == status_code::cancelled);
  REQUIRE_FALSE(status::cancelled().message().empty());
  REQUIRE(status::not_converged("x").code() == status_code::not_converged);
  REQUIRE(status::internal_error("x").code() == status_code::internal_error);
}

TEST_CASE("status: every code has a distinct name", "[status]") {
  std::set<std::string> names;
  for (int c = 0; c <= static_cast<int>(status_code::internal_error); ++c) {
    const auto name = tessera::to_string(static_cast<status_code>(c));
    REQUIRE(name != "unknown");
    names.insert(std::string(name));
  }
  REQUIRE(names.size() == static_cast<std::size_t>(status_code::internal_error) + 1);
  REQUIRE(tessera::to_string(static_cast<status_code>(99)) == "unknown");
}

TEST_CASE("result: holds a value or an error", "[status]") {
  result<int> v = 7;
  REQUIRE(v.ok());
  REQUIRE(*v == 7);
  REQUIRE(v.value() == 7);
  REQUIRE(v.error().ok());
  REQUIRE(v.value_or(3) == 7);

  result<int> e = status::out_of_range("index 9 outside [0, 4)");
  REQUIRE_FALSE(e.ok());
  REQUIRE_FALSE(static_cast<bool>(e));
  REQUIRE(e.error().code() == status_code::out_of_range);
  REQUIRE(e.value_or(3) == 3);

  result<std::string> s = std::string("abc");
  REQUIRE(s->size() == 3);
  std::string moved = std::move(s).value();
  REQUIRE(moved == "abc");
}

TEST_CASE("result: an ok status without a value becomes an internal error", "[status]") {
  result<int> r = status{};
  REQUIRE_FALSE(r.ok());
  REQUIRE(r.error().code() == status_code::internal_error);
  // so `if (!r) return r.error();` never reports success without a value
  auto forward = [&]() -> status { return r ? status{} : r.error(); };
  REQUIRE_FALSE(forward().ok());
}

TEST_CASE("result: move-only values", "[status]") {
  result<std::unique_ptr<int>> r = std::make_unique<int>(5);
  REQUIRE(r.ok());
  REQUIRE(**r == 5);
  std::unique_ptr<int> p = std::move(r).value();
  REQUIRE(*p == 5);
  result<std::unique_ptr<int>> e = status::io_error("x");
  REQUIRE(std::move(e).value_or(nullptr) == nullptr);
}

enum class sample_enum { a = 3, b = 4 };

TEST_CASE("detail::cat formats strings and numbers", "[status]") {
  using tessera::detail::cat;
  REQUIRE(cat("w = ", 5, ", h = ", -3) == "w = 5, h = -3");
  REQUIRE(cat(std::uint8_t{200}) == "200");  // small integers print as numbers, not characters
  REQUIRE(cat(std::int64_t{-9223372036854775807LL - 1}) == "-9223372036854775808");
  REQUIRE(cat(std::numeric_limits<std::uint64_t>::max()) == "18446744073709551615");
  REQUIRE(cat(0.5) == "0.5");
  REQUIRE(cat(1.0f / 3.0f) == "0.333333343");
  REQUIRE(cat(std::numeric_limits<double>::quiet_NaN()) == "nan");
  REQUIRE(cat(true, ' ', false) == "true false");
  REQUIRE(cat(sample_enum::b) == "4");
  REQUIRE(cat(std::string_view("sv"), std::string("s")) == "svs");
  const char* null_text = nullptr;
  REQUIRE(cat("p=", null_text) == "p=(null)");
  REQUIRE(cat() == "");
}
