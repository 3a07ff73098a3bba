// Helpers shared by the fabric commands (tessera fabric, catmap, tones): checked parsing of the
// cat-map family, size caps, reading a source PNG within them, and printing tones.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include <tessera/core/image_buffer.hpp>
#include <tessera/fabric/cat_map_period.hpp>
#include <tessera/fabric/source_image.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "png_limits.hpp"

namespace fabric_cli {

/// Largest output side and pixel count the fabric commands accept, and the largest side of the
/// square a fabric is generated at (its float and 8-bit working copies stay around 1 GB).
inline constexpr tessera::index_t max_side = 16384;
inline constexpr tessera::index_t max_pixels = tessera::index_t{1} << 26;
inline constexpr tessera::index_t max_square = 8192;

/// --family a,b: two integers with |a|, |b| <= 2^53 (exact in the parsed double; the map reduces
/// them modulo N anyway). The default is the paper's map (1, 1).
inline tessera::result<tessera::cat_map_family> family(const cli::arguments& args) {
  if (!args.has("--family")) return tessera::cat_map_family{};
  auto v = args.numbers("--family", 2);
  if (!v) return v.error();
  constexpr double limit = 9007199254740992.0;  // 2^53
  for (const double x : *v)
    if (x != std::floor(x) || std::abs(x) > limit)
      return tessera::status::invalid_argument("--family expects two integers a,b with |a|, |b| <= 2^53, got '" +
                                               args.str("--family") + "'");
  return tessera::cat_map_family{static_cast<std::int64_t>((*v)[0]), static_cast<std::int64_t>((*v)[1])};
}

/// Reads a PNG as float RGB after checking its size against the caps, so a huge file is refused
/// before it is decoded.
inline tessera::result<tessera::image_buffer<float, 3>> read_source(const std::string& path) {
  auto info = tessera::read_png_info(path);
  if (!info) return info.error();
  if (info->width > max_side || info->height > max_side || info->width * info->height > max_pixels)
    return tessera::status::invalid_argument(path + ": " + std::to_string(info->width) + " x " +
                                             std::to_string(info->height) + " is larger than the " +
                                             std::to_string(max_side) + " per side and " + std::to_string(max_pixels) +
                                             " pixels the fabric commands accept");
  return cli::read_png_file<float, 3>(path);
}

/// "#rrggbb" of an RGB colour in [0, 1].
inline std::string hex(const tessera::pixel<float, 3>& c) {
  char buf[8];
  auto byte = [](float v) { return static_cast<int>(std::lround(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255.0f)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c[0]), byte(c[1]), byte(c[2]));
  return buf;
}

/// A palette in the form `tessera fabric --palette` reads: "#rrggbb:share,...", shares to 4 places.
inline std::string palette_text(const tessera::palette& tones) {
  std::string out;
  for (const tessera::tone& t : tones) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%s:%.4f", out.empty() ? "" : ",", hex(t.color).c_str(), t.proportion);
    out += buf;
  }
  return out;
}

/// A JSON array of shares to 4 places: [0.7500,0.2500].
inline std::string shares_json(const std::vector<double>& shares) {
  std::string out = "[";
  for (std::size_t i = 0; i < shares.size(); ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%.4f", i ? "," : "", shares[i]);
    out += buf;
  }
  return out + "]";
}

}  // namespace fabric_cli
