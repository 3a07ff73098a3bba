// python/src/images.cpp: PNG files and procedural exemplars as NumPy arrays.
#include <cstdint>
#include <string>

#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>

#include "bindings.hpp"
#include "common.hpp"

namespace tessera::python {

void bind_images(py::module_& m) {
  m.def(
      "read_png",
      [](const std::string& path, std::uint64_t max_pixels) {
        const png_read_options limits{.max_pixels = max_pixels,
                                      .max_bytes = std::max<std::uint64_t>(std::uint64_t{1} << 30, 16 * max_pixels)};
        png_info info;
        {
          py::gil_scoped_release nogil;
          auto i = read_png_info(path);
          if (!i) {
            py::gil_scoped_acquire gil;
            raise(i.error());
          }
          info = *i;
        }
        py::array out;
        const pixel_format fmt{info.bit_depth == 16 ? channel_type::uint16 : channel_type::uint8, info.channels};
        check(dispatch_channels<std::uint8_t>(fmt.channels, [&]<class T8, int C>(format_tag<T8, C>) {
          auto read = [&]<class T>() {
            result<image_buffer<T, C>> img = status::internal_error("not read");
            {
              py::gil_scoped_release nogil;
              img = read_png<T, C>(path, limits);
            }
            out = to_array(value_or_raise(std::move(img)));
          };
          if (fmt.type == channel_type::uint16)
            read.template operator()<std::uint16_t>();
          else
            read.template operator()<std::uint8_t>();
        }));
        return out;
      },
      py::arg("path"), py::arg("max_pixels") = std::uint64_t{1} << 28,
      R"doc(Reads a PNG file as an H x W x C array in the file's own format: uint8 for 8-bit files (and
1, 2, 4-bit ones), uint16 for 16-bit files; C = 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA (palettes
expand to RGB or RGBA). The array is always three-dimensional. `max_pixels` bounds the decoded size
(a small file can inflate to gigabytes). Raises tessera.IOError when the file cannot be read,
tessera.ParseError for a malformed file, tessera.SizeOverflow above the limit.)doc");

  m.def(
      "write_png",
      [](const std::string& path, const py::array& image) {
        check(visit_image(
            image,
            [&](const auto& view) {
              py::gil_scoped_release nogil;
              return write_png(path, view);
            },
            "write_png: image"));
      },
      py::arg("path"), py::arg("image"),
      R"doc(Writes an H x W or H x W x C array (C = 1-4) as a PNG file: uint8 as an 8-bit PNG, uint16
and float32 as 16-bit (floats clamped to [0, 1]). The array is read in place (no copy) when its rows
hold packed pixels. Raises tessera.IOError when the file cannot be written.)doc");

  m.def(
      "exemplar",
      [](const std::string& kind, index_t width, index_t height, std::uint64_t seed) {
        const auto k = value_or_raise(parse_exemplar_kind(kind));
        result<image_buffer<std::uint8_t, 3>> img = status::internal_error("not rendered");
        {
          py::gil_scoped_release nogil;
          img = make_exemplar<std::uint8_t, 3>(k, {.width = width, .height = height, .seed = seed});
        }
        return to_array(value_or_raise(std::move(img)));
      },
      py::arg("kind"), py::arg("width") = 128, py::arg("height") = 128, py::arg("seed") = 1,
      R"doc(A procedural exemplar as an H x W x 3 uint8 array: kind is one of "grass", "sand", "rock",
"bricks", "cells", "weave", "dots" (what `tessera synth --exemplar grass` renders, with the same seed).)doc");
}

}  // namespace tessera::python
