// python/src/patch.cpp: tessera.PatchModel, the patch synthesis of paper 002 (image/patch_model.hpp,
// image/patch_synthesis.hpp): build once from an exemplar, synthesize any window of the unbounded
// texture, save to bytes and pickle.
#include <string>

#include "bindings.hpp"
#include <tessera/io/patch_model_file.hpp>

#include "patch_model.hpp"

namespace tessera::python {
namespace {

template <class F>
decltype(auto) by_type(channel_type t, F&& f) {
  switch (t) {
    case channel_type::uint16: return f.template operator()<std::uint16_t>();
    case channel_type::float32: return f.template operator()<float>();
    default: return f.template operator()<std::uint8_t>();
  }
}

any_patch_model build(const py::array& exemplar, index_t patch_width, index_t patch_height, index_t overlap,
                      int candidates, bool exact_sets, int pca_dims, index_t pca_samples, int search_pool,
                      int refine_iterations, bool seams, int threads, const py::object& progress,
                      double min_patch_fraction) {
  patch_model_options o;
  o.min_patch_fraction = min_patch_fraction;
  o.patch_width = patch_width;
  o.patch_height = patch_height;
  o.overlap = overlap;
  o.candidates = candidates;
  o.exact_sets = exact_sets;
  o.pca_dims = pca_dims;
  o.pca_samples = pca_samples;
  o.search_pool = search_pool;
  o.refine_iterations = refine_iterations;
  o.seams = seams;
  call_progress p(progress);
  const pixel_format fmt = visit_image(
      exemplar, [](const auto& v) { return pixel_format_of<typename std::remove_cvref_t<decltype(v)>::pixel_type>; },
      "PatchModel: exemplar");
  return by_type(fmt.type, [&]<class T>() { return build_model<T>(exemplar, o, threads, p); });
}

fill_fallback parse_fallback(const std::string& f) {
  if (f == "sets") return fill_fallback::most_sets;
  if (f == "overlap") return fill_fallback::overlap_error;
  if (f == "estimate") return fill_fallback::estimated_error;
  raise_invalid(
      "synthesize: fallback must be \"sets\" (paper 002, the default), \"estimate\" or \"overlap\" (quality "
      "mode), got '" +
      f + "'");
}

seam_mode parse_seams(const py::object& seams, const any_patch_model& m) {
  if (seams.is_none()) return m.options.seams ? seam_mode::cut : seam_mode::feather;
  const std::string s = py::str(seams);
  if (s == "feather") return seam_mode::feather;
  if (s == "cut") return seam_mode::cut;
  raise_invalid("synthesize: seams must be \"feather\", \"cut\" or None (cut when the model has seams), got '" + s +
                "'");
}

template <class F>
decltype(auto) visit_model(const any_patch_model& m, F&& f) {
  return std::visit([&](const auto& by_c) { return std::visit([&](const auto& ptr) { return f(*ptr); }, by_c); },
                    m.model);
}

py::bytes save(const any_patch_model& m) {
  std::string bytes = by_type(m.format.type, [&]<class T>() { return save_model<T>(m); });
  return py::bytes(bytes);
}

any_patch_model load(const py::bytes& data, int threads) {
  const std::string bytes = data;
  const pixel_format fmt = value_or_raise(
      patch_model_file_format(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "PatchModel.load"));
  return by_type(fmt.type, [&]<class T>() { return load_model<T>(bytes, fmt, threads); });
}

}  // namespace

void bind_patch(py::module_& m) {
  py::class_<any_patch_model, std::shared_ptr<any_patch_model>> c(m, "PatchModel", R"doc(
A patch-synthesis model (paper 002, image/patch_model.hpp): the exemplar's patches at every phase and
their compatible sets, built once; synthesize() then renders any window of the unbounded texture the
model and a seed define. Immutable; safe to share between threads; picklable.

The exemplar is an H x W or H x W x C array (C = 1-4) of uint8, uint16 or float32 (finite); the model
keeps that format and synthesize() returns it. The options are those of the C++ patch_model_options,
with the same names and defaults: 0 for patch_width, patch_height or overlap means "chosen by the
periodicity analysis" (paper section 2.1). `threads` (0: all cores) runs the build; `progress` is an
optional callable receiving the fraction done (0 to 1); returning False cancels (tessera.Cancelled),
and Ctrl-C stops the build with KeyboardInterrupt. Raises tessera.InvalidArgument (a ValueError) for
options or an exemplar the library refuses, with its message.)doc");
  c.def(py::init(&build), py::arg("exemplar"), py::kw_only(), py::arg("patch_width") = 0, py::arg("patch_height") = 0,
        py::arg("overlap") = 0, py::arg("candidates") = 8, py::arg("exact_sets") = false, py::arg("pca_dims") = 8,
        py::arg("pca_samples") = 384, py::arg("search_pool") = 16, py::arg("refine_iterations") = 4,
        py::arg("seams") = false, py::arg("threads") = 0, py::arg("progress") = py::none(),
        py::arg("min_patch_fraction") = 0.375, "Builds the model of `exemplar` (see the class documentation).");
  c.def(
      "synthesize",
      [](const any_patch_model& self, index_t width, index_t height, index_t x, index_t y, std::uint64_t seed,
         int threads, const py::object& progress, const py::object& seams, const py::object& out,
         const std::string& fallback, int fallback_budget, const py::object& stats, index_t feather_width) {
        if (!stats.is_none() && !py::isinstance<py::dict>(stats))
          throw py::type_error("synthesize: stats must be a dict or None");
        synthesis_request r{.width = width,
                            .height = height,
                            .origin = {x, y},
                            .seed = seed,
                            .seams = parse_seams(seams, self),
                            .fallback = parse_fallback(fallback),
                            .fallback_budget = fallback_budget,
                            .feather_width = feather_width,
                            .threads = threads,
                            .out = out,
                            .stats = stats};
        call_progress p(progress);
        return by_type(self.format.type, [&]<class T>() { return synthesize_model<T>(self, r, p); });
      },
      py::arg("width"), py::arg("height"), py::arg("x") = 0, py::arg("y") = 0, py::arg("seed") = 0,
      py::arg("threads") = 0, py::arg("progress") = py::none(), py::arg("seams") = py::none(),
      py::arg("out") = py::none(), py::arg("fallback") = "sets", py::arg("fallback_budget") = 8,
      py::arg("stats") = py::none(), py::arg("feather_width") = 5,
      R"doc(The width x height window at (x, y) of the unbounded texture of this model and `seed`, as an
H x W x C array of the exemplar's dtype. Any window is a pure function of (model, seed, x, y): windows
tile the texture seamlessly and equal `tessera synth --window x,y,w,h --seed S` of the CLI (which
builds its model with default options, seams=True for --seams cut) pixel for pixel. `seams` is
"feather" (the paper's linear blend) or "cut" (minimum-error seams); None: "cut" when the model was
built with seams=True, else "feather", as the CLI does. Releases the GIL; `threads` (0: all cores);
`progress` as for the constructor, and Ctrl-C raises KeyboardInterrupt. Raises tessera.InvalidArgument
for a non-positive size, tessera.SizeOverflow for a window too large to allocate, tessera.OutOfRange for
a window beyond the texture plane of +-2^52. `out`: an array to render into instead of a new one (shape
(height, width, C) or (height, width) for C = 1, the model's dtype, writable, packed pixels in rows; row
padding allowed); it is returned. Reusing one buffer for many windows avoids the allocation and page
faults of a new array, which are most of the Python-side cost of a fast synthesis. `fallback`: how a
vacant cell is filled when its four neighbours' compatible sets share no patch (on photographs nearly
always): "sets" (paper 002, the default: the patch in the most sets), "estimate" (the patch of the
union of the four sets with the smallest overlap error against all four neighbours, the errors the
sets miss estimated from the strips' PCA descriptors; about 2.4 times the CPU time) or "overlap"
(quality mode: as "estimate" with the missing errors computed exactly, several times slower), as
`tessera synth --fallback`; `fallback_budget` (1-256) bounds the overlap errors computed
per cell in that mode. `stats`: a dict to fill with the statistics `tessera synth --stats` prints
(cells, placed, filled, empty_intersections, computed_seams, evaluated_errors, fill_overlap_rms) and
synthesis_ms, the time of the C++ call alone (benchmarks/python_overhead.py compares it with the
call's wall time). `feather_width`: width in pixels of the blend band centred in each overlap when
feathering (default 5; 0: the whole overlap, the paper's weights), as `tessera synth --feather`;
raises tessera.InvalidArgument when negative.)doc");
  c.def("save", &save, "The model as bytes (io/patch_model_file.hpp, format version 1); PatchModel.load reads them.");
  c.def_static("load", &load, py::arg("data"), py::arg("threads") = 0,
               R"doc(A model from the bytes of save(). Raises tessera.ParseError (a ValueError) for bytes that are
not a model, truncated or corrupted, tessera.Unsupported (a NotImplementedError) for a model saved by
another format version. Rebuilds the compatible sets (deterministic: the model synthesizes exactly what
the saved one did).)doc");
  c.def(py::pickle([](const any_patch_model& self) { return save(self); },
                   [](const py::bytes& state) { return std::make_shared<any_patch_model>(load(state, 0)); }));
  c.def_property_readonly(
      "dtype",
      [](const any_patch_model& self) { return by_type(self.format.type, [&]<class T>() { return dtype_of<T>(); }); },
      "NumPy dtype of the exemplar and of synthesized arrays.");
  c.def_property_readonly(
      "channels", [](const any_patch_model& self) { return self.format.channels; }, "Channels per pixel (1-4).");
  c.def_property_readonly(
      "patch_width",
      [](const any_patch_model& self) { return visit_model(self, [](const auto& mm) { return mm.patch_width(); }); },
      "Cell pitch in x (resolved: the analysis' choice when built with 0).");
  c.def_property_readonly(
      "patch_height",
      [](const any_patch_model& self) { return visit_model(self, [](const auto& mm) { return mm.patch_height(); }); },
      "Cell pitch in y (resolved).");
  c.def_property_readonly(
      "overlap",
      [](const any_patch_model& self) { return visit_model(self, [](const auto& mm) { return mm.overlap(); }); },
      "Overlap width between neighbouring patches (resolved).");
  c.def_property_readonly(
      "candidates", [](const any_patch_model& self) { return self.options.candidates; },
      "k, the size of each compatible set asked for (1-64).");
  c.def_property_readonly(
      "exact_sets", [](const any_patch_model& self) { return self.options.exact_sets; }, "Exact top-k sets.");
  c.def_property_readonly(
      "pca_dims", [](const any_patch_model& self) { return self.options.pca_dims; },
      "PCA dimensions of the strip descriptors.");
  c.def_property_readonly(
      "pca_samples", [](const any_patch_model& self) { return self.options.pca_samples; },
      "Strips sampled to estimate the PCA basis.");
  c.def_property_readonly(
      "search_pool", [](const any_patch_model& self) { return self.options.search_pool; },
      "Approximate sets: kd-tree candidates re-ranked per patch and side.");
  c.def_property_readonly(
      "refine_iterations", [](const any_patch_model& self) { return self.options.refine_iterations; },
      "Approximate sets: coherence propagation rounds.");
  c.def_property_readonly(
      "seams", [](const any_patch_model& self) { return self.options.seams; },
      "Whether minimum-error seams were precomputed (synthesize then cuts by default).");
  c.def_property_readonly(
      "num_patches",
      [](const any_patch_model& self) { return visit_model(self, [](const auto& mm) { return mm.num_patches(); }); },
      "Patches in the model (every phase).");
  c.def_property_readonly(
      "memory_bytes",
      [](const any_patch_model& self) { return visit_model(self, [](const auto& mm) { return mm.memory_bytes(); }); },
      "Bytes the model holds.");
  c.def_property_readonly(
      "exemplar",
      [](const any_patch_model& self) {
        return visit_model(self, [](const auto& mm) { return to_array(mm.exemplar()); });
      },
      "A copy of the exemplar (H x W x C).");
  c.def("__repr__", [](const any_patch_model& self) {
    return visit_model(self, [&](const auto& mm) {
      return cat("PatchModel(", mm.exemplar().width(), " x ", mm.exemplar().height(), " x ", self.format.channels, " ",
                 std::string(to_string(self.format.type)), ", patch ", mm.patch_width(), " x ", mm.patch_height(),
                 ", overlap ", mm.overlap(), ", ", mm.num_patches(), " patches)");
    });
  });
}

}  // namespace tessera::python
