// tessera/io/patch_model_file.hpp: patch models (image/patch_model.hpp) as bytes and files, so a model
// is built once and shipped (to a render farm's workers, a Python pickle, a cache on disk).
//   encode_patch_model(model, options)       the bytes of a model
//   patch_model_file_format(data, size)      its pixel format, to dispatch on before decoding
//   decode_patch_model<T, C>(data, size)     the model back, bit-identical in what it synthesizes
//   save_patch_model / load_patch_model      the same on files
//
// Format version 1 (little-endian): the magic "TSPMODEL", u32 format version, u8 channel type
// (0 uint8, 1 uint16, 2 float32), u8 channels, u16 zero; the options the model was built with (its
// resolved patch_width, patch_height and overlap; candidates, exact_sets, seams, pca_dims, pca_samples,
// search_pool, refine_iterations); the exemplar's width, height and pixels; an FNV-1a 64 checksum of
// everything before it. Version 1 stores the exemplar and the resolved options, not the compatible
// sets: decoding rebuilds the sets with build_patch_model, which is deterministic, so the decoded model
// synthesizes exactly what the encoded one did (with the size analysis skipped: analysis() is empty).
// Decoding checks every field (magic, version, format, sizes against the byte count, option ranges,
// finite float pixels, checksum) before allocating, and returns a parse_error or unsupported status
// naming what is wrong; a file from another format version is `unsupported`, naming both versions.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "../core/config.hpp"
#include "../core/executor.hpp"
#include "../core/format.hpp"
#include "../core/image_buffer.hpp"
#include "../core/status.hpp"
#include "../image/patch_model.hpp"
#include "files.hpp"

TESSERA_NAMESPACE_BEGIN

/// The format version encode_patch_model writes and decode_patch_model reads.
inline constexpr std::uint32_t patch_model_file_version = 1;

/// A decoded model and the options it was built with (patch sizes resolved; progress empty).
template <Channel T, int C>
struct patch_model_file {
  patch_model<T, C> model;      ///< the model, rebuilt from the stored exemplar and options
  patch_model_options options;  ///< the options it was built with, patch sizes resolved
};

namespace detail {
inline constexpr char patch_model_magic[8] = {'T', 'S', 'P', 'M', 'O', 'D', 'E', 'L'};
inline constexpr std::size_t patch_model_header_bytes = 8 + 4 + 4;
inline constexpr std::size_t patch_model_options_bytes = 8 * 3 + 4 + 1 + 1 + 4 + 8 + 4 + 4 + 8 * 2;

inline std::uint64_t fnv1a64(const unsigned char* data, std::size_t size) noexcept {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 0x100000001b3ull;
  return h;
}

struct le_writer {
  std::vector<unsigned char>& out;
  void u(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
  }
};

struct le_reader {
  const unsigned char* data;
  std::size_t size;
  std::size_t pos = 0;
  std::uint64_t u(int bytes) {  // callers check the size first
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t{data[pos + to_size(i)]} << (8 * i);
    pos += to_size(bytes);
    return v;
  }
  std::int64_t i64() { return static_cast<std::int64_t>(u(8)); }
  std::int32_t i32() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(u(4))); }
};

template <Channel T>
void put_channel(le_writer& w, T v) {
  if constexpr (std::is_same_v<T, float>) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    w.u(bits, 4);
  } else {
    w.u(v, static_cast<int>(sizeof(T)));
  }
}
template <Channel T>
T get_channel(le_reader& r) {
  if constexpr (std::is_same_v<T, float>) {
    const auto bits = static_cast<std::uint32_t>(r.u(4));
    float v = 0;
    std::memcpy(&v, &bits, 4);
    return v;
  } else {
    return static_cast<T>(r.u(static_cast<int>(sizeof(T))));
  }
}

