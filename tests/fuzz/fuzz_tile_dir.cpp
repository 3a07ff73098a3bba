// Fuzz target "tile_dir": a whole tile directory. The input is the text of tiles.json, optionally
// followed by a line "--tile--" and the bytes of one tile file, which is stored as tile_0.png and
// as tile_0.obj; then load_wang_tiles (image tiles) and load_geometric_tile_set read the directory.
// The directory is private to the process (under $TMPDIR); nothing outside it may be read.
#include <tessera/io/geometric_tiles.hpp>
#include <tessera/io/wang_tiles.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <string_view>

#include "fuzz_target.hpp"

namespace {
const std::string& fuzz_dir() {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    const auto d = std::filesystem::path(tmp != nullptr ? tmp : "/tmp") /
                   ("tessera_fuzz_tile_dir_" + std::to_string(::getpid())) / "set";
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}
}  // namespace

TESSERA_FUZZ_TARGET(tile_dir, data, size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string_view marker = "\n--tile--\n";
  const std::size_t cut = input.find(marker);
  const std::string_view manifest = input.substr(0, cut);
  const std::string_view tile = cut == std::string_view::npos ? std::string_view{} : input.substr(cut + marker.size());
  const std::string& dir = fuzz_dir();
  FUZZ_CHECK(tessera::detail::write_file(tessera::tile_manifest_path(dir), manifest).ok());
  FUZZ_CHECK(tessera::detail::write_file(dir + "/tile_0.png", tile).ok());
  FUZZ_CHECK(tessera::detail::write_file(dir + "/tile_0.obj", tile).ok());
  auto image = tessera::load_wang_tiles<std::uint8_t, 3>(dir);
  if (image.ok()) FUZZ_CHECK(image->size() > 0);
  auto geometric = tessera::load_geometric_tile_set(dir);
  if (geometric.ok()) FUZZ_CHECK(geometric->tiles.size() == geometric->edges.size());
  return 0;
}
