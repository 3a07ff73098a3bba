// python/src/terrain.cpp: tessera's terrain family (paper 003), one frame at a time: make_terrain
// (a heightfield mesh as V, F arrays) and render_terrain_frame (project, scale field, triangle
// synthesis and rendering for one camera).
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <tessera/terrain/assign_scale_field.hpp>
#include <tessera/terrain/build_exemplar_pyramid.hpp>
#include <tessera/terrain/make_terrain.hpp>
#include <tessera/terrain/prepare_terrain_mesh.hpp>
#include <tessera/terrain/project_mesh.hpp>
#include <tessera/terrain/render_terrain_frame.hpp>
#include <tessera/terrain/synthesize_triangles.hpp>
#include <tessera/terrain/terrain_camera.hpp>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "common.hpp"
#include "mesh_arrays.hpp"

namespace tessera::python {
namespace {

terrain_shading parse_shading(const std::string& s) {
  if (s == "texture") return terrain_shading::texture;
  if (s == "scale_field") return terrain_shading::scale_field;
  if (s == "regions") return terrain_shading::regions;
  raise_invalid(cat("shading must be 'texture', 'scale_field' or 'regions', got '", s, "'"));
}

vec3 to_vec3(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

/// The exemplar as 8-bit RGB (any accepted dtype and channel count converts).
image_buffer<std::uint8_t, 3> rgb8_exemplar(const py::array& exemplar) {
  return visit_image(
      exemplar,
      [](const auto& view) {
        auto buf = value_or_raise(image_buffer<std::uint8_t, 3>::create(view.width(), view.height()));
        for (index_t y = 0; y < view.height(); ++y)
          for (index_t x = 0; x < view.width(); ++x)
            buf.write(x, y, convert_pixel<pixel<std::uint8_t, 3>>(view.read(x, y)));
        return buf;
      },
      "exemplar");
}

}  // namespace

void bind_terrain(py::module_& m) {
  m.def(
      "make_terrain",
      [](std::int64_t cells_x, std::int64_t cells_y, double size_x, double size_y, double height, double feature_size,
         int octaves, std::uint64_t seed, int threads) {
        const terrain_options o{.cells_x = cells_x,
                                .cells_y = cells_y,
                                .size_x = size_x,
                                .size_y = size_y,
                                .height = height,
                                .feature_size = feature_size,
                                .octaves = octaves,
                                .seed = seed};
        tri_mesh mesh = value_or_raise(with_executor(threads, [&](auto& exec) { return make_terrain(o, exec); }));
        return mesh_to_arrays(mesh);
      },
      py::arg("cells_x") = 128, py::arg("cells_y") = 128, py::arg("size_x") = 100.0, py::arg("size_y") = 100.0,
      py::arg("height") = 14.0, py::arg("feature_size") = 0.4, py::arg("octaves") = 6, py::arg("seed") = 1,
      py::arg("threads") = 0,
      R"doc(A fractal-noise heightfield (z up) of cells_x x cells_y grid cells covering size_x x size_y centred on 0,
as (V, F): float64 (n x 3) vertices and int64 (m x 3) triangles. A pure function of the arguments.
Raises InvalidArgument / SizeOverflow naming the argument (cells < 1, more than 2**28 vertices, ...).)doc");

  m.def(
      "render_terrain_frame",
      [](const py::array& vertices, const py::array& faces, const py::array& exemplar, std::int64_t width,
         std::int64_t height, std::optional<std::string> camera, std::array<double, 3> eye,
         std::array<double, 3> target, std::array<double, 3> up, double fov_y_degrees, double near, double far,
         double min_scale, std::uint64_t seed, const std::string& shading, double feather, std::array<double, 3> sun,
         double ambient, int threads, py::object progress_fn) {
        const tri_mesh source = mesh_from_arrays(vertices, faces, "terrain");
        const image_buffer<std::uint8_t, 3> ex = rgb8_exemplar(exemplar);
        const terrain_shading shade = parse_shading(shading);
        terrain_camera cam;
        if (camera) {
          const camera_preset p = value_or_raise(parse_camera_preset(*camera));
          aabb box;
          for (const vec3& v : source.positions) box.extend(v);
          cam = value_or_raise(make_camera_preset(p, box, width, height));
        } else {
          const look_at_camera la{.eye = to_vec3(eye),
                                  .target = to_vec3(target),
                                  .up = to_vec3(up),
                                  .fov_y_degrees = fov_y_degrees,
                                  .near = near,
                                  .far = far};
          cam = value_or_raise(make_camera(la, width, height));
        }
        call_progress progress(std::move(progress_fn));
        struct frame_result {
          image_buffer<std::uint8_t, 3> image;
          scale_field field;
          index_t visible = 0;
        };
        frame_result r = progress.value_or_raise(with_executor(threads, [&](auto& exec) -> result<frame_result> {
          auto prepared = prepare_terrain_mesh(source, "terrain");
          if (!prepared) return prepared.error();
          auto pyramid = build_exemplar_pyramid(ex, {.min_scale = min_scale}, exec);
          if (!pyramid) return pyramid.error();
          if (!progress.report(0.2)) return status::cancelled();
          screen_projection proj;
          frame_result out;
          if (auto s = project_mesh(*prepared, cam, proj, {}, exec); !s) return s;
          if (auto s = assign_scale_field(
                  *prepared, proj, {.min_scale = min_scale, .max_levels = pyramid->num_levels()}, out.field, exec);
              !s)
            return s;
          if (!progress.report(0.4)) return status::cancelled();
          triangle_synthesis syn;
          triangle_synthesis_options so;
          so.seed = seed;
          if (auto s = synthesize_triangles(*prepared, proj, out.field, ex.width(), ex.height(), so, syn, exec); !s)
            return s;
          if (!progress.report(0.8)) return status::cancelled();
          auto img = image_buffer<std::uint8_t, 3>::create(width, height);
          if (!img) return img.error();
          out.image = std::move(*img);
          render_terrain_options ro;
          ro.shading = shade;
          ro.feather = feather;
          ro.sun = sun;
          ro.ambient = ambient;
          if (auto s = render_terrain_frame(*prepared, proj, out.field, syn, *pyramid, out.image, ro, exec); !s)
            return s;
          out.visible = proj.num_visible();
          progress.report(1.0);
          return out;
        }));
        py::dict info;
        info["image"] = to_array(std::move(r.image));
        info["level"] = py::array_t<std::int32_t>(static_cast<py::ssize_t>(r.field.level.size()), r.field.level.data());
        info["scale"] = py::array_t<float>(static_cast<py::ssize_t>(r.field.scale.size()), r.field.scale.data());
        info["distance"] =
            py::array_t<double>(static_cast<py::ssize_t>(r.field.distance.size()), r.field.distance.data());
        info["levels"] = r.field.levels;
        info["visible_faces"] = r.visible;
        return info;
      },
      py::arg("vertices"), py::arg("faces"), py::arg("exemplar"), py::arg("width") = 640, py::arg("height") = 360,
      py::arg("camera") = py::none(), py::arg("eye") = std::array<double, 3>{0, -60, 20},
      py::arg("target") = std::array<double, 3>{0, 0, 0}, py::arg("up") = std::array<double, 3>{0, 0, 1},
      py::arg("fov_y_degrees") = 60.0, py::arg("near") = 0.01, py::arg("far") = 1000.0, py::arg("min_scale") = 0.5,
      py::arg("seed") = 1, py::arg("shading") = "texture", py::arg("feather") = 3.0,
      py::arg("sun") = std::array<double, 3>{0, 0, 0}, py::arg("ambient") = 0.35, py::arg("threads") = 0,
      py::arg("progress") = py::none(),
      R"doc(One synthesized frame of a terrain mesh (paper 003) seen by a camera: the mesh (V float64 n x 3, F
int32/int64 m x 3) is projected, every visible triangle gets a scale by its view distance (the scale
field), triangles are synthesized from the exemplar (any dtype, converted to 8-bit RGB) and rendered.
camera: a preset name ('grazing', 'oblique', 'overview', fitted to the mesh bounds) or None to use
eye / target / up / fov_y_degrees / near / far. shading: 'texture', 'scale_field' or 'regions'.
Returns a dict: image (height x width x 3 uint8), level (int32 per face, -1 culled), scale (float32
per face), distance (float64 per face, NaN culled), levels, visible_faces. Deterministic in the
inputs and seed for any thread count. Releases the GIL; progress(fraction) may cancel.)doc");
}

}  // namespace tessera::python