/// The header's pixel format after checking magic, version and size.
inline result<pixel_format> read_patch_model_header(const unsigned char* data, std::size_t size,
                                                    std::string_view name) {
  if (data == nullptr || size < patch_model_header_bytes)
    return status::parse_error(cat(name, ": ", size, " bytes is too short for a tessera patch model (header of ",
                                   patch_model_header_bytes, " bytes)"));
  if (std::memcmp(data, patch_model_magic, 8) != 0)
    return status::parse_error(cat(name, ": not a tessera patch model (the magic \"TSPMODEL\" is missing)"));
  le_reader r{data, size, 8};
  const auto version = static_cast<std::uint32_t>(r.u(4));
  if (version != patch_model_file_version)
    return status::unsupported(cat(name, ": patch model format version ", version,
                                   "; this build of tessera reads version ", patch_model_file_version));
  const auto type = r.u(1), channels = r.u(1), reserved = r.u(2);
  if (type > 2) return status::parse_error(cat(name, ": unknown channel type ", type, " at byte 12"));
  if (channels < 1 || channels > 4)
    return status::parse_error(cat(name, ": channel count ", channels, " at byte 13 is not in 1-4"));
  if (reserved != 0) return status::parse_error(cat(name, ": reserved bytes 14-15 are not zero"));
  return pixel_format{type == 0   ? channel_type::uint8
                      : type == 1 ? channel_type::uint16
                                  : channel_type::float32,
                      static_cast<int>(channels)};
}
}  // namespace detail

/// The bytes of `model`, built with `options` (their size fields may be 0: the model's resolved sizes
/// are stored). Errors: invalid_argument for an empty (default-constructed) model. O(exemplar pixels).
template <Channel T, int C>
result<std::vector<unsigned char>> encode_patch_model(const patch_model<T, C>& model,
                                                      const patch_model_options& options) {
  const image_buffer<T, C>& ex = model.exemplar();
  if (ex.empty() || model.patch_width() <= 0)
    return status::invalid_argument("encode_patch_model: the model is empty (not built)");
  std::vector<unsigned char> out(detail::patch_model_magic, detail::patch_model_magic + 8);
  out.reserve(ex.size_bytes() + 128);
  detail::le_writer w{out};
  w.u(patch_model_file_version, 4);
  w.u(channel_type_of<T> == channel_type::uint8 ? 0 : channel_type_of<T> == channel_type::uint16 ? 1 : 2, 1);
  w.u(C, 1);
  w.u(0, 2);
  w.u(static_cast<std::uint64_t>(model.patch_width()), 8);
  w.u(static_cast<std::uint64_t>(model.patch_height()), 8);
  w.u(static_cast<std::uint64_t>(model.overlap()), 8);
  w.u(static_cast<std::uint32_t>(options.candidates), 4);
  w.u(options.exact_sets ? 1 : 0, 1);
  w.u(model.has_seams() ? 1 : 0, 1);
  w.u(static_cast<std::uint32_t>(options.pca_dims), 4);
  w.u(static_cast<std::uint64_t>(options.pca_samples), 8);
  w.u(static_cast<std::uint32_t>(options.search_pool), 4);
  w.u(static_cast<std::uint32_t>(options.refine_iterations), 4);
  w.u(static_cast<std::uint64_t>(ex.width()), 8);
  w.u(static_cast<std::uint64_t>(ex.height()), 8);
  const T* p = ex.data();
  const auto n = detail::to_size(ex.width() * ex.height() * C);
  for (std::size_t i = 0; i < n; ++i) detail::put_channel<T>(w, p[i]);
  w.u(detail::fnv1a64(out.data(), out.size()), 8);
  return out;
}

/// The pixel format of encoded model bytes (to pick decode_patch_model's T and C). Checks the magic,
/// the version (unsupported for another one) and the format fields; parse_error otherwise.
inline result<pixel_format> patch_model_file_format(const unsigned char* data, std::size_t size,
                                                    std::string_view name = "patch model") {
  return detail::read_patch_model_header(data, size, name);
}

