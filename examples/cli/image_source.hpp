// Image inputs of the `tessera` command: an option naming either a PNG file or a procedural
// exemplar kind (grass, sand, rock, bricks, cells, weave, dots; image/exemplars.hpp) rendered at
// --exemplar-size with --seed, so every command also runs on generated data.
#pragma once

#include <fstream>
#include <string>
#include <utility>

#include <tessera/core/format.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>

#include "cli.hpp"
#include "png_limits.hpp"

namespace cli {

/// The error for an image option naming neither a file nor a procedural kind.
inline tessera::status unknown_image_source(std::string_view option, const std::string& name) {
  return tessera::status::invalid_argument(std::string(option) + " '" + name +
                                           "' is neither a readable file nor a procedural kind (grass, sand, rock, "
                                           "bricks, cells, weave, dots)");
}

/// The pixel format of the image `option` names: the PNG's own (8 or 16 bits, 1 to 4 channels) or
/// 8-bit RGB for a procedural kind.
inline tessera::result<tessera::pixel_format> image_source_format(const arguments& args, std::string_view option) {
  const std::string name = args.str(option);
  if (std::ifstream(name).good()) {
    auto info = tessera::read_png_info(name);
    if (!info) return info.error();
    return png_format(*info);
  }
  if (!tessera::parse_exemplar_kind(name)) return unknown_image_source(option, name);
  return tessera::pixel_format{tessera::channel_type::uint8, 3};
}

/// The bounds of --exemplar-size: a procedural exemplar is at least 8 and at most 4096 pixels a side.
inline constexpr long long min_exemplar_size = 8, max_exemplar_size = 4096;

/// Reads (or renders) the image `option` names as C channels of T; a procedural kind is rendered
/// at --exemplar-size (8 to 4096), `default_size` when that option is absent.
template <tessera::Channel T, int C>
tessera::result<tessera::image_buffer<T, C>> load_image_source(const arguments& args, std::string_view option,
                                                               long long default_size = 128) {
  const std::string name = args.str(option);
  if (std::ifstream(name).good()) return read_png_file<T, C>(name);
  auto kind = tessera::parse_exemplar_kind(name);
  if (!kind) return unknown_image_source(option, name);
  auto size = args.integer("--exemplar-size", default_size, min_exemplar_size, max_exemplar_size);
  if (!size) return size.error();
  return tessera::make_exemplar<T, C>(*kind, {.width = static_cast<tessera::index_t>(*size),
                                              .height = static_cast<tessera::index_t>(*size),
                                              .seed = args.seed()});
}

/// Calls `f(format_tag<T, C>{})` with the format of the image `option` names (8 or 16 bits: see
/// dispatch_png_format).
template <class F>
tessera::status with_image_source(const arguments& args, std::string_view option, F&& f) {
  auto fmt = image_source_format(args, option);
  if (!fmt) return fmt.error();
  return dispatch_png_format(*fmt, std::forward<F>(f));
}

/// The --exemplar-size option that goes with image sources.
inline option_spec exemplar_size_option(long long default_size = 128) {
  return {"--exemplar-size", "N",
          "side of a procedural exemplar named instead of a file, 8 to 4096 (default " + std::to_string(default_size) +
              ")"};
}

}  // namespace cli
