// The `tessera` command's small framework: subcommand registry, argument parsing with generated
// --help, one-line JSON statistics and timing helpers. Each subcommand lives in its own
// cmd_<name>.cpp and registers itself with a static `cli::registrar`, so adding a capability never
// touches another file. The registry adds the options every command shares (--seed, --threads,
// --stats, --repeat); the parsers below (size, extent, color_pair, ...) are the one vocabulary of
// docs/cli.md, and an option's older spellings are declared as its `aliases`.
#pragma once

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tessera/core/executor.hpp>
#include <tessera/core/status.hpp>
#include <tessera/core/vec.hpp>
#include <tessera/io/files.hpp>

namespace cli {

using tessera::index_t;

/// One option of a subcommand. `value` names the argument ("WxH", "FILE"); empty for a flag.
/// `aliases` are older spellings still accepted (documented in docs/cli.md as such).
struct option_spec {
  std::string name;  ///< with dashes: "--out"
  std::string value;
  std::string help;
  std::vector<std::string> aliases = {};
};

class arguments;

/// Which of the shared options (common_options) the registry adds to a command.
enum class shared_options { all, stats_only };

struct command {
  std::string name;     ///< "synth", or "wang build" for a two-word command
  std::string summary;  ///< one line for `tessera --help`
  std::string usage;    ///< "tessera synth --exemplar E.png --size WxH --out O.png [options]"
  std::vector<option_spec> options;
  std::function<int(const arguments&)> run;
  std::string positional = {};  ///< name of positional arguments ("FILE"), empty if none
  /// The options positional arguments stand for, in order ({"--in", "--out"}): `tessera info F` is
  /// `tessera info --in F`. Empty: positional arguments are kept as such (args.positional()).
  std::vector<std::string> positional_options = {};
  shared_options shared = shared_options::all;
};

/// Options most commands share; the registry appends those a command does not declare itself.
inline std::vector<option_spec> common_options() {
  return {{"--seed", "S", "random seed (default 1); same seed, same output"},
          {"--threads", "T", "worker threads (default: all cores); output does not depend on it"},
          {"--stats", "", "print one JSON line of timings and quality figures to stdout"},
          {"--repeat", "N", "run the timed step N times and report the median (default 1)"}};
}

/// `c` with the shared options it does not declare itself appended (all of them, or --stats only).
inline command with_shared_options(command c) {
  for (auto& o : common_options()) {
    if (c.shared == shared_options::stats_only && o.name != "--stats") continue;
    const bool declared =
        std::any_of(c.options.begin(), c.options.end(), [&](const option_spec& d) { return d.name == o.name; });
    if (!declared) c.options.push_back(std::move(o));
  }
  return c;
}

/// Parsed arguments of one subcommand.
class arguments {
 public:
  /// Parses argv[first..argc). Unknown options and missing values are errors (message in `error`).
  static std::optional<arguments> parse(const command& cmd, int argc, char** argv, int first, std::string& error) {
    arguments a;
    a.command_ = cmd.name;
    for (int i = first; i < argc; ++i) {
      std::string arg = argv[i];
      if (arg == "--help" || arg == "-h") {
        a.values_["--help"] = "";
        continue;
      }
      if (arg.size() > 2 && arg.rfind("--", 0) == 0) {
        std::string value;
        bool inline_value = false;
        if (auto eq = arg.find('='); eq != std::string::npos) {
          value = arg.substr(eq + 1);
          arg = arg.substr(0, eq);
          inline_value = true;
        }
        auto it = std::find_if(cmd.options.begin(), cmd.options.end(), [&](const option_spec& o) {
          return o.name == arg || std::find(o.aliases.begin(), o.aliases.end(), arg) != o.aliases.end();
        });
        if (it == cmd.options.end()) {
          error = "unknown option " + arg + " (see tessera " + cmd.name + " --help)";
          return std::nullopt;
        }
        if (!it->value.empty() && !inline_value) {
          if (i + 1 >= argc) {
            error = "option " + arg + " needs a value " + it->value;
            return std::nullopt;
          }
          value = argv[++i];
        }
        // an alias stores under the option's name and remembers the spelling for messages
        if (auto sp = a.spelled_.find(it->name); sp != a.spelled_.end() && sp->second != arg) {
          error = sp->second + " and " + arg + " are the same option: give one";
          return std::nullopt;
        }
        a.values_[it->name] = value;
        a.spelled_[it->name] = arg;
      } else {
        if (cmd.positional.empty()) {
          error = "unexpected argument '" + arg + "' (see tessera " + cmd.name + " --help)";
          return std::nullopt;
        }
        a.positional_.push_back(arg);
      }
    }
    if (!cmd.positional_options.empty()) {
      if (a.positional_.size() > cmd.positional_options.size()) {
        error = "unexpected argument '" + a.positional_[cmd.positional_options.size()] + "' (see tessera " + cmd.name +
                " --help)";
        return std::nullopt;
      }
      for (std::size_t k = 0; k < a.positional_.size(); ++k) {
        const std::string& opt = cmd.positional_options[k];
        if (a.has(opt)) {
          error = "'" + a.positional_[k] + "' and " + a.spelled(opt) + " both give " + opt + ": give one";
          return std::nullopt;
        }
        a.values_[opt] = a.positional_[k];
      }
    }
    return a;
  }

