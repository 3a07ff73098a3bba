#!/usr/bin/env bash
# Quick start 2: install what is missing, build everything, run every test.
#   scripts/test.sh               Release build in build/, all tests (unit, CLI, examples, structural)
#   scripts/test.sh --sanitize    AddressSanitizer + UndefinedBehaviorSanitizer build in build-asan/
#                                 (-Og; library tests only), same tests except the structural
#                                 build-shape checks, the examples, the Python module (an ASan
#                                 extension cannot load into an uninstrumented interpreter; the
#                                 C++ it calls is instrumented in the library tests) and the tessera command's tests
#                                 (its instrumented compile, ~5 minutes of a 2-core CI, kept CI
#                                 over 40 minutes; the library code it runs is instrumented in the
#                                 library tests, its file readers in the fuzzers)
# The sanitizer build uses -Og, not -O1: GCC 12 compiles the instrumented tests in ~60% of the CPU
# time of -O1 and they run about as fast (tests/geometry/test_element_merge.cpp: compile 31 s against
# 52 s, run 9.7 and 9.6 s against 10.3 and 8.0 s in two runs; -O0 compiles in 27 s but runs 3x
# slower), and the sanitizers check the same accesses. Warnings are errors in the Release build; here they are only printed (the optimizer's
# flow warnings differ with -Og and the instrumentation, and would fail the run on false positives).
# TESSERA_SANITIZE_FUZZ_REPLAY=OFF leaves the fuzz corpus replay out of the sanitizer build (.ci/run, whose
# fuzz step replays the same corpus under ASan + UBSan).
# Arguments after the options go to ctest (e.g. scripts/test.sh -R adapters).
set -euo pipefail
source "$(dirname "$0")/common.sh"

sanitize=0
if [[ ${1:-} == --sanitize ]]; then
  sanitize=1
  shift
fi

setup
if ((sanitize)); then
  build=${TESSERA_ASAN_BUILD_DIR:-$TESSERA_ROOT/build-asan}
  step "configure $build (ASan + UBSan, -Og)"
  configure "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-Og -g1" \
    -DTESSERA_SANITIZE=ON -DTESSERA_BUILD_TESTS=ON -DTESSERA_BUILD_CLI=OFF -DTESSERA_BUILD_EXAMPLES=OFF \
    -DTESSERA_BUILD_BENCHMARKS=OFF -DTESSERA_WERROR=OFF -DTESSERA_BUILD_PYTHON=OFF \
    -DTESSERA_FUZZ_REPLAY="${TESSERA_SANITIZE_FUZZ_REPLAY:-ON}"
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
else
  build=${TESSERA_BUILD_DIR:-$TESSERA_ROOT/build}
  step "configure $build (Release)"
  configure "$build" -DCMAKE_BUILD_TYPE=Release -DTESSERA_BUILD_TESTS=ON -DTESSERA_BUILD_CLI=ON \
    -DTESSERA_BUILD_EXAMPLES=ON
fi

step "build ($JOBS jobs)"
cmake --build "$build" -j "$JOBS"

step "test"
ctest --test-dir "$build" --output-on-failure -j "$JOBS" "$@"