/// Decodes a model of pixel type (T, C) and rebuilds its compatible sets on `exec`. Errors:
/// parse_error naming the field for malformed, truncated or corrupted bytes (and a format other than
/// (T, C)); unsupported for another format version; the errors of build_patch_model for stored
/// options it refuses. O(bytes) checks, then a model build.
template <Channel T, int C, Executor E = serial_executor>
result<patch_model_file<T, C>> decode_patch_model(const unsigned char* data, std::size_t size, E&& exec = {},
                                                  std::string_view name = "patch model") {
  auto fmt = detail::read_patch_model_header(data, size, name);
  if (!fmt) return fmt.error();
  if (fmt->type != channel_type_of<T> || fmt->channels != C)
    return status::parse_error(cat(name, ": holds ", to_string(fmt->type), " x ", fmt->channels, " pixels, decoded as ",
                                   to_string(channel_type_of<T>), " x ", C));
  constexpr std::size_t fixed = detail::patch_model_header_bytes + detail::patch_model_options_bytes + 8;
  if (size < fixed)
    return status::parse_error(cat(name, ": truncated (", size, " bytes, at least ", fixed, " expected)"));
  if (detail::fnv1a64(data, size - 8) != detail::le_reader{data, size, size - 8}.u(8))
    return status::parse_error(cat(name, ": checksum mismatch (the bytes are corrupted or truncated)"));
  detail::le_reader r{data, size, detail::patch_model_header_bytes};
  patch_model_options o;
  o.patch_width = r.i64();
  o.patch_height = r.i64();
  o.overlap = r.i64();
  o.candidates = r.i32();
  const auto exact = r.u(1), seams = r.u(1);
  o.pca_dims = r.i32();
  o.pca_samples = r.i64();
  o.search_pool = r.i32();
  o.refine_iterations = r.i32();
  const index_t w = r.i64(), h = r.i64();
  if (exact > 1 || seams > 1) return status::parse_error(cat(name, ": exact_sets and seams must be 0 or 1"));
  o.exact_sets = exact == 1;
  o.seams = seams == 1;
  if (o.patch_width < 2 || o.patch_height < 2 || o.overlap < 1)
    return status::parse_error(
        cat(name, ": patch ", o.patch_width, " x ", o.patch_height, " with overlap ", o.overlap, " is invalid"));
  if (o.search_pool > 65536 || o.pca_samples > (index_t{1} << 32))
    return status::parse_error(
        cat(name, ": search_pool ", o.search_pool, " or pca_samples ", o.pca_samples, " is beyond any model's"));
  if (w < 1 || h < 1 || w > max_image_elements / C || h > max_image_elements / (w * C))
    return status::parse_error(cat(name, ": exemplar size ", w, " x ", h, " is invalid"));
  const std::size_t pixels_bytes = detail::to_size(w * h * C) * sizeof(T);
  if (size - fixed != pixels_bytes)
    return status::parse_error(
        cat(name, ": ", size, " bytes, but a ", w, " x ", h, " x ", C, " exemplar needs ", fixed + pixels_bytes));
  auto ex = image_buffer<T, C>::create(w, h);
  if (!ex) return ex.error();
  T* p = ex->data();
  for (std::size_t i = 0, n = detail::to_size(w * h * C); i < n; ++i) p[i] = detail::get_channel<T>(r);
  if (auto s = validate_finite_pixels(*ex, cat(name, ": exemplar")); !s) return status::parse_error(s.message());
  auto model = build_patch_model(*ex, o, exec);
  if (!model) return status(model.error().code(), cat(name, ": ", model.error().message()));
  return patch_model_file<T, C>{std::move(*model), o};
}

/// Writes encode_patch_model's bytes to `path`. io_error naming the file when it cannot be written.
template <Channel T, int C>
status save_patch_model(const std::string& path, const patch_model<T, C>& model, const patch_model_options& options) {
  auto bytes = encode_patch_model(model, options);
  if (!bytes) return bytes.error();
  return write_file(path, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

/// Reads a model of pixel type (T, C) from `path` (see decode_patch_model; messages name the file).
template <Channel T, int C, Executor E = serial_executor>
result<patch_model_file<T, C>> load_patch_model(const std::string& path, E&& exec = {}) {
  auto bytes = read_file(path);
  if (!bytes) return bytes.error();
  return decode_patch_model<T, C>(reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size(), exec, path);
}

TESSERA_NAMESPACE_END
