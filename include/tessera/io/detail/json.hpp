// tessera/io/detail/json.hpp: a small, tolerant JSON reader and writer for tessera's manifests
// (io/tile_manifest.hpp). Internal; no stability promise.
//
// Reads standard JSON and also tolerates what hand-edited files contain: trailing commas, // and
// /* */ comments, and a UTF-8 byte-order mark. A member name repeated in one object is an error.
// Errors report line and column. Numbers are doubles;
// strings support the standard escapes (\uXXXX is encoded as UTF-8, surrogate pairs included).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../../core/config.hpp"
#include "../../core/status.hpp"

TESSERA_NAMESPACE_BEGIN
namespace detail {

struct json_member;

/// A JSON value: null, bool, number, string, array or object (members keep file order).
struct json_value {
  enum class kind { null, boolean, number, string, array, object };
  kind type = kind::null;
  bool boolean = false;
  double number = 0;
  std::string string;
  std::vector<json_value> array;
  std::vector<json_member> object;  // json_member, not std::pair: a pair may not hold an incomplete type

  [[nodiscard]] bool is_number() const noexcept { return type == kind::number; }
  [[nodiscard]] bool is_string() const noexcept { return type == kind::string; }
  [[nodiscard]] bool is_array() const noexcept { return type == kind::array; }
  [[nodiscard]] bool is_object() const noexcept { return type == kind::object; }
  /// The member named `key` of an object, or nullptr.
  [[nodiscard]] const json_value* find(std::string_view key) const noexcept;
  static json_value make_number(double v);
  static json_value make_string(std::string v);
};

/// One member of a JSON object. Like std::pair, it destructures as `auto& [key, value]`.
struct json_member {
  std::string first;
  json_value second;
};

inline const json_value* json_value::find(std::string_view key) const noexcept {
  for (const auto& member : object)
    if (member.first == key) return &member.second;
  return nullptr;
}
inline json_value json_value::make_number(double v) {
  json_value j;
  j.type = kind::number;
  j.number = v;
  return j;
}
inline json_value json_value::make_string(std::string v) {
  json_value j;
  j.type = kind::string;
  j.string = std::move(v);
  return j;
}

class json_parser {
 public:
  json_parser(std::string_view text, std::string_view name) : text_(text), name_(name) {}

  result<json_value> parse() {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
    json_value v;
    if (auto s = value(v, 0); !s) return s;
    skip();
    if (pos_ != text_.size()) return fail("unexpected text after the JSON value");
    return v;
  }

 private:
  static constexpr int max_depth = 64;

