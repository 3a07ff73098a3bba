#!/usr/bin/env bash
# Builds the Google Benchmark programs (benchmarks/bench_<family>.cpp) in build-bench/ and runs them,
# writing one JSON file per program to out/bench/. Timings on a loaded machine are noisy: every
# benchmark runs 3 repetitions and the programs report same-run baselines, so read ratios.
#   scripts/bench.sh                          all programs
#   scripts/bench.sh bench_image              only these programs
#   scripts/bench.sh -- --benchmark_filter=X  extra arguments for every program
set -euo pipefail
source "$(dirname "$0")/common.sh"

programs=()
while (($#)) && [[ $1 != -- ]]; do
  programs+=("$1")
  shift
done
[[ ${1:-} == -- ]] && shift

setup
build=${TESSERA_BENCH_BUILD_DIR:-$TESSERA_ROOT/build-bench}
out=$TESSERA_ROOT/out/bench
step "configure $build (Release, benchmarks)"
configure "$build" -DCMAKE_BUILD_TYPE=Release -DTESSERA_BUILD_BENCHMARKS=ON -DTESSERA_BUILD_TESTS=OFF \
  -DTESSERA_BUILD_EXAMPLES=OFF -DTESSERA_BUILD_CLI=OFF
step "build ($JOBS jobs)"
if ((${#programs[@]})); then
  cmake --build "$build" -j "$JOBS" --target "${programs[@]}"
else
  cmake --build "$build" -j "$JOBS"
  for exe in "$build"/benchmarks/bench_*; do
    [[ -x $exe ]] && programs+=("$(basename "$exe")")
  done
fi
if ((${#programs[@]} == 0)); then
  echo "bench: no benchmark programs yet (benchmarks/bench_<family>.cpp)"
  exit 0
fi

mkdir -p "$out"
for name in "${programs[@]}"; do
  step "run $name"
  "$build/benchmarks/$name" --benchmark_repetitions=3 --benchmark_out="$out/$name.json" \
    --benchmark_out_format=json "$@"
  echo "bench: wrote $out/$name.json"
done
