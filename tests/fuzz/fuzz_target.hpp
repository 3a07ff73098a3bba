// One fuzz target per reader of untrusted bytes. Each fuzz_<name>.cpp defines its entry point with
// TESSERA_FUZZ_TARGET(name): built with -DTESSERA_FUZZER (clang, -fsanitize=fuzzer) it is the
// libFuzzer entry point LLVMFuzzerTestOneInput; otherwise it registers itself with the corpus replay
// driver (replay_main.cpp), which feeds every file of tests/fuzz/corpus/<name>/ through it in the
// normal test suite, built with any compiler, so findings stay fixed.
//
// A target returns 0. It aborts (FUZZ_CHECK) when a reader breaks a promise beyond "no crash": a
// successful read that does not survive a write and a re-read, for instance.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#define FUZZ_CHECK(cond)                                                                 \
  do {                                                                                   \
    if (!(cond)) {                                                                       \
      std::fprintf(stderr, "%s:%d: fuzz check failed: %s\n", __FILE__, __LINE__, #cond); \
      std::abort();                                                                      \
    }                                                                                    \
  } while (0)

namespace tessera_fuzz {
using target_fn = int (*)(const std::uint8_t*, std::size_t);
inline std::map<std::string, target_fn>& targets() {
  static std::map<std::string, target_fn> t;
  return t;
}
inline bool register_target(const char* name, target_fn f) {
  targets()[name] = f;
  return true;
}
}  // namespace tessera_fuzz

#ifdef TESSERA_FUZZER
#define TESSERA_FUZZ_TARGET(name, data, size) \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
#else
#define TESSERA_FUZZ_TARGET(name, data, size)                                                                    \
  static int fuzz_##name(const std::uint8_t*, std::size_t);                                                      \
  [[maybe_unused]] static const bool fuzz_registered_##name = tessera_fuzz::register_target(#name, fuzz_##name); \
  static int fuzz_##name(const std::uint8_t* data, std::size_t size)
#endif
