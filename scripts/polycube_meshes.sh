#!/usr/bin/env bash
# Real closed meshes for the polycube table of docs/surface.md: fetches Debian's libcgal-demo package
# (CGAL 5.5's data directory; the meshes are not committed), extracts the closed meshes of genus 0-4
# with 23 to 75k faces listed below, and runs `tessera polycube --stats` on each at two tile counts.
# With OpenSCAD installed (`apt-get install openscad`, optional), CAD parts are added: OpenSCAD's own
# examples 001-005 (genus 5, CC0, /usr/share/openscad/examples/Old) and scripts/meshes/*.scad (genus 3),
# exported as OFF.
#   scripts/polycube_meshes.sh [BUILD_DIR (default build)] [OUT_DIR (default BUILD_DIR/polycube_meshes)]
# Needs apt-get (run `apt-get update` once first) and a built `tessera` (target tessera_cli).
set -euo pipefail
build=${1:-build}
out=${2:-$build/polycube_meshes}
meshes="anchor_dense armadillo bear blobby bones bull camel couplingdown cow dino elephant elk fandisk femur hand
handle homer knot1 rotor_small triceratops turbine bunny00 joint eight part 3torus double-torus-example"
mkdir -p "$out"
out=$(cd "$out" && pwd)
if [ ! -f "$out/.fetched" ]; then
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download libcgal-demo >/dev/null)
  dpkg -x "$tmp"/libcgal-demo_*.deb "$tmp/x"
  files=""
  for m in $meshes; do files="$files data/meshes/$m.off"; done
  # shellcheck disable=SC2086
  tar xzf "$tmp/x/usr/share/doc/libcgal-dev/data.tar.gz" -C "$tmp" $files
  mv "$tmp"/data/meshes/*.off "$out/"
  rm -rf "$tmp"
  touch "$out/.fetched"
fi
if command -v openscad >/dev/null; then
  here=$(cd "$(dirname "$0")" && pwd)
  for m in example001 example002 example003 example004 example005; do
    [ -f "$out/$m.off" ] || (cd /usr/share/openscad/examples/Old && openscad -q -o "$out/$m.off" "$m.scad")
    meshes="$meshes $m"
  done
  for m in three_holes plate_three_holes; do
    [ -f "$out/$m.off" ] || openscad -q -o "$out/$m.off" "$here/meshes/$m.scad"
    meshes="$meshes $m"
  done
fi
for m in $meshes; do
  for n in 8 16; do
    printf '%s %s ' "$m" "$n"
    "$build/bin/tessera" polycube --in "$out/$m.off" --out "$out/${m}_pc$n.obj" --tiles-across "$n" --threads 2 \
      --stats 2>&1 | head -c 400 || true
    echo
  done
done
