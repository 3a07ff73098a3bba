// tessera/io/wang_tiles.hpp: Wang tile directories — DIR/tile_<index>.png plus DIR/tiles.json
// (io/tile_manifest.hpp) — written by `tessera wang build` and read by `tessera wang tile`.
// Needs PNG support: link tessera::io (stb).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"
#include "../image/wang_tiles.hpp"
#include "tile_manifest.hpp"
#include "png.hpp"

TESSERA_NAMESPACE_BEGIN

/// Writes every tile of `set` as DIR/tile_<i>.png and the manifest DIR/tiles.json (with `extra`
/// top-level numeric fields), creating DIR. Errors: io_error naming the file that failed.
/// Thread safety: reads `set`; do not write the same directory concurrently.
template <Channel T, int C>
[[nodiscard]] status save_wang_tiles(const std::string& dir, const wang_tile_set<T, C>& set,
                                     std::vector<manifest_field> extra = {}) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return status::io_error(detail::cat(dir, ": cannot create the tile directory (", ec.message(), ")"));
  tile_manifest m;
  m.tile_size = static_cast<double>(set.tile_size());
  m.horizontal_colors = set.edges().horizontal_colors();
  m.vertical_colors = set.edges().vertical_colors();
  m.extra = std::move(extra);
  for (index_t i = 0; i < set.size(); ++i) {
    tile_manifest_entry e;
    e.index = i;
    e.file = detail::cat("tile_", i, ".png");
    e.edges = set.edges()[i];
    if (auto s = write_png((std::filesystem::path(dir) / e.file).string(), set.tile(i)); !s) return s;
    m.tiles.push_back(std::move(e));
  }
  return write_tile_manifest(dir, m);
}

/// Reads a tile directory into a set of (T, C) tiles (pixels converted as read_png does).
/// Errors: those of read_tile_manifest (missing or malformed DIR/tiles.json, missing tile files, each
/// naming the file); a tile PNG that cannot be decoded or whose size differs from the manifest's
/// tile_size (names the file and both sizes).
template <Channel T, int C>
[[nodiscard]] result<wang_tile_set<T, C>> load_wang_tiles(const std::string& dir) {
  auto m = read_tile_manifest(dir);
  if (!m) return m.error();
  auto edges = manifest_tile_set(*m);
  if (!edges) return edges.error();
  std::vector<image_buffer<T, C>> tiles;
  tiles.reserve(m->tiles.size());
  for (const auto& t : m->tiles) {
    const std::string path = (std::filesystem::path(dir) / t.file).string();
    auto img = read_png<T, C>(path);
    if (!img) return img.error();
    const auto size = static_cast<index_t>(m->tile_size);  // a whole number: kind image
    if (img->width() != size || img->height() != size)
      return status::invalid_argument(detail::cat(path, " is ", img->width(), " x ", img->height(), " but ",
                                                  tile_manifest_path(dir), " says tile_size ", size));
    tiles.push_back(std::move(*img));
  }
  return wang_tile_set<T, C>::create(std::move(*edges), static_cast<index_t>(m->tile_size), tiles);
}

TESSERA_NAMESPACE_END
