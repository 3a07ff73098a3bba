// python/src/fabric.cpp: tessera's fabric family (paper 001): cat map, its period, the game-of-life
// perturbation and make_fabric (presets and any source image).
#include <cstdint>
#include <string>

#include <tessera/fabric/cat_map.hpp>
#include <tessera/fabric/cat_map_period.hpp>
#include <tessera/fabric/life_perturbation.hpp>
#include <tessera/fabric/make_fabric.hpp>

#include "bindings.hpp"
#include "common.hpp"

namespace tessera::python {
namespace {

non_square_mode parse_non_square(const std::string& s) {
  if (s == "reject") return non_square_mode::reject;
  if (s == "centered_square") return non_square_mode::centered_square;
  if (s == "square_tiles") return non_square_mode::square_tiles;
  raise_invalid(cat("non_square must be 'reject', 'centered_square' or 'square_tiles', got '", s, "'"));
}
source_fit parse_fit(const std::string& s) {
  if (s == "reject") return source_fit::reject;
  if (s == "centered_square") return source_fit::centered_square;
  if (s == "crop_or_repeat") return source_fit::crop_or_repeat;
  raise_invalid(cat("fit must be 'reject', 'centered_square' or 'crop_or_repeat', got '", s, "'"));
}
life_test parse_live_test(const std::string& s) {
  if (s == "brighter_than_pixel") return life_test::brighter_than_pixel;
  if (s == "above_threshold") return life_test::above_threshold;
  raise_invalid(cat("live_test must be 'brighter_than_pixel' or 'above_threshold', got '", s, "'"));
}

/// A new image of `image`'s format and size, filled by f(view, buffer&, executor) -> status.
template <class F>
py::array map_image(const py::array& image, int threads, call_progress& progress, F&& f) {
  return visit_image(image, [&](const auto& view) {
    using V = std::remove_cvref_t<decltype(view)>;
    using T = std::remove_const_t<typename V::value_type>;
    constexpr int C = V::channels;
    auto out = progress.value_or_raise(with_executor(threads, [&](auto& exec) -> result<image_buffer<T, C>> {
      auto made = image_buffer<T, C>::create(view.width(), view.height());
      if (!made) return made.error();
      if (auto s = f(view, *made, exec); !s) return s;
      return std::move(*made);
    }));
    return to_array(std::move(out));
  });
}

life_perturbation_options life_options(int generations, int live_count, bool live_exact, int dead_count,
                                       int crowding_count, const std::string& live_test, float threshold,
                                       std::uint64_t seed) {
  life_perturbation_options o;
  o.generations = generations;
  o.live_count = live_count;
  o.live_exact = live_exact;
  o.dead_count = dead_count;
  o.crowding_count = crowding_count;
  o.live_test = parse_live_test(live_test);
  o.threshold = threshold;
  o.seed = seed;
  return o;
}

}  // namespace

void bind_fabric(py::module_& m) {
  m.def(
      "cat_map_period",
      [](std::int64_t n, std::int64_t a, std::int64_t b) {
        return value_or_raise(cat_map_period(n, cat_map_family{.a = a, .b = b}));
      },
      py::arg("n"), py::arg("a") = 1, py::arg("b") = 1,
      R"doc(The period of the cat map [1 a; b ab+1] on an n x n image: the smallest k > 0 such that k steps
return every image to itself (paper 001, section 2). n in [1, 2**62]; raises InvalidArgument otherwise.)doc");

  m.def(
      "cat_map",
      [](const py::array& image, std::int64_t steps, std::int64_t a, std::int64_t b, const std::string& non_square,
         std::int64_t tile_size, int threads) {
        cat_map_options o;
        o.family = {.a = a, .b = b};
        o.non_square = parse_non_square(non_square);
        o.tile_size = tile_size;
        call_progress progress;
        return map_image(image, threads, progress,
                         [&](const auto& in, auto& out, auto& exec) { return cat_map(in, out, steps, o, exec); });
      },
      py::arg("image"), py::arg("steps"), py::arg("a") = 1, py::arg("b") = 1, py::arg("non_square") = "reject",
      py::arg("tile_size") = 0, py::arg("threads") = 0,
      R"doc(Applies `steps` iterations of the cat map (paper 001, eq. 3; the family [1 a; b ab+1]) to a square
image and returns a new H x W x C array of the same dtype. Negative steps apply the inverse map, so
cat_map(cat_map(img, n), -n) equals img. non_square: 'reject' (default), 'centered_square' or
'square_tiles' (tiles of tile_size, 0 = gcd(W, H)). The cost does not depend on steps. Releases the
GIL; threads: 0 = all cores, identical output for every count.)doc");

  m.def(
      "life_perturbation",
      [](const py::array& image, int generations, int live_count, bool live_exact, int dead_count, int crowding_count,
         const std::string& live_test, float threshold, std::uint64_t seed, int threads, py::object progress_fn) {
        life_perturbation_options o =
            life_options(generations, live_count, live_exact, dead_count, crowding_count, live_test, threshold, seed);
        call_progress progress(std::move(progress_fn));
        o.progress = progress.sink();
        return map_image(image, threads, progress,
                         [&](const auto& in, auto& out, auto& exec) { return life_perturbation(in, out, o, exec); });
      },
      py::arg("image"), py::arg("generations") = 1, py::arg("live_count") = 3, py::arg("live_exact") = true,
      py::arg("dead_count") = 6, py::arg("crowding_count") = 0, py::arg("live_test") = "brighter_than_pixel",
      py::arg("threshold") = 0.5f, py::arg("seed") = 1, py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(The game-of-life luminance perturbation of paper 001 (section 1.2-1.3): each generation brightens a
pixel whose live neighbours number live_count (exactly, or at least when live_exact=False), darkens it
when at least dead_count are dead (or crowding_count are live), by random factors from `seed`.
live_test: 'brighter_than_pixel' or 'above_threshold' (with threshold in [0, 1]). Returns a new array
of the input's dtype and shape; hue and alpha are kept. Releases the GIL; progress(fraction) is called
once per generation and may return False to cancel.)doc");

  m.def(
      "fabric_presets", [] { return py::make_tuple("flannel", "twill", "linen", "tweed"); },
      "The names of the paper's fabric presets: ('flannel', 'twill', 'linen', 'tweed').");

  m.def(
      "make_fabric",
      [](const std::string& preset, std::int64_t width, std::int64_t height, std::int64_t tile_size, std::uint64_t seed,
         int threads, py::object progress_fn) {
        const fabric_preset p = value_or_raise(parse_fabric_preset(preset));
        check(validate_image_extent(width, height, 3, "make_fabric: output"));
        call_progress progress(std::move(progress_fn));
        const fabric_preset_options o{.tile_size = tile_size, .seed = seed, .progress = progress.sink()};
        auto out =
            progress.value_or_raise(with_executor(threads, [&](auto& exec) -> result<image_buffer<std::uint8_t, 3>> {
              auto made = image_buffer<std::uint8_t, 3>::create(width, height);
              if (!made) return made.error();
              if (auto s = make_fabric(p, *made, o, exec); !s) return s;
              return std::move(*made);
            }));
        return to_array(std::move(out));
      },
      py::arg("preset"), py::arg("width") = 256, py::arg("height") = 256, py::arg("tile_size") = 0, py::arg("seed") = 1,
      py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(A preset fabric of paper 001 ('flannel', 'twill', 'linen' or 'tweed', see fabric_presets()) as a
height x width x 3 uint8 array. The fabric is periodic with side tile_size (0 = max(width, height)) and
tiles the output without seams. Deterministic in (preset, size, tile_size, seed). Releases the GIL.)doc");

  m.def(
      "fabric_from_image",
      [](const py::array& source, std::int64_t width, std::int64_t height, std::int64_t iterations, std::int64_t a,
         std::int64_t b, int generations, std::uint64_t seed, std::int64_t tile_size, const std::string& fit,
         int threads, py::object progress_fn) {
        fabric_options o;
        o.iterations = iterations;
        o.family = {.a = a, .b = b};
        o.perturbation.generations = generations;
        o.perturbation.seed = seed;
        o.tile_size = tile_size;
        o.fit = parse_fit(fit);
        check(validate_image_extent(width, height, 3, "fabric_from_image: output"));
        call_progress progress(std::move(progress_fn));
        o.progress = progress.sink();
        return visit_image(
            source,
            [&](const auto& view) {
              using V = std::remove_cvref_t<decltype(view)>;
              using T = std::remove_const_t<typename V::value_type>;
              constexpr int C = V::channels;
              auto out = progress.value_or_raise(with_executor(threads, [&](auto& exec) -> result<image_buffer<T, C>> {
                auto made = image_buffer<T, C>::create(width, height);
                if (!made) return made.error();
                if (auto s = make_fabric(view, *made, o, exec); !s) return s;
                return std::move(*made);
              }));
              return to_array(std::move(out));
            },
            "source");
      },
      py::arg("source"), py::arg("width"), py::arg("height"), py::arg("iterations") = 60, py::arg("a") = 1,
      py::arg("b") = 1, py::arg("generations") = 0, py::arg("seed") = 1, py::arg("tile_size") = 0,
      py::arg("fit") = "reject", py::arg("threads") = 0, py::arg("progress") = py::none(),
      R"doc(A fabric from any source image (paper 001, section 1.3): the source's N x N square (fit: 'reject' =
it must already be N x N, 'centered_square', 'crop_or_repeat') mapped by `iterations` cat-map steps,
perturbed for `generations` game-of-life generations (seeded by `seed`), and tiled over a height x
width output of the source's dtype and channels. N = tile_size or max(width, height). Releases the GIL.)doc");
}

}  // namespace tessera::python
