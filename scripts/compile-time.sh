#!/usr/bin/env bash
# Measures how long a translation unit containing only `#include <tessera/tessera.hpp>` takes to
# compile at -O2 (goal: under 3 s on the 2-core reference machine), median of 3 runs, without ccache.
#   scripts/compile-time.sh            the umbrella header
#   scripts/compile-time.sh --headers  also every public header alone, slowest first
#   scripts/compile-time.sh --families every public header of one family in one TU (the include cost
#                                      of core, image, tiling, fabric, terrain, geometry, surface...),
#                                      CPU seconds, median of 3
#   scripts/compile-time.sh --engine   tests/consumer/common/four_families.cpp (patch synthesis, Wang
#                                      tiles, terrain, geometric tiles) header-only and as with
#                                      tessera::compiled (-DTESSERA_COMPILED=1): wall, CPU, peak RSS
#                                      (one run each; docs/compile_once.md)
set -euo pipefail
source "$(dirname "$0")/common.sh"

cxx=${CXX:-c++}
flags=(-std=c++20 -O2 -I"$TESSERA_ROOT/include" -isystem /usr/include/eigen3 -isystem /usr/include/stb)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# median_seconds HEADER: median wall time of 3 compiles of a TU including HEADER.
median_seconds() {
  printf '#include <%s>\n' "$1" >"$tmp/tu.cpp"
  local times=() i start end
  for i in 1 2 3; do
    start=$(date +%s%N)
    "$cxx" "${flags[@]}" -c "$tmp/tu.cpp" -o "$tmp/tu.o" || { echo "compile-time: $1 does not compile" >&2; exit 1; }
    end=$(date +%s%N)
    times+=("$(((end - start) / 1000000))")
  done
  printf '%s\n' "${times[@]}" | sort -n | sed -n 2p | awk '{printf "%.2f", $1 / 1000}'
}

umbrella=$(median_seconds tessera/tessera.hpp)
echo "umbrella tessera/tessera.hpp: $umbrella s at -O2 ($("$cxx" --version | head -1); goal < 3 s)"
if [[ ${1:-} == --families ]]; then
  # CPU seconds (user + sys), median of 3: steadier than wall time on a shared machine
  cd "$TESSERA_ROOT/include"
  for family in core image tiling fabric terrain geometry surface render io; do
    find "tessera/$family" -maxdepth 1 -name '*.hpp' | sort | sed 's/.*/#include <&>/' >"$tmp/tu.cpp"
    for i in 1 2 3; do
      /usr/bin/time -f "%U %S" -o "$tmp/time" "$cxx" "${flags[@]}" -c "$tmp/tu.cpp" -o "$tmp/tu.o"
      awk '{printf "%.2f\n", $1 + $2}' "$tmp/time"
    done | sort -n | sed -n 2p | sed "s|$| s CPU  $family/ (every public header)|"
  done
fi
if [[ ${1:-} == --engine ]]; then
  for mode in header-only compiled; do
    extra=()
    [[ $mode == compiled ]] && extra=(-DTESSERA_COMPILED=1)
    /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$cxx" "${flags[@]}" "${extra[@]}" \
      -c "$TESSERA_ROOT/tests/consumer/common/four_families.cpp" -o "$tmp/engine.o"
    read -r wall user sys rss <"$tmp/time"
    echo "four_families.cpp $mode: $wall s wall, $(awk "BEGIN{print $user + $sys}") s CPU, $((rss / 1024)) MB peak RSS"
  done
fi
if [[ ${1:-} == --headers ]]; then
  cd "$TESSERA_ROOT/include"
  for h in $(find tessera -name '*.hpp' ! -path '*/adapters/openmesh.hpp' | sort); do
    t=$(median_seconds "$h")
    echo "$t s  $h"
  done | sort -rn
fi
