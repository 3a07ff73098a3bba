#!/usr/bin/env bash
# Quality benchmark of patch synthesis (paper 002, issue 16) on real photographs, against G'MIC's
# patch-matching resynthesis (`gmic IN -syntexturize_matchpatch W,H`). Run on demand, not in CI.
#
# The photographs are the texture set of Debian's `sweethome3d` package (photographs of stone, brick,
# pebbles, grass, hedge, wood and plaster, 256 pixels wide; fetched with `apt-get download`, unpacked
# into the cache, never installed). GIMP's pattern set (Debian's `gimp-data`, also fetched with
# `apt-get download`) is kept aside to check the result: `--set gimp` runs the same comparison on its
# photographic patterns (fabric, bark, cracked paint, crystals, stone, wood, leather, paper, water;
# 50 to 156 pixels), which were never used while tuning. Installs `gmic` with apt-get when it is
# missing (root only).
#
# For every photograph: `tessera synth` and G'MIC at the same output size, then `tessera metrics`
# on both outputs (neighbourhood energy 7 x 7 at 1x, 1/2x and 1/4x, histogram distance, repetition,
# and the seam step ratio on the lines of tessera's patch grid: a visible grid on tessera's output, a
# control on G'MIC's, which has no seams there), the times (tessera: model preparation + synthesis; G'MIC: the whole command), a markdown table and a
# side-by-side picture (exemplar | tessera | G'MIC, 256 x 256 crops at full resolution; exemplars
# shorter than 256 are padded with black).
#
#   scripts/quality-patch.sh [--set S] [--size N] [--out DIR] [--images DIR] [--label L] [-- extra synth args]
#
#   --set S      sweethome3d (default; the photographs tuned on) or gimp (the held-out check)
#   --size N     output side (default 512, as `-syntexturize_matchpatch 512,512`)
#   --out DIR    table and JSON (default build/quality-patch/<set>-<label>)
#   --images DIR side-by-side PNGs (default: none; docs use docs/images/patch/quality)
#   --label L    name of this run (default "default")
#   --threads T  threads of tessera (default 2)
#   --only A,B   only these photographs
# Anything after `--` goes to `tessera synth` (e.g. -- --fallback overlap, the quality mode; -- --feather 0,
# the paper's feathering over the whole overlap).
# Environment: TESSERA_BIN (default build/bin/tessera), TESSERA_QUALITY_CACHE (default
# build/quality-patch/cache: photographs and G'MIC outputs, reused between runs).
set -euo pipefail
source "$(dirname "$0")/common.sh"

size=512
set=sweethome3d
label=default
out=
images=
threads=2
only=
extra=()
while (($#)); do
  case $1 in
    --set) set=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --images) images=$2; shift 2 ;;
    --label) label=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "quality-patch.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
bin=${TESSERA_BIN:-$TESSERA_ROOT/build/bin/tessera}
cache=${TESSERA_QUALITY_CACHE:-$TESSERA_ROOT/build/quality-patch/cache}
out=${out:-$TESSERA_ROOT/build/quality-patch/$set-$label}
[[ $set == sweethome3d || $set == gimp ]] || { echo "quality-patch.sh: --set expects sweethome3d or gimp, got $set" >&2; exit 2; }
py=/usr/bin/python3
[[ -x $py ]] || py=python3
[[ -x $bin ]] || { echo "quality-patch.sh: $bin not built (cmake --build build --target tessera)" >&2; exit 1; }
mkdir -p "$cache" "$out"
[[ -n $images ]] && mkdir -p "$images"

# --- tools and photographs ----------------------------------------------------------------------
if ! command -v gmic >/dev/null; then
  step "install gmic"
  apt-get install -y gmic || { apt-get update && apt-get install -y gmic; }
fi
# fetch_deb PACKAGE: downloads a Debian package (not installed) and unpacks it into $tmp/x (a new
# temporary directory)
fetch_deb() {
  step "fetch the $1 package (apt-get download; not installed)"
  tmp=$(mktemp -d)
  (cd "$tmp" && { apt-get download "$1" || { apt-get update && apt-get download "$1"; }; })
  dpkg -x "$tmp/$1"_*.deb "$tmp/x"
  mkdir -p "$cache/photos"
}