  status fail(std::string_view what) const {
    int line = 1, col = 1;
    for (std::size_t i = 0; i < pos_ && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        col = 1;
      } else
        ++col;
    }
    return status::parse_error(cat(name_, ":", line, ":", col, ": ", what));
  }
  void skip() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        ++pos_;
      } else if (text_.substr(pos_, 2) == "//") {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (text_.substr(pos_, 2) == "/*") {
        const std::size_t end = text_.find("*/", pos_ + 2);
        pos_ = end == std::string_view::npos ? text_.size() : end + 2;
      } else {
        break;
      }
    }
  }
  bool literal(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }
  status value(json_value& out, int depth) {
    if (depth > max_depth) return fail("nesting deeper than 64 levels");
    skip();
    if (pos_ >= text_.size()) return fail("unexpected end of file, expected a value");
    const char c = text_[pos_];
    if (c == '{') return object(out, depth);
    if (c == '[') return array(out, depth);
    if (c == '"') {
      out.type = json_value::kind::string;
      return string(out.string);
    }
    if (literal("true")) {
      out.type = json_value::kind::boolean;
      out.boolean = true;
      return {};
    }
    if (literal("false")) {
      out.type = json_value::kind::boolean;
      out.boolean = false;
      return {};
    }
    if (literal("null")) {
      out.type = json_value::kind::null;
      return {};
    }
    return number(out);
  }
  status number(json_value& out) {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && (std::string_view("+-.eE0123456789").find(text_[pos_]) != std::string_view::npos))
      ++pos_;
    if (pos_ == start) return fail(cat("unexpected character '", text_[pos_], "'"));
    const std::string token(text_.substr(start, pos_ - start));
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || !std::isfinite(v)) {
      pos_ = start;
      return fail(cat("malformed number '", token, "'"));
    }
    out.type = json_value::kind::number;
    out.number = v;
    return {};
  }
  static void put_utf8(std::string& s, std::uint32_t cp) {
    if (cp < 0x80) {
      s += static_cast<char>(cp);
    } else if (cp < 0x800) {
      s += static_cast<char>(0xC0 | (cp >> 6));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      s += static_cast<char>(0xE0 | (cp >> 12));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      s += static_cast<char>(0xF0 | (cp >> 18));
      s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }
  bool hex4(std::uint32_t& cp) {
    if (pos_ + 4 > text_.size()) return false;
    cp = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = text_[pos_++];
      cp <<= 4;
      if (h >= '0' && h <= '9')
        cp |= static_cast<std::uint32_t>(h - '0');
      else if (h >= 'a' && h <= 'f')
        cp |= static_cast<std::uint32_t>(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F')
        cp |= static_cast<std::uint32_t>(h - 'A' + 10);
      else
        return false;
    }
    return true;
  }
  status string(std::string& out) {
    ++pos_;  // opening quote
    out.clear();
    while (pos_ < text_.size()) {
      const char c = text_[pos_++];
      if (c == '"') return {};
      if (static_cast<unsigned char>(c) < 0x20) return fail("control character inside a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= text_.size()) break;
      const char e = text_[pos_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          std::uint32_t cp = 0;
          if (!hex4(cp)) return fail("malformed \\u escape");
          if (cp >= 0xD800 && cp < 0xDC00 && text_.substr(pos_, 2) == "\\u") {
            pos_ += 2;
            std::uint32_t lo = 0;
            if (!hex4(lo) || lo < 0xDC00 || lo >= 0xE000) return fail("malformed surrogate pair");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          }
          put_utf8(out, cp);
          break;
        }
        default: --pos_; return fail(cat("unknown escape '\\", e, "'"));
      }
    }
    return fail("unterminated string");
  }
  status array(json_value& out, int depth) {
    ++pos_;
    out.type = json_value::kind::array;
    for (;;) {
      skip();
      if (pos_ < text_.size() && text_[pos_] == ']') {
        ++pos_;
        return {};
      }  // also after a trailing comma
      json_value v;
      if (auto s = value(v, depth + 1); !s) return s;
      out.array.push_back(std::move(v));
      skip();
      if (pos_ >= text_.size()) return fail("unexpected end of file inside an array");
      if (text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (text_[pos_] == ']') {
        ++pos_;
        return {};
      }
      return fail("expected ',' or ']' in an array");
    }
  }
  /// Called when an object closes: a member name given twice is an error (which value would count
  /// is ambiguous, and a rewritten file would keep both). O(n log n).
  status unique_members(const json_value& obj) {
    if (obj.object.size() < 2) return {};
    std::vector<std::string_view> keys;
    keys.reserve(obj.object.size());
    for (const auto& m : obj.object) keys.emplace_back(m.first);
    std::sort(keys.begin(), keys.end());
    const auto dup = std::adjacent_find(keys.begin(), keys.end());
    if (dup != keys.end()) return fail(cat("duplicate member \"", *dup, "\" in an object"));
    return {};
  }
  status object(json_value& out, int depth) {
    ++pos_;
    out.type = json_value::kind::object;
    for (;;) {
      skip();
      if (pos_ < text_.size() && text_[pos_] == '}') {
        ++pos_;
        return unique_members(out);
      }
      if (pos_ >= text_.size() || text_[pos_] != '"') return fail("expected a member name in quotes");
      std::string key;
      if (auto s = string(key); !s) return s;
      skip();
      if (pos_ >= text_.size() || text_[pos_] != ':') return fail(cat("expected ':' after member \"", key, "\""));
      ++pos_;
      json_value v;
      if (auto s = value(v, depth + 1); !s) return s;
      out.object.push_back({std::move(key), std::move(v)});
      skip();
      if (pos_ >= text_.size()) return fail("unexpected end of file inside an object");
      if (text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (text_[pos_] == '}') {
        ++pos_;
        return unique_members(out);
      }
      return fail("expected ',' or '}' in an object");
    }
  }

  std::string_view text_;
  std::string_view name_;
  std::size_t pos_ = 0;
};

/// Parses JSON text; errors are parse_error statuses "NAME:LINE:COL: what".
inline result<json_value> parse_json(std::string_view text, std::string_view name) {
  return json_parser(text, name).parse();
}

/// A JSON string literal for `s` (quotes and escapes added).
inline std::string json_quote(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// A JSON number: integers exactly, other values with 17 significant digits (round-trips doubles).
inline std::string json_number(double v) {
  char buf[40];
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9.007199254740992e15)
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
  else
    std::snprintf(buf, sizeof buf, "%.17g", std::isfinite(v) ? v : 0.0);
  return buf;
}

}  // namespace detail
TESSERA_NAMESPACE_END