  [[nodiscard]] const std::string& command_name() const { return command_; }
  [[nodiscard]] bool has(std::string_view name) const { return values_.count(std::string(name)) != 0; }
  [[nodiscard]] std::string str(std::string_view name, std::string fallback = {}) const {
    auto it = values_.find(std::string(name));
    return it == values_.end() ? fallback : it->second;
  }
  [[nodiscard]] const std::vector<std::string>& positional() const { return positional_; }

  /// The spelling the user gave for option `name` (an alias, or `name` itself): what messages name.
  [[nodiscard]] std::string spelled(std::string_view name) const {
    auto it = spelled_.find(std::string(name));
    return it == spelled_.end() ? std::string(name) : it->second;
  }
  /// The status for a missing required option.
  static tessera::status missing(std::string_view name) {
    return tessera::status::invalid_argument("missing required option " + std::string(name));
  }
  /// A required option: status naming it when absent.
  [[nodiscard]] tessera::result<std::string> required(std::string_view name) const {
    if (!has(name)) return missing(name);
    return str(name);
  }
  /// An integer option in [lo, hi]; `fallback` when absent. Overflow and trailing text are errors.
  [[nodiscard]] tessera::result<long long> integer(std::string_view name, long long fallback,
                                                   long long lo = std::numeric_limits<long long>::min(),
                                                   long long hi = std::numeric_limits<long long>::max()) const {
    if (!has(name)) return fallback;
    const std::string s = str(name);
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno == ERANGE) return bad(name, s, "an integer");
    if (v < lo || v > hi) return bad(name, s, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }
  /// A finite number option in [lo, hi]; `fallback` when absent.
  [[nodiscard]] tessera::result<double> number(std::string_view name, double fallback,
                                               double lo = -std::numeric_limits<double>::max(),
                                               double hi = std::numeric_limits<double>::max()) const {
    if (!has(name)) return fallback;
    const std::string s = str(name);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(v)) return bad(name, s, "a finite number");
    if (v < lo || v > hi) return bad(name, s, "a number in [" + format_number(lo) + ", " + format_number(hi) + "]");
    return v;
  }
  /// A required size "WxH" (or a single "N" meaning N x N): positive integers, each at most
  /// `max_side`, and at most `max_pixels` in all, so a typo cannot ask for terabytes.
  [[nodiscard]] tessera::result<std::pair<index_t, index_t>> size(std::string_view name, index_t max_side = 65536,
                                                                  index_t max_pixels = index_t{1} << 28) const {
    if (!has(name)) return missing(name);
    const std::string s = str(name);
    std::vector<double> v;
    if (!split_numbers(s, 'x', v) || (v.size() != 1 && v.size() != 2)) return bad(name, s, "WxH");
    const double wd = v[0], hd = v.size() == 2 ? v[1] : v[0];
    if (!(wd >= 1 && hd >= 1) || wd != std::floor(wd) || hd != std::floor(hd))
      return bad(name, s, "positive integers WxH");
    if (wd > double(max_side) || hd > double(max_side) || wd * hd > double(max_pixels))
      return bad(name, s,
                 "at most " + std::to_string(max_side) + " per side and " + std::to_string(max_pixels) + " in all");
    return std::pair{static_cast<index_t>(wd), static_cast<index_t>(hd)};
  }
  /// A required extent in real units "WxH" (or a single "W" meaning W x W; the older "W,H" is an
  /// accepted alias): finite numbers in (0, max_side].
  [[nodiscard]] tessera::result<std::pair<double, double>> extent(std::string_view name, double max_side) const {
    if (!has(name)) return missing(name);
    const std::string s = str(name);
    std::vector<double> v;
    if ((!split_numbers(s, 'x', v) || (v.size() != 1 && v.size() != 2)) &&
        (v.clear(), !split_numbers(s, ',', v) || v.size() != 2))
      return bad(name, s, "WxH");
    const double w = v[0], h = v.size() == 2 ? v[1] : v[0];
    if (!(w > 0 && h > 0 && w <= max_side && h <= max_side))
      return bad(name, s, "positive numbers WxH, at most " + format_number(max_side) + " each");
    return std::pair{w, h};
  }
  /// Edge colour counts "NH,NV": integers in [1, max_colors];
  /// `fallback` when absent. The same rule for every Wang command.
  [[nodiscard]] tessera::result<std::pair<int, int>> color_pair(std::string_view name, int max_colors,
                                                                std::pair<int, int> fallback = {2, 2}) const {
    if (!has(name)) return fallback;
    const std::string s = str(name);
    std::vector<double> v;
    const std::string expected = "two integers NH,NV in [1, " + std::to_string(max_colors) + "]";
    if (!split_numbers(s, ',', v) || v.size() != 2) return bad(name, s, expected);
    // range-checked before any conversion to int (1e10 must not wrap)
    for (double c : v)
      if (!(c >= 1 && c <= max_colors) || c != std::floor(c)) return bad(name, s, expected);
    return std::pair{static_cast<int>(v[0]), static_cast<int>(v[1])};
  }
  /// Edge colour counts "NH,NV" of a planar set or "NX,NY,NZ" of a three-axis set (geo-wang build):
  /// two or three integers in [1, max_colors]; {2, 2} when absent.
  [[nodiscard]] tessera::result<std::vector<int>> color_counts(std::string_view name, int max_colors) const {
    if (!has(name)) return std::vector<int>{2, 2};
    const std::string s = str(name);
    std::vector<double> v;
    const std::string expected = "two integers NH,NV or three NX,NY,NZ in [1, " + std::to_string(max_colors) + "]";
    if (!split_numbers(s, ',', v) || (v.size() != 2 && v.size() != 3)) return bad(name, s, expected);
    std::vector<int> out;
    for (double c : v) {
      if (!(c >= 1 && c <= max_colors) || c != std::floor(c)) return bad(name, s, expected);
      out.push_back(static_cast<int>(c));
    }
    return out;
  }
  /// One of `choices` (the first is the default when the option is absent).
  [[nodiscard]] tessera::result<std::string> choice(std::string_view name,
                                                    const std::vector<std::string>& choices) const {
    if (!has(name)) return choices.front();
    const std::string s = str(name);
    if (std::find(choices.begin(), choices.end(), s) != choices.end()) return s;
    std::string list;
    for (std::size_t k = 0; k < choices.size(); ++k)
      list += (k == 0 ? "" : k + 1 == choices.size() ? " or " : ", ") + choices[k];
    return bad(name, s, list);
  }
  /// Comma-separated finite numbers, exactly `count` of them ("x,y,z").
  [[nodiscard]] tessera::result<std::vector<double>> numbers(std::string_view name, std::size_t count) const {
    const std::string s = str(name);
    std::vector<double> v;
    if (!split_numbers(s, ',', v) || v.size() != count)
      return bad(name, s, std::to_string(count) + " comma-separated numbers");
    return v;
  }
  /// Checks the options every command shares (--seed, --threads, --repeat); main() calls it before
  /// a command runs, so seed(), threads() and repeat() below never see an invalid value.
  [[nodiscard]] tessera::status check_common() const {
    if (has("--seed")) {
      const std::string s = str("--seed");
      char* end = nullptr;
      errno = 0;
      (void)std::strtoull(s.c_str(), &end, 10);
      if (s.empty() || s[0] == '-' || *end != '\0' || errno == ERANGE)
        return bad("--seed", s, "an integer in [0, 2^64 - 1]");
    }
    if (auto t = integer("--threads", 0, 0, max_threads); !t) return t.error();
    if (auto r = integer("--repeat", 1, 1, 100000); !r) return r.error();
    return {};
  }
  static constexpr long long max_threads = 1024;
  [[nodiscard]] std::uint64_t seed() const {
    return has("--seed") ? std::strtoull(str("--seed").c_str(), nullptr, 10) : std::uint64_t{1};
  }
  [[nodiscard]] int threads() const { return static_cast<int>(integer("--threads", 0, 0, max_threads).value_or(0)); }
  [[nodiscard]] int repeat() const { return static_cast<int>(integer("--repeat", 1, 1, 100000).value_or(1)); }
  [[nodiscard]] bool stats() const { return has("--stats"); }

