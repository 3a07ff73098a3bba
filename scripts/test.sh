#!/usr/bin/env bash
# Quick start 2: install what is missing, build everything, run every test.
#   scripts/test.sh               Release build in build/, all tests (unit, CLI, examples, structural,
#                                 Python); the library tests and the fuzz corpus replay are built with
#                                 AddressSanitizer + UndefinedBehaviorSanitizer (-Og, assertions on)
#                                 inside it (TESSERA_TESTS_SANITIZE; TESSERA_TESTS_SANITIZE=OFF in the
#                                 environment builds them like the library instead), the library, the
#                                 command and the examples as users build them, the Python module at -O1
#                                 (TESSERA_PYTHON_OPTIMIZE; pip and plain CMake builds use -O2), and
#                                 every public header alone (TESSERA_CHECK_DETAIL_HEADERS=ON adds detail/)
#   scripts/test.sh --sanitize    a whole build with ASan + UBSan in build-asan/ (-Og): the same library
#                                 tests and fuzz corpus replay; not the structural build-shape checks,
#                                 the examples, the Python module (an ASan extension cannot load into an
#                                 uninstrumented interpreter) or the tessera command's tests. CI does
#                                 not need it since the default build instruments the library tests.
# The instrumented code uses -Og, not -O1: GCC 12 compiles the instrumented tests in ~60% of the CPU
# time of -O1 and they run about as fast (tests/geometry/test_element_merge.cpp: compile 31 s against
# 52 s, run 9.7 and 9.6 s against 10.3 and 8.0 s in two runs; -O0 compiles in 27 s but runs 3x
# slower), and the sanitizers check the same accesses. Warnings are errors in the rest of the Release
# build; in instrumented code they are only printed (the optimizer's flow warnings differ with -Og and
# the instrumentation, and would fail the run on false positives).
# TESSERA_SANITIZE_FUZZ_REPLAY=OFF leaves the fuzz corpus replay out of the --sanitize build.
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
else
  build=${TESSERA_BUILD_DIR:-$TESSERA_ROOT/build}
  step "configure $build (Release; library tests with ASan + UBSan)"
  configure "$build" -DCMAKE_BUILD_TYPE=Release -DTESSERA_BUILD_TESTS=ON -DTESSERA_BUILD_CLI=ON \
    -DTESSERA_BUILD_EXAMPLES=ON -DTESSERA_TESTS_SANITIZE="${TESSERA_TESTS_SANITIZE:-ON}" \
    -DTESSERA_PYTHON_OPTIMIZE="${TESSERA_PYTHON_OPTIMIZE:--O1}" \
    -DTESSERA_CHECK_DETAIL_HEADERS="${TESSERA_CHECK_DETAIL_HEADERS:-OFF}"
fi
# read by the instrumented test executables only
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

step "build ($JOBS jobs)"
cmake --build "$build" -j "$JOBS"

step "test"
ctest --test-dir "$build" --output-on-failure -j "$JOBS" "$@"
