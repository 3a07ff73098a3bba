#!/usr/bin/env bash
# A real terrain for the ground-anchored figures of docs/terrain.md: fetches Debian's
# python-matplotlib-data package (its sample jacksboro_fault_dem.npz, a USGS 3 arc-second DEM of
# 344 x 403 samples; the data is not committed), turns it into a z-up OBJ in metres (275 772
# faces), writes a 40-camera fly-over moving 1 % of the view distance per frame, and runs
# `tessera terrain --anchor ground` and `--anchor screen` over it with --stats, then prints the
# summaries (stability, continuity, level jump, frame time, texture stretch) and, as an independent
# check from the TSUV file alone, the anisotropy of frame 0's uv maps.
#   scripts/real_terrain.sh [BUILD_DIR (default build)] [OUT_DIR (default BUILD_DIR/real_terrain)]
# Needs apt-get (run `apt-get update` once first), Debian's /usr/bin/python3 with numpy, and a
# built `tessera` (target tessera_cli).
set -euo pipefail
build=${1:-build}
out=${2:-$build/real_terrain}
here=$(cd "$(dirname "$0")" && pwd)
py=/usr/bin/python3
mkdir -p "$out"
if [ ! -f "$out/jacksboro.obj" ]; then
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download python-matplotlib-data >/dev/null)
  dpkg -x "$tmp"/python-matplotlib-data_*.deb "$tmp/x"
  "$py" "$here/real_terrain.py" mesh "$tmp/x/usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz" \
    "$out/jacksboro.obj"
  rm -rf "$tmp"
fi
"$py" "$here/real_terrain.py" path "$out/jacksboro.obj" "$out/path.txt" 40
for anchor in ground screen; do
  mkdir -p "$out/$anchor"
  "$build/bin/tessera" terrain --mesh "$out/jacksboro.obj" --exemplar sand --viewport 960x540 --anchor "$anchor" \
    --path "$out/path.txt" --frames-out "$out/$anchor" --sun 1,-1,2 --stats --threads 2 >"$out/$anchor.jsonl"
  printf '%s: ' "$anchor"
  "$py" "$here/real_terrain.py" stats "$out/$anchor.jsonl"
done
printf 'anisotropy s1 / s2 of the uv map (ground, frame 0, from the TSUV file alone; stretch_* above is the full measure): '
"$py" "$here/real_terrain.py" stretch "$out/jacksboro.obj" "$out/ground/frame_0000.tsuv"
