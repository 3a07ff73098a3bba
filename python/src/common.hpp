// python/src/common.hpp: what every part of the tessera Python module shares: status -> exception,
// NumPy arrays <-> image views (zero-copy where the layout allows), progress callables with
// KeyboardInterrupt, and running work with the GIL released on an executor.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include <unistd.h>

#include <tessera/core/executor.hpp>
#include <tessera/core/format.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/core/image_checks.hpp>
#include <tessera/core/image_view.hpp>
#include <tessera/core/progress.hpp>
#include <tessera/core/status.hpp>

namespace tessera::python {
namespace py = pybind11;

// ---- errors -------------------------------------------------------------------------------------

/// The Python exception class for a status code (tessera.InvalidArgument, ...); set up by bind_errors.
PyObject* exception_for(status_code code);

/// Raises the exception of `s`'s code with its message (precondition: !s.ok()).
[[noreturn]] inline void raise(const status& s) {
  PyErr_SetString(exception_for(s.code()), s.message().c_str());
  throw py::error_already_set();
}
/// Raises when `s` is a failure.
inline void check(const status& s) {
  if (!s.ok()) raise(s);
}
/// The value of `r`, or raises its status.
template <class T>
T value_or_raise(result<T>&& r) {
  if (!r.ok()) raise(r.error());
  return std::move(r).value();
}
/// Raises tessera.InvalidArgument (a ValueError) with `message`.
[[noreturn]] inline void raise_invalid(std::string message) { raise(status::invalid_argument(std::move(message))); }

// ---- images -------------------------------------------------------------------------------------

/// Name of a NumPy dtype for messages.
inline std::string dtype_name(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

namespace detail_py {
template <class T>
bool is_dtype(const py::array& a) {
  return a.dtype().is(py::dtype::of<T>()) ||
         (a.dtype().kind() == py::dtype::of<T>().kind() &&
          a.dtype().itemsize() == static_cast<py::ssize_t>(sizeof(T)) && a.dtype().attr("isnative").cast<bool>());
}

/// Checks the layout of an H x W or H x W x C array of T and returns (data, width, height, stride).
template <class T, int C>
image_view<const T, C> view_of(const py::array& a, const char* what) {
  const py::ssize_t h = a.shape(0), w = a.shape(1);
  if (h == 0 || w == 0)
    raise_invalid(
        cat(what, ": the image is empty (", static_cast<long long>(h), " x ", static_cast<long long>(w), ")"));
  const py::ssize_t item = static_cast<py::ssize_t>(sizeof(T));
  const py::ssize_t pixel_stride = a.ndim() == 3 ? a.strides(1) : a.strides(1);
  const bool channels_packed = a.ndim() == 2 || a.strides(2) == item || C == 1;
  if (!channels_packed || pixel_stride != item * C || a.strides(0) <= 0 || a.strides(0) % item != 0 ||
      a.strides(0) < w * C * item)
    throw py::value_error(cat(what, ": the array's memory layout is not supported (strides ",
                              static_cast<long long>(a.strides(0)), ", ", static_cast<long long>(a.strides(1)),
                              a.ndim() == 3 ? ", " + std::to_string(a.strides(2)) : std::string(),
                              " bytes); rows must hold packed pixels at a positive row stride: "
                              "use numpy.ascontiguousarray(array)"));
  return image_view<const T, C>(static_cast<const T*>(a.data()), static_cast<index_t>(w), static_cast<index_t>(h),
                                static_cast<index_t>(a.strides(0) / item));
}
}  // namespace detail_py

/// The channel count of an H x W (1) or H x W x C (C) array; raises for any other shape.
inline int channels_of(const py::array& a, const char* what) {
  if (a.ndim() == 2) return 1;
  if (a.ndim() == 3 && a.shape(2) >= 1 && a.shape(2) <= 4) return static_cast<int>(a.shape(2));
  std::string shape;
  for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? " x " : "") + std::to_string(a.shape(i));
  throw py::value_error(cat(what, ": expected an H x W or H x W x C array with C = 1 to 4, got shape (", shape, ")"));
}

/// Calls f(image_view<const T, C>) for a fixed channel type T (the array must have that dtype) and
/// the array's channel count; see visit_image.
template <class T, class F>
decltype(auto) visit_image_of(const py::array& a, F&& f, const char* what = "image") {
  if (!detail_py::is_dtype<T>(a))
    throw py::type_error(
        cat(what, ": expected a ", std::string(to_string(channel_type_of<T>)), " array, got ", dtype_name(a)));
  const int c = channels_of(a, what);
  auto run = [&]<int C>() -> decltype(auto) {
    auto v = detail_py::view_of<T, C>(a, what);
    if constexpr (std::is_same_v<T, float>) check(validate_finite_pixels(v, what));
    return f(v);
  };
  switch (c) {
    case 1: return run.template operator()<1>();
    case 2: return run.template operator()<2>();
    case 3: return run.template operator()<3>();
    default: return run.template operator()<4>();
  }
}

/// Calls f(image_view<const T, C>) for the array's dtype (uint8, uint16, float32) and channel count
/// (H x W: 1; H x W x C: C = 1-4), without copying: rows may be padded, but pixels within a row must be
/// packed and the row stride positive. Float images must be finite. Raises TypeError for another
/// dtype, ValueError for another shape or layout (the message says to use numpy.ascontiguousarray).
template <class F>
decltype(auto) visit_image(const py::array& a, F&& f, const char* what = "image") {
  if (detail_py::is_dtype<std::uint8_t>(a)) return visit_image_of<std::uint8_t>(a, std::forward<F>(f), what);
  if (detail_py::is_dtype<std::uint16_t>(a)) return visit_image_of<std::uint16_t>(a, std::forward<F>(f), what);
  if (detail_py::is_dtype<float>(a)) return visit_image_of<float>(a, std::forward<F>(f), what);
  throw py::type_error(cat(what, ": expected a uint8, uint16 or float32 array (native byte order), got ", dtype_name(a),
                           "; convert with array.astype(numpy.float32) or numpy.uint8"));
}

/// visit_image, with the array copied into an image_buffer<T, C>: calls f(const image_buffer<T, C>&).
/// For exemplars: the buffer type is the one tessera::compiled instantiates the builders for
/// (docs/compile_once.md), so the module does not compile them again; the copy costs nothing next to
/// building a model, a quilt or a tile set.
template <class F>
decltype(auto) visit_exemplar(const py::array& a, F&& f, const char* what = "exemplar") {
  return visit_image(
      a,
      [&]<class T, int C>(const image_view<const T, C>& view) -> decltype(auto) {
        const auto buffer = value_or_raise(to_buffer<T, C>(view, what));
        return f(buffer);
      },
      what);
}

/// The runtime pixel format of an array (raises like visit_image).
inline pixel_format format_of(const py::array& a, const char* what = "image") {
  return visit_image(
      a, [](const auto& v) { return pixel_format_of<typename std::remove_cvref_t<decltype(v)>::pixel_type>; }, what);
}

/// A NumPy dtype of channel type T.
template <class T>
py::dtype dtype_of() {
  return py::dtype::of<T>();
}

/// A new, uninitialized, C-contiguous H x W x C array of T (the caller validated the size).
template <class T>
py::array new_array(index_t width, index_t height, int channels) {
  return py::array(dtype_of<T>(), {static_cast<py::ssize_t>(height), static_cast<py::ssize_t>(width),
                                   static_cast<py::ssize_t>(channels)});
}

/// An H x W x C array (always three dimensions, also for C = 1) owning `img`'s pixels: the buffer is
/// moved into the array, no pixel is copied.
template <Channel T, int C>
py::array to_array(image_buffer<T, C>&& img) {
  auto* owned = new image_buffer<T, C>(std::move(img));
  py::capsule keep(owned, [](void* p) { delete static_cast<image_buffer<T, C>*>(p); });
  const auto item = static_cast<py::ssize_t>(sizeof(T));
  return py::array(
      dtype_of<T>(),
      {static_cast<py::ssize_t>(owned->height()), static_cast<py::ssize_t>(owned->width()), py::ssize_t{C}},
      {item * C * static_cast<py::ssize_t>(owned->width()), item * C, item}, owned->data(), keep);
}
/// An H x W x C array holding a copy of any Image's pixels.
template <class Image>
py::array to_array(const Image& img) {
  using T = channel_t<Image>;
  constexpr int C = channels_v<Image>;
  auto buf = value_or_raise(to_buffer<T, C>(img, "image"));
  return to_array(std::move(buf));
}

// ---- progress, cancellation and executors -------------------------------------------------------

/// A Python progress callable for one call: `progress(fraction)` with fraction in [0, 1], called on the
/// calling thread with the GIL held. Each report also checks for signals (Ctrl-C): a pending
/// KeyboardInterrupt, or an exception raised by the callable, cancels the C++ work; rethrow() then
/// raises it in place of the status_code::cancelled status. A callable returning False cancels too
/// (tessera.Cancelled).
struct call_progress {
  explicit call_progress(py::object callable = py::none()) : callable_(std::move(callable)) {
    if (!callable_.is_none() && !PyCallable_Check(callable_.ptr()))
      throw py::type_error("progress must be a callable taking the fraction done (0 to 1), or None");
  }
  call_progress(const call_progress&) = delete;
  call_progress& operator=(const call_progress&) = delete;

