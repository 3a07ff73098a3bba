// tessera: the command-line face of the library. One subcommand per capability; each lives in its
// own cmd_*.cpp and registers itself (see cli.hpp).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include <tessera/version.hpp>

#include "cli.hpp"

namespace {

void print_overview() {
  std::printf("tessera %s: texture synthesis from the command line\n\n", TESSERA_VERSION_STRING);
  std::printf("usage: tessera <command> [options]    (tessera <command> --help for its options)\n\ncommands:\n");
  auto cmds = cli::registry();
  std::sort(cmds.begin(), cmds.end(), [](const cli::command& a, const cli::command& b) { return a.name < b.name; });
  for (const auto& c : cmds) std::printf("  %-16s %s\n", c.name.c_str(), c.summary.c_str());
}

void print_help(const cli::command& c) {
  std::printf("%s\n\nusage: %s\n", c.summary.c_str(), c.usage.c_str());
  if (!c.options.empty()) std::printf("\noptions:\n");
  for (const auto& o : c.options) {
    const std::string left = o.name + (o.value.empty() ? "" : " " + o.value);
    std::string help = o.help;
    for (std::size_t k = 0; k < o.aliases.size(); ++k)  // older spellings still accepted (docs/cli.md)
      help += (k == 0 ? " (also " : ", ") + o.aliases[k] + (k + 1 == o.aliases.size() ? ")" : "");
    std::printf("  %-22s %s\n", left.c_str(), help.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    print_overview();
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::printf("tessera %s\n", TESSERA_VERSION_STRING);
    return 0;
  }
  // Two-word commands ("wang build") take precedence over one-word ones.
  const cli::command* found = nullptr;
  int first = 2;
  for (const auto& c : cli::registry()) {
    if (argc >= 3 && c.name == std::string(argv[1]) + " " + argv[2]) {
      found = &c;
      first = 3;
      break;
    }
  }
  if (!found)
    for (const auto& c : cli::registry())
      if (c.name == argv[1]) found = &c;
  if (!found) {
    bool group = false;  // "tessera wang" alone: list the "wang ..." commands
    for (const auto& c : cli::registry())
      if (c.name.rfind(std::string(argv[1]) + " ", 0) == 0) {
        if (!group) std::printf("tessera %s: choose a subcommand:\n", argv[1]);
        std::printf("  %-16s %s\n", c.name.c_str(), c.summary.c_str());
        group = true;
      }
    if (group) return 2;
    std::fprintf(stderr, "tessera: unknown command '%s'\n\n", argv[1]);
    print_overview();
    return 2;
  }
  std::string error;
  auto args = cli::arguments::parse(*found, argc, argv, first, error);
  if (!args) {
    std::fprintf(stderr, "tessera %s: %s\n", found->name.c_str(), error.c_str());
    return 2;
  }
  if (args->has("--help")) {
    print_help(*found);
    return 0;
  }
  if (auto s = args->check_common(); !s) {
    std::fprintf(stderr, "tessera %s: %s\n", found->name.c_str(), s.to_string().c_str());
    return 2;
  }
  return found->run(*args);
}