 private:
  /// The error naming the option as the user spelled it (an alias or its name).
  [[nodiscard]] tessera::status bad(std::string_view name, const std::string& value,
                                    const std::string& expected) const {
    return tessera::status::invalid_argument(spelled(name) + " expects " + expected + ", got '" + value + "'");
  }
  static std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }
  static bool split_numbers(const std::string& s, char sep, std::vector<double>& out) {
    std::size_t start = 0;
    while (start <= s.size()) {
      const std::size_t end = std::min(s.find(sep, start), s.size());
      const std::string part = s.substr(start, end - start);
      char* stop = nullptr;
      const double v = std::strtod(part.c_str(), &stop);
      if (part.empty() || *stop != '\0' || !std::isfinite(v)) return false;
      out.push_back(v);
      start = end + 1;
    }
    return !out.empty();
  }

  std::string command_;
  std::map<std::string, std::string> values_;
  std::map<std::string, std::string> spelled_;  ///< option name -> the spelling given (name or alias)
  std::vector<std::string> positional_;
};

/// The registry of subcommands, filled by static registrars before main runs.
inline std::vector<command>& registry() {
  static std::vector<command> commands;
  return commands;
}
struct registrar {
  explicit registrar(command c) { registry().push_back(with_shared_options(std::move(c))); }
};

