// tessera/io/detail/ply_format.hpp: the PLY header (format, elements, typed properties) and the two
// value sources the reader pulls from: ASCII tokens (reporting lines) and binary little/big-endian
// scalars (reporting byte offsets). Internal: no stability promise.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "file.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

enum class ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
enum class ply_encoding { ascii, binary_little_endian, binary_big_endian };

inline int ply_type_size(ply_type t) noexcept {
  static constexpr int sizes[8] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[static_cast<int>(t)];
}
inline bool ply_type_from_name(std::string_view n, ply_type& t) noexcept {
  struct entry {
    std::string_view a, b;
    ply_type t;
  };
  static constexpr entry table[8] = {{"char", "int8", ply_type::int8},        {"uchar", "uint8", ply_type::uint8},
                                     {"short", "int16", ply_type::int16},     {"ushort", "uint16", ply_type::uint16},
                                     {"int", "int32", ply_type::int32},       {"uint", "uint32", ply_type::uint32},
                                     {"float", "float32", ply_type::float32}, {"double", "float64", ply_type::float64}};
  for (const entry& e : table)
    if (n == e.a || n == e.b) {
      t = e.t;
      return true;
    }
  return false;
}
inline bool ply_is_integer(ply_type t) noexcept { return t != ply_type::float32 && t != ply_type::float64; }

struct ply_property {
  std::string name;
  bool is_list = false;
  ply_type count_type = ply_type::uint8;  ///< lists only
  ply_type value_type = ply_type::float32;
};
struct ply_element {
  std::string name;
  index_t count = 0;
  index_t header_line = 0;
  std::vector<ply_property> properties;
  [[nodiscard]] int find(std::string_view n) const noexcept {
    for (std::size_t i = 0; i < properties.size(); ++i)
      if (properties[i].name == n) return static_cast<int>(i);
    return -1;
  }
};
struct ply_header {
  ply_encoding encoding = ply_encoding::ascii;
  std::vector<ply_element> elements;
  std::size_t data_offset = 0;  ///< first byte after end_header's line ending
  index_t data_line = 1;        ///< line number of the first data line (ASCII)
};

/// Parses the header of a PLY file held in `data`. Errors: parse_error "NAME, line N: ...".
inline result<ply_header> parse_ply_header(std::string_view data, std::string_view name) {
  line_scanner lines(data);
  std::string_view line;
  if (!lines.next(line) || line != "ply")
    return parse_error_at_line(name, 1, "not a PLY file (the first line must be 'ply')");
  ply_header h;
  bool have_format = false;
  while (true) {
    if (!lines.next(line)) return parse_error_at_line(name, lines.line_number(), "truncated header: no end_header");
    const index_t n = lines.line_number();
    if (has_binary_bytes(line)) return parse_error_at_line(name, n, "binary data inside the header");
    std::string_view rest = line;
    const std::string_view key = next_token(rest);
    if (key == "end_header") break;
    if (key.empty() || key == "comment" || key == "obj_info") continue;
    if (key == "format") {
      const auto enc = next_token(rest), version = next_token(rest);
      if (have_format) return parse_error_at_line(name, n, "a second format line");
      if (enc == "ascii")
        h.encoding = ply_encoding::ascii;
      else if (enc == "binary_little_endian")
        h.encoding = ply_encoding::binary_little_endian;
      else if (enc == "binary_big_endian")
        h.encoding = ply_encoding::binary_big_endian;
      else
        return parse_error_at_line(name, n, cat("unknown format '", enc, "'"));
      if (version != "1.0") return parse_error_at_line(name, n, cat("unsupported PLY version '", version, "'"));
      have_format = true;
    } else if (key == "element") {
      ply_element e;
      e.name = std::string(next_token(rest));
      const auto count = next_token(rest);
      long long c = -1;
      if (e.name.empty() || !parse_int(count, c) || c < 0)
        return parse_error_at_line(name, n, "expected 'element NAME COUNT' with a non-negative count");
      e.count = static_cast<index_t>(c);
      e.header_line = n;
      // one vertex and one face element: the reader's indices and per-face uvs refer to them
      if (e.name == "vertex" || e.name == "face")
        for (const ply_element& earlier : h.elements)
          if (earlier.name == e.name)
            return parse_error_at_line(
                name, n, cat("a second '", e.name, "' element (the first is on line ", earlier.header_line, ")"));
      h.elements.push_back(std::move(e));
    } else if (key == "property") {
      if (h.elements.empty()) return parse_error_at_line(name, n, "a property before any element");
      ply_property p;
      auto type = next_token(rest);
      if (type == "list") {
        p.is_list = true;
        const auto ct = next_token(rest);
        if (!ply_type_from_name(ct, p.count_type) || !ply_is_integer(p.count_type))
          return parse_error_at_line(name, n, cat("invalid list count type '", ct, "'"));
        type = next_token(rest);
      }
      if (!ply_type_from_name(type, p.value_type))
        return parse_error_at_line(name, n, cat("unknown type '", type, "'"));
      p.name = std::string(next_token(rest));
      if (p.name.empty()) return parse_error_at_line(name, n, "a property without a name");
      h.elements.back().properties.push_back(std::move(p));
    } else {
      return parse_error_at_line(name, n, cat("unknown header keyword '", key, "'"));
    }
  }
  if (!have_format) return parse_error_at_line(name, lines.line_number(), "the header has no format line");
  h.data_offset = lines.offset();
  h.data_line = lines.line_number() + 1;
  return h;
}

