// tessera/io/detail/file.hpp: what the file readers and writers share: whole-file reads and writes
// with statuses that name the file, a line scanner that counts lines (LF, CRLF or CR endings), token
// splitting and exact number parsing / shortest round-trip formatting (std::from_chars/to_chars).
// Internal: no stability promise.
#pragma once

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

#include "../../core/config.hpp"
#include "../../core/status.hpp"
#include "../files.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

using tessera::file_extension;  // public in io/files.hpp; the readers' own spelling stays
using tessera::read_file;
using tessera::write_file;

/// Splits text into lines, numbering them from 1. Accepts LF, CRLF and lone CR endings.
class line_scanner {
 public:
  explicit line_scanner(std::string_view text) noexcept : text_(text) {}
  /// The next line without its ending; false at the end of the text.
  bool next(std::string_view& line) noexcept {
    if (pos_ >= text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
    line = text_.substr(start, pos_ - start);
    if (pos_ < text_.size()) {
      if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
      ++pos_;
    }
    ++line_;
    return true;
  }
  /// Number of the line last returned by next() (1-based).
  [[nodiscard]] index_t line_number() const noexcept { return line_; }
  /// Offset of the first byte not yet scanned.
  [[nodiscard]] std::size_t offset() const noexcept { return pos_; }
  /// Bytes not yet scanned.
  [[nodiscard]] std::size_t remaining() const noexcept { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  index_t line_ = 0;
};

inline constexpr bool is_space(char c) noexcept { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

/// Removes and returns the next whitespace-separated token of `s` (empty when none is left).
inline std::string_view next_token(std::string_view& s) noexcept {
  std::size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  std::size_t j = i;
  while (j < s.size() && !is_space(s[j])) ++j;
  const std::string_view tok = s.substr(i, j - i);
  s.remove_prefix(j);
  return tok;
}

/// Cuts a '#' comment off a line.
inline std::string_view strip_comment(std::string_view line) noexcept {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// True when the line holds bytes no text mesh format contains (NUL and other control characters):
/// a binary file given to a text reader.
inline bool has_binary_bytes(std::string_view line) noexcept {
  for (char c : line) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 && !is_space(c)) return true;
  }
  return false;
}

/// Parses a whole token as a finite double (a leading '+' is accepted). False for anything else,
/// including nan, inf and values that overflow a double.
inline bool parse_double(std::string_view tok, double& out) noexcept {
  if (!tok.empty() && tok[0] == '+') {
    tok.remove_prefix(1);
    if (!tok.empty() && (tok[0] == '+' || tok[0] == '-')) return false;
  }
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), out);
  return r.ec == std::errc{} && r.ptr == tok.data() + tok.size() && std::isfinite(out);
}

/// Parses a whole token as a decimal integer (a leading '+' is accepted).
template <class Int>
bool parse_int(std::string_view tok, Int& out) noexcept {
  if (!tok.empty() && tok[0] == '+') {
    tok.remove_prefix(1);
    if (!tok.empty() && (tok[0] == '+' || tok[0] == '-')) return false;
  }
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), out);
  return r.ec == std::errc{} && r.ptr == tok.data() + tok.size();
}

/// Appends the shortest decimal form that reads back as exactly `v`.
inline void append_number(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}
inline void append_number(std::string& out, float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}
template <class Int>
requires std::is_integral_v<Int>
void append_number(std::string& out, Int v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

/// Capacity to reserve for `claimed` elements a file header announces: never more than the
/// `remaining` bytes can hold at `least_bytes` each, and at most 2^20 up front (a vector grows past
/// that as elements are actually read), so a header cannot make a reader allocate before reading.
inline std::size_t bounded_reserve(long long claimed, std::size_t remaining, std::size_t least_bytes) noexcept {
  if (claimed <= 0) return 0;
  std::size_t n = to_size(claimed);
  if (least_bytes > 0) n = std::min(n, remaining / least_bytes + 1);
  return std::min<std::size_t>(n, std::size_t{1} << 20);
}

/// "PATH, line N: message" as a parse_error.
inline status parse_error_at_line(std::string_view path, index_t line, std::string_view message) {
  return status::parse_error(cat(path, ", line ", line, ": ", message));
}
/// "PATH, byte N: message" as a parse_error.
inline status parse_error_at_byte(std::string_view path, std::size_t offset, std::string_view message) {
  return status::parse_error(cat(path, ", byte ", offset, ": ", message));
}

}  // namespace detail
TESSERA_NAMESPACE_END
