// tessera/io/mesh_preview.hpp: a shaded preview of a mesh (render/render_mesh_preview.hpp) written as
// a PNG. Needs PNG support: link tessera::io (stb).
#pragma once

#include <string>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/image.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../render/render_mesh_preview.hpp"
#include "png.hpp"

TESSERA_NAMESPACE_BEGIN

/// Renders a preview (render_mesh_preview) and writes it as a PNG. Errors: those of the renderer,
/// io_error when the file cannot be written.
template <Mesh M, Executor E = serial_executor>
status write_mesh_preview(const std::string& path, const M& mesh, const mesh_preview_options& o = {}, E&& exec = {}) {
  auto img = render_mesh_preview(mesh, o, exec);
  if (!img) return img.error();
  return write_png(path, *img);
}

/// Renders a textured preview (render_textured_mesh_preview) and writes it as a PNG. Errors: those of
/// the renderer, io_error when the file cannot be written.
template <Mesh M, Image I, Executor E = serial_executor>
status write_textured_mesh_preview(const std::string& path, const M& mesh, const I& texture,
                                   const mesh_preview_options& o = {}, E&& exec = {}) {
  auto img = render_textured_mesh_preview(mesh, texture, o, exec);
  if (!img) return img.error();
  return write_png(path, *img);
}

TESSERA_NAMESPACE_END
