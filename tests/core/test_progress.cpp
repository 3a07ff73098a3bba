#include <tessera/core/progress.hpp>

#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

TEST_CASE("progress: default reports and never cancels", "[progress]") {
  const tessera::progress p;
  REQUIRE(p.report(0.5));
  REQUIRE(p.report(2.0, "stage"));
  REQUIRE_FALSE(p.cancelled());
}

TEST_CASE("progress: the callback sees clamped fractions and can cancel", "[progress]") {
  std::vector<double> seen;
  std::vector<std::string> stages;
  tessera::progress p{.callback = [&](double f, std::string_view stage) {
    seen.push_back(f);
    stages.emplace_back(stage);
    return f < 0.9;
  }};
  REQUIRE(p.report(-1.0, "a"));
  REQUIRE(p.report(0.25, "b"));
  REQUIRE(p.report(std::numeric_limits<double>::quiet_NaN()));
  REQUIRE_FALSE(p.report(7.0, "c"));
  REQUIRE(seen == std::vector<double>{0.0, 0.25, 0.0, 1.0});
  REQUIRE(stages == std::vector<std::string>{"a", "b", "", "c"});
}

TEST_CASE("progress: a cancellation token stops before the callback runs", "[progress]") {
  tessera::cancellation_token stop;
  int calls = 0;
  tessera::progress p{.callback = [&](double, std::string_view) { return ++calls, true; }, .token = &stop};
  REQUIRE(p.report(0.1));
  REQUIRE_FALSE(p.cancelled());
  std::thread other([&] { stop.cancel(); });  // raised from another thread
  other.join();
  REQUIRE(stop.cancelled());
  REQUIRE(p.cancelled());
  REQUIRE_FALSE(p.report(0.2));
  REQUIRE(calls == 1);
  stop.reset();
  REQUIRE(p.report(0.3));
  REQUIRE(calls == 2);
}
