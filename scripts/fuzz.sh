#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan) in build-fuzz/ and runs each
# for a bounded time, one after the other.
#   scripts/fuzz.sh [SECONDS] [TARGET...]   SECONDS per target (default 60); default: every target
# Environment: TESSERA_FUZZ_BUILD_DIR (default build-fuzz), TESSERA_FUZZ_NICE (default 10; the
# fuzzers run under `nice`), CXX (default clang++-14, else clang++), TESSERA_FUZZ_NO_BUILD=1 (run
# the fuzzers already built), JOBS (build jobs, default 2), TESSERA_FUZZ_JOBS (fuzzers run at a time,
# default JOBS).
# Each target starts from its seed corpus tests/fuzz/corpus/<target>/ and grows a working corpus in
# <build>/corpus/<target>/ (kept between runs). A finding (crash-*, leak-*, timeout-*, oom-*) lands in
# <build>/findings/<target>/ and makes the script fail; once fixed, copy it into
# tests/fuzz/corpus/<target>/crash_<what> so that the normal suite replays it ("fuzz: <target> corpus").
# The last line of each run (executions, "cov:" edges, "ft:" features) is appended to <build>/fuzz-summary.txt (TESSERA_FUZZ_SUMMARY).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
targets=("$@")
if ((${#targets[@]} == 0)); then targets=(png obj off ply tile_manifest tile_dir tsuv patch_model remesh); fi
build=${TESSERA_FUZZ_BUILD_DIR:-$root/build-fuzz}
nice_level=${TESSERA_FUZZ_NICE:-10}
cxx=${CXX:-}
if [[ -z $cxx ]]; then
  if command -v clang++-14 >/dev/null 2>&1; then cxx=clang++-14; else cxx=clang++; fi
fi
if ! command -v "$cxx" >/dev/null 2>&1; then
  echo "fuzz: needs clang with libFuzzer (Debian: apt-get install clang libclang-rt-14-dev)" >&2
  exit 1
fi

start=$SECONDS
if [[ ${TESSERA_FUZZ_NO_BUILD:-0} != 1 ]]; then
  echo "== fuzz: configure and build $build ($cxx)"
  cmake -S "$root" -B "$build" -G Ninja -Wno-dev -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DTESSERA_BUILD_TESTS=ON -DTESSERA_BUILD_CLI=OFF \
    -DTESSERA_BUILD_EXAMPLES=OFF -DTESSERA_BUILD_BENCHMARKS=OFF -DTESSERA_WERROR=OFF -DTESSERA_TEST_PCH=OFF \
    -DTESSERA_BUILD_FUZZERS=ON >/dev/null
  cmake --build "$build" -j "${JOBS:-2}" --target "${targets[@]/#/fuzz_}"
  echo "== fuzz: built in $((SECONDS - start)) s"
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
summary=${TESSERA_FUZZ_SUMMARY:-$build/fuzz-summary.txt}
# run_target T: one bounded libFuzzer run of target T; its exit code goes to <build>/fuzz-T.rc.
run_target() {
  local t=$1 work=$build/corpus/$1 findings=$build/findings/$1 rc=0
  mkdir -p "$work" "$findings"
  rm -f "$build/fuzz-$t.rc"
  (cd "$findings" && TMPDIR=$build nice -n "$nice_level" "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" "$work" \
    "$root/tests/fuzz/corpus/$t") >"$build/fuzz-$t.log" 2>&1 || rc=$?
  echo "$rc" >"$build/fuzz-$t.rc"
}
# Each fuzzer is one single-threaded process: TESSERA_FUZZ_JOBS of them run at a time (default JOBS,
# default 2), so 7 targets x SECONDS take about 4 x SECONDS on two cores instead of 7 x SECONDS.
fuzz_jobs=${TESSERA_FUZZ_JOBS:-${JOBS:-2}}
for t in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= fuzz_jobs)); do wait -n || true; done
  echo "== fuzz: $t for $seconds s"
  run_target "$t" &
done
wait
failed=()
for t in "${targets[@]}"; do
  work=$build/corpus/$t findings=$build/findings/$t log=$build/fuzz-$t.log
  rc=$(cat "$build/fuzz-$t.rc" 2>/dev/null || echo "?")
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  cov=$(grep -o 'cov: [0-9]*' <<<"$last" | tail -1 || true)
  ft=$(grep -o 'ft: [0-9]*' <<<"$last" | tail -1 || true)
  line="$t: ${seconds} s, ${execs} executions, ${cov:-cov: ?}, ${ft:-ft: ?}, corpus $(find "$work" -type f | wc -l) files"
  if [[ $rc != 0 ]] || compgen -G "$findings/*" >/dev/null; then
    line+=", FINDING (exit $rc, see $log and $findings)"
    failed+=("$t")
  fi
  echo "$line" | tee -a "$summary"
done
echo "== fuzz: total $((SECONDS - start)) s; summary in $summary"
if ((${#failed[@]})); then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