/// Prints an error for a failed status; returns the process exit code (1).
inline int fail(const arguments& args, const tessera::status& s) {
  std::fprintf(stderr, "tessera %s: %s\n", args.command_name().c_str(), s.to_string().c_str());
  return 1;
}

/// One JSON object on one line: json_line().add("width", 512).add("name", "x").print();
class json_line {
 public:
  json_line& add(std::string_view key, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return raw(key, buf);
  }
  json_line& add(std::string_view key, long long v) { return raw(key, std::to_string(v)); }
  json_line& add(std::string_view key, std::uint64_t v) { return raw(key, std::to_string(v)); }
  json_line& add(std::string_view key, int v) { return raw(key, std::to_string(v)); }
  json_line& add(std::string_view key, index_t v) { return raw(key, std::to_string(v)); }
  json_line& add(std::string_view key, bool v) { return raw(key, v ? "true" : "false"); }
  json_line& add(std::string_view key, std::string_view v) { return raw(key, quote(v)); }
  json_line& add(std::string_view key, const char* v) { return add(key, std::string_view(v)); }
  /// Adds an already-formatted JSON value (an array, a nested object).
  json_line& raw(std::string_view key, std::string_view json) {
    if (!body_.empty()) body_ += ",";
    body_ += quote(key) + ":" + std::string(json);
    return *this;
  }
  [[nodiscard]] std::string str() const { return "{" + body_ + "}"; }
  void print() const { std::printf("%s\n", str().c_str()); }

  static std::string quote(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
      if (c == '"' || c == '\\')
        out += '\\', out += c;
      else if (c == '\n')
        out += "\\n";
      else if (static_cast<unsigned char>(c) < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out += buf;
      } else
        out += c;
    }
    return out + "\"";
  }

 private:
  std::string body_;
};

/// Wall-clock milliseconds of one call.
template <class F>
double time_ms(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// Median wall-clock milliseconds over `repeat` calls (at least one).
template <class F>
double median_ms(int repeat, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < std::max(1, repeat); ++i) t.push_back(time_ms(f));
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace cli
