// Fuzz target "png": the chunk walk of io/detail/png_chunks.hpp, then stb's inflate and unfilter
// through decode_png in three pixel formats; a decoded image must survive encode_png + decode_png
// unchanged.
#include <tessera/io/png.hpp>

#include <cstring>

#include "fuzz_target.hpp"

TESSERA_FUZZ_TARGET(png, data, size) {
  // small limits: the fuzzer's memory budget, not the library's defaults
  const tessera::png_read_options limits{.max_pixels = std::uint64_t{1} << 22, .max_bytes = std::uint64_t{1} << 26};
  auto info = tessera::decode_png_info(data, size, "fuzz.png");
  auto rgba = tessera::decode_png<std::uint8_t, 4>(data, size, "fuzz.png", limits);
  FUZZ_CHECK(info.ok() || !rgba.ok());  // whatever decodes has a valid header
  if (!rgba.ok()) return 0;
  FUZZ_CHECK(rgba->width() == info->width && rgba->height() == info->height);
  (void)tessera::decode_png<std::uint16_t, 1>(data, size, "fuzz.png", limits);
  (void)tessera::decode_png<float, 3>(data, size, "fuzz.png", limits);
  if (rgba->width() * rgba->height() <= 65536) {
    auto bytes = tessera::encode_png(*rgba);
    FUZZ_CHECK(bytes.ok());
    auto back = tessera::decode_png<std::uint8_t, 4>(bytes->data(), bytes->size(), "roundtrip.png", limits);
    FUZZ_CHECK(back.ok());
    FUZZ_CHECK(back->width() == rgba->width() && back->height() == rgba->height());
    const std::size_t n = static_cast<std::size_t>(rgba->width() * rgba->height()) * 4;
    FUZZ_CHECK(std::memcmp(back->data(), rgba->data(), n) == 0);
  }
  return 0;
}
