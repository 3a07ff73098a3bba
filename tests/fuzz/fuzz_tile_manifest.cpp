// Fuzz target "tile_manifest": tiles.json text through parse_tile_manifest (image tile sets) and
// the geometric manifest reader; a manifest that reads must validate, and its rewrite must read
// back equal (a duplicate member once made the rewrite unreadable).
#include <tessera/geometry/geometric_tile_files.hpp>
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
  if (auto g = tessera::detail::parse_geometric_manifest(text, "fuzz.json"); g.ok()) {
    FUZZ_CHECK(tessera::validate_tile_manifest(g->first).ok());
    FUZZ_CHECK(g->second > 0);
  }
  return 0;
}