# name:file:what (sweethome3d: photographs of the package's texture catalogue, the tiled and painted
# ones left out; gimp: the photographic RGB patterns, the legacy, sky and synthetic ones left out)
if [[ $set == sweethome3d ]]; then
  photos=(
    stone_wall:stoneWall:"stone wall (cut blocks)"
    stone_wall_2:stone2Wall:"stone wall (rough blocks)"
    paving:pavingStone:"paving stones"
    pebbles:pebbles:"pebbles"
    marble:marbleWall:"speckled stone"
    roughcast:roughcast:"roughcast plaster"
    red_bricks:smallRedBricks:"brick wall"
    hedge:boxTree:"box hedge (foliage)"
    grass:grass:"grass"
    wood:woodenFloor:"parquet (wood)"
    old_wood:oldWoodenFloor:"old floor boards (wood)"
  )
  if [[ ! -f $cache/photos/stoneWall.png ]]; then
    fetch_deb sweethome3d
    (cd "$cache/photos" && unzip -o -j -q "$tmp"/x/usr/share/sweethome3d/sweethome3d.jar \
      'com/eteks/sweethome3d/io/resources/textures/*.jpg')
    for f in "$cache"/photos/*.jpg; do gmic -v -1 "$f" -o "${f%.jpg}.png" >/dev/null 2>&1; done
    rm -rf "$tmp"
  fi
else
  photos=(
    burlap:burlap:"burlap (fabric)"
    leather:leather:"leather"
    bark:bark:"bark"
    cracked:cracked:"cracked paint"
    amethyst:amethyst:"amethyst (crystals)"
    ground:ground1:"ground (soil and pebbles)"
    rock:rock:"rock"
    stone:stone33:"stone"
    pink_marble:pink_marble:"pink marble"
    terra:terra:"terracotta"
    brick:brick:"bricks"
    burlwood:burlwood:"burl wood"
    walnut:walnut:"walnut"
    pine:pine:"pine"
    parquet:parque1:"parquet"
    crinkle:crinklepaper:"crinkled paper"
    java:java:"coffee beans"
    ice:ice:"ice"
    rain:rain:"rain on water"
  )
  if [[ ! -f $cache/photos/burlap.png ]]; then
    fetch_deb gimp-data
    # GIMP patterns (.pat): a big-endian header (header size, version, width, height, bytes per
    # pixel, "GPAT", name) and the raw pixels; written as PNM, converted by gmic
    for f in "$tmp"/x/usr/share/gimp/2.0/patterns/*/*.pat; do
      n=$(basename "$f" .pat)
      $py -c '
import struct, sys
d = open(sys.argv[1], "rb").read()
hs, ver, w, h, bpp = struct.unpack(">5I", d[:20])
if d[20:24] == b"GPAT" and bpp in (1, 3) and len(d) >= hs + w * h * bpp:
    open(sys.argv[2], "wb").write((b"P5" if bpp == 1 else b"P6") + b"\n%d %d\n255\n" % (w, h) + d[hs:hs + w * h * bpp])
' "$f" "$cache/photos/$n.pnm"
      [[ -f $cache/photos/$n.pnm ]] && gmic -v -1 "$cache/photos/$n.pnm" -o "$cache/photos/$n.png" >/dev/null 2>&1
      rm -f "$cache/photos/$n.pnm"
    done
    rm -rf "$tmp"
  fi
fi

now() { date +%s.%N; }
runs=()
for entry in "${photos[@]}"; do
  IFS=: read -r name file what <<<"$entry"
  [[ -n $only && ,$only, != *,$name,* ]] && continue
  ex=$cache/photos/$file.png
  step "$name ($what)"
  # G'MIC (cached: its output does not depend on our changes)
  g=$cache/gmic_${set}_${name}_$size.png
  if [[ ! -f $g || ! -f $g.json ]]; then
    t0=$(now)
    gmic -v -1 "$ex" -syntexturize_matchpatch "$size,$size" -o "$g" >/dev/null 2>&1
    t1=$(now)
    "$bin" metrics --exemplar "$ex" --in "$g" --step 4 --levels 3 --threads "$threads" |
      $py -c "import json,sys; d=json.loads(sys.stdin.read()); d['time_ms']=($t1-$t0)*1e3; print(json.dumps(d))" >"$g.json"
  fi
  # tessera
  t=$out/tessera_$name.png
  "$bin" synth --exemplar "$ex" --size "${size}x$size" --out "$t" --threads "$threads" --stats "${extra[@]}" \
    >"$out/synth_$name.json"
  # the seams of tessera's patch grid, measured on both outputs (on G'MIC's, which has no grid there, as
  # the control: how much two regions of a good output differ across arbitrary lines)
  read -r pitch overlap < <($py -c "import json,sys; d=json.load(open(sys.argv[1])); print(f'{d[\"patch\"]}x{d[\"patch_height\"]} {d[\"overlap\"]}')" \
    "$out/synth_$name.json")
  grid=(--patch "$pitch" --overlap "$overlap")
  "$bin" metrics --exemplar "$ex" --in "$t" --step 4 --levels 3 "${grid[@]}" --threads "$threads" >"$out/metrics_$name.json"
  "$bin" metrics --exemplar "$ex" --in "$g" --step 8 --levels 1 "${grid[@]}" --threads "$threads" >"$out/gmic_grid_$name.json"
  if [[ -n $images ]]; then
    # exemplar | tessera | G'MIC, 256 x 256 crops at full resolution
    gmic -v -1 "$ex" "$t" "$g" -crop 0,0,255,255,0 -append x -o "$images/$name.png" >/dev/null 2>&1
  fi
  runs+=("$name:$what")
