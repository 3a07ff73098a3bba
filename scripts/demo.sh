#!/usr/bin/env bash
# Quick start 1: install what is missing, build the `tessera` command and the examples, and run the
# demo on data the repository generates. Everything goes to out/demo/; the script lists what it wrote.
#
# Layout for the lead: one function per family (demo_<family>), each a self-contained block that
# writes under "$OUT/<family>" and runs in a few seconds; add a block and list it in DEMO_BLOCKS.
set -euo pipefail
source "$(dirname "$0")/common.sh"

setup
BUILD=${TESSERA_BUILD_DIR:-$TESSERA_ROOT/build}
OUT=$TESSERA_ROOT/out/demo
TESSERA=$BUILD/bin/tessera

step "configure $BUILD (Release)"
configure "$BUILD" -DCMAKE_BUILD_TYPE=Release -DTESSERA_BUILD_CLI=ON -DTESSERA_BUILD_EXAMPLES=ON
step "build the tessera command and the examples ($JOBS jobs)"
cmake --build "$BUILD" -j "$JOBS" --target tessera_cli tessera_examples

rm -rf "$OUT"
mkdir -p "$OUT"

# run CMD...: prints the command, then runs it (the demo stops at the first failure).
run() {
  printf '$ %s\n' "${*/#$TESSERA_ROOT\//}"
  "$@"
}
# has_command NAME: true when the tessera command has subcommand NAME (capabilities land one by one).
has_command() { "$TESSERA" --help 2>/dev/null | grep -q "^  $1 "; }

# ---- foundation: adapters and the file commands ---------------------------------------------------
# The numbered examples run tessera over user-owned, engine, raw-buffer, Eigen, GLM and OpenMesh
# types; then the CLI inspects and converts what they wrote.
demo_foundation() {
  local out=$OUT/foundation
  mkdir -p "$out"
  step "foundation: examples"
  local src name
  for src in "$TESSERA_ROOT"/examples/[0-9][0-9]_*.cpp; do
    name=$(basename "$src" .cpp)
    if [[ -x $BUILD/examples/example_$name ]]; then
      run "$BUILD/examples/example_$name" "$out"
    else
      echo "(skipping $name: not built; OpenMesh missing?)"
    fi
  done
  if has_command info; then
    step "foundation: tessera info / convert"
    run "$TESSERA" info "$out/01_hello.png"
    run "$TESSERA" info "$out/07_eigen_mesh.obj"
    if has_command convert; then
      run "$TESSERA" convert "$out/07_eigen_mesh.obj" "$out/07_eigen_mesh.ply"
      run "$TESSERA" info "$out/07_eigen_mesh.ply"
    fi
  fi
}

# ---- (families add their blocks here: demo_image, demo_wang, demo_fabric, demo_terrain, ...) ------

DEMO_BLOCKS=(foundation)
for block in "${DEMO_BLOCKS[@]}"; do
  "demo_$block"
done

step "demo: wrote these files"
find "$OUT" -type f | sort | sed "s|^$TESSERA_ROOT/||"
