// tessera/io/wang_tiles.hpp: Wang tile directories — DIR/tile_<index>.png plus DIR/tiles.json
// (io/tile_manifest.hpp) — written by `tessera wang build` and read by `tessera wang tile`.
// Needs PNG support: link tessera::io (stb).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "../core/config.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"
#include "../image/axis_wang_tiles.hpp"
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

/// Writes a three-axis set (image/axis_wang_tiles.hpp) as DIR/tile_<i>.png and DIR/tiles.json with
/// "version": 2, "axis_colors" and each tile's "face" (io/tile_manifest.hpp). Errors: an empty set,
/// io_error naming the file that failed.
template <Channel T, int C>
[[nodiscard]] status save_wang_tiles(const std::string& dir, const axis_wang_tile_set<T, C>& set,
                                     std::vector<manifest_field> extra = {}) {
  if (set.size() == 0) return status::invalid_argument("save_wang_tiles: the three-axis set is empty");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return status::io_error(detail::cat(dir, ": cannot create the tile directory (", ec.message(), ")"));
  tile_manifest m;
  m.tile_size = static_cast<double>(set.tile_size());
  m.axis_colors = set.axis_colors();
  m.extra = std::move(extra);
  for (index_t i = 0; i < set.size(); ++i) {
    tile_manifest_entry e;
    e.index = i;
    e.file = detail::cat("tile_", i, ".png");
    e.edges = set.tile_info(i).edges;
    e.face = set.tile_info(i).face;
    if (auto s = write_png((std::filesystem::path(dir) / e.file).string(), set.tile(i)); !s) return s;
    m.tiles.push_back(std::move(e));
  }
  return write_tile_manifest(dir, m);
}

/// Reads a three-axis tile directory (save_wang_tiles of an axis_wang_tile_set) into a set of (T, C)
/// tiles. Errors: those of read_tile_manifest; a planar manifest ("use load_wang_tiles"); tiles that
/// are not the complete three-axis set in order (naming the first that differs); a tile PNG that
/// cannot be decoded or is not tile_size² (naming the file).
template <Channel T, int C>
[[nodiscard]] result<axis_wang_tile_set<T, C>> load_axis_wang_tiles(const std::string& dir) {
  auto m = read_tile_manifest(dir);
  if (!m) return m.error();
  const std::string path = tile_manifest_path(dir);
  if (m->axis_colors == axis_color_counts{0, 0, 0})
    return status::invalid_argument(
        detail::cat(path, ": a planar tile set, not a three-axis one (load_wang_tiles reads it)"));
  const axis_color_counts n = m->axis_colors;
  if (static_cast<index_t>(m->tiles.size()) != axis_tile_count(n))
    return status::invalid_argument(detail::cat(path, ": ", m->tiles.size(), " tiles, the complete three-axis set of ",
                                                n[0], ", ", n[1], ", ", n[2], " colours has ", axis_tile_count(n)));
  std::array<std::vector<image_buffer<T, C>>, 6> tiles;
  for (const auto& t : m->tiles) {
    if (axis_tile{t.face, t.edges} != axis_tile_at(t.index, n))
      return status::invalid_argument(
          detail::cat(path, ": tile ", t.index, " is not tile ", t.index, " of the complete three-axis set"));
    const std::string file = (std::filesystem::path(dir) / t.file).string();
    auto img = read_png<T, C>(file);
    if (!img) return img.error();
    const auto size = static_cast<index_t>(m->tile_size);
    if (img->width() != size || img->height() != size)
      return status::invalid_argument(
          detail::cat(file, " is ", img->width(), " x ", img->height(), " but ", path, " says tile_size ", size));
    tiles[detail::to_size(t.face)].push_back(std::move(*img));
  }
  std::array<wang_tile_set<T, C>, 6> faces;
  for (int f = 0; f < cube_faces; ++f) {
    const auto ax = cube_face_axes(f);
    auto edges = tile_set_edges::complete(n[detail::to_size(ax[0])], n[detail::to_size(ax[1])]);
    if (!edges) return edges.error();
    auto set =
        wang_tile_set<T, C>::create(std::move(*edges), static_cast<index_t>(m->tile_size), tiles[detail::to_size(f)]);
    if (!set) return set.error();
    faces[detail::to_size(f)] = std::move(*set);
  }
  return axis_wang_tile_set<T, C>::create(n, std::move(faces));
}

TESSERA_NAMESPACE_END