  /// The tessera progress sink (valid while *this lives).
  [[nodiscard]] tessera::progress sink() {
    return {.callback = [this](double fraction, std::string_view) { return report(fraction); }, .token = nullptr};
  }
  /// Called with the GIL released; acquires it.
  bool report(double fraction) {
    py::gil_scoped_acquire gil;
    if (error_) return false;
    if (PyErr_CheckSignals() != 0) {
      error_ = std::make_shared<py::error_already_set>();
      return false;
    }
    if (callable_.is_none()) return true;
    try {
      py::object r = callable_(fraction);
      return r.is_none() || r.cast<bool>();
    } catch (py::error_already_set& e) { error_ = std::make_shared<py::error_already_set>(std::move(e)); } catch (...) {
      // a C++ exception from a cast: store it as a Python error
      try {
        throw;
      } catch (const std::exception& e) { PyErr_SetString(PyExc_RuntimeError, e.what()); }
      error_ = std::make_shared<py::error_already_set>();
    }
    return false;
  }
  /// Raises the stored exception (KeyboardInterrupt or the callable's), if any. Call with the GIL.
  void rethrow() {
    if (error_) {
      auto e = std::move(error_);
      throw py::error_already_set(*e);
    }
  }
  /// check(s), raising the callable's exception in place of a cancelled status.
  void check(const status& s) {
    rethrow();
    python::check(s);
  }
  template <class T>
  T value_or_raise(result<T>&& r) {
    rethrow();
    return python::value_or_raise(std::move(r));
  }

