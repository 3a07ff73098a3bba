// Example 31: the period of the cat map on an N x N image (paper 001 §1.1 and §2: the iteration
// returns to the source, with a period that depends on N). Prints a table for sizes from the paper's
// 400 to 10^12 (computed from the factorization of N, never by iterating images) and plots the
// period against N for N = 1..1000.
//
//   example_31_cat_map_period [OUTPUT_DIR]      (default: the current directory)
#include <chrono>
#include <cstdio>
#include <string>

#include <tessera/core/image_buffer.hpp>
#include <tessera/fabric/cat_map_period.hpp>
#include <tessera/io/png.hpp>

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  std::printf("%16s %20s %10s %12s\n", "N", "period", "period/N", "time (us)");
  for (std::int64_t n : {std::int64_t{100}, std::int64_t{256}, std::int64_t{400}, std::int64_t{401}, std::int64_t{512},
                         std::int64_t{1000}, std::int64_t{1024}, std::int64_t{2048}, std::int64_t{4096},
                         std::int64_t{1000003}, std::int64_t{999999999989}, std::int64_t{1000000000000}}) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto p = tessera::cat_map_period(n);
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    if (!p) {
      std::fprintf(stderr, "%s\n", p.error().to_string().c_str());
      return 1;
    }
    std::printf("%16lld %20llu %10.3f %12.1f\n", static_cast<long long>(n), static_cast<unsigned long long>(*p),
                static_cast<double>(*p) / static_cast<double>(n), us);
  }

  // period(N) for N = 1..1000: x = N, y = period / 10 (the period never exceeds 3N)
  const tessera::index_t w = 1000, h = 310;
  tessera::image_buffer<std::uint8_t, 3> plot(w, h, {255, 255, 255});
  for (tessera::index_t x = 0; x < w; ++x) {
    plot.write(x, h - 1 - x / 10, {200, 200, 200});                                         // period = N
    plot.write(x, h - 1 - std::min<tessera::index_t>(h - 1, 3 * x / 10), {240, 190, 190});  // period = 3N
  }
  for (std::int64_t n = 1; n <= 1000; ++n) {
    const auto period = tessera::cat_map_period(n);
    if (!period) return std::fprintf(stderr, "%s\n", period.error().to_string().c_str()), 1;
    const auto p = static_cast<tessera::index_t>(*period);
    const tessera::index_t x = n - 1, y = h - 1 - p / 10;
    const bool paper = n == 400;
    for (tessera::index_t dy = -1; dy <= 1; ++dy)
      for (tessera::index_t dx = -1; dx <= 1; ++dx)
        if (x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h && (paper || dx == 0 || dy == 0))
          plot.write(
              x + dx, y + dy,
              paper ? tessera::pixel<std::uint8_t, 3>{200, 30, 30} : tessera::pixel<std::uint8_t, 3>{20, 40, 110});
  }
  const std::string path = dir + "/period.png";
  if (auto s = tessera::write_png(path, plot); !s) {
    std::fprintf(stderr, "%s\n", s.to_string().c_str());
    return 1;
  }
  std::printf("wrote %s\n", path.c_str());
  return 0;
}
