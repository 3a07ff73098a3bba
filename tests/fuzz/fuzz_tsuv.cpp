// Fuzz target "tsuv": terrain texture-coordinate files (TSUV, io/terrain_uv_file.hpp) through
// decode_terrain_uvs; what decodes must encode and decode again to the same bytes.
#include <tessera/io/terrain_uv_file.hpp>

#include <cstring>

#include "fuzz_target.hpp"

TESSERA_FUZZ_TARGET(tsuv, data, size) {
  auto uv = tessera::decode_terrain_uvs(data, size);
  if (!uv.ok()) return 0;
  auto bytes = tessera::encode_terrain_uvs(*uv);
  FUZZ_CHECK(bytes.ok());
  FUZZ_CHECK(bytes->size() == size);
  auto again = tessera::decode_terrain_uvs(bytes->data(), bytes->size());
  FUZZ_CHECK(again.ok());
  return 0;
}