 private:
  py::object callable_;
  std::shared_ptr<py::error_already_set> error_;
};

namespace detail_py {
/// The pool kept between calls: starting and joining its threads cost a 1024² synthesis on 2 threads
/// about a third of its time. Never destroyed (its threads would be joined after the interpreter is
/// gone); a forked child, which inherits the object but not the threads, leaves it alone.
struct kept_pool {
  std::atomic<bool> in_use{false};  // not a mutex: a progress callable may call tessera again (nested)
  thread_pool_executor* pool = nullptr;
  int threads = -1;
  pid_t pid = 0;
};
inline kept_pool& the_kept_pool() {
  static auto* kept = new kept_pool;
  return *kept;
}
}  // namespace detail_py

/// Runs f(executor) with the GIL released on a thread_pool_executor of `threads` (0: the hardware
/// concurrency; 1: the calling thread only, as serial_executor: such a pool starts no thread and runs
/// every loop in order). One executor type keeps each kernel instantiated once (compile time).
/// With threads != 1 the pool is kept between calls; a call made while another uses it (from another
/// Python thread, or from a progress callable) gets its own. Returns f's result.
template <class F>
decltype(auto) with_executor(int threads, F&& f) {
  if (threads < 0) raise_invalid(cat("threads must be >= 0 (0: all cores), got ", threads));
  if (threads > thread_pool_executor::max_threads)
    raise_invalid(cat("threads must be at most ", thread_pool_executor::max_threads, ", got ", threads));
  py::gil_scoped_release nogil;
  if (threads != 1) {
    auto& kept = detail_py::the_kept_pool();
    if (!kept.in_use.exchange(true, std::memory_order_acquire)) {
      struct release {
        std::atomic<bool>& flag;
        ~release() { flag.store(false, std::memory_order_release); }
      } released{kept.in_use};
      const pid_t pid = ::getpid();
      if (kept.pool != nullptr && (kept.threads != threads || kept.pid != pid)) {
        if (kept.pid == pid) delete kept.pool;  // in a forked child its threads do not exist: leave it
        kept.pool = nullptr;
      }
      if (kept.pool == nullptr) {
        kept.pool = new thread_pool_executor(threads);
        kept.threads = threads;
        kept.pid = pid;
      }
      return f(*kept.pool);
    }
  }
  thread_pool_executor pool(threads);
  return f(pool);
}

}  // namespace tessera::python
