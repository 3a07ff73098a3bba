// Fuzz target "patch_model": patch model bytes (io/patch_model_file.hpp) through
// patch_model_file_format and decode_patch_model (uint8, 1 and 3 channels, as Python pickles of
// 8-bit exemplars); what decodes must encode to the same bytes.
#include <algorithm>
#include <cstdint>

#include <tessera/io/patch_model_file.hpp>

#include "fuzz_target.hpp"

namespace {
template <int C>
int round_trip(const unsigned char* data, std::size_t size) {
  auto file = tessera::decode_patch_model<std::uint8_t, C>(data, size);
  if (!file.ok()) return 0;
  auto bytes = tessera::encode_patch_model(file->model, file->options);
  FUZZ_CHECK(bytes.ok());
  FUZZ_CHECK(bytes->size() == size);
  FUZZ_CHECK(std::equal(bytes->begin(), bytes->end(), data));
  return 0;
}
}  // namespace

TESSERA_FUZZ_TARGET(patch_model, data, size) {
  auto fmt = tessera::patch_model_file_format(data, size);
  if (!fmt.ok() || fmt->type != tessera::channel_type::uint8) return 0;
  if (fmt->channels == 1) return round_trip<1>(data, size);
  if (fmt->channels == 3) return round_trip<3>(data, size);
  return 0;
}
