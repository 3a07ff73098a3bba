// Fuzz target "tsuv": terrain texture-coordinate files (TSUV, io/terrain_uv_file.hpp) through
// decode_terrain_uvs; what decodes must encode, decode again and re-encode to the same bytes (a file
// of an older version is written as the current version, so only its re-encoding is a fixed point).
#include <tessera/io/terrain_uv_file.hpp>

#include "fuzz_target.hpp"

TESSERA_FUZZ_TARGET(tsuv, data, size) {
  auto uv = tessera::decode_terrain_uvs(data, size);
  if (!uv.ok()) return 0;
  auto bytes = tessera::encode_terrain_uvs(*uv);
  FUZZ_CHECK(bytes.ok());
  auto again = tessera::decode_terrain_uvs(bytes->data(), bytes->size());
  FUZZ_CHECK(again.ok());
  auto bytes_again = tessera::encode_terrain_uvs(*again);
  FUZZ_CHECK(bytes_again.ok());
  FUZZ_CHECK(*bytes_again == *bytes);
  return 0;
}