done

step "table"
$py - "$out" "$cache" "$size" "$set-$label" "$set" "${runs[@]}" <<'EOF'
import json, statistics, sys
out, cache, size, label, pset, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5], sys.argv[6:]
rows, agg = [], {k: [] for k in ("te1", "ge1", "te2", "ge2", "te4", "ge4", "tr", "gr", "th", "gh", "ts", "gs", "r1", "r2", "r4")}
fmt = lambda v: f"{v:.4f}"
for run in runs:
    name, what = run.split(":", 1)
    s = json.load(open(f"{out}/synth_{name}.json"))
    m = json.load(open(f"{out}/metrics_{name}.json"))
    g = json.load(open(f"{cache}/gmic_{pset}_{name}_{size}.png.json"))
    gg = json.load(open(f"{out}/gmic_grid_{name}.json"))
    vals = dict(te1=m["energy_1x"], ge1=g["energy_1x"], te2=m["energy_2x"], ge2=g["energy_2x"],
                te4=m["energy_4x"], ge4=g["energy_4x"], ts=m["seam_step_ratio"], gs=gg["seam_step_ratio"],
                tr=m["repetition"], gr=g["repetition"], th=m["histogram_distance"], gh=g["histogram_distance"])
    for k, v in vals.items(): agg[k].append(v)
    for l in "124": agg["r" + l].append(vals["te" + l] / vals["ge" + l])
    win = lambda a, b: "**" + fmt(a) + "**" if a <= b else fmt(a)
    fallback = f'{s["empty_intersections"]}/{s["filled"]}'
    band = f', {s["feather_width"]}' if s.get("seams") == "feather" and "feather_width" in s else ""
    rows.append(f'| {what} | {s["exemplar_width"]}×{s["exemplar_height"]} | {s["patch"]}×{s["patch_height"]}, {s["overlap"]}{band} '
                f'| {fallback} | {win(vals["te1"], vals["ge1"])} / {fmt(vals["ge1"])} '
                f'| {win(vals["te2"], vals["ge2"])} / {fmt(vals["ge2"])} '
                f'| {win(vals["te4"], vals["ge4"])} / {fmt(vals["ge4"])} | {vals["tr"]:.2f} / {vals["gr"]:.2f} '
                f'| {vals["th"]:.3f} / {vals["gh"]:.3f} | {vals["ts"]:.2f} / {vals["gs"]:.2f} '
                f'| {s["preprocess_ms"]:.0f} + {s["synthesis_ms"]:.1f} / {g["time_ms"]:.0f} |')
med = {k: statistics.median(v) for k, v in agg.items()}
lines = [f"Run `{label}`, {size}×{size} outputs, tessera / G'MIC in every cell (bold: tessera no higher).", "",
         "| photograph | exemplar | patch, overlap, feather band | fallback | energy 1× | energy ½× | energy ¼× | repetition | histogram | seam steps | time ms (tessera model + synthesis / G'MIC) |",
         "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"] + rows + [
         f'| **median** | | | | {fmt(med["te1"])} / {fmt(med["ge1"])} | {fmt(med["te2"])} / {fmt(med["ge2"])} '
         f'| {fmt(med["te4"])} / {fmt(med["ge4"])} '
         f'| {med["tr"]:.2f} / {med["gr"]:.2f} | {med["th"]:.3f} / {med["gh"]:.3f} | {med["ts"]:.2f} / {med["gs"]:.2f} | |', "",
         "Median of the per-photograph ratios tessera / G'MIC: " + ", ".join(
             f'{n} {statistics.median(agg["r" + l]):.2f} (no higher on {sum(r <= 1 for r in agg["r" + l])} of {len(agg["r" + l])})'
             for n, l in (("1×", "1"), ("½×", "2"), ("¼×", "4"))) + "."]
open(f"{out}/table.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
EOF
