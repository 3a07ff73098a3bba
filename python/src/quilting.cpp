// python/src/quilting.cpp: image quilting (image/quilt.hpp, Efros & Freeman 2001) and constrained
// quilting with masks (image/constrained_quilt.hpp: inpainting a hole from an exemplar or from the
// image itself).
#include <tessera/image/constrained_quilt.hpp>
#include <tessera/image/quilt.hpp>

#include "bindings.hpp"
#include "common.hpp"

namespace tessera::python {
namespace {

quilt_options make_options(index_t patch_size, index_t overlap, double tolerance, bool seamless, double boundary_weight,
                           std::uint64_t seed) {
  quilt_options o;
  o.patch_size = patch_size;
  o.overlap = overlap;
  o.tolerance = tolerance;
  o.seamless = seamless;
  o.boundary_weight = boundary_weight;
  o.seed = seed;
  return o;
}

/// The mask as a one-channel uint8 view: bool or uint8, H x W (or H x W x 1).
image_view<const std::uint8_t, 1> mask_view(py::array& mask) {
  if (mask.dtype().kind() == 'b') mask = py::array(mask.attr("astype")(py::dtype::of<std::uint8_t>()));
  if (mask.dtype().kind() == 'b' || !detail_py::is_dtype<std::uint8_t>(mask))
    throw py::type_error("constrained_quilt: mask must be a bool or uint8 array, got " + dtype_name(mask));
  if (channels_of(mask, "constrained_quilt: mask") != 1)
    throw py::value_error("constrained_quilt: mask must be H x W (or H x W x 1)");
  return detail_py::view_of<std::uint8_t, 1>(mask, "constrained_quilt: mask");
}

}  // namespace

void bind_quilting(py::module_& m) {
  m.def(
      "quilt",
      [](const py::array& exemplar, index_t width, index_t height, index_t patch_size, index_t overlap,
         double tolerance, bool seamless, std::uint64_t seed, int threads, const py::object& progress) {
        quilt_options o = make_options(patch_size, overlap, tolerance, seamless, 64, seed);
        call_progress p(progress);
        o.progress = p.sink();
        return visit_exemplar(
            exemplar,
            [&]<class T, int C>(const image_buffer<T, C>& ex) {
              auto out = value_or_raise(image_buffer<T, C>::create(width, height));
              const status s = with_executor(threads, [&](auto& exec) { return quilt(ex, out, o, exec); });
              p.check(s);
              return to_array(std::move(out));
            },
            "quilt: exemplar");
      },
      py::arg("exemplar"), py::arg("width"), py::arg("height"), py::kw_only(), py::arg("patch_size") = 0,
      py::arg("overlap") = 0, py::arg("tolerance") = 0.1, py::arg("seamless") = false, py::arg("seed") = 1,
      py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(Image quilting (Efros & Freeman 2001): a width x height texture (H x W x C, the exemplar's dtype)
of square patches joined by minimum-error cuts. Options as the C++ quilt_options: patch_size (0: a
quarter of the exemplar's smaller side, in [8, 64]), overlap (0: patch_size / 6), tolerance, seamless
(the output tiles with itself), seed. Releases the GIL; threads (0: all cores); progress callable;
Ctrl-C raises KeyboardInterrupt. Same seed, same output for any thread count.)doc");

  m.def(
      "constrained_quilt",
      [](const py::array& image, py::array mask, const py::object& exemplar, index_t patch_size, index_t overlap,
         double tolerance, double boundary_weight, std::uint64_t seed, int threads, const py::object& progress) {
        quilt_options o = make_options(patch_size, overlap, tolerance, false, boundary_weight, seed);
        call_progress p(progress);
        o.progress = p.sink();
        const auto hole = mask_view(mask);
        return visit_image(
            image,
            [&](const auto& img) {
              using V = std::remove_cvref_t<decltype(img)>;
              using T = typename V::value_type;
              constexpr int C = V::channels;
              auto out = value_or_raise(image_buffer<T, C>::create(img.width(), img.height()));
              status s;
              if (exemplar.is_none()) {
                s = with_executor(threads, [&](auto& exec) { return constrained_quilt(img, hole, out, o, exec); });
              } else {
                const py::array ex = exemplar;
                if (!detail_py::is_dtype<T>(ex) || channels_of(ex, "constrained_quilt: exemplar") != C)
                  throw py::type_error("constrained_quilt: the exemplar must have the image's dtype and channels");
                const auto exv = detail_py::view_of<T, C>(ex, "constrained_quilt: exemplar");
                s = with_executor(threads, [&](auto& exec) { return constrained_quilt(exv, img, hole, out, o, exec); });
              }
              p.check(s);
              return to_array(std::move(out));
            },
            "constrained_quilt: image");
      },
      py::arg("image"), py::arg("mask"), py::arg("exemplar") = py::none(), py::kw_only(), py::arg("patch_size") = 0,
      py::arg("overlap") = 0, py::arg("tolerance") = 0.1, py::arg("boundary_weight") = 64.0, py::arg("seed") = 1,
      py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(Constrained quilting (inpainting): fills the pixels of `image` where `mask` (H x W, bool or uint8
>= 128) is set, with texture from `exemplar` (same dtype and channels as the image) or, when it is
None, from the hole-free windows of the image itself. Pixels outside the mask are returned unchanged,
bit for bit. Options as quilt(), plus boundary_weight (weight of the fixed pixels bordering the hole).
Returns a new H x W x C array.)doc");
}

}  // namespace tessera::python
