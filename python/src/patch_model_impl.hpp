// python/src/patch_model_impl.hpp: the per-format bodies of patch_model.hpp's functions; included by
// patch_model_u8.cpp, patch_model_u16.cpp and patch_model_f32.cpp only, each instantiating one T.
#pragma once

#include <chrono>

#include <tessera/io/patch_model_file.hpp>

#include "patch_model.hpp"

namespace tessera::python {

template <class T>
any_patch_model build_model(const py::array& exemplar, const patch_model_options& options, int threads,
                            call_progress& progress) {
  any_patch_model out;
  out.options = options;
  out.options.progress = {};
  visit_image_of<T>(
      exemplar,
      [&]<int C>(const image_view<const T, C>& view) {
        patch_model_options o = options;
        o.progress = progress.sink();
        // The exemplar as an image_buffer: the type tessera::compiled instantiates build_patch_model for
        // (docs/compile_once.md), so the module does not compile the builder again; a copy of the
        // exemplar costs nothing next to building the model.
        const auto ex = value_or_raise(to_buffer<T, C>(view, "PatchModel: exemplar"));
        auto built = with_executor(threads, [&](auto& exec) { return build_patch_model(ex, o, exec); });
        auto model = progress.value_or_raise(std::move(built));
        out.model = models_of<T>(std::make_shared<const patch_model<T, C>>(std::move(model)));
        out.format = {channel_type_of<T>, C};
      },
      "PatchModel: exemplar");
  return out;
}

template <class T>
py::array synthesize_model(const any_patch_model& model, const synthesis_request& r, call_progress& progress) {
  return std::visit(
      [&]<int C>(const std::shared_ptr<const patch_model<T, C>>& m) {
        patch_synthesis_options so{.origin = r.origin,
                                   .seed = r.seed,
                                   .seams = r.seams,
                                   .feather_width = r.feather_width,
                                   .fallback = r.fallback,
                                   .fallback_budget = r.fallback_budget};
        so.progress = progress.sink();
        // synthesized in place into an uninitialized NumPy array (no fill, no copy)
        check(validate_image_extent(r.width, r.height, C, "synthesize"));
        py::array out;
        image_view<T, C> view;
        if (r.out.is_none()) {
          out = new_array<T>(r.width, r.height, C);
          view = image_view<T, C>(static_cast<T*>(out.mutable_data()), r.width, r.height);
        } else {
          // the caller's array, rendered in place (no allocation: repeated windows reuse one buffer)
          if (!py::isinstance<py::array>(r.out)) throw py::type_error("synthesize: out must be a NumPy array or None");
          out = py::reinterpret_borrow<py::array>(r.out);
          if (!detail_py::is_dtype<T>(out))
            throw py::type_error(cat("synthesize: out has dtype ", dtype_name(out), ", the model renders ",
                                     py::str(dtype_of<T>()).cast<std::string>()));
          if (channels_of(out, "synthesize: out") != C || out.shape(0) != r.height || out.shape(1) != r.width)
            raise_invalid(cat("synthesize: out must have shape (", r.height, ", ", r.width, ", ", C, ")"));
          if (!out.writeable()) raise_invalid("synthesize: out is read-only");
          const auto checked = detail_py::view_of<T, C>(out, "synthesize: out");
          view = image_view<T, C>(static_cast<T*>(out.mutable_data()), r.width, r.height, checked.stride());
        }
        double ms = 0;  // the C++ call alone, as `tessera synth --stats` times it
        auto st = with_executor(r.threads, [&](auto& exec) {
          const auto t0 = std::chrono::steady_clock::now();
          auto s = synthesize(*m, view, so, exec);
          ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          return s;
        });
        const patch_synthesis_stats stats = progress.value_or_raise(std::move(st));
        if (!r.stats.is_none()) {
          auto d = py::reinterpret_borrow<py::dict>(r.stats);
          d["synthesis_ms"] = ms;
          d["cells"] = stats.cells;
          d["placed"] = stats.placed;
          d["filled"] = stats.filled;
          d["empty_intersections"] = stats.empty_intersections;
          d["computed_seams"] = stats.computed_seams;
          d["evaluated_errors"] = stats.evaluated_errors;
          d["fill_overlap_rms"] = stats.fill_overlap_rms;
        }
        return out;
      },
      std::get<models_of<T>>(model.model));
}

template <class T>
std::string save_model(const any_patch_model& model) {
  return std::visit(
      [&]<int C>(const std::shared_ptr<const patch_model<T, C>>& m) {
        auto bytes = value_or_raise(encode_patch_model(*m, model.options));
        return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      },
      std::get<models_of<T>>(model.model));
}

template <class T>
any_patch_model load_model(const std::string& bytes, pixel_format format, int threads) {
  any_patch_model out;
  out.format = format;
  check(dispatch_channels<T>(format.channels, [&]<class U, int C>(format_tag<U, C>) {
    auto loaded = with_executor(threads, [&](auto& exec) {
      return decode_patch_model<T, C>(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), exec);
    });
    auto file = value_or_raise(std::move(loaded));
    out.options = file.options;
    out.model = models_of<T>(std::make_shared<const patch_model<T, C>>(std::move(file.model)));
  }));
  return out;
}

}  // namespace tessera::python
