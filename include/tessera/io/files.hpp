// tessera/io/files.hpp: whole-file reads and writes whose errors name the file, and the lower-case
// extension of a path: what every reader and writer of tessera::io uses, public for tools built on it
// (the tessera command line among them).
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "../core/config.hpp"
#include "../core/status.hpp"

TESSERA_NAMESPACE_BEGIN

/// Reads a whole file into memory. io_error naming the file when it cannot be opened or read.
inline result<std::string> read_file(const std::string& path) {
  errno = 0;
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr)
    return status::io_error(
        cat(path, ": cannot open file (", errno != 0 ? std::strerror(errno) : "unknown error", ")"));
  std::string data;
  char buf[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(buf, 1, sizeof buf, f);
    data.append(buf, n);
    if (n < sizeof buf) break;
  }
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return status::io_error(cat(path, ": read error (is it a directory?)"));
  return data;
}

/// Writes `data` to a file, replacing it. io_error naming the file on failure.
inline status write_file(const std::string& path, std::string_view data) {
  errno = 0;
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr)
    return status::io_error(
        cat(path, ": cannot open for writing (", errno != 0 ? std::strerror(errno) : "unknown error", ")"));
  // an empty view may hold a null pointer, which fwrite must not receive even for 0 bytes
  const bool ok = data.empty() || std::fwrite(data.data(), 1, data.size(), f) == data.size();
  if (std::fclose(f) != 0 || !ok) return status::io_error(cat(path, ": write failed (disk full?)"));
  return {};
}

/// Lower-case file extension without the dot ("Mesh.OBJ" -> "obj"; "" when there is none).
inline std::string file_extension(std::string_view path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return {};
  std::string ext(path.substr(dot + 1));
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return ext;
}

TESSERA_NAMESPACE_END
