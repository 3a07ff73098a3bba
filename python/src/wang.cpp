// python/src/wang.cpp: Wang tile sets (image/wang_tiles.hpp), their directories (io/wang_tiles.hpp),
// composition through colourings (image/compose_tiles.hpp: the infinite hash colouring, scanline,
// periodic, or an explicit grid of edge colours) and atlases (image/wang_atlas.hpp).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>

#include <tessera/core/tile_coloring.hpp>
#include <tessera/image/compose_tiles.hpp>
#include <tessera/image/wang_atlas.hpp>
#include <tessera/image/wang_tiles.hpp>
#include <tessera/io/png.hpp>
#include <tessera/io/tile_manifest.hpp>
#include <tessera/io/wang_tiles.hpp>
#include <tessera/tiling/hash_coloring.hpp>
#include <tessera/tiling/periodic_coloring.hpp>
#include <tessera/tiling/scanline_coloring.hpp>

#include "bindings.hpp"
#include "common.hpp"

namespace tessera::python {
namespace {

template <class T>
using sets_of = std::variant<std::shared_ptr<const wang_tile_set<T, 1>>, std::shared_ptr<const wang_tile_set<T, 2>>,
                             std::shared_ptr<const wang_tile_set<T, 3>>, std::shared_ptr<const wang_tile_set<T, 4>>>;

/// tessera.WangTileSet: a tile set of any pixel format (immutable, shared between copies).
struct any_wang_set {
  std::variant<sets_of<std::uint8_t>, sets_of<std::uint16_t>, sets_of<float>> set;

  /// f(const wang_tile_set<T, C>&) for the held format.
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit(
        [&](const auto& per_type) -> decltype(auto) {
          return std::visit([&](const auto& s) -> decltype(auto) { return f(*s); }, per_type);
        },
        set);
  }
};

/// The pixel type of a wang_tile_set.
template <class S>
struct set_format;
template <Channel T, int C>
struct set_format<wang_tile_set<T, C>> {
  using channel = T;
  static constexpr int channels = C;
};
template <class S>
using set_channel_t = typename set_format<std::remove_cvref_t<S>>::channel;
template <class S>
inline constexpr int set_channels_v = set_format<std::remove_cvref_t<S>>::channels;

template <Channel T, int C>
any_wang_set hold(wang_tile_set<T, C>&& s) {
  return {sets_of<T>(std::make_shared<const wang_tile_set<T, C>>(std::move(s)))};
}

/// The grid (in tiles) a grid colouring needs to cover the window (x, y, width, height) from cell (0, 0).
std::pair<index_t, index_t> covering_grid(index_t x, index_t y, index_t width, index_t height, index_t tile,
                                          const std::string& kind) {
  if (x < 0 || y < 0)
    raise_invalid(cat("compose: coloring '", kind, "' is a grid starting at the plane's origin; the window (", x, ", ",
                      y, ") must not be negative (use coloring='hash' for windows anywhere)"));
  return {(x + width + tile - 1) / tile, (y + height + tile - 1) / tile};
}

/// An explicit colouring: an int array of rows x cols x 4 edge colours [north, east, south, west].
stored_tile_coloring explicit_coloring(const py::array& colors, int nh, int nv, index_t& cols) {
  if (colors.dtype().kind() != 'i' && colors.dtype().kind() != 'u')
    throw py::type_error(
        "compose: coloring array must hold integers (rows x cols x 4: north, east, south, west), got " +
        dtype_name(colors));
  if (colors.ndim() != 3 || colors.shape(2) != 4 || colors.shape(0) < 1 || colors.shape(1) < 1)
    throw py::value_error("compose: coloring array must be rows x cols x 4 (north, east, south, west)");
  const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(colors);
  if (!a) throw py::type_error("compose: coloring array cannot be read as int64");
  const auto r = a.unchecked<3>();
  stored_tile_coloring c{nh, nv, {}};
  if (r.shape(0) * r.shape(1) > max_coloring_cells)
    throw py::value_error(
        cat("compose: coloring array of ", r.shape(0), " x ", r.shape(1), " cells exceeds ", max_coloring_cells));
  c.colors.reserve(static_cast<std::size_t>(r.shape(0) * r.shape(1)));
  for (py::ssize_t row = 0; row < r.shape(0); ++row)
    for (py::ssize_t col = 0; col < r.shape(1); ++col) {
      std::array<int, 4> e{};
      for (int side = 0; side < 4; ++side) {
        const std::int64_t v = r(row, col, side);
        const int n = is_horizontal_side(side) ? nh : nv;
        if (v < 0 || v >= n)
          throw py::value_error(cat("compose: coloring[", row, ", ", col, ", ", side, "] = ", v, " is outside [0, ", n,
                                    ") (", side_name(side), " edge colours of this set)"));
        e[static_cast<std::size_t>(side)] = static_cast<int>(v);
      }
      c.colors.push_back(e);
    }
  cols = static_cast<index_t>(r.shape(1));
  return c;
}

py::array edges_array(const tile_set_edges& edges) {
  py::array_t<std::int32_t> out({static_cast<py::ssize_t>(edges.size()), py::ssize_t{4}});
  auto w = out.mutable_unchecked<2>();
  for (index_t i = 0; i < edges.size(); ++i) {
    const wang_edges e = edges[i];
    w(i, 0) = e.north;
    w(i, 1) = e.east;
    w(i, 2) = e.south;
    w(i, 3) = e.west;
  }
  return out;
}

pixel_format format_named(const std::string& dtype, int channels) {
  channel_type t = channel_type::uint8;
  if (dtype == "uint16")
    t = channel_type::uint16;
  else if (dtype == "float32")
    t = channel_type::float32;
  else if (dtype != "uint8")
    raise_invalid(cat("WangTileSet.load: dtype must be 'uint8', 'uint16' or 'float32', got '", dtype, "'"));
  if (channels < 1 || channels > 4) raise_invalid(cat("WangTileSet.load: channels must be 1-4, got ", channels));
  return {t, channels};
}

}  // namespace

