#!/usr/bin/env bash
# Quick start 1: install what is missing, build the `tessera` command and the examples, and run the
# demo on data the repository generates. Everything goes to out/demo/; the script lists what it wrote.
#
# Layout for the lead: one function per family (demo_<family>), each a self-contained block that
# writes under "$OUT/<family>" and runs in a few seconds; add a block and list it in DEMO_BLOCKS.
# demo_foundation runs first and leaves the procedural exemplars in "$OUT/foundation/<kind>.png"
# (grass sand rock bricks cells weave dots, 128 x 128) for the later blocks.
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
  local examples=$OUT/examples
  mkdir -p "$examples"
  step "examples: every numbered example (foundation 0x, images 1x-2x, fabric 3x, terrain 4x, geometry 5x)"
  local src name
  for src in "$TESSERA_ROOT"/examples/[0-9][0-9]_*.cpp; do
    name=$(basename "$src" .cpp)
    if [[ -x $BUILD/examples/example_$name ]]; then
      run "$BUILD/examples/example_$name" "$examples"
    else
      echo "(skipping $name: not built; OpenMesh missing?)"
    fi
  done
  if has_command sample; then
    step "foundation: tessera sample (procedural exemplars used by the other demos)"
    local kind
    for kind in grass sand rock bricks cells weave dots; do
      run "$TESSERA" sample --kind "$kind" --size 128x128 --seed 1 --out "$out/$kind.png"
    done
  fi
  if has_command info; then
    step "foundation: tessera info / convert"
    run "$TESSERA" info --in "$examples/01_hello.png"
    run "$TESSERA" info --in "$examples/07_eigen_mesh.obj"
    if has_command convert; then
      run "$TESSERA" convert --in "$examples/07_eigen_mesh.obj" --out "$out/07_eigen_mesh.ply" --binary
      run "$TESSERA" info --in "$out/07_eigen_mesh.ply"
      run "$TESSERA" convert --in "$examples/01_hello.png" --out "$out/01_hello_grey16.png" --channels 1 --depth 16
    fi
  fi
}

# ---- image quilting and Wang tiles ------------------------------------------------------------------
demo_wang() {
  local out=$OUT/wang
  mkdir -p "$out"
  step "wang: image quilting, a seamless texture, a Wang tile set and a hash-coloured plane"
  run "$TESSERA" quilt --exemplar bricks --size 512x512 --seed 3 --out "$out/quilt_bricks.png" --stats
  run "$TESSERA" quilt --exemplar cells --size 256x256 --seamless --out "$out/seamless_cells.png" --stats
  run "$TESSERA" wang build --exemplar cells --colors 2,2 --tile 64 --out "$out/tiles" --stats
  run "$TESSERA" wang tile --tiles "$out/tiles" --grid 16x9 --coloring hash --seed 5 --out "$out/plane.png" --stats
  run "$TESSERA" wang tile --tiles "$out/tiles" --grid 16x9 --coloring hash --seed 5 --outline --out "$out/plane_outlined.png"
}

# ---- fabric (paper 001) ------------------------------------------------------------------------------
demo_fabric() {
  local out=$OUT/fabric
  mkdir -p "$out"
  step "fabric: presets, a palette tweed, the inverse cat map and a period"
  local preset
  for preset in flannel twill tweed; do
    run "$TESSERA" fabric --preset "$preset" --size 400 --out "$out/$preset.png" --stats
  done
  run "$TESSERA" fabric --palette "#1f3324:5,#4f6b3f:3,#b8b08a:1.5" --layout blocks --iterations 45 \
    --generations 3 --out "$out/palette_tweed.png" --stats
  run "$TESSERA" catmap --in "$out/twill.png" --iterations -31 --out "$out/twill_source.png" --stats --repeat 5
  run "$TESSERA" catmap --period 1000000000000
}

# ---- large textures by patch distribution (paper 002) -----------------------------------------------
demo_patch() {
  local out=$OUT/patch
  mkdir -p "$out"
  step "patch synthesis: 1024² textures, a far-away window with seam cuts and its source map"
  local kind
  for kind in grass bricks sand; do
    run "$TESSERA" synth --exemplar "$kind" --size 1024x1024 --out "$out/$kind.png" --repeat 5 --stats
  done
  run "$TESSERA" synth --exemplar weave --window -1000000,500000,512,512 --seams cut \
    --source-map "$out/weave_source.png" --out "$out/weave_window.png" --stats
}

# ---- terrain (paper 003) -----------------------------------------------------------------------------
demo_terrain() {
  local out=$OUT/terrain
  mkdir -p "$out"
  step "terrain: a grazing frame textured by synthesis, the same frame tiled, and its scale field"
  run "$TESSERA" terrain --exemplar grass --grid 128 --camera grazing --viewport 960x540 --min-scale 0.5 \
    --out "$out/grass.png" --tiled-out "$out/grass_tiled.png" --scale-out "$out/scale_field.png" --stats
  run "$TESSERA" terrain --exemplar rock --grid 128 --camera oblique --viewport 960x540 \
    --out "$out/rock.png" --tiled-out "$out/rock_tiled.png" --stats
  step "terrain: a ground-anchored fly-through (texture fixed to the ground, incremental frames), one line per frame"
  run "$TESSERA" terrain --exemplar sand --grid 128 --anchor ground --viewport 480x270 \
    --path "$TESSERA_ROOT/docs/images/terrain/anchored_flythrough_path.txt" --frames-out "$out/flythrough" --stats
}

demo_surface() {
  local out=$OUT/surface
  mkdir -p "$out"
  step "surface: a polycube map of a torus (8 tiles across), its quad layout, previews"
  run "$TESSERA" polycube --in "$TESSERA_ROOT/tests/data/surface/torus.obj" --out "$out/torus_polycube.obj" \
    --tiles-across 8 --quads-out "$out/torus_quads.obj" --stats
  run "$TESSERA" render --in "$out/torus_polycube.obj" --out "$out/torus_polycube.png"
}

# ---- geometric textures (paper 000) ---------------------------------------------------------------------
demo_geometry() {
  local out=$OUT/geometry
  mkdir -p "$out"
  step "geometry: an exemplar, a quilted larger texture, a geometric Wang tile set and a tiled plane"
  run "$TESSERA" exemplar --kind stones --out "$out/stones.obj" --seed 3
  run "$TESSERA" mesh-quilt --exemplar "$out/stones.obj" --size 16x12 --out "$out/quilt.obj" --stats
  run "$TESSERA" geo-wang build --exemplar "$out/stones.obj" --colors 2,2 --tile 6.4 --out "$out/tiles" --stats
  run "$TESSERA" geo-wang tile --tiles "$out/tiles" --grid 8x6 --out "$out/plane.obj" --stats
  run "$TESSERA" render --in "$out/quilt.obj" --out "$out/quilt.png"
  run "$TESSERA" render --in "$out/plane.obj" --out "$out/plane.png" --tile 6.4
}

DEMO_BLOCKS=(foundation patch wang fabric terrain geometry surface)
for block in "${DEMO_BLOCKS[@]}"; do
  "demo_$block"
done

step "demo: wrote these files"
find "$OUT" -type f | sort | sed "s|^$TESSERA_ROOT/||"
