// Fuzz target "tile_manifest": tiles.json text through parse_tile_manifest, as an image and as a
// geometric tile set; a manifest that reads must validate, and its rewrite must read back equal (a
// duplicate member once made the rewrite unreadable).
#include <tessera/io/tile_manifest.hpp>

#include <string_view>

#include "fuzz_target.hpp"

TESSERA_FUZZ_TARGET(tile_manifest, data, size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (auto m = tessera::parse_tile_manifest(text, "fuzz.json"); m.ok()) {
    FUZZ_CHECK(tessera::validate_tile_manifest(*m).ok());
    auto back = tessera::parse_tile_manifest(tessera::format_tile_manifest(*m), "rewritten.json");
    FUZZ_CHECK(back.ok());
    FUZZ_CHECK(*back == *m);
    FUZZ_CHECK(tessera::manifest_tile_set(*m).ok());
  }
  if (auto g = tessera::parse_tile_manifest(text, "fuzz.json", tessera::tile_set_kind::geometric); g.ok()) {
    FUZZ_CHECK(tessera::validate_tile_manifest(*g).ok());
    FUZZ_CHECK(g->tile_size > 0);
    auto back = tessera::parse_tile_manifest(tessera::format_tile_manifest(*g), "rewritten.json",
                                             tessera::tile_set_kind::geometric);
    FUZZ_CHECK(back.ok());
    FUZZ_CHECK(*back == *g);
  }
  return 0;
}