void bind_wang(py::module_& m) {
  py::class_<any_wang_set>(m, "WangTileSet", R"doc(A set of square image Wang tiles with their edge colours
(Cohen et al. 2003): build with tessera.build_wang_tiles, save/load a tile directory, compose any
window of the tiled plane through a colouring, pack into an atlas. Immutable; shares its pixels
between copies.)doc")
      .def_static(
          "load",
          [](const std::string& dir, const py::object& dtype, int channels) {
            pixel_format fmt{};
            {
              auto manifest = read_tile_manifest(dir);
              if (!manifest) raise(manifest.error());
              if (manifest->tiles.empty()) raise_invalid(cat("WangTileSet.load: ", dir, " lists no tiles"));
              auto info = read_png_info((std::filesystem::path(dir) / manifest->tiles.front().file).string());
              if (!info) raise(info.error());
              fmt = {info->bit_depth == 16 ? channel_type::uint16 : channel_type::uint8, info->channels};
            }
            if (!dtype.is_none())
              fmt = format_named(py::str(dtype).cast<std::string>(), channels ? channels : fmt.channels);
            else if (channels)
              fmt.channels = channels;
            any_wang_set out;
            check(dispatch_format(fmt, [&]<class T, int C>(format_tag<T, C>) -> status {
              result<wang_tile_set<T, C>> s = status::internal_error("not loaded");
              {
                py::gil_scoped_release nogil;
                s = load_wang_tiles<T, C>(dir);
              }
              out = hold(value_or_raise(std::move(s)));
              return {};
            }));
            return out;
          },
          py::arg("directory"), py::arg("dtype") = py::none(), py::arg("channels") = 0,
          R"doc(Reads a tile directory (tiles.json + tile_<i>.png, as written by save() or `tessera wang build`).
The pixel format is the PNGs' own (uint8 or uint16, their channel count) unless dtype ('uint8',
'uint16', 'float32') or channels (1-4) ask for another. Raises tessera.IOError / ParseError naming
the file.)doc")
      .def(
          "save",
          [](const any_wang_set& s, const std::string& dir) {
            check(s.visit([&](const auto& set) {
              py::gil_scoped_release nogil;
              return save_wang_tiles(dir, set);
            }));
          },
          py::arg("directory"), "Writes the set as DIR/tiles.json and DIR/tile_<i>.png (creating DIR).")
      .def_property_readonly(
          "tile_size", [](const any_wang_set& s) { return s.visit([](const auto& t) { return t.tile_size(); }); },
          "Side of every tile in pixels.")
      .def_property_readonly(
          "num_tiles", [](const any_wang_set& s) { return s.visit([](const auto& t) { return t.size(); }); },
          "Number of tiles.")
      .def("__len__", [](const any_wang_set& s) { return s.visit([](const auto& t) { return t.size(); }); })
      .def_property_readonly(
          "horizontal_colors",
          [](const any_wang_set& s) { return s.visit([](const auto& t) { return t.edges().horizontal_colors(); }); },
          "Colours of the north/south edges.")
      .def_property_readonly(
          "vertical_colors",
          [](const any_wang_set& s) { return s.visit([](const auto& t) { return t.edges().vertical_colors(); }); },
          "Colours of the east/west edges.")
      .def_property_readonly(
          "shared_border",
          [](const any_wang_set& s) { return s.visit([](const auto& t) { return t.shared_border(); }); },
          "Depth in pixels within which tiles agree along equal-coloured edges and at corners.")
      .def_property_readonly(
          "exact_mip_levels",
          [](const any_wang_set& s) { return s.visit([](const auto& t) { return t.exact_mip_levels(); }); },
          "Mip levels (level 0 included) an atlas of this set samples exactly across tile borders.")
      .def_property_readonly(
          "dtype",
          [](const any_wang_set& s) {
            return s.visit([](const auto& t) { return dtype_of<set_channel_t<decltype(t)>>(); });
          },
          "NumPy dtype of the tiles.")
      .def_property_readonly(
          "channels",
          [](const any_wang_set& s) { return s.visit([](const auto& t) { return set_channels_v<decltype(t)>; }); },
          "Channels per pixel.")
      .def_property_readonly(
          "edges", [](const any_wang_set& s) { return s.visit([](const auto& t) { return edges_array(t.edges()); }); },
          "int32 array (num_tiles x 4): each tile's edge colours [north, east, south, west].")
      .def(
          "tile",
          [](const any_wang_set& s, index_t i) {
            return s.visit([&](const auto& t) {
              if (i < 0 || i >= t.size())
                throw py::index_error(cat("WangTileSet.tile: index ", i, " outside [0, ", t.size(), ")"));
              return to_array(t.tile(i));
            });
          },
          py::arg("index"), "Tile `index` as a new H x W x C array.")
      .def(
          "compose",
          [](const any_wang_set& s, index_t width, index_t height, index_t x, index_t y, const py::object& coloring,
             std::uint64_t seed, std::uint64_t variant_seed, index_t period, bool outline, int threads) {
            return s.visit([&](const auto& set) -> py::array {
              using T = set_channel_t<decltype(set)>;
              constexpr int C = set_channels_v<decltype(set)>;
              check(validate_image_extent(width, height, C, "compose"));
              auto out = value_or_raise(image_buffer<T, C>::create(width, height));
              const int nh = set.edges().horizontal_colors(), nv = set.edges().vertical_colors();
              const index_t ts = set.tile_size();
              const compose_options options{.x = x, .y = y, .outline = outline, .seed = variant_seed};
              status composed;
              if (py::isinstance<py::array>(coloring)) {
                index_t cols = 0;
                const stored_tile_coloring c = explicit_coloring(coloring, nh, nv, cols);
                composed =
                    with_executor(threads, [&](auto& exec) { return compose_tiles(set, c, cols, out, options, exec); });
              } else {
                const std::string kind = py::str(coloring).cast<std::string>();
                if (kind == "hash") {
                  // the infinite plane: any window, O(1) per cell (compiled once in tessera::compiled)
                  const hash_coloring c = value_or_raise(hash_coloring::for_set(set.edges(), seed));
                  composed =
                      with_executor(threads, [&](auto& exec) { return compose_tiles(set, c, out, options, exec); });
                } else if (kind == "scanline" || kind == "periodic") {
                  const auto [cols, rows] = covering_grid(x, y, width, height, ts, kind);
                  stored_tile_coloring c;
                  if (kind == "scanline") {
                    c = store_coloring(value_or_raise(scanline_coloring::create(set.edges(), cols, rows, seed)));
                  } else {
                    if (period < 1) raise_invalid(cat("compose: period must be >= 1, got ", period));
                    c = store_coloring(
                        value_or_raise(periodic_coloring::create(set.edges(), period, period, cols, rows, seed)));
                  }
                  composed = with_executor(threads,
                                           [&](auto& exec) { return compose_tiles(set, c, cols, out, options, exec); });
                } else {
                  raise_invalid(
                      cat("compose: coloring must be 'hash', 'scanline', 'periodic' or an int array rows x "
                          "cols x 4, got '",
                          kind, "'"));
                }
              }
              check(composed);
              return to_array(std::move(out));
            });
          },
          py::arg("width"), py::arg("height"), py::arg("x") = 0, py::arg("y") = 0, py::kw_only(),
          py::arg("coloring") = "hash", py::arg("seed") = 1, py::arg("variant_seed") = 1, py::arg("period") = 4,
          py::arg("outline") = false, py::arg("threads") = 0,
          R"doc(The window (x, y, width, height), in pixels, of the plane tiled by this set (Cohen et al. 2003 §3),
as an H x W x C array. coloring: 'hash' (default: the infinite hash colouring, any window anywhere,
O(1) per cell; the same pixels as `tessera wang tile`), 'scanline' (Cohen's scanline colouring) or
'periodic' (period x period tiles) of a grid from the plane's origin covering the window, or an
explicit int array rows x cols x 4 of edge colours [north, east, south, west] per cell (every cell's
edges must name a tile of the set). seed: the colouring's; variant_seed: picks among tiles with
equal edges. outline draws tile borders. Releases the GIL; threads (0: all cores).)doc")
      .def(
          "atlas",
          [](const any_wang_set& s, const std::string& layout, int mip_levels, index_t padding) {
            return s.visit([&](const auto& set) {
              wang_atlas_options o{};
              if (layout == "padded")
                o.layout = atlas_layout::padded;
              else if (layout != "edge_ordered")
                raise_invalid(cat("atlas: layout must be 'edge_ordered' or 'padded', got '", layout, "'"));
              o.mip_levels = mip_levels;
              o.padding = padding;
              auto a = value_or_raise(build_wang_atlas(set, o));
              py::dict d;
              d["layout"] = layout;
              d["tile_size"] = a.tile_size;
              d["padding"] = a.padding;
              d["slot_size"] = a.slot_size;
              d["mip_levels"] = a.mip_levels;
              d["slot_col"] = py::array_t<index_t>(static_cast<py::ssize_t>(a.slot_col.size()), a.slot_col.data());
              d["slot_row"] = py::array_t<index_t>(static_cast<py::ssize_t>(a.slot_row.size()), a.slot_row.data());
              d["image"] = to_array(std::move(a.image));
              return d;
            });
          },
          py::arg("layout") = "edge_ordered", py::arg("mip_levels") = 0, py::arg("padding") = 0,
          R"doc(Packs the set into one texture (image/wang_atlas.hpp): 'edge_ordered' (Wei 2004; needs a complete
set) or 'padded'. Returns a dict: image (H x W x C), tile_size, padding, slot_size, mip_levels (levels
that sample exactly across tile borders), slot_col and slot_row (each tile's slot; for the
edge-ordered layout slots follow the edges, Wei's edge_order_index).)doc");

  m.def(
      "build_wang_tiles",
      [](const py::array& exemplar, index_t tile_size, int horizontal_colors, int vertical_colors, int mip_levels,
         index_t overlap, index_t patch_size, index_t border, double tolerance, double boundary_weight,
         index_t min_candidates, std::uint64_t seed, int threads, const py::object& progress) {
        wang_tile_options o{.tile_size = tile_size,
                            .horizontal_colors = horizontal_colors,
                            .vertical_colors = vertical_colors,
                            .mip_levels = mip_levels,
                            .overlap = overlap,
                            .patch_size = patch_size,
                            .border = border,
                            .tolerance = tolerance,
                            .boundary_weight = boundary_weight,
                            .min_candidates = min_candidates,
                            .seed = seed};
        call_progress p(progress);
        o.progress = p.sink();
        return visit_exemplar(
            exemplar,
            [&](const auto& ex) {
              auto built = with_executor(threads, [&](auto& exec) { return build_wang_tiles(ex, o, exec); });
              return hold(p.value_or_raise(std::move(built)));
            },
            "build_wang_tiles: exemplar");
      },
      py::arg("exemplar"), py::kw_only(), py::arg("tile_size") = 64, py::arg("horizontal_colors") = 2,
      py::arg("vertical_colors") = 2, py::arg("mip_levels") = 0, py::arg("overlap") = 0, py::arg("patch_size") = 0,
      py::arg("border") = 0, py::arg("tolerance") = 0.1, py::arg("boundary_weight") = 64.0,
      py::arg("min_candidates") = 4, py::arg("seed") = 1, py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(Builds the complete Wang tile set (horizontal_colors² x vertical_colors² tiles) from an exemplar
(Cohen et al. 2003 §4, paper 000 §3's frame + interior pipeline). Options as the C++
wang_tile_options (0 = automatic for mip_levels, overlap, patch_size, border). Same seed, same tiles
for any thread count. Releases the GIL; progress callable; Ctrl-C raises KeyboardInterrupt.)doc");
}

}  // namespace tessera::python