/// ASCII data: whitespace-separated tokens over any number of lines.
class ply_ascii_source {
 public:
  ply_ascii_source(std::string_view data, index_t first_line, std::string_view name)
      : lines_(data), first_line_(first_line), name_(name) {}
  /// Reads one value of type t. False at the end of the data or on a malformed token (see error()).
  bool read(ply_type t, double& out) {
    std::string_view tok = next_token(rest_);
    while (tok.empty()) {
      std::string_view line;
      if (!lines_.next(line)) {
        error_ = "truncated: the data ends early";
        return false;
      }
      if (has_binary_bytes(line)) {
        error_ = "binary data in an ASCII PLY file";
        return false;
      }
      rest_ = line;
      tok = next_token(rest_);
    }
    if (ply_is_integer(t)) {
      long long v = 0;
      if (!parse_int(tok, v)) return fail(tok, "an integer");
      out = static_cast<double>(v);
    } else if (!parse_double(tok, out)) {
      return fail(tok, "a finite number");
    }
    return true;
  }
  [[nodiscard]] status error_status(std::string_view context) const { return error_here(cat(context, ": ", error_)); }
  /// A parse_error at the line of the last value read.
  [[nodiscard]] status error_here(std::string_view message) const {
    return parse_error_at_line(name_, first_line_ + std::max<index_t>(lines_.line_number(), 1) - 1, message);
  }
  [[nodiscard]] std::size_t remaining() const noexcept { return lines_.remaining() + rest_.size(); }
  /// Smallest number of bytes one value occupies ("0" and a separator).
  static constexpr std::size_t min_value_bytes(ply_type) noexcept { return 2; }

 private:
  bool fail(std::string_view tok, std::string_view expected) {
    error_ = cat("'", tok, "' is not ", expected);
    return false;
  }
  line_scanner lines_;
  std::string_view rest_;
  index_t first_line_;
  std::string_view name_;
  std::string error_;
};

/// Binary data: packed scalars in little- or big-endian order.
class ply_binary_source {
 public:
  ply_binary_source(std::string_view data, std::size_t offset, bool big_endian, std::string_view name)
      : data_(data), pos_(offset), big_(big_endian), name_(name) {}
  bool read(ply_type t, double& out) {
    const auto n = to_size(ply_type_size(t));
    if (data_.size() - pos_ < n) {
      error_ = cat("truncated: the file ends inside a value (", data_.size() - pos_, " bytes left)");
      return false;
    }
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    if (big_ != (std::endian::native == std::endian::big))
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
      case ply_type::int8: out = static_cast<std::int8_t>(b[0]); break;
      case ply_type::uint8: out = b[0]; break;
      case ply_type::int16: out = load<std::int16_t>(b); break;
      case ply_type::uint16: out = load<std::uint16_t>(b); break;
      case ply_type::int32: out = load<std::int32_t>(b); break;
      case ply_type::uint32: out = load<std::uint32_t>(b); break;
      case ply_type::float32: out = load<float>(b); break;
      case ply_type::float64: out = load<double>(b); break;
    }
    value_start_ = pos_;
    pos_ += n;
    if (!ply_is_integer(t) && !std::isfinite(out)) {
      error_ = "a value is not a finite number";
      return false;
    }
    return true;
  }
  [[nodiscard]] status error_status(std::string_view context) const {
    return parse_error_at_byte(name_, error_.rfind("truncated", 0) == 0 ? pos_ : value_start_,
                               cat(context, ": ", error_));
  }
  /// A parse_error at the offset of the last value read.
  [[nodiscard]] status error_here(std::string_view message) const {
    return parse_error_at_byte(name_, value_start_, message);
  }
  /// A parse_error at the offset of the next value.
  [[nodiscard]] status error_ahead(std::string_view message) const { return parse_error_at_byte(name_, pos_, message); }
  [[nodiscard]] std::size_t remaining() const noexcept { return data_.size() - pos_; }
  static std::size_t min_value_bytes(ply_type t) noexcept { return to_size(ply_type_size(t)); }

 private:
  template <class T>
  static T load(const unsigned char* b) noexcept {
    T v;
    std::memcpy(&v, b, sizeof v);
    return v;
  }
  std::string_view data_;
  std::size_t pos_;
  std::size_t value_start_ = 0;
  bool big_;
  std::string_view name_;
  std::string error_;
};

}  // namespace detail
TESSERA_NAMESPACE_END
