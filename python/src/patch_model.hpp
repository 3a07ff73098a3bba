// python/src/patch_model.hpp: the state behind tessera.PatchModel: one patch_model<T, C> per pixel
// format, held in a variant. The heavy kernels (build, synthesize) are instantiated per channel type in
// patch_model_u8.cpp, patch_model_u16.cpp and patch_model_f32.cpp (three translation units that
// compile in parallel).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>

#include <tessera/image/patch_model.hpp>
#include <tessera/image/patch_synthesis.hpp>

#include "common.hpp"

namespace tessera::python {

template <class T>
using models_of = std::variant<std::shared_ptr<const patch_model<T, 1>>, std::shared_ptr<const patch_model<T, 2>>,
                               std::shared_ptr<const patch_model<T, 3>>, std::shared_ptr<const patch_model<T, 4>>>;

/// A built model of any format, with the options it was built with (progress excluded).
struct any_patch_model {
  std::variant<models_of<std::uint8_t>, models_of<std::uint16_t>, models_of<float>> model;
  patch_model_options options;
  pixel_format format;
};

/// What one synthesis call asks for.
struct synthesis_request {
  index_t width = 0, height = 0;
  texture_offset origin;
  std::uint64_t seed = 0;
  seam_mode seams = seam_mode::feather;
  fill_fallback fallback = fill_fallback::most_sets;
  int fallback_budget = 8;
  index_t feather_width = 5;  ///< patch_synthesis_options::feather_width
  int threads = 0;
  /// An array to render into (H x W x C, or H x W for one channel, of the model's dtype, writable,
  /// packed pixels in rows), or None for a new array.
  py::object out = py::none();
  /// A dict to fill with the synthesis statistics and `synthesis_ms` (the C++ call alone), or None.
  py::object stats = py::none();
};

/// Builds a model from an exemplar array of channel type T (GIL released while building).
template <class T>
any_patch_model build_model(const py::array& exemplar, const patch_model_options& options, int threads,
                            call_progress& progress);
/// Renders a window of a model whose channel type is T as an H x W x C array.
template <class T>
py::array synthesize_model(const any_patch_model& model, const synthesis_request& request, call_progress& progress);
/// Serializes a model whose channel type is T (io/patch_model_file.hpp).
template <class T>
std::string save_model(const any_patch_model& model);
/// Loads a model of channel type T from serialized bytes (GIL released while rebuilding).
template <class T>
any_patch_model load_model(const std::string& bytes, pixel_format format, int threads);

extern template any_patch_model build_model<std::uint8_t>(const py::array&, const patch_model_options&, int,
                                                          call_progress&);
extern template any_patch_model build_model<std::uint16_t>(const py::array&, const patch_model_options&, int,
                                                           call_progress&);
extern template any_patch_model build_model<float>(const py::array&, const patch_model_options&, int, call_progress&);
extern template py::array synthesize_model<std::uint8_t>(const any_patch_model&, const synthesis_request&,
                                                         call_progress&);
extern template py::array synthesize_model<std::uint16_t>(const any_patch_model&, const synthesis_request&,
                                                          call_progress&);
extern template py::array synthesize_model<float>(const any_patch_model&, const synthesis_request&, call_progress&);
extern template std::string save_model<std::uint8_t>(const any_patch_model&);
extern template std::string save_model<std::uint16_t>(const any_patch_model&);
extern template std::string save_model<float>(const any_patch_model&);
extern template any_patch_model load_model<std::uint8_t>(const std::string&, pixel_format, int);
extern template any_patch_model load_model<std::uint16_t>(const std::string&, pixel_format, int);
extern template any_patch_model load_model<float>(const std::string&, pixel_format, int);

}  // namespace tessera::python
