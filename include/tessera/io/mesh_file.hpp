// tessera/io/mesh_file.hpp: triangle-mesh files by extension.
//   read_mesh(path)                      .obj, .off, .ply (any case)  -> result<tri_mesh>
//   write_mesh(path, mesh, {.binary})    same formats, from any Mesh
// See io/obj.hpp, io/off.hpp and io/ply.hpp for what each format reads and writes.
#pragma once

#include <string>
#include <string_view>

#include "../core/config.hpp"
#include "../core/mesh.hpp"
#include "../core/status.hpp"
#include "../core/tri_mesh.hpp"
#include "detail/file.hpp"
#include "obj.hpp"
#include "off.hpp"
#include "ply.hpp"

TESSERA_NAMESPACE_BEGIN

/// The mesh file formats read_mesh and write_mesh handle.
enum class mesh_format { obj, off, ply };

/// "obj", "off" or "ply".
constexpr std::string_view to_string(mesh_format f) noexcept {
  return f == mesh_format::obj ? "obj" : f == mesh_format::off ? "off" : "ply";
}

/// The mesh format of a path by its extension (case-insensitive). unsupported naming the path and
/// the extension otherwise.
inline result<mesh_format> mesh_format_of(std::string_view path) {
  const std::string ext = detail::file_extension(path);
  if (ext == "obj") return mesh_format::obj;
  if (ext == "off") return mesh_format::off;
  if (ext == "ply") return mesh_format::ply;
  return status::unsupported(detail::cat(path, ": unknown mesh file extension '", ext.empty() ? "(none)" : ext,
                                         "' (expected .obj, .off or .ply)"));
}

/// True when the path has a mesh extension this header reads.
inline bool is_mesh_path(std::string_view path) { return mesh_format_of(path).ok(); }

/// Options of write_mesh.
struct mesh_write_options {
  bool binary = false;  ///< PLY only: binary little-endian instead of ASCII
};

/// Reads an OBJ, OFF or PLY file chosen by extension. Errors: unsupported for other extensions,
/// io_error when the file cannot be read, parse_error naming the file and line or byte.
inline result<tri_mesh> read_mesh(const std::string& path) {
  auto fmt = mesh_format_of(path);
  if (!fmt) return fmt.error();
  switch (*fmt) {
    case mesh_format::obj: return read_obj(path);
    case mesh_format::off: return read_off(path);
    case mesh_format::ply: return read_ply(path);
  }
  return status::internal_error("read_mesh: unknown format");
}

/// Writes any Mesh as an OBJ, OFF or PLY file chosen by extension (uvs are written to OBJ and PLY;
/// OFF cannot hold them). Errors: unsupported for other extensions, the validate_mesh status for an
/// invalid mesh, io_error when the file cannot be written.
template <Mesh M>
status write_mesh(const std::string& path, const M& m, const mesh_write_options& opts = {}) {
  auto fmt = mesh_format_of(path);
  if (!fmt) return fmt.error();
  switch (*fmt) {
    case mesh_format::obj: return write_obj(path, m);
    case mesh_format::off: return write_off(path, m);
    case mesh_format::ply: return write_ply(path, m, {.binary = opts.binary});
  }
  return status::internal_error("write_mesh: unknown format");
}

TESSERA_NAMESPACE_END
